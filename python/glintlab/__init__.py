"""glintlab from Python: scenes as dicts or files, renders as NumPy arrays,
direct evaluation of glint BRDFs, validation suites, image I/O and
parameter sweeps on Dask distributed (docs/PYTHON.md).

Conventions: an image is a float32 NumPy array of shape (H, W, 3) holding
linear radiance (row 0 at the top); `tonemap` turns it into display values
for matplotlib. Tables (`sweep`, `compare_table`) are pandas DataFrames with
each mean's standard error in the column beside it ("<name>_se"). Long
calls show a progress bar once they run for a second (`set_progress`).

Scene documents follow docs/SCENE_FORMAT.md. Errors of the strict scene
loader are raised as `SceneError` with the loader's message (file, JSON
path, allowed range); other library errors as `Error`.
"""

import copy
import json
import os
import re

import numpy as np

from . import _glintlab
from ._display import tonemap
from ._glintlab import Error, Scene, SceneError
from ._progress import _Bar, progress_enabled, set_progress

__all__ = [
    "Error", "SceneError", "OverrideError", "Scene", "parse_scene", "load_document",
    "apply_overrides", "set_model", "render", "models", "eval_brdf", "eval_ndf", "validate",
    "validation_suites", "compare", "compare_table", "export", "read_image", "write_image",
    "tonemap",
    "sweep", "set_progress", "progress_enabled", "with_gl", "__version__",
]
__version__ = _glintlab.__version__  # the C++ library's version, as `glintlab --version`
with_gl = _glintlab.with_gl  # whether gpu=True renders are available (built with OpenGL)


class OverrideError(SceneError):
    """An override's JSON pointer is malformed or its parent does not exist."""


def load_document(scene, file=None):
    """(document dict, file name) of a scene given as a path or a dict.

    A dict is deep-copied (the caller's dict is never modified); `file` names
    it in error messages and anchors its relative paths (default "<dict>",
    i.e. the current directory)."""
    if isinstance(scene, (str, os.PathLike)):
        path = os.fspath(scene)
        try:
            with open(path, encoding="utf-8") as f:
                text = f.read()
        except OSError as e:
            raise SceneError(f"{path}: cannot open scene file: {e.strerror}") from None
        try:
            return json.loads(text), path if file is None else os.fspath(file)
        except json.JSONDecodeError as e:
            raise SceneError(f"{path}: invalid JSON: {e}") from None
    if isinstance(scene, dict):
        return copy.deepcopy(scene), "<dict>" if file is None else os.fspath(file)
    raise TypeError(f"scene: expected a dict, a path or a glintlab.Scene, got {type(scene).__name__}")


def _pointer_tokens(pointer):
    """RFC 6901 reference tokens of `pointer` ("" is the whole document)."""
    if not isinstance(pointer, str) or (pointer and not pointer.startswith("/")):
        raise OverrideError(f"override {pointer!r}: a JSON pointer starts with '/' (RFC 6901)")
    if pointer == "":
        return []
    tokens = pointer[1:].split("/")
    for t in tokens:
        if re.search(r"~(?![01])", t):
            raise OverrideError(f"override {pointer!r}: '~' must be followed by 0 or 1 "
                                f"(RFC 6901: ~0 is '~', ~1 is '/')")
    return [t.replace("~1", "/").replace("~0", "~") for t in tokens]


def _array_index(pointer, prefix, token, size, allow_end):
    if token == "-" and allow_end:
        return size
    if not token.isdigit() or (len(token) > 1 and token[0] == "0"):
        raise OverrideError(f"override {pointer}: {prefix or '/'} is an array, "
                            f"{token!r} is not an index")
    i = int(token)
    if i >= size + (1 if allow_end else 0):
        raise OverrideError(f"override {pointer}: {prefix or '/'} has {size} entries, "
                            f"no index {i}")
    return i


