"""glintlab.sweep on Dask distributed: cluster results equal serial ones,
a killed worker loses nothing and counts nothing twice, outputs are written."""

import json
import os
import re
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pandas as pd
import pytest

import glintlab

AXES = {"/materials/0/log_density": [8, 12, 16], "model": ["smooth", "deliot2023"]}


def _values(table):
    return table.drop(columns=["render_s"])


def test_cluster_sweep_equals_serial_sweep(tiny_scene, cluster):
    _, client = cluster
    serial = glintlab.sweep(tiny_scene, AXES, client="serial", reference={"model": "smooth"})
    dist = glintlab.sweep(tiny_scene, AXES, client=client, reference={"model": "smooth"})
    assert list(dist["point"]) == list(range(6))
    pd.testing.assert_frame_equal(_values(serial), _values(dist))
    # Points differ (the sweep is not a constant), and rel_error against the
    # smooth reference is 0 exactly for the smooth model's own points.
    assert serial["mean_luminance"].nunique() > 1
    assert (serial.loc[serial["model"] == "smooth", "rel_error"] == 0).all()
    # The row of a point is that point's own render.
    row = serial.iloc[3]
    image = glintlab.render(tiny_scene, model=row["model"],
                            overrides={"/materials/0/log_density": int(row["/materials/0/log_density"])},
                            seed=glintlab._sweep.point_seed(1, {"/materials/0/log_density": 12,
                                                                "model": "deliot2023"}))
    assert row["mean_luminance"] == glintlab._sweep.mean_luminance(image)


def test_killed_worker_still_gives_each_point_once(tiny_scene, cluster):
    lc, client = cluster
    axes = {"/materials/0/log_density": [6, 8, 10, 12, 14, 16], "/lights/0/irradiance": [1.0, 2.0]}
    # Renders long enough (64x64, 8 spp) that the kill lands while tasks run.
    kw = dict(res=(64, 64), spp=8)
    expected = glintlab.sweep(tiny_scene, axes, client="serial", **kw)
    pids = client.run(os.getpid)
    victim_addr, victim_pid = sorted(pids.items())[0]
    result = {}
    runner = threading.Thread(
        target=lambda: result.update(table=glintlab.sweep(tiny_scene, axes, client=client, **kw)))
    runner.start()
    # Wait until the victim runs a task, then kill its process outright.
    deadline = time.monotonic() + 60
    while not client.processing().get(victim_addr) and time.monotonic() < deadline:
        time.sleep(0.005)
    assert client.processing().get(victim_addr), "the victim never received a task"
    os.kill(victim_pid, signal.SIGKILL)
    runner.join(timeout=120)
    assert not runner.is_alive()
    table = result["table"]
    assert sorted(table["point"]) == list(range(12)) and table["point"].is_unique
    pd.testing.assert_frame_equal(_values(expected), _values(table))
    # The nanny restarted the worker: the cluster still has two.
    client.wait_for_workers(2, timeout=60)
    assert victim_pid not in client.run(os.getpid).values()


def test_outputs_and_command_line(tiny_scene, cluster, tmp_path):
    lc, client = cluster
    scene_file = tmp_path / "tiny.json"
    scene_file.write_text(json.dumps(tiny_scene))
    spec = {"scene": "tiny.json", "axes": {"/materials/0/log_density": [8, 16],
                                           "model": ["deliot2023", "zirr2016"]},
            "metrics": ["mean_luminance", "rel_error"], "reference": {"model": "smooth"},
            "res": [16, 16], "output": "out"}
    (tmp_path / "sweep.json").write_text(json.dumps(spec))
    env = dict(os.environ)
    subprocess.run([sys.executable, "-m", "glintlab.sweep", str(tmp_path / "sweep.json"),
                    "--scheduler", lc.scheduler_address], check=True, env=env, capture_output=True)
    out = tmp_path / "out"
    table = pd.read_csv(out / "sweep.csv")
    assert list(table["point"]) == [0, 1, 2, 3]
    in_process = glintlab.sweep(scene_file, spec["axes"], metrics=spec["metrics"],
                                reference=spec["reference"], res=(16, 16), client="serial")
    np.testing.assert_allclose(table["rel_error"], in_process["rel_error"], rtol=1e-12)
    plots = sorted(p for p in os.listdir(out) if p.endswith(".png"))
    # (2 metrics + render_s) × 2 axes
    assert len(plots) == 6
    for p in plots:
        with open(out / p, "rb") as f:
            assert f.read(8) == b"\x89PNG\r\n\x1a\n"
        assert os.path.getsize(out / p) > 1000


def test_bad_axes_are_rejected_before_any_task(tiny_scene):
    with pytest.raises(glintlab.OverrideError, match="/materials/2/log_density"):
        glintlab.sweep(tiny_scene, {"/materials/2/log_density": [1]}, client="serial")
    with pytest.raises(ValueError, match="reference"):
        glintlab.sweep(tiny_scene, {"model": ["smooth"]}, metrics=["rel_error"], client="serial")


def test_script_without_main_guard_finishes(tiny_scene, tmp_path):
    """A user's first script: glintlab.sweep at module level with the default
    client. With a process cluster every spawned worker re-ran the script (no
    `if __name__ == "__main__":`) and the sweep hung; the default cluster is
    one of threads, so the script ends with the table."""
    scene = tmp_path / "tiny.json"
    scene.write_text(json.dumps(tiny_scene))
    script = tmp_path / "first_sweep.py"
    script.write_text(
        "import glintlab\n"
        f"table = glintlab.sweep({str(scene)!r}, {{'/materials/0/log_density': [8, 12]}})\n"
        "print('ROWS', len(table))\n")
    done = subprocess.run([sys.executable, str(script)], capture_output=True, text=True,
                          timeout=300, env=os.environ.copy(), cwd=tmp_path)
    assert done.returncode == 0, done.stderr[-2000:]
    assert "ROWS 2" in done.stdout


def test_density_example_plots_standard_errors(tmp_path):
    """examples/sweep_density.py: every point over several material seeds,
    against the truth of the same seeds, with its standard error; a black
    truth is listed, not dropped (it was a silent NaN, and one realization of
    the truth put every model ~70 % off at ln 10)."""
    from conftest import SOURCE_DIR
    example = os.path.join(SOURCE_DIR, "examples", "sweep_density.py")
    done = subprocess.run([sys.executable, example, "--realizations", "2", "-o", str(tmp_path)],
                          capture_output=True, text=True, timeout=600, env=os.environ.copy())
    assert done.returncode == 0, done.stderr[-2000:]
    table = pd.read_csv(tmp_path / "sweep.csv")
    assert sorted(table["/materials/0/seed"].unique()) == [1, 2]
    assert (tmp_path / "rel_error_vs_density.png").exists()
    assert re.search(r"model +log_density +rel_error +se +realizations", done.stdout)
