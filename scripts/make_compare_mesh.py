#!/usr/bin/env python3
"""Writes scenes/compare/blob.gltf: the glTF mesh of the compare scenes.

A sphere of radius 1 whose radius is modulated by 1 + 0.12 sin(3 theta) cos(4 phi)
(a smooth lumpy blob: curvature of both signs, unlike the analytic sphere),
48 x 24 quads, with analytic-free normals (averaged face normals) and
spherical uvs (u = phi / 2 pi, v = theta / pi) times 4. One embedded buffer
(base64 data URI), so the file is self-contained text. CC0.
Run: /usr/bin/python3 scripts/make_compare_mesh.py
"""
import base64
import json
import math
import struct
import pathlib

NU, NV, UV_SCALE = 48, 24, 4.0


def radius(theta, phi):
    return 1.0 + 0.12 * math.sin(3.0 * theta) * math.cos(4.0 * phi)


pos, uv = [], []
for j in range(NV + 1):
    theta = math.pi * j / NV
    for i in range(NU + 1):
        phi = 2.0 * math.pi * i / NU
        r = radius(theta, phi)
        pos.append((r * math.sin(theta) * math.cos(phi), r * math.cos(theta),
                    r * math.sin(theta) * math.sin(phi)))
        uv.append((UV_SCALE * i / NU, UV_SCALE * j / NV))
idx = []
for j in range(NV):
    for i in range(NU):
        a = j * (NU + 1) + i
        b, c, d = a + 1, a + NU + 1, a + NU + 2
        # Counter-clockwise seen from outside (normal outwards).
        idx += [a, b, c, b, d, c]


def sub(p, q):
    return (p[0] - q[0], p[1] - q[1], p[2] - q[2])


def cross(p, q):
    return (p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0])


nrm = [[0.0, 0.0, 0.0] for _ in pos]
for t in range(0, len(idx), 3):
    a, b, c = idx[t:t + 3]
    n = cross(sub(pos[b], pos[a]), sub(pos[c], pos[a]))
    for k in (a, b, c):
        for e in range(3):
            nrm[k][e] += n[e]
# Vertices on the u seam and at the poles share a position: sum their normals.
by_pos = {}
for k, p in enumerate(pos):
    by_pos.setdefault(tuple(round(x, 6) for x in p), []).append(k)
for ks in by_pos.values():
    s = [sum(nrm[k][e] for k in ks) for e in range(3)]
    for k in ks:
        nrm[k] = list(s)
for n in nrm:
    length = math.sqrt(sum(x * x for x in n)) or 1.0
    n[:] = [x / length for x in n]
# Outward check (the centre is inside): flip the winding if needed.
if sum(n[0] * p[0] + n[1] * p[1] + n[2] * p[2] for n, p in zip(nrm, pos)) < 0:
    raise SystemExit("inward normals: winding is wrong")

blob = b"".join(struct.pack("<3f", *p) for p in pos)
off_n = len(blob)
blob += b"".join(struct.pack("<3f", *n) for n in nrm)
off_uv = len(blob)
blob += b"".join(struct.pack("<2f", *t) for t in uv)
off_i = len(blob)
blob += b"".join(struct.pack("<H", i) for i in idx)
while len(blob) % 4:
    blob += b"\0"
lo = [min(p[e] for p in pos) for e in range(3)]
hi = [max(p[e] for p in pos) for e in range(3)]
n = len(pos)
doc = {
    "asset": {"version": "2.0", "generator": "glintlab scripts/make_compare_mesh.py (CC0)"},
    "scene": 0,
    "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0, "name": "blob"}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                "indices": 3}]}],
    "buffers": [{"byteLength": len(blob),
                 "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
    "bufferViews": [
        {"buffer": 0, "byteOffset": 0, "byteLength": off_n, "target": 34962},
        {"buffer": 0, "byteOffset": off_n, "byteLength": off_uv - off_n, "target": 34962},
        {"buffer": 0, "byteOffset": off_uv, "byteLength": off_i - off_uv, "target": 34962},
        {"buffer": 0, "byteOffset": off_i, "byteLength": 2 * len(idx), "target": 34963},
    ],
    "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": n, "type": "VEC3", "min": lo, "max": hi},
        {"bufferView": 1, "componentType": 5126, "count": n, "type": "VEC3"},
        {"bufferView": 2, "componentType": 5126, "count": n, "type": "VEC2"},
        {"bufferView": 3, "componentType": 5123, "count": len(idx), "type": "SCALAR"},
    ],
}
out = pathlib.Path(__file__).resolve().parent.parent / "scenes" / "compare" / "blob.gltf"
out.write_text(json.dumps(doc, indent=1) + "\n")
print(f"wrote {out} ({n} vertices, {len(idx) // 3} triangles)")
