#!/usr/bin/env python3
"""Builds glintlab binaries with one part of a GPU shader replaced by a cheap
stand-in, to measure where a glint model's frame time goes
(docs/BENCHMARKS.md "Where the time goes on a GPU"). The images of a variant
are WRONG; only its frame time means something, next to the unmodified
binary's ("full") in the same run on the same machine.

Each variant is a textual replacement in the shared GLSL (which the build
embeds into the binary); the script applies it, rebuilds the `glintlab`
target, copies the stripped binary to OUT/<variant>, and restores the file
(also on failure), so the tree is unchanged afterwards. A replacement that no
longer matches the source exactly once stops the script: update it with the
code.

Usage: scripts/shader_cost_variants.py BUILD_DIR OUT_DIR [VARIANT...]
       (default: full and every variant; --list prints them; --check only
       verifies that every replacement still matches, as ctest does)
Then time each binary, e.g.
    OUT/d_nohash bench --gpu --res 1920x1080 --frames 20 --warmup 5 \
        --scene PLANE_25 --model smooth deliot2023 --log-density 12 20 --json
"""
import os
import shutil
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
GLINTS = os.path.join(ROOT, "src", "glintlab", "glints")
DELIOT = os.path.join(GLINTS, "deliot2023", "deliot2023.glsl")
DELIOT_GPU = os.path.join(GLINTS, "deliot2023", "deliot2023_gpu.glsl")
CHERMAIN = os.path.join(GLINTS, "chermain2020", "chermain2020.glsl")
KNEIPHOF = os.path.join(GLINTS, "kneiphof2025", "kneiphof2025.glsl")

# name -> (what it removes, [(file, exact text, replacement)])
VARIANTS = {
    "d_nogrids": (
        "deliot2023: D(h) returned after the exit test (no grids, vertices or counts)",
        [(DELIOT,
          "    Deliot2023PixelPart px =\n        deliot2023_cached_pixel_part(",
          "    return d_h;\n    Deliot2023PixelPart px =\n        deliot2023_cached_pixel_part(")]),
    "d_nocorners": (
        "deliot2023: per vertex p_gate x mean instead of the 4 corners' draws (their hashes and quantiles)",
        [(DELIOT,
          "    float count = 0.0f;\n    do {\n",
          "    float count = law.p_gate * law.mean + at.x * 1e-30f;\n    open = 0;\n    do {\n")]),
    "d_nohash": (
        "deliot2023: the corners' uniform pair from a fract() of the corner, not hashed",
        [(DELIOT,
          "vec2 xi = deliot2023_corner_uniforms(corner & ivec2(DELIOT2023_LATTICE_MASK), vs);",
          "vec2 xi = fract(vec2(corner) * vec2(0.6180339f, 0.7548776f) + float(vs & 255u) * 0.0037f);")]),
    "d_noquantile": (
        "deliot2023 corners: a linear stand-in for the gated law's normal quantile",
        [(DELIOT,
          "            float g = clamp(law.mean + law.sd * normal_quantile(gauss_xi[c]), lo, law.top);\n",
          "            float g = clamp(law.mean + law.sd * (3.0f * gauss_xi[c] - 1.5f), lo, law.top);\n")]),
    "d_unrollall": (
        "deliot2023: NVIDIA's #pragma optionNV(unroll all) (nothing removed)",
        [(DELIOT_GPU,
          "#define GLINTLAB_DELIOT2023_EXPECTATION_EXITS 1\n",
          "#define GLINTLAB_DELIOT2023_EXPECTATION_EXITS 1\n#pragma optionNV(unroll all)\n")]),
    "d_nounroll": (
        "deliot2023: NVIDIA's #pragma optionNV(unroll none) (nothing removed)",
        [(DELIOT_GPU,
          "#define GLINTLAB_DELIOT2023_EXPECTATION_EXITS 1\n",
          "#define GLINTLAB_DELIOT2023_EXPECTATION_EXITS 1\n#pragma optionNV(unroll none)\n")]),
    "c_nocells": (
        "chermain2020: every cell in the ellipse returns the analytic target (no stream, no fetch)",
        [(CHERMAIN,
          "            vec2 sdf = chermain2020_cell_sdf(cell, level, d, log_density, relative_area,\n"
          "                                             density_randomization, seed, lookup);",
          "            vec2 sdf = vec2(lookup.target_p22, fract(float(cell.x) * 0.618f));")]),
    "c_nomarginals": (
        "chermain2020: the marginals' dictionary texel pair computed, not fetched",
        [(CHERMAIN,
          "    vec2 ab = chermain2020_dict_fetch_pair(dist * d.n_levels + level, k, d.table_size);",
          "    vec2 ab = vec2(1.0f - float(k) / float(d.table_size), "
          "1.0f - float(k + 1) / float(d.table_size)) * float(dist + level + 1);")]),
    "k_factor1": (
        "kneiphof2025 IBL: the glint factor replaced by 1 (smooth term and weight fetches kept)",
        [(KNEIPHOF,
          "        factor =\n"
          "            kneiphof2025_ibl_factor(fp, log_density, seed, screen_space_scale,\n"
          "                                    density_randomization, levels, p_a, p_b, L_a, L_b, conditional);",
          "        factor = min(1.0f, 1.0f + p_a.x + p_b.x + 1e-30f * float(seed));")]),
    "k_lobe_onelayer": (
        "kneiphof2025: the layer fetches read one layer (no blend of two)",
        [(KNEIPHOF,
          "    vec4 b = textureLod(layers, vec3(uv.x, uv.y, l1), 0.0f);\n    return mix(a, b, l - l0);",
          "    return a * (1.0f + 1e-30f * (l - l0 + l1));")]),
    "k_lobe_nolatlong": (
        "kneiphof2025: the layer fetches at a lat-long uv without acos / atan (d.xy remapped)",
        [(KNEIPHOF,
          "    vec2 uv = kneiphof2025_latlong_uv(dir);\n    float l = clamp",
          "    vec2 uv = dir.xy * 0.5f + 0.5f;\n    float l = clamp")]),
    "k_lobe_nofetch": (
        "kneiphof2025: the lobe's 32 samples read no texture (constant radiance)",
        [(KNEIPHOF,
          "    if (!residual) return kneiphof2025_radiance_fetch(dir, level);\n",
          "    return vec3(0.5f + 1e-30f * (dir.x + level));\n")]),
    "k_fastlatlong": (
        "kneiphof2025: polynomial acos (Abramowitz & Stegun 4.4.45, 7e-5 rad) and atan "
        "(octant-reduced minimax, 1e-5 rad) in the lat-long mapping",
        [(KNEIPHOF,
          "    float theta = acos(clamp(d.y, -1.0f, 1.0f));\n    float phi = atan(d.x, -d.z) - kneiphof2025_env_rotation;",
          "    float y = clamp(d.y, -1.0f, 1.0f);\n"
          "    float ay = abs(y);\n"
          "    float ac = sqrt(1.0f - ay) * (1.5707288f + ay * (-0.2121144f + ay * (0.0742610f - 0.0187293f * ay)));\n"
          "    float theta = y >= 0.0f ? ac : PI - ac;\n"
          "    float X = -d.z; float Y = d.x; float ax = abs(X); float ayy = abs(Y);\n"
          "    float q = min(ax, ayy) / max(max(ax, ayy), 1e-30f); float q2 = q * q;\n"
          "    float at = q * (0.99997726f + q2 * (-0.33262347f + q2 * (0.19354346f + q2 * (-0.11643287f + q2 * (0.05265332f - 0.01172120f * q2)))));\n"
          "    if (ayy > ax) at = 1.5707963f - at; if (X < 0.0f) at = PI - at; if (Y < 0.0f) at = -at;\n"
          "    float phi = at - kneiphof2025_env_rotation;")]),
}


