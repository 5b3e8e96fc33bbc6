"""glintlab.compare: the binding of `glintlab compare` (compare/compare.h)
returns the CLI's metrics.json document."""

import json
import subprocess

import pytest

import glintlab
from conftest import CLI

# A point and a sphere light (zirr2016 shades no sphere light), ln density 12:
# a few hundred facets per pixel, so the explicit truth is cheap and lit.
SCENE = {
    "film": {"width": 20, "height": 20},
    "camera": {"eye": [0, 0, 3.2], "target": [0, 0, 0], "fov_deg": 45},
    "render": {"integrator": "direct", "spp": 2, "seed": 1},
    "materials": [{"name": "glitter", "type": "glint", "model": "explicit", "ndf": "ggx",
                   "roughness": 0.3, "log_density": 12, "fresnel": {"type": "none"}}],
    "shapes": [{"type": "sphere", "radius": 1, "material": "glitter"}],
    "lights": [{"type": "point", "position": [2, 2, 3], "intensity": 8},
               {"type": "sphere", "center": [-2, 1, 2], "radius": 0.3, "radiance": 10}],
}


def test_compare_matches_the_cli_json(tmp_path):
    scene = tmp_path / "tiny.json"
    scene.write_text(json.dumps(SCENE))
    result = glintlab.compare(scene, models=["smooth", "zirr2016"], realizations=2, frames=2,
                              output=tmp_path / "out")
    rows = {m["model"]: m for m in result["models"]}
    assert set(rows) == {"explicit", "smooth", "zirr2016"}
    assert rows["explicit"]["reference"]
    assert not rows["zirr2016"]["compared"] and "sphere" in rows["zirr2016"]["reason"]
    smooth = rows["smooth"]
    assert smooth["compared"] and smooth["nan_count"] == 0 and smooth["negative_count"] == 0
    assert (tmp_path / "out" / "grid.png").exists()
    assert (tmp_path / "out" / "metrics.csv").exists()
    # The CLI on the same scene and options: the same deterministic metrics
    # (fixed seeds, per-pixel sample streams); only the timings differ.
    cli = subprocess.run([CLI, "compare", str(scene), "--models", "smooth,zirr2016",
                          "--realizations", "2", "--frames", "2", "--json", "-o",
                          str(tmp_path / "cli")], check=True, capture_output=True, text=True)
    cli_rows = {m["model"]: m for m in json.loads(cli.stdout)["models"]}
    for key in ("mean_rel_err", "mean_rel_err_se", "blurred_rel_rmse", "variance_ratio",
                "sampling_variance", "structure_variance_ratio", "wasserstein", "flicker_ratio",
                "flicker_se", "flicker_ratio_se"):
        assert smooth[key] == cli_rows["smooth"][key], key
    assert result["flicker_paths"] == 4  # the CLI's default too


def test_compare_matches_the_facet_extent_unless_asked_not_to(tmp_path):
    scene = tmp_path / "tiny.json"
    scene.write_text(json.dumps(SCENE))
    common = dict(models=["jakob2014"], realizations=2, frames=2, res="12x12",
                  truth_realizations=3)
    matched = {m["model"]: m for m in glintlab.compare(scene, **common)["models"]}
    assert matched["jakob2014"]["facet_extent"] == "gamma_deg 1"
    assert matched["explicit"]["facet_extent"] == "gamma_deg 1"
    defaults = {m["model"]: m for m in glintlab.compare(
        scene, match_facet_extent=False, **common)["models"]}
    assert defaults["jakob2014"]["facet_extent"] == "the model's defaults"


def test_compare_errors_name_the_option(tmp_path):
    scene = tmp_path / "tiny.json"
    scene.write_text(json.dumps(SCENE))
    with pytest.raises(glintlab.Error, match="unknown model"):
        glintlab.compare(scene, models="nosuch")
    with pytest.raises(glintlab.Error, match="realizations"):
        glintlab.compare(scene, realizations=1)
