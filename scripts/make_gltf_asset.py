#!/usr/bin/env python3
"""Writes scenes/gltf/glint_tiles.glb, the textured glTF asset of the
scenes and tests that read a file's own materials (docs/SCENE_FORMAT.md,
"glTF materials"). Python's standard library and NumPy only; about 40 KiB.

  node "plate"   a 2 x 2 quad in the xz plane (normal +y), uvs 0..1 over it,
                 material "Paint"
  node "ball"    a uv sphere of radius 0.5 at (0, 0.5, 0), material "Trim"

  "Paint"  pbrMetallicRoughness with
           baseColorTexture          64 x 64 sRGB PNG: a blue/orange checker of
                                     8 x 8 cells, KHR_texture_transform scale 2
           metallicRoughnessTexture  64 x 64 PNG: G (perceptual roughness) 0.3
                                     left of u = 1/2 and 0.6 right of it; B
                                     (metallic) 1 in the top half, 0 below
           normalTexture             64 x 64 PNG: gentle bumps, scale 1
  "Trim"   factors only: base colour (0.9, 0.8, 0.6), metallic 1, roughness 0.4,
           with KHR_materials_ior (ior 1.45) and KHR_materials_sheen (which
           glintlab names in a warning)

The images are stored in the GLB's binary chunk. Run from the repository root:
  python3 scripts/make_gltf_asset.py
"""
import json
import os
import struct
import zlib

import numpy as np

OUT = os.path.join("scenes", "gltf", "glint_tiles.glb")
SIZE = 64


def png(rgb):
    """An 8-bit RGB PNG of the uint8 array rgb (rows from the top)."""
    h, w, _ = rgb.shape
    raw = b"".join(b"\x00" + rgb[y].tobytes() for y in range(h))

    def chunk(tag, data):
        body = tag + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    header = struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9))
            + chunk(b"IEND", b""))


def textures():
    y, x = np.mgrid[0:SIZE, 0:SIZE]
    u, v = (x + 0.5) / SIZE, (y + 0.5) / SIZE
    checker = ((x // 8 + y // 8) % 2).astype(bool)
    base = np.where(checker[..., None], [40, 90, 200], [230, 140, 40]).astype(np.uint8)
    mr = np.zeros((SIZE, SIZE, 3), np.uint8)
    mr[..., 1] = np.where(u < 0.5, round(0.3 * 255), round(0.6 * 255))
    mr[..., 2] = np.where(v < 0.5, 255, 0)
    two_pi = 2 * np.pi
    gu = 0.25 * np.cos(two_pi * 2 * u) * np.cos(two_pi * 3 * v)
    gv = -0.25 * np.sin(two_pi * 2 * u) * np.sin(two_pi * 3 * v)
    n = np.stack([-gu, gv, np.ones_like(gu)], axis=-1)
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    normal = np.clip(np.round((n * 0.5 + 0.5) * 255), 0, 255).astype(np.uint8)
    return png(base), png(mr), png(normal)


def quad():
    p = np.array([[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]], np.float32)
    n = np.tile(np.array([0, 1, 0], np.float32), (4, 1))
    uv = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], np.float32)
    idx = np.array([0, 2, 1, 0, 3, 2], np.uint16)  # counter-clockwise seen from +y
    return p, n, uv, idx


def sphere(rings=24, segments=48, radius=0.5, center=(0, 0.5, 0)):
    theta = np.linspace(0, np.pi, rings + 1)
    phi = np.linspace(0, 2 * np.pi, segments + 1)
    t, f = np.meshgrid(theta, phi, indexing="ij")
    n = np.stack([np.sin(t) * np.cos(f), np.cos(t), -np.sin(t) * np.sin(f)], -1).reshape(-1, 3)
    p = (radius * n + np.array(center)).astype(np.float32)
    uv = np.stack([f / (2 * np.pi), t / np.pi], -1).reshape(-1, 2).astype(np.float32)
    idx = []
    for r in range(rings):
        for s in range(segments):
            a, b = r * (segments + 1) + s, (r + 1) * (segments + 1) + s
            idx += [a, b, a + 1, a + 1, b, b + 1]
    return p, n.astype(np.float32), uv, np.array(idx, np.uint16)


def main():
    blob = bytearray()
    views, accessors = [], []

    def add_view(data, target=None):
        while len(blob) % 4:
            blob.append(0)
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data)})
        if target:
            views[-1]["target"] = target
        blob.extend(data)
        return len(views) - 1

    def add_accessor(array, kind):
        view = add_view(array.tobytes(), 34963 if kind == "SCALAR" else 34962)
        acc = {"bufferView": view, "count": len(array), "type": kind,
               "componentType": 5123 if array.dtype == np.uint16 else 5126}
        if kind == "VEC3" and array.dtype == np.float32:
            acc["min"] = array.min(0).tolist()
            acc["max"] = array.max(0).tolist()
        accessors.append(acc)
        return len(accessors) - 1

    meshes = []
    for name, (p, n, uv, idx), material in (("plate", quad(), 0), ("ball", sphere(), 1)):
        prim = {"attributes": {"POSITION": add_accessor(p, "VEC3"),
                               "NORMAL": add_accessor(n, "VEC3"),
                               "TEXCOORD_0": add_accessor(uv, "VEC2")},
                "indices": add_accessor(idx, "SCALAR"), "material": material}
        meshes.append({"name": name, "primitives": [prim]})
    images = [{"bufferView": add_view(data), "mimeType": "image/png", "name": name}
              for name, data in zip(("base_color", "metallic_roughness", "normal"), textures())]
    doc = {
        "asset": {"version": "2.0", "generator": "glintlab scripts/make_gltf_asset.py"},
        "extensionsUsed": ["KHR_texture_transform", "KHR_materials_ior", "KHR_materials_sheen"],
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"name": "plate", "mesh": 0}, {"name": "ball", "mesh": 1}],
        "meshes": meshes,
        "materials": [
            {"name": "Paint",
             "pbrMetallicRoughness": {
                 "baseColorTexture": {"index": 0, "extensions": {
                     "KHR_texture_transform": {"scale": [2, 2]}}},
                 "metallicRoughnessTexture": {"index": 1}},
             "normalTexture": {"index": 2, "scale": 1.0}},
            {"name": "Trim",
             "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.8, 0.6, 1],
                                      "metallicFactor": 1.0, "roughnessFactor": 0.4},
             "extensions": {"KHR_materials_ior": {"ior": 1.45},
                            "KHR_materials_sheen": {"sheenColorFactor": [1, 1, 1]}}},
        ],
        "textures": [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 0},
                     {"source": 2, "sampler": 0}],
        "samplers": [{"wrapS": 10497, "wrapT": 10497}],
        "images": images,
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(blob)}],
    }
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    while len(blob) % 4:
        blob.append(0)
    total = 12 + 8 + len(text) + 8 + len(blob)
    out = struct.pack("<4sII", b"glTF", 2, total)
    out += struct.pack("<I4s", len(text), b"JSON") + text
    out += struct.pack("<I4s", len(blob), b"BIN\x00") + bytes(blob)
    os.makedirs(os.path.dirname(OUT), exist_ok=True)
    with open(OUT, "wb") as f:
        f.write(out)
    print(f"{OUT}: {len(out)} bytes")


if __name__ == "__main__":
    main()