def apply_overrides(document, overrides):
    """Sets each JSON pointer (RFC 6901) of `overrides` to its value, in
    order, in `document` (modified in place and returned). The pointer's
    parent must exist; the last token may name a new object key (the strict
    loader then checks it) or, in an array, an existing index or "-"
    (append). Raises OverrideError naming the pointer otherwise."""
    if overrides is not None and not isinstance(overrides, dict):
        raise TypeError(f"overrides: expected a dict {{JSON pointer: value}}, got "
                        f"{type(overrides).__name__}")
    for pointer, value in (overrides or {}).items():
        tokens = _pointer_tokens(pointer)
        if not tokens:
            raise OverrideError("override \"\": replacing the whole document is not an override")
        node, prefix = document, ""
        for token in tokens[:-1]:
            if isinstance(node, dict):
                if token not in node:
                    raise OverrideError(f"override {pointer}: {prefix}/{token} does not exist")
                node = node[token]
            elif isinstance(node, list):
                node = node[_array_index(pointer, prefix, token, len(node), False)]
            else:
                raise OverrideError(f"override {pointer}: {prefix or '/'} is neither an object "
                                    f"nor an array")
            prefix += "/" + token.replace("~", "~0").replace("/", "~1")
        last = tokens[-1]
        value = copy.deepcopy(value)
        if isinstance(node, dict):
            node[last] = value
        elif isinstance(node, list):
            i = _array_index(pointer, prefix, last, len(node), True)
            if i == len(node):
                node.append(value)
            else:
                node[i] = value
        else:
            raise OverrideError(f"override {pointer}: {prefix or '/'} is neither an object "
                                f"nor an array")
    return document


def set_model(document, model):
    """Sets `model` on every glint material of `document` (in place) and
    fits what the model requires, as `glintlab render --model` and the
    viewer do (kneiphof2025 needs GGX, wang2020 Beckmann, ...; each change
    is noted on stderr)."""
    names = [m["name"] for m in models()]
    if model not in names:
        raise SceneError(f"model: unknown glint model \"{model}\" (known: {', '.join(names)})")
    materials = document.get("materials", [])
    if any(isinstance(m, dict) and m.get("type") == "glint" for m in materials):
        # NumPy textures travel through the JSON text as placeholders.
        stash = []

        def swap(node, restore):
            items = node.items() if isinstance(node, dict) else enumerate(node)
            for key, value in list(items):
                if not restore and isinstance(value, np.ndarray):
                    stash.append(value)
                    node[key] = f"<numpy {len(stash) - 1}>"
                elif restore and isinstance(value, str) and value.startswith("<numpy "):
                    node[key] = stash[int(value[7:-1])]
                elif isinstance(value, (dict, list)):
                    swap(value, restore)

        swap(materials, False)
        switched = json.loads(_glintlab.set_glint_model(json.dumps({"materials": materials}), model))
        swap(materials, True)
        materials[:] = switched["materials"]
        swap(materials, True)
    return document


def _texture_arrays(doc, name):
    """Replaces every NumPy array given as a texture ({"texture": array}) by
    the name the loader knows it under ("<array N>") and returns the arrays:
    float32, C order, shape (H, W), (H, W, 1), (H, W, 3) or (H, W, 4),
    finite, linear values (like an EXR)."""
    arrays = []

    def check(a, where):
        if a.ndim not in (2, 3) or (a.ndim == 3 and a.shape[2] not in (1, 3, 4)):
            raise SceneError(f"{name}: {where}: a texture array has shape (H, W), (H, W, 1), "
                             f"(H, W, 3) or (H, W, 4), got {a.shape}")
        if a.shape[0] < 1 or a.shape[1] < 1 or a.shape[0] > 65536 or a.shape[1] > 65536:
            raise SceneError(f"{name}: {where}: texture size {a.shape[1]}x{a.shape[0]} is outside "
                             "[1, 65536] per side")
        if not np.issubdtype(a.dtype, np.number) or np.issubdtype(a.dtype, np.complexfloating):
            raise SceneError(f"{name}: {where}: a texture array holds real numbers, got {a.dtype}")
        f = np.ascontiguousarray(a, dtype=np.float32)
        bad = ~np.isfinite(f)
        if bad.any():
            y, x = np.argwhere(bad)[0][:2]
            raise SceneError(f"{name}: {where}: texel (x={x}, y={y}) is not finite "
                             "(a texture array must hold finite values)")
        return f

    def walk(node, where):
        if isinstance(node, dict):
            for key, value in node.items():
                if key == "texture" and isinstance(value, np.ndarray):
                    arrays.append(check(value, f"{where}/texture"))
                    node[key] = f"<array {len(arrays) - 1}>"
                else:
                    walk(value, f"{where}/{key}")
        elif isinstance(node, list):
            for i, value in enumerate(node):
                walk(value, f"{where}/{i}")

    walk(doc, "")
    return arrays


