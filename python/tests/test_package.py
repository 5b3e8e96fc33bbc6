"""The installed package as a user meets it: the command beside the module,
the public names documented, display values, progress bars that can be
silenced, compare tables and sweeps with standard errors."""

import inspect
import json
import math
import os
import subprocess
import sys

import matplotlib.pyplot as plt
import numpy as np
import pytest

import glintlab
from glintlab import _progress, _sweep

from conftest import SOURCE_DIR


def test_module_runs_the_command_of_its_own_version():
    done = subprocess.run([sys.executable, "-m", "glintlab", "--version"], capture_output=True,
                          text=True, check=True, cwd=os.path.expanduser("~"))
    assert done.stdout.strip() == f"glintlab {glintlab.__version__}"
    # An unknown command is the program's own error and exit status.
    bad = subprocess.run([sys.executable, "-m", "glintlab", "rendr"], capture_output=True,
                         text=True)
    assert bad.returncode == 1 and "unknown command 'rendr'" in bad.stderr


def test_every_public_function_has_a_docstring():
    for name in glintlab.__all__:
        obj = getattr(glintlab, name)
        if callable(obj) and not inspect.isclass(obj):
            assert (obj.__doc__ or "").strip(), f"glintlab.{name} has no docstring"
    assert "float32" in glintlab.__doc__ and "(H, W, 3)" in glintlab.__doc__


def test_tonemap_gives_the_values_write_image_stores(tmp_path):
    rng = np.random.default_rng(3)
    image = (rng.random((9, 13, 3)) ** 3 * 4).astype(np.float32)
    image[0, 0] = 0.001  # the linear segment of the sRGB curve
    for exposure in (0.0, -1.5):
        glintlab.write_image(tmp_path / "t.png", image, exposure=exposure)
        stored = plt.imread(tmp_path / "t.png")[..., :3]
        shown = glintlab.tonemap(image, exposure=exposure)
        assert shown.dtype == np.float32 and shown.shape == image.shape
        # 8-bit rounding of the PNG: half a step, plus float slack.
        np.testing.assert_allclose(shown, stored, atol=0.5 / 255 + 1e-4)
    with pytest.raises(ValueError, match="NaN"):
        glintlab.tonemap(np.full((2, 2, 3), np.nan, np.float32))


def test_progress_bar_shows_and_can_be_silenced(tiny_scene, capsys, monkeypatch):
    monkeypatch.setattr(_progress, "_DELAY_S", 0.0)  # show at once, for the test
    previous = glintlab.set_progress(True)
    try:
        glintlab.render(tiny_scene, res=(40, 20))
        assert "render" in capsys.readouterr().err
        glintlab.render(tiny_scene, res=(40, 20), progress=False)
        assert capsys.readouterr().err == ""
        glintlab.set_progress(False)
        assert not glintlab.progress_enabled()
        glintlab.render(tiny_scene, res=(40, 20))
        assert capsys.readouterr().err == ""
        glintlab.render(tiny_scene, res=(40, 20), progress=True)
        assert "render:" in capsys.readouterr().err
    finally:
        glintlab.set_progress(previous)
    with pytest.raises(TypeError, match="progress"):
        glintlab.render(tiny_scene, progress="yes")


def test_compare_reports_progress_and_gives_a_table(tmp_path):
    scene = os.path.join(SOURCE_DIR, "scenes", "compare", "lights_point_directional.json")
    fractions = []
    result = glintlab.compare(scene, models=["smooth", "deliot2023"], res=(24, 24),
                              realizations=2, frames=2, flicker_paths=2,
                              progress=fractions.append)
    assert fractions == sorted(fractions) and fractions[-1] == 1.0 and len(fractions) > 2
    table = glintlab.compare_table(result)
    assert list(table["model"]) == ["explicit", "smooth", "deliot2023"]
    assert list(table.columns[:4]) == ["model", "truth", "reference", "backend"]
    cols = list(table.columns)
    assert cols.index("mean_rel_err_se") == cols.index("mean_rel_err") + 1
    assert cols.index("flicker_ratio_se") == cols.index("flicker_ratio") + 1
    row = table.set_index("model").loc["deliot2023"]
    entry = next(m for m in result["models"] if m["model"] == "deliot2023")
    assert row["mean_rel_err"] == entry["mean_rel_err"]
    assert math.isfinite(row["mean_rel_err_se"]) and row["mean_rel_err_se"] > 0


def test_sweep_realizations_give_standard_errors(tiny_scene):
    axes = {"/materials/0/log_density": [8, 14]}
    one = glintlab.sweep(tiny_scene, axes, metrics=["mean_luminance"], client="serial")
    assert one["mean_luminance_se"].isna().all()
    three = glintlab.sweep(tiny_scene, axes, metrics=["mean_luminance"], client="serial",
                           realizations=3)
    cols = list(three.columns)
    assert cols.index("mean_luminance_se") == cols.index("mean_luminance") + 1
    # Realization 0 is the one-realization sweep's render; realizations 1
    # and 2 are other microstructures (glint seed + r) with their own seeds.
    values = {"/materials/0/log_density": 8}
    lum = []
    for r in range(3):
        doc = json.loads(json.dumps(tiny_scene))
        doc["materials"][0]["log_density"] = 8
        doc["materials"][0]["seed"] = r
        image = glintlab.render(doc, seed=_sweep.realization_seed(1, values, r))
        lum.append(_sweep.mean_luminance(image))
    assert lum[0] == one["mean_luminance"][0]
    assert len(set(lum)) == 3
    assert three["mean_luminance"][0] == pytest.approx(np.mean(lum), rel=1e-12)
    assert three["mean_luminance_se"][0] == pytest.approx(np.std(lum, ddof=1) / math.sqrt(3),
                                                          rel=1e-9)
    for bad in (0, 1.5, True, 2000):
        with pytest.raises(ValueError, match="realizations"):
            glintlab.sweep(tiny_scene, axes, client="serial", realizations=bad)


def test_export_writes_the_shader_and_returns_the_manifest(tmp_path):
    manifest = glintlab.export("chermain2020", tmp_path / "out", lang="glsles", resources=False)
    assert manifest["model"] == "chermain2020" and manifest["language"] == "glsles"
    assert manifest["files"][-1] == "chermain2020.glsles.manifest.json"
    for name in manifest["files"]:
        assert (tmp_path / "out" / name).is_file()
    assert manifest["resources"] == []
    with pytest.raises(glintlab.Error, match="explicit.*exportable"):
        glintlab.export("explicit", tmp_path / "x")
    with pytest.raises(glintlab.Error, match="hlsl"):
        glintlab.export("smooth", tmp_path / "y", lang="cuda")
