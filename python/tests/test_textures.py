"""Textured material parameters from Python: a NumPy array in place of a
texture file (docs/SCENE_FORMAT.md "Textures", docs/PYTHON.md)."""

import copy
import os

import numpy as np
import pytest

import glintlab


def _ramp():
    # alpha from 0.15 to 0.45 across u, a second channel that must be ignored
    h, w = 16, 32
    a = np.zeros((h, w, 3), np.float32)
    a[..., 0] = np.linspace(0.15, 0.45, w, dtype=np.float32)[None, :]
    a[..., 1] = 0.9
    return a


def test_array_texture_renders_as_the_same_texture_from_an_exr_file(tiny_scene, tmp_path):
    ramp = _ramp()
    glintlab.write_image(tmp_path / "ramp.exr", ramp)
    from_file = copy.deepcopy(tiny_scene)
    from_file["materials"][0]["roughness"] = {"texture": "ramp.exr", "channel": "r"}
    from_array = copy.deepcopy(tiny_scene)
    from_array["materials"][0]["roughness"] = {"texture": ramp, "channel": "r"}
    a = glintlab.render(from_file, file=tmp_path / "scene.json", res=(24, 20), threads=1)
    b = glintlab.render(from_array, res=(24, 20), threads=1)
    assert a.max() > 0
    assert np.array_equal(a, b)
    # The map matters: the constant roughness gives another image.
    c = glintlab.render(tiny_scene, res=(24, 20), threads=1)
    assert not np.array_equal(b, c)
    # The caller's dict keeps its array (the module works on a copy).
    assert isinstance(from_array["materials"][0]["roughness"]["texture"], np.ndarray)


def test_array_textures_survive_a_model_switch(tiny_scene):
    tiny_scene["materials"][0]["log_density"] = {"texture": np.full((8, 8), 11.0, np.float32)}
    image = glintlab.render(tiny_scene, model="zirr2016", res=(16, 16), threads=1)
    assert image.shape == (16, 16, 3) and np.isfinite(image).all()


@pytest.mark.parametrize("array, message", [
    (np.zeros((4, 4, 2), np.float32), "has shape (H, W), (H, W, 1), (H, W, 3) or (H, W, 4)"),
    (np.zeros((0, 4), np.float32), "outside [1, 65536]"),
    (np.array([[0.2, np.nan]], np.float32), "texel (x=1, y=0) is not finite"),
    (np.array([["a"]]), "holds real numbers"),
])
def test_bad_arrays_name_the_json_path(tiny_scene, array, message):
    tiny_scene["materials"][0]["roughness"] = {"texture": array}
    with pytest.raises(glintlab.SceneError) as e:
        glintlab.parse_scene(tiny_scene)
    assert "/materials/0/roughness/texture" in str(e.value)
    assert message in str(e.value)


def test_array_values_are_checked_against_the_parameters_range(tiny_scene):
    tiny_scene["materials"][0]["log_density"] = {"texture": np.full((2, 2), 70.0, np.float32)}
    with pytest.raises(glintlab.SceneError, match=r"outside the parameter's range \[-20, 60\]"):
        glintlab.parse_scene(tiny_scene)


def test_the_extension_checks_array_shapes_itself():
    # The module's parse_scene checks first; the extension must not read a
    # 1-D array out of bounds when called directly.
    with pytest.raises(ValueError, match="expected shape"):
        glintlab._glintlab.parse_scene("{}", "x", [np.zeros(4, np.float32)])


def test_normal_map_array_renders_as_the_same_map_from_an_exr_file(tiny_scene, tmp_path):
    # Bumps along u: unit normals stored as themselves ("encoding": "signed").
    h, w = 16, 32
    x = np.sin(np.linspace(0, 4 * np.pi, w, dtype=np.float32))[None, :] * 0.4
    n = np.stack(np.broadcast_arrays(x, np.zeros((h, 1), np.float32), np.ones((h, w), np.float32)),
                 axis=-1)
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    glintlab.write_image(tmp_path / "n.exr", n)
    from_file = copy.deepcopy(tiny_scene)
    from_file["materials"][0]["normal_map"] = {"texture": "n.exr", "encoding": "signed"}
    from_array = copy.deepcopy(tiny_scene)
    from_array["materials"][0]["normal_map"] = {"texture": n, "encoding": "signed"}
    a = glintlab.render(from_file, file=tmp_path / "scene.json", res=(24, 20), threads=1)
    b = glintlab.render(from_array, res=(24, 20), threads=1)
    assert a.max() > 0 and np.isfinite(a).all()
    assert np.array_equal(a, b)
    assert not np.array_equal(b, glintlab.render(tiny_scene, res=(24, 20), threads=1))
    # A map that is not one names the array's JSON path and the texel.
    bad = copy.deepcopy(tiny_scene)
    not_unit = np.zeros((4, 4, 3), np.float32)
    not_unit[..., 0] = 2.0
    bad["materials"][0]["normal_map"] = {"texture": not_unit, "encoding": "signed"}
    with pytest.raises(glintlab.SceneError, match=r"normal_map.*texel \(x=0, y=0\)"):
        glintlab.parse_scene(bad)


def test_a_gltf_file_renders_with_its_own_textured_materials(tmp_path):
    """A glTF shape without "material" is shaded by the file's materials
    (docs/SCENE_FORMAT.md "glTF materials"): the plate's base colour map is
    a blue/orange checker, so blue and orange pixels both appear; an
    override to a grey diffuse material takes the base colour map as its
    albedo, and a plain grey material removes the checker."""
    from conftest import SOURCE_DIR
    asset = os.path.join(SOURCE_DIR, "scenes", "gltf", "glint_tiles.glb")
    scene = {
        "film": {"width": 32, "height": 24},
        "camera": {"eye": [0.0, 2.5, 0.1], "target": [0, 0, 0], "fov_deg": 50},
        "render": {"integrator": "direct", "spp": 2, "seed": 1},
        "materials": [{"name": "grey", "type": "diffuse", "albedo": 0.5}],
        "shapes": [{"type": "gltf", "name": "tiles", "file": asset,
                    "material_overrides": {"Paint": {"type": "diffuse"}}}],
        "lights": [{"type": "directional", "direction": [0, 1, 0], "irradiance": 3}],
    }
    image = glintlab.render(scene, threads=1)
    assert np.isfinite(image).all()
    corner = image[2:6, 6:26].reshape(-1, 3)  # the plate's far edge, beyond the ball
    blue = (corner[:, 2] > 1.5 * corner[:, 0]).sum()
    orange = (corner[:, 0] > 1.5 * corner[:, 2]).sum()
    assert blue > 0 and orange > 0, corner
    plain = copy.deepcopy(scene)
    del plain["shapes"][0]["material_overrides"]
    plain["shapes"][0]["material"] = "grey"
    grey = glintlab.render(plain, threads=1)[2:6, 6:26].reshape(-1, 3)
    assert np.allclose(grey[:, 0], grey[:, 2], rtol=1e-5)
