"""A sweep along a textured plane's depth (docs/VALIDATION.md, "Textured
parameters and normal maps"): from the camera to the horizon a pixel's
footprint grows from below one texel to over ten, so every level of detail
of the maps' mip chains and of each model's grid is crossed. A change of
level must not show as a step in the image: each rows' mean is a smooth
function of depth.

The maps vary across u only, at the texel scale (ln N 10 / 13 in
alternating texels, alpha 0.2 / 0.4 in alternating pairs), so rows average
them and the profile has no texture of its own. Two checks:

- The textured smooth material against itself rendered at 8x the
  resolution and box-averaged (footprints 3 levels finer): their ratio
  moves from the near rows, where both resolve the stripes, to the far
  ones, where both filter them, and its second difference over blocks of
  rows stays below 5 standard errors.
- Each glint model against the smooth material of the same maps (the
  same filtered inputs, so what is left are the model's own levels): the
  same bound on the blocks' ratio, which also stays within 5 % + 3 se of 1.

Standard errors come from two renders with different seeds. Both
statistics are standard normal without a step; 5 sigma over ~12 blocks
with a sigma estimated from 12 pairs (about 20 % uncertain) leaves a false
alarm below 1e-3, while a step of one filtered level (the one-NDF limit
moves the smooth profile by up to 20 % between levels here) is tens of
sigmas.
"""

import numpy as np
import pytest

import glintlab

WIDTH, HEIGHT, BLOCK = 32, 128, 8


def _maps():
    x = np.arange(64)[None, :].repeat(4, 0)
    density = np.where(x % 2 == 0, 10.0, 13.0).astype(np.float32)
    roughness = np.where((x // 2) % 2 == 0, 0.2, 0.4).astype(np.float32)
    return density, roughness


def _scene(model, ndf, width, height, spp, seed):
    density, roughness = _maps()
    return {
        "film": {"width": width, "height": height},
        # A grazing view down a 60-unit plane: 13-20 degrees of elevation.
        "camera": {"eye": [0, 0.6, 3], "target": [0, 0, 0.2], "fov_deg": 30},
        "render": {"integrator": "direct", "spp": spp, "seed": seed},
        "materials": [{"name": "m", "type": "glint", "model": model, "ndf": ndf, "seed": seed,
                       "log_density": {"texture": density},
                       "roughness": {"texture": roughness}}],
        "shapes": [{"type": "quad", "size": [3, 60], "uv_scale": [4, 80], "material": "m"}],
        "lights": [{"type": "directional", "direction": [0, 0.35, -1], "irradiance": 2}],
    }


def _rows(model, ndf="beckmann", scale=1, spp=4, seed=1):
    image = glintlab.render(_scene(model, ndf, WIDTH * scale, HEIGHT * scale, spp, seed),
                            threads=2)[..., 0].astype(np.float64)
    if scale > 1:
        image = image.reshape(HEIGHT, scale, WIDTH, scale).mean(axis=(1, 3))
    assert np.isfinite(image).all() and image.min() >= 0.0
    return image.mean(axis=1)


def _plane_rows(rows):
    # From a few rows below the plane's far edge (pixels there are partly sky).
    lit = np.flatnonzero(rows > 0)
    assert lit.size > 3 * BLOCK * 4, "the plane must fill most of the image"
    return slice(lit[0] + 6, HEIGHT)


def _blocks(values):
    n = values.size // BLOCK * BLOCK
    return values[:n].reshape(-1, BLOCK).mean(axis=1)


def _second_differences(ratio, se):
    # In standard errors: a trend's slope cancels, a step leaves +d then -d.
    return np.abs(ratio[2:] - 2 * ratio[1:-1] + ratio[:-2]) / (se * np.sqrt(6))


def test_the_filtered_maps_change_smoothly_with_the_level_of_detail():
    fine = _rows("smooth", scale=8, spp=1)
    plane = _plane_rows(fine)
    a = _blocks(_rows("smooth", seed=1)[plane] / fine[plane])
    b = _blocks(_rows("smooth", seed=2)[plane] / fine[plane])
    se = np.std(a - b) / np.sqrt(2) / np.sqrt(2)  # of the two seeds' mean block
    ratio = (a + b) / 2
    second = _second_differences(ratio, se)
    assert second.max() < 5.0, f"ratio to the 8x render by block: {np.round(ratio, 3)}"


@pytest.mark.parametrize("model,ndf", [("deliot2023", "beckmann"), ("zirr2016", "beckmann"),
                                       ("chermain2020", "beckmann"), ("kneiphof2025", "ggx")])
def test_each_models_levels_leave_no_step_along_the_depth(model, ndf):
    smooth = _rows("smooth", ndf)
    plane = _plane_rows(smooth)
    a = _blocks(_rows(model, ndf, seed=1)[plane] / smooth[plane])
    b = _blocks(_rows(model, ndf, seed=2)[plane] / smooth[plane])
    se = np.std(a - b) / np.sqrt(2) / np.sqrt(2)
    ratio = (a + b) / 2
    second = _second_differences(ratio, se)
    assert second.max() < 5.0, f"{model} / smooth by block: {np.round(ratio, 3)}, se {se:.3f}"
    assert np.abs(ratio - 1).max() < 0.05 + 3 * se, np.round(ratio, 3)
