#!/usr/bin/env python3
"""Writes the texture maps of the textured compare scenes
(scenes/compare/textured_*.json) into scenes/compare/textures/:

  density.exr    ln N: a smooth field of 10-12 with a disc of 13 and a bar
                 of 9 (steps, where a model's density must not seam)
  roughness.exr  alpha: 0.12-0.32 in a smooth field (resolved by the
                 footprints: the filtered alpha^2 is the footprint's NDF)
  roughness_checker.exr
                 the same field with a checker of 0.1/0.3 in one quadrant
                 (sub-footprint variation: a mixture of NDFs, which one
                 filtered NDF approximates; docs/MODELS.md)
  colour.png     sRGB stripes and a gradient (the tint)

Run from the repository root with the Python module on the path:
  env/bin/python scripts/make_compare_textures.py
"""
import os

import numpy as np

import glintlab

N = 256
OUT = os.path.join("scenes", "compare", "textures")


def main():
    os.makedirs(OUT, exist_ok=True)
    v, u = np.mgrid[0:N, 0:N].astype(np.float32)
    u = (u + 0.5) / N
    v = (v + 0.5) / N
    field = 0.5 + 0.25 * np.sin(2 * np.pi * (u + 0.3 * v)) + 0.25 * np.cos(2 * np.pi * 2 * v)
    ln_n = 10.0 + 2.0 * field
    ln_n[(u - 0.62) ** 2 + (v - 0.4) ** 2 < 0.15 ** 2] = 13.0
    ln_n[(np.abs(v - 0.8) < 0.05) & (u < 0.7)] = 9.0
    alpha = 0.12 + 0.2 * field
    alpha_checker = alpha.copy()
    checker = ((np.floor(u * 32) + np.floor(v * 32)) % 2).astype(np.float32)
    quadrant = (u < 0.5) & (v < 0.5)
    alpha_checker[quadrant] = np.where(checker[quadrant] > 0, 0.3, 0.1)
    colour = np.stack([0.35 + 0.6 * u, 0.55 + 0.35 * np.sin(2 * np.pi * 4 * v) ** 2,
                       0.9 - 0.5 * u], axis=-1)
    grey = lambda a: np.repeat(a[..., None], 3, axis=2).astype(np.float32)  # noqa: E731
    glintlab.write_image(os.path.join(OUT, "density.exr"), grey(ln_n))
    glintlab.write_image(os.path.join(OUT, "roughness.exr"), grey(alpha))
    glintlab.write_image(os.path.join(OUT, "roughness_checker.exr"), grey(alpha_checker))
    glintlab.write_image(os.path.join(OUT, "colour.png"), colour.astype(np.float32))


if __name__ == "__main__":
    main()
