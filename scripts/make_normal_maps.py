#!/usr/bin/env python3
"""Writes the tangent-space normal maps of the normal-mapped compare scenes
(scenes/compare/normal_*.json) into scenes/compare/textures/, as EXR files
that store the unit normal itself ("encoding": "signed"; glTF's convention:
x along +u, y up in the image, i.e. along -v, z out of the surface):

  bumps.exr      128 x 128, low frequency: a smooth periodic height field (a few bumps
                 across the map), tilts up to about 25 degrees
  scratches.exr  256 x 256, high frequency: 48 straight V-grooves 3 texels wide in
                 random directions that wrap around the tile, walls at 27
                 degrees; flat between them
  ridges.exr     128 x 128, diagonal: 16 sinusoidal ridges along u = v, slopes up to
                 0.3 with s_x = -s_y, so the footprint's slopes are correlated

Both tile with period 1 in u and v. Run from the repository root with the
Python module on the path:
  env/bin/python scripts/make_normal_maps.py
"""
import os

import numpy as np

import glintlab

N = 256
OUT = os.path.join("scenes", "compare", "textures")


def normals(grad_u, grad_v):
    """Unit normals of a height field h(u, v) from its uv gradient."""
    # y is up in the image (-v): dh/dy = -dh/dv.
    n = np.stack([-grad_u, grad_v, np.ones_like(grad_u)], axis=-1)
    return (n / np.linalg.norm(n, axis=-1, keepdims=True)).astype(np.float32)


def bumps(u, v):
    two_pi = 2 * np.pi
    a = 0.035
    grad_u = a * two_pi * (3 * np.cos(two_pi * 3 * u) * np.cos(two_pi * 2 * v)
                           + 0.5 * 2 * np.cos(two_pi * (2 * u + 5 * v)))
    grad_v = a * two_pi * (-2 * np.sin(two_pi * 3 * u) * np.sin(two_pi * 2 * v)
                           + 0.5 * 5 * np.cos(two_pi * (2 * u + 5 * v)))
    return normals(grad_u, grad_v)


def scratches(u, v):
    rng = np.random.default_rng(7)
    grad_u = np.zeros_like(u)
    grad_v = np.zeros_like(u)
    half_width = 1.5 / N
    slope = 0.5
    for _ in range(48):
        # Integer directions keep every groove periodic on the unit tile.
        a, b = rng.integers(-4, 5, size=2)
        if a == 0 and b == 0:
            a = 1
        length = np.hypot(a, b)
        phase = b * u - a * v + rng.random()
        signed = (np.mod(phase + 0.5, 1.0) - 0.5) / length  # distance across the groove
        inside = np.abs(signed) < half_width
        side = np.sign(signed) * inside
        grad_u += slope * side * b / length
        grad_v += slope * side * (-a) / length
    return normals(grad_u, grad_v)


def ridges(u, v):
    # h = a sin(2 pi 16 (u + v)) / (2 pi 16): the gradient is (c, c) in uv,
    # (c, -c) in the tangent frame (y along -v): perfectly anti-correlated.
    c = 0.3 * np.cos(2 * np.pi * 16 * (u + v))
    return normals(c, c)


def main():
    os.makedirs(OUT, exist_ok=True)
    for name, size, make in (("bumps.exr", 128, bumps), ("scratches.exr", N, scratches),
                             ("ridges.exr", 128, ridges)):
        v, u = np.mgrid[0:size, 0:size].astype(np.float64)
        glintlab.write_image(os.path.join(OUT, name), make((u + 0.5) / size, (v + 0.5) / size))


if __name__ == "__main__":
    main()