def parse_scene(document, file=None, model=None, overrides=None):
    """A validated `Scene` from a dict or a path, after `model` and
    `overrides`; raises SceneError naming the file and JSON path. A material
    parameter's texture may be a NumPy array in place of a file:
    {"texture": array, ...} (float32 (H, W[, 1|3|4]) of linear values, uv
    (0, 0) at row 0, column 0; docs/SCENE_FORMAT.md "Textures")."""
    if isinstance(document, Scene):
        if model is not None or overrides:
            raise TypeError("model/overrides need a dict or a path, not a parsed Scene")
        return document
    doc, name = load_document(document, file)
    if model is not None:
        set_model(doc, model)
    apply_overrides(doc, overrides)
    arrays = _texture_arrays(doc, name)
    return _glintlab.parse_scene(json.dumps(doc), name, arrays)


def render(scene, model=None, overrides=None, gpu=False, spp=None, seed=None, res=None,
           threads=0, progress=None, file=None):
    """Renders `scene` (dict, path or Scene) to a linear float32 array of
    shape (H, W, 3), like `glintlab render` (same seed and resolution: the
    same pixels). `res` is (W, H) or "WxH"; `model` switches every glint
    material's model; `overrides` {JSON pointer: value} as apply_overrides.
    `progress`: None (a bar after a second, see set_progress), True, False,
    or a callable(fraction) called as tiles finish (CPU renders only). The
    GIL is released while rendering."""
    parsed = parse_scene(scene, file=file, model=model, overrides=overrides)
    width, height = (None, None) if res is None else _resolution(res)
    with _Bar(None if gpu and progress is None else progress, "render") as bar:
        return _glintlab.render(parsed, gpu=gpu, spp=spp, seed=seed, width=width, height=height,
                                threads=threads, progress=bar.hook)


def _resolution(res):
    if isinstance(res, str):
        w, sep, h = res.partition("x")
        if not sep or not w.isdigit() or not h.isdigit():
            raise ValueError(f"res: expected 'WxH' or (W, H), got {res!r}")
        return int(w), int(h)
    try:
        w, h = res
    except (TypeError, ValueError):
        raise ValueError(f"res: expected 'WxH' or (W, H), got {res!r}") from None
    sides = []
    for side in (w, h):
        # Integers only (16.5 used to be truncated to 16 without a word).
        if isinstance(side, bool) or not isinstance(side, (int, np.integer)):
            raise ValueError(f"res: expected integer sides in [1, 16384], got {res!r}")
        sides.append(int(side))
    return tuple(sides)


def models():
    """Every glint model: list of dicts {name, description, lights, backends}."""
    return _glintlab.models()


def _material_scene(material):
    """A one-material scene around `material` (a glint material dict), so
    that the strict loader reads it exactly as in a scene file."""
    if not isinstance(material, dict):
        raise TypeError("material: expected a glint material dict (docs/SCENE_FORMAT.md)")
    mat = copy.deepcopy(material)
    mat.setdefault("name", "material")
    info = {m["name"]: m for m in models()}.get(mat.get("model", "smooth"))
    lights = info["lights"] if info else ["directional"]
    if "directional" in lights:
        light = {"type": "directional", "direction": [0, 1, 0], "irradiance": 1}
    elif "point" in lights:
        light = {"type": "point", "position": [0, 1, 0], "intensity": 1}
    else:
        light = {"type": "environment", "radiance": 1}
    return {
        "film": {"width": 1, "height": 1},
        "camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "fov_deg": 30},
        "materials": [mat],
        "shapes": [{"name": "sphere", "type": "sphere", "radius": 1, "material": mat["name"]}],
        "lights": [light],
    }