def build(build_dir, out_dir, name):
    subprocess.run(["ninja", "glintlab"], cwd=build_dir, check=True, stdout=subprocess.DEVNULL)
    target = os.path.join(out_dir, name)
    shutil.copy(os.path.join(build_dir, "glintlab"), target)
    subprocess.run(["strip", target], check=True)


def main(argv):
    if "--list" in argv:
        for name, (what, _) in VARIANTS.items():
            print(f"{name:14s} {what}")
        return 0
    if "--check" in argv:  # every replacement still matches its source once (ctest)
        stale = [f"{name}: {os.path.relpath(path, ROOT)}"
                 for name, (_, edits) in VARIANTS.items() for path, text, _ in edits
                 if open(path).read().count(text) != 1]
        for s in stale:
            print(f"stale variant {s}: update its text with the code", file=sys.stderr)
        return 1 if stale else 0
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    build_dir, out_dir = os.path.abspath(argv[0]), os.path.abspath(argv[1])
    names = argv[2:] or ["full", *VARIANTS]
    unknown = [n for n in names if n != "full" and n not in VARIANTS]
    if unknown:
        print(f"unknown variant(s) {unknown}; known: full {' '.join(VARIANTS)}", file=sys.stderr)
        return 2
    os.makedirs(out_dir, exist_ok=True)
    try:
        for name in names:
            saved = {}
            try:
                for path, text, replacement in ([] if name == "full" else VARIANTS[name][1]):
                    source = saved.get(path) or open(path).read()
                    current = open(path).read()
                    if current.count(text) != 1:
                        raise SystemExit(f"{name}: the text to replace is not found exactly once in {path}")
                    saved.setdefault(path, source)
                    with open(path, "w") as f:
                        f.write(current.replace(text, replacement))
                build(build_dir, out_dir, name)
            finally:
                for path, source in saved.items():
                    with open(path, "w") as f:
                        f.write(source)
            print(f"built {os.path.join(out_dir, name)}", flush=True)
    finally:
        # Leave the build directory's binary that of the unmodified sources.
        subprocess.run(["ninja", "glintlab"], cwd=build_dir, check=True, stdout=subprocess.DEVNULL)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
