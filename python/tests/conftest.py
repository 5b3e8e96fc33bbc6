"""Shared fixtures of the glintlab Python tests. ctest runs them
(`python.pytest`) on the interpreter of a virtual environment into which
the `python.install` fixture installed glintlab with pip, with
GLINTLAB_CLI and GLINTLAB_SOURCE_DIR set by python/CMakeLists.txt."""

import copy
import os

import pytest

CLI = os.environ.get("GLINTLAB_CLI", "")
SOURCE_DIR = os.environ.get(
    "GLINTLAB_SOURCE_DIR", os.path.dirname(os.path.dirname(os.path.dirname(__file__))))

# A glinty sphere under a directional light, small enough that one render
# takes milliseconds.
TINY_SCENE = {
    "film": {"width": 16, "height": 16},
    "camera": {"eye": [0.0, 0.0, 3.2], "target": [0, 0, 0], "fov_deg": 45},
    "render": {"integrator": "direct", "spp": 1, "seed": 1},
    "materials": [{
        "name": "glitter", "type": "glint", "model": "deliot2023", "ndf": "beckmann",
        "roughness": 0.3, "log_density": 10, "fresnel": {"type": "conductor", "metal": "silver"},
        "color": [0.9, 0.85, 0.75],
        "deliot2023": {"microfacet_roughness": 0.025, "screen_space_scale": 1.5},
    }],
    "shapes": [{"name": "sphere", "type": "sphere", "radius": 1.0, "material": "glitter"}],
    "lights": [{"type": "directional", "direction": [0.5, 0.6, 0.8], "irradiance": 1.5}],
}


@pytest.fixture
def tiny_scene():
    return copy.deepcopy(TINY_SCENE)


@pytest.fixture(scope="session")
def cluster():
    """One 2-process LocalCluster for the sweep tests, on 127.0.0.1 only,
    without dashboard; closed (workers and nannies gone) at session end."""
    from distributed import Client, LocalCluster
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address=None) as c, Client(c) as client:
        yield c, client