def _directions(name, v):
    """(N, 3) float32 directions; each row finite with a length a float can
    normalise (zero, NaN, Inf and denormal rows used to give NaN silently)."""
    a = np.atleast_2d(np.asarray(v, dtype=np.float32))
    if a.ndim != 2 or a.shape[1] != 3:
        raise ValueError(f"{name}: expected an array of shape (N, 3), got {a.shape}")
    with np.errstate(all="ignore"):
        length = np.sqrt(np.sum(a.astype(np.float64) ** 2, axis=1))
    bad = np.flatnonzero(~(np.isfinite(a).all(axis=1) & (length >= 1e-6)))
    if bad.size:
        i = int(bad[0])
        raise ValueError(f"{name}: row {i} = {a[i].tolist()} is not a direction (finite, with "
                         f"length >= 1e-6); {bad.size} such row(s)")
    return a


def _eval(material, wo, wi, footprint, ndf, file):
    scene = _glintlab.parse_scene(json.dumps(_material_scene(material)), file)
    wo = _directions("wo", wo)
    wi = _directions("wi", wi)
    fp = {}
    if footprint is not None:
        n = wo.shape[0]
        for key in ("uv", "duvdx", "duvdy"):
            if key not in footprint:
                raise ValueError(f"footprint: missing {key!r} (needs uv, duvdx, duvdy)")
            a = np.asarray(footprint[key], dtype=np.float32)
            fp[key] = np.broadcast_to(a, (n, 2)).copy() if a.ndim == 1 else a
            bad = np.flatnonzero(~np.isfinite(np.atleast_2d(fp[key])).all(axis=1))
            if bad.size:
                raise ValueError(f"footprint {key}: row {int(bad[0])} is not finite")
        # The scene format's uv range (mesh uvs): beyond it no texture or
        # glint grid has a fractional part left to index.
        if np.abs(fp["uv"]).max(initial=0.0) > 1e6:
            raise ValueError("footprint uv: components must lie in [-1e6, 1e6]")
    return _glintlab.eval_glint(scene, 0, wo, wi, ndf=ndf, **fp)


def eval_brdf(material, wo, wi, footprint=None, file="<material>"):
    """f(wo, wi) (N, 3) of a glint material dict for (N, 3) direction arrays
    in its shading frame (z = normal; normalised here). `footprint` is a
    dict of uv, duvdx, duvdy, each (N, 2) or (2,); without it the model's
    smooth limit is evaluated (as at secondary bounces)."""
    return _eval(material, wo, wi, footprint, False, file)


def eval_ndf(material, wo, wi, footprint=None, file="<material>"):
    """The footprint NDF D_P(h), h = normalize(wo + wi), per channel (N, 3)."""
    return _eval(material, wo, wi, footprint, True, file)


def validation_suites():
    """Names of the suites `validate` runs (as `glintlab validate --help`)."""
    return list(_glintlab.validation_suites())


def validate(suite, seed=1):
    """The report of a validation suite as `glintlab validate SUITE --json`
    prints it (a dict; "passed" says whether every check passed)."""
    return json.loads(_glintlab.validate_json(suite, seed))


def compare(scene, models=None, material=None, realizations=4, res=None, spp=None, frames=8,
            orbit_deg=4.0, seed=1, gpu=False, threads=0, overrides=None, output=None,
            truth_realizations=0, match_facet_extent=True, flicker_paths=4, progress=None):
    """`glintlab compare` on a scene file: every model that can shade the
    scene's lights against the explicit ground truth (docs/VALIDATION.md
    "compare"). Returns the metrics.json document as a dict (one entry per
    model in "models"); `output` (a directory) also writes the images and
    tables. `overrides` is a list of "POINTER=VALUE" strings (render --set).
    `truth_realizations` (0: `realizations`) are the truth's seeds;
    `match_facet_extent=False` keeps every model's default facet extent
    instead of the truth's (CLI --model-extent); `flicker_paths` camera
    paths (each another realization) give the flicker and its standard
    error (CLI --flicker-paths). `progress` as in render, over the renders.
    `compare_table` turns the result into a DataFrame."""
    width, height = _resolution(res) if res is not None else (0, 0)
    if isinstance(models, str):
        models = [models]
    with _Bar(progress, "compare") as bar:
        hook = None if bar.hook is None else (lambda done, total: bar.update(done / total))
        return json.loads(_glintlab.compare_json(
            os.fspath(scene), list(overrides or []), material or "", list(models or []),
            int(realizations), width, height, int(spp or 0), int(frames), float(orbit_deg),
            int(seed), bool(gpu), int(threads), os.fspath(output) if output else "",
            int(truth_realizations), bool(match_facet_extent), int(flicker_paths), hook))


def compare_table(result):
    """The models of a `compare` result as a pandas DataFrame, one row per
    compared model in the result's order: "model", "truth" (the ground
    truth it is measured against; a truth row of its own heads each facet
    extent, "reference" True), "backend", then its numeric metrics, each
    standard error ("<metric>_se") beside its metric (docs/VALIDATION.md
    "compare" defines them). Models that were not compared are left out;
    `result["models"]` says why."""
    import pandas as pd
    rows = []
    for m in result.get("models", []):
        if not m.get("compared"):
            continue
        row = {"model": m["model"], "truth": m.get("truth"), "reference": m.get("reference"),
               "backend": m.get("backend")}
        for key, value in m.items():
            if key not in row and (value is None or (isinstance(value, (int, float)) and
                                                     not isinstance(value, bool))):
                row[key] = float("nan") if value is None else value  # JSON null: not defined
        rows.append(row)
    table = pd.DataFrame(rows)
    metrics = [c for c in table.columns if c not in ("model", "truth", "reference", "backend")]
    ordered = [c for c in metrics if not c.endswith("_se")]
    columns = ["model", "truth", "reference", "backend"]
    for c in ordered:
        columns.append(c)
        if c + "_se" in table.columns:
            columns.append(c + "_se")
    columns += [c for c in metrics if c not in columns]
    return table[columns] if rows else table


def export(model, output, lang="glsl", scene=None, material=None, env=None, resources=True):
    """`glintlab export MODEL -o OUTPUT`: writes one model's standalone
    fragment shader (lang "glsl" 4.50, "glsles" 3.00 for WebGL2, "hlsl"
    SM 5.0), its resources and a JSON manifest into the directory `output`
    (docs/INTEGRATION.md). `scene` (a scene file) and `material` export that
    glint material's values and resources instead of the model's defaults;
    `env` an environment map for kneiphof2025's prefiltered maps;
    `resources=False` writes the shaders and the manifest only. Returns the
    manifest as a dict, with "files" the names written (manifest last)."""
    files = _glintlab.export_model(str(model), os.fspath(output), str(lang),
                                   os.fspath(scene) if scene else "", material or "",
                                   os.fspath(env) if env else "", bool(resources))
    with open(os.path.join(os.fspath(output), files[-1]), encoding="utf-8") as f:
        manifest = json.load(f)
    manifest["files"] = files
    return manifest


def read_image(path):
    """A linear float32 (H, W, 3) array from .exr/.hdr/.png/.jpg."""
    return _glintlab.read_image(os.fspath(path))


def write_image(path, array, exposure=0.0):
    """Writes a linear (H, W, 3) array as .exr (float32), .hdr or .png (sRGB)."""
    _glintlab.write_image(os.fspath(path), np.asarray(array, dtype=np.float32), exposure)


from ._sweep import sweep  # noqa: E402  (needs the functions above)
