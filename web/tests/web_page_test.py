#!/usr/bin/python3
"""Tests of the WebGL2 page (web/, docs/WEB.md) in headless Chromium.

    web_page_test.py load    --export DIR            every exported model loads without error
    web_page_test.py compare --export DIR [MODEL...] browser frame vs `render --gpu`
    web_page_test.py asset   --export DIR            a .glb through the file picker

DIR holds the files of scripts/export_web.sh (the `glintlab export ... --lang
glsles` output and models.json). The page is served from a Python
http.server on a free port (web/ at /, DIR at /export/) and driven through
selenium with Debian's chromium + chromium-driver, WebGL2 on SwiftShader.
Exit status 77 (ctest SKIP_RETURN_CODE) only when chromium or its driver is
absent; every other problem fails.
"""

import argparse
import base64
import functools
import http.server
import json
import os
import shutil
import sys
import tempfile
import threading
import time

SKIP = 77
HERE = os.path.dirname(os.path.abspath(__file__))
WEB_DIR = os.path.dirname(HERE)
CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
CHROMEDRIVER = shutil.which("chromedriver") or "/usr/bin/chromedriver"
ALL_MODELS = ["smooth", "zirr2016", "chermain2020", "deliot2023", "kneiphof2025", "wang2020"]


def skip(reason):
    print(f"SKIP: {reason}")
    sys.exit(SKIP)


class Handler(http.server.SimpleHTTPRequestHandler):
    """web/ at /, the export directory at /export/ (no caching, no log)."""

    export_dir = None

    def translate_path(self, path):
        path = path.split("?", 1)[0].split("#", 1)[0]
        if path.startswith("/gltf/"):  # the repository's glTF assets (the asset URL test)
            rel = path[len("/gltf/"):]
            return os.path.join(os.path.dirname(GLB), *[p for p in rel.split("/") if p not in ("", "..")])
        if path.startswith("/export/"):
            rel = path[len("/export/"):]
            return os.path.join(self.export_dir, *[p for p in rel.split("/") if p not in ("", "..")])
        rel = [p for p in path.split("/") if p not in ("", "..")]
        return os.path.join(WEB_DIR, *rel)

    def end_headers(self):
        self.send_header("Cache-Control", "no-store")
        super().end_headers()

    def log_message(self, *args):
        pass


class Page:
    """One HTTP server and one headless Chromium for the whole run."""

    def __init__(self, export_dir):
        if not (os.path.exists(CHROMIUM) and os.path.exists(CHROMEDRIVER)):
            skip(f"chromium ({CHROMIUM}) or chromedriver ({CHROMEDRIVER}) is not installed "
                 "(Debian packages chromium, chromium-driver)")
        try:
            from selenium import webdriver
            from selenium.webdriver.chrome.options import Options
            from selenium.webdriver.chrome.service import Service
        except ImportError:
            skip("python3-selenium is not installed")
        Handler.export_dir = export_dir
        self.server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), Handler)
        threading.Thread(target=self.server.serve_forever, daemon=True).start()
        self.base = f"http://127.0.0.1:{self.server.server_address[1]}"
        options = Options()
        options.binary_location = CHROMIUM
        self.profile = tempfile.mkdtemp(prefix="glintlab_chromium_")
        for arg in ["--headless=new", "--no-sandbox", "--disable-dev-shm-usage",
                    "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                    "--ignore-gpu-blocklist", "--window-size=800,700",
                    f"--user-data-dir={self.profile}"]:
            options.add_argument(arg)
        options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
        self.driver = webdriver.Chrome(options=options, service=Service(CHROMEDRIVER))
        self.driver.set_script_timeout(30)

    def close(self):
        self.driver.quit()
        self.server.shutdown()
        shutil.rmtree(self.profile, ignore_errors=True)

    def open(self, query, timeout=40.0):
        """Loads index.html?query and waits for the first frame or an error;
        returns (state, browser log entries since the last call)."""
        self.driver.get(f"{self.base}/index.html?{query}")
        return self._wait(timeout)

    def navigate(self, query, timeout=40.0):
        """The same in the loaded page (window.glintlab.navigate: the models
        already loaded keep their compiled programs)."""
        self.driver.execute_script("window.glintlab.navigate(arguments[0]);", f"?{query}")
        return self._wait(timeout)

    def _wait(self, timeout):
        deadline = time.monotonic() + timeout
        while True:
            s = self.driver.execute_script(
                "const g = window.glintlab; return g ? {ready: g.ready, error: g.error, "
                "glErrors: g.glErrors, frames: g.frames} : null;")
            if s and (s["ready"] or s["error"]):
                break
            if time.monotonic() > deadline:
                s = s or {"ready": False, "error": "window.glintlab never appeared"}
                s["error"] = s.get("error") or f"no frame within {timeout} s"
                break
            time.sleep(0.05)
        return s, self.driver.get_log("browser")

    def hdr(self):
        """The page's linear frame: (height, width, 4) float32, alpha = coverage."""
        import numpy as np
        w, h = self.driver.execute_script("return window.glintlab.size;")
        data = base64.b64decode(self.driver.execute_script("return window.glintlab.readHdr();"))
        return np.frombuffer(data, dtype="<f4").reshape(h, w, 4)


    def display(self):
        """The canvas as displayed: (height, width, 4) uint8."""
        import numpy as np
        w, h = self.driver.execute_script("return window.glintlab.size;")
        data = base64.b64decode(self.driver.execute_script("return window.glintlab.readDisplay();"))
        return np.frombuffer(data, dtype=np.uint8).reshape(h, w, 4)


def srgb8(linear):
    """core/image.cpp write_png: sRGB encode, clamp, 8 bits (rounded)."""
    import numpy as np
    x = np.clip(linear, 0.0, 1.0)
    s = np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1.0 / 2.4) - 0.055)
    return np.round(s * 255.0)


def exported_models(export_dir):
    return [m for m in ALL_MODELS
            if os.path.exists(os.path.join(export_dir, f"{m}.glsles.manifest.json"))]


def errors_in(log):
    """Console errors and warnings of the browser log (favicon requests are
    answered by the page's own data: icon, so no entry is expected)."""
    return [e for e in log if e["level"] in ("SEVERE", "WARNING")]


# ---- (a) every model loads -------------------------------------------------

def test_load(page, export_dir):
    import numpy as np
    models = exported_models(export_dir)
    if not models:
        print(f"FAIL: no exported model in {export_dir}")
        return False
    ok = True
    views = [(m, shape, "default", "") for m in models for shape in ("sphere", "plane")]
    # The other fragment stages of the exports (deliot2023's noise_texture).
    for m in models:
        with open(os.path.join(export_dir, f"{m}.glsles.manifest.json")) as f:
            views += [(m, "sphere", s["variant"], "") for s in json.load(f)["shaders"]
                      if s["stage"] == "fragment" and s["variant"] != "default"]
    # Every model with the page's maps through the export's inputs (those
    # that take density and roughness as uniforms bind the colour map only).
    views += [(m, "plane", "default", "&textures=tiles&normal_map=bumps") for m in models]
    for model, shape, variant, maps in sorted(views, key=lambda v: models.index(v[0])):
        # A fresh page per model (its own console), its other views in it.
        query = f"model={model}&shape={shape}&variant={variant}&w=64&h=64&static=1{maps}"
        first = (shape, variant, maps) == ("sphere", "default", "")
        state, log = page.open(query) if first else page.navigate(query)
        problems = []
        if state.get("error"):
            problems.append(f"page error: {state['error']}")
        if state.get("glErrors"):
            problems.append(f"WebGL errors: {state['glErrors']}")
        problems += [f"console {e['level']}: {e['message']}" for e in errors_in(log)]
        if not problems:
            # A frame with light on the shape: a shader that compiled
            # but wrote nothing (or NaN) would pass the checks above.
            img = page.hdr()
            covered = img[..., 3] > 0.5
            rgb = img[..., :3]
            if not np.all(np.isfinite(rgb)):
                problems.append("non-finite pixels")
            elif covered.sum() < 100 or rgb[covered].sum() <= 0.0:
                problems.append(f"empty frame ({covered.sum()} covered pixels, "
                                f"sum {rgb[covered].sum():.3g})")
            else:
                # The canvas shows the frame tone mapped (exposure -1 by
                # default, sRGB): within one 8-bit step of the encode of
                # the read-back (rounding of the 8-bit target).
                exposure = page.driver.execute_script("return window.glintlab.state.exposure;")
                want = srgb8(rgb * 2.0 ** exposure)
                shown = page.display()[..., :3].astype(np.float64)
                off = np.abs(shown - want).max()
                if off > 1.0:
                    problems.append(f"canvas differs from the tone-mapped frame by {off:.0f}/255")
        print(f"{model:13s} {shape:6s} {variant:13s} {'maps ' if maps else ''}"
              f"{'ok' if not problems else 'FAIL'}")
        for p in problems:
            print(f"    {p}")
        ok = ok and not problems
    return ok


# ---- (b) browser frame vs native render -----------------------------------

# The compared view: 128 x 128 (the CPU-vs-GPU tests' size), seed 1,
# log_density 12, one directional light; kneiphof2025 adds the exported
# environment (forest.exr, scripts/export_web.sh) and is compared on the
# sphere, every other model on the PLANE_25 view and on the sphere.
VIEW = {"w": 128, "h": 128, "seed": 1, "log_density": 12, "roughness": 0.3,
        "ndf": "beckmann", "color": [0.9, 0.85, 0.75], "f0": [0.95, 0.93, 0.88],
        "exposure": 0.0}
SHAPES = {
    "plane": {"eye": [0.0, 1.27, 2.72], "light": [0.0, 0.55, -1.0], "irradiance": 1.0},
    "sphere": {"eye": [0.0, 0.0, 3.2], "light": [0.5, 0.6, 0.8], "irradiance": 1.5},
}


def material_view(model, export_dir):
    """seed, log_density, roughness, Fresnel of the compared view: VIEW's,
    or those the export fixes (wang2020's tables are built for the default
    material, the manifest's u_glint_* and u_fresnel_* uniforms)."""
    v = {"seed": VIEW["seed"], "log_density": VIEW["log_density"], "roughness": VIEW["roughness"],
         "fresnel": {"type": "schlick", "f0": VIEW["f0"]}}
    with open(os.path.join(export_dir, f"{model}.glsles.manifest.json")) as f:
        for r in json.load(f)["resources"]:
            u = r.get("uniforms", {})
            # wang2020's prefiltered table integrates the material's Fresnel.
            if "u_fresnel_mode" in u:
                mode = ["none", "schlick", "conductor", "dielectric"][u["u_fresnel_mode"]]
                v["fresnel"] = {"type": mode}
                if mode == "schlick":
                    v["fresnel"]["f0"] = u["u_fresnel_f0"]
                elif mode != "none":
                    raise ValueError(f"{model}: the test covers Fresnel none and schlick, "
                                     f"the export has {mode}")
            if "u_glint_alpha" in u:
                v["roughness"] = u["u_glint_alpha"][0]
            if "u_glint_log_density" in u:
                v["log_density"] = u["u_glint_log_density"]
            if "u_glint_seed" in u:
                v["seed"] = u["u_glint_seed"]
    return v


def bumps_normals(size=64):
    """web/normal_map.js bumpsNormals: unit normals (size, size, 3), row 0 at
    v = 0, n = normalize(-0.5 cos 4πu, -0.5 sin 6πv, 1) at texel centres."""
    import numpy as np
    c = (np.arange(size) + 0.5) / size
    u, v = np.meshgrid(c, c)
    n = np.stack([-0.5 * np.cos(4 * np.pi * u), -0.5 * np.sin(6 * np.pi * v), np.ones_like(u)], -1)
    return (n / np.linalg.norm(n, axis=-1, keepdims=True)).astype(np.float32)


def tiles_maps(size=64):
    """web/material_maps.js tilesMaps: ln N (size, size), α (size, size),
    linear colour (size, size, 3), row 0 at v = 0."""
    import numpy as np
    y, x = np.mgrid[0:size, 0:size]
    ln_n = (14 + np.floor(4 * x / size)).astype(np.float32)
    alpha = np.where(((x // 8) + (y // 8)) % 2 == 0, 0.2, 0.4).astype(np.float32)
    t = (y + 0.5) / size
    color = np.stack([0.9 - 0.6 * t, np.full_like(t, 0.6), 0.3 + 0.6 * t], -1).astype(np.float32)
    return ln_n, alpha, color


# Models compared with the page's textured parameters ("tiles": density,
# roughness and colour maps through the export's inputs) against the native
# renderer with the same texels as the material's textures, on both shapes,
# and their limits. The footprint lookups' level of detail follows
# SwiftShader's per-quad derivatives (see LIMITS): measured mismatching
# 0.02 % (smooth), 1.8 % (chermain2020, plane), 1.5 % (deliot2023, sphere),
# means within 1.9 %, smoothed L1 <= 0.035. The page without the maps
# against the textured native frame measures smoothed 0.35-0.70 and
# mismatching 9-71 %. chermain2020's pixel fraction gets 2x room over the
# measured value, as its plain limit does.
TEXTURED_LIMITS = {
    "smooth": (0.03, 0.05, 0.01),
    "chermain2020": (0.03, 0.05, 0.04),
    "deliot2023": (0.05, 0.20, 0.20),
}
TEXTURED_MODELS = tuple(TEXTURED_LIMITS)

# Models compared with the page's normal map ("bumps" through the export's
# LEAN inputs) against the native renderer with the same texels as the
# material's normal_map, on both shapes, and their limits. The LEAN lookup
# reads the footprint, and SwiftShader's per-quad derivatives (see LIMITS)
# move its level of detail, so the tilted frame and the widened α differ
# a little per pixel: measured on the plane, mismatching 0.3 % (smooth),
# 15 % (chermain2020), 21 % (deliot2023), smoothed L1 0.012-0.04, sphere
# 0.4 % and 0.06; means within 0.75 %. A map read with its y flipped
# (the bitangent's sign) measures 50-60 % mismatching and smoothed
# 0.48-0.52 on the plane, 1.36-1.51 on the sphere: the limits 30 % and
# 0.10 (0.20 for the gated deliot2023) separate the two.
NORMAL_MAP_LIMITS = {
    "smooth": (0.03, 0.05, 0.01),
    "chermain2020": (0.03, 0.10, 0.30),
    "deliot2023": (0.05, 0.20, 0.30),
}
NORMAL_MAP_MODELS = tuple(NORMAL_MAP_LIMITS)


def page_query(model, shape, env, mat, normal_map=False, textures=False):
    s = SHAPES[shape]
    q = {"model": model, "shape": shape, "w": VIEW["w"], "h": VIEW["h"], "seed": mat["seed"],
         "log_density": mat["log_density"], "roughness": mat["roughness"],
         "ndf": "ggx" if model == "kneiphof2025" else VIEW["ndf"],
         "color": ",".join(map(str, VIEW["color"])), "fresnel": mat["fresnel"]["type"],
         "light": ",".join(map(str, s["light"])),
         "irradiance": s["irradiance"], "eye": ",".join(map(str, s["eye"])),
         "target": "0,0,0", "fov": 45, "env": 1 if env else 0, "exposure": VIEW["exposure"],
         "static": 1}
    if "f0" in mat["fresnel"]:
        q["f0"] = ",".join(map(str, mat["fresnel"]["f0"]))
    if normal_map:
        q["normal_map"] = "bumps"
    if textures:
        q["textures"] = "tiles"
    return "&".join(f"{k}={v}" for k, v in q.items())


def native_scene(model, shape, env_file, mat, normal_map=False, textures=False):
    s = SHAPES[shape]
    material = {"name": "glitter", "type": "glint", "model": model,
                "ndf": "ggx" if model == "kneiphof2025" else VIEW["ndf"],
                "roughness": mat["roughness"], "log_density": mat["log_density"],
                "seed": mat["seed"], "color": VIEW["color"],
                "fresnel": mat["fresnel"]}
    if normal_map:
        material["normal_map"] = {"texture": bumps_normals(), "encoding": "signed"}
    if textures:
        ln_n, alpha, color = tiles_maps()
        material["log_density"] = {"texture": ln_n}
        material["roughness"] = {"texture": alpha}
        material["color"] = {"texture": color}
    if shape == "plane":
        geometry = {"name": "plane", "type": "quad", "size": [8, 8], "uv_scale": [8, 8],
                    "material": "glitter"}
    else:
        geometry = {"name": "sphere", "type": "sphere", "radius": 1.0, "material": "glitter"}
    lights = [{"type": "directional", "direction": s["light"], "irradiance": s["irradiance"]}]
    if env_file:
        lights.append({"type": "environment", "file": env_file})
    return {"film": {"width": VIEW["w"], "height": VIEW["h"], "exposure": VIEW["exposure"]},
            "camera": {"eye": s["eye"], "target": [0, 0, 0], "fov_deg": 45},
            "render": {"integrator": "direct", "spp": 1, "seed": VIEW["seed"]},
            "materials": [material], "shapes": [geometry], "lights": lights}


def luminance(rgb):
    return 0.2126 * rgb[..., 0] + 0.7152 * rgb[..., 1] + 0.0722 * rgb[..., 2]


def compare(a, b, mask, block=8, abs_tol=0.02, rel_tol=0.1):
    """realtime/image_compare.h on luminance, over the pixels of `mask`:
    relative error of the mean, relative L1 of the 8 x 8 block means,
    fraction of pixels with |a - b| > 0.02 + 0.1 max(a, b)."""
    import numpy as np
    la, lb = luminance(a) * mask, luminance(b) * mask
    n = mask.sum()
    mean_a, mean_b = la.sum() / n, lb.sum() / n
    h, w = la.shape
    ba = la[:h - h % block, :w - w % block].reshape(h // block, block, w // block, block).mean((1, 3))
    bb = lb[:h - h % block, :w - w % block].reshape(h // block, block, w // block, block).mean((1, 3))
    diff = np.abs(la - lb)
    bad = (diff > abs_tol + rel_tol * np.maximum(la, lb)) & (mask > 0)
    return {"mean_browser": float(mean_a), "mean_native": float(mean_b),
            "mean_rel": float(abs(mean_a - mean_b) / max(mean_b, 1e-12)),
            "smoothed_l1": float(np.abs(ba - bb).sum() / max(np.abs(bb).sum(), 1e-12)),
            "mismatch": float(bad.sum() / n)}


# Limits (mean rel. error, smoothed L1, mismatching fraction), docs/WEB.md
# "Browser vs native". Both sides rasterise the same triangles with the same
# camera, so the smooth model agrees to fp32 rounding (measured 1e-4, 0
# pixels): the limits are those of the CPU-vs-GPU tests (docs/VALIDATION.md
# "CPU vs GPU": 3%, 5%, 1%). chermain2020's D_P is continuous in the
# footprint: 3%, 5% and 2% (measured 0.5-0.6% mismatching; 2x room as the
# wang2020 GPU test gives its threshold flips). The gated models decide each
# glint by xi < p(footprint): SwiftShader's derivatives are per 2x2 quad
# (dFdx of the quad's lower row for both rows, dFdy of its left column; the
# exported shader's dFdx/dFdy, where Mesa's dFdyFine is per column) and its
# interpolation and transcendentals differ from llvmpipe's in the last bits,
# so ~10% of the PLANE pixels flip (measured 8.5-10%) and one flipped glint
# moves an 8 x 8 block of the sparse sphere by several percent (measured
# smoothed L1 0.06-0.11). Their limits: mean 5% (the CPU-vs-GPU limit of
# gated models), smoothed 20%, mismatching 20%; the same view with seed 2
# instead of 1 measures 63-67% mismatching (plane) and 0.58-0.67 smoothed
# (sphere), so a wrong pattern fails.
LIMITS = {
    "smooth": (0.03, 0.05, 0.01),
    "chermain2020": (0.03, 0.05, 0.02),
    "zirr2016": (0.05, 0.20, 0.20),
    "deliot2023": (0.05, 0.20, 0.20),
    "kneiphof2025": (0.05, 0.20, 0.20),
    # Gated too since its "effective" scale count keeps the micro scale under
    # the light: a particle is lit iff its mirror direction is within the 1°
    # cone, a threshold the last bits flip (measured 1.7%, 0.028, 1.0%).
    "wang2020": (0.05, 0.20, 0.20),
}


def test_compare(page, export_dir, models, env_file):
    import numpy as np
    import glintlab
    ok = True
    for model in models:
        if model not in LIMITS:
            print(f"FAIL: no documented limit for {model}")
            ok = False
            continue
        if model == "kneiphof2025" and not env_file:
            print("FAIL: kneiphof2025 is compared under the exported environment: pass --env FILE")
            ok = False
            continue
        shapes = ["sphere"] if model in ("kneiphof2025", "wang2020") else ["plane", "sphere"]
        cases = [(shape, env_file if model == "kneiphof2025" else None, "")
                 for shape in shapes]
        if model in NORMAL_MAP_MODELS:
            cases += [(shape, None, "normal map") for shape in shapes]
        if model in TEXTURED_MODELS:
            cases += [(shape, None, "textures") for shape in shapes]
        # wang2020 under the environment too: the page's §4.4 glint blur
        # (3 taps under "auto", one sample per pixel) against the native
        # renderer's post pass.
        if model == "wang2020" and env_file:
            cases.append(("sphere", env_file, ""))
        mat = material_view(model, export_dir)
        for i, (shape, env, maps) in enumerate(cases):
            normal_map, textures = maps == "normal map", maps == "textures"
            query = page_query(model, shape, env is not None, mat, normal_map, textures)
            state, log = page.open(query) if i == 0 else page.navigate(query)
            if state.get("error") or state.get("glErrors") or errors_in(log):
                print(f"FAIL {model} {shape}: {state.get('error')} {state.get('glErrors')} "
                      f"{errors_in(log)}")
                ok = False
                continue
            browser = page.hdr()
            native = glintlab.render(native_scene(model, shape, env, mat, normal_map, textures),
                                     gpu=True, file=f"<{model} {shape} view of the page>")
            native = np.asarray(native, dtype=np.float32)
            # The environment's background is drawn from the prefiltered
            # map's finest layer on the page and from the map itself natively:
            # only the shape's pixels are compared (alpha = coverage).
            mask = (browser[..., 3] > 0.5).astype(np.float32) if env else \
                np.ones(browser.shape[:2], np.float32)
            r = compare(browser[..., :3], native, mask)
            lim = (NORMAL_MAP_LIMITS if normal_map else TEXTURED_LIMITS if textures
                   else LIMITS)[model]
            passed = r["mean_rel"] <= lim[0] and r["smoothed_l1"] <= lim[1] and \
                r["mismatch"] <= lim[2]
            view = shape + (" + environment" if env else "") + (f" + {maps}" if maps else "")
            print(f"{model:13s} {view:20s} mean {r['mean_browser']:.5f} / {r['mean_native']:.5f} "
                  f"rel {r['mean_rel']:.4f} (<= {lim[0]})  smoothed {r['smoothed_l1']:.4f} "
                  f"(<= {lim[1]})  mismatching {100 * r['mismatch']:.2f}% (<= {100 * lim[2]:g}%)"
                  f"  {'ok' if passed else 'FAIL'}")
            ok = ok and passed
            if model == "wang2020" and env:
                ok = check_glint_blur(page, query, browser, native, mat, env, mask) and ok
    return ok


# The page's §4.4 glint blur (wang2020 under the environment) against the
# native post pass: the blur's contribution, frame with "auto" minus frame
# with "glint_blur": "none", on both sides. Measured: relative L1 of the
# difference of the two contributions 0.028 (correlation 0.992); a page
# without the blur gives 1.0, so the limit 0.2 separates the two.
BLUR_LIMIT = 0.2


def check_glint_blur(page, query, browser, native, mat, env, mask):
    import numpy as np
    import glintlab
    state, log = page.navigate(query + "&p.glint_blur=none")
    if state.get("error") or state.get("glErrors") or errors_in(log):
        print(f"FAIL wang2020 glint_blur none: {state.get('error')} {state.get('glErrors')} "
              f"{errors_in(log)}")
        return False
    unblurred = page.hdr()
    scene = native_scene("wang2020", "sphere", env, mat)
    scene["materials"][0]["wang2020"] = {"glint_blur": "none"}
    native_unblurred = np.asarray(glintlab.render(scene, gpu=True, file="<wang2020 no blur>"),
                                  dtype=np.float32)
    page_part = luminance(browser[..., :3]) - luminance(unblurred[..., :3])
    native_part = luminance(native) - luminance(native_unblurred)
    scale = np.abs(native_part).sum()
    rel = float(np.abs(page_part - native_part).sum() / max(scale, 1e-12))
    passed = scale > 0 and rel <= BLUR_LIMIT
    print(f"wang2020      glint blur's contribution: relative L1 {rel:.4f} (<= {BLUR_LIMIT}), "
          f"native L1 {scale:.4g}  {'ok' if passed else 'FAIL'}")
    # The tables integrate the export's Fresnel: a URL asking for another
    # is refused, naming the tables (last: the page then shows the error).
    other = {"type": "schlick", "f0": [0.5, 0.5, 0.5]} if mat["fresnel"]["type"] != "schlick" \
        else {"type": "none"}
    state, _ = page.navigate(page_query("wang2020", "sphere", True, dict(mat, fresnel=other)))
    refused = "exported tables were built for Fresnel" in (state.get("error") or "")
    print(f"wang2020      a URL's other Fresnel ({other['type']}) refused: "
          f"{'ok' if refused else 'FAIL: ' + str(state.get('error'))}")
    return passed and refused


# ---- (c) a user's .glb through the file picker -----------------------------

GLB = os.path.join(os.path.dirname(WEB_DIR), "scenes", "gltf", "glint_tiles.glb")


def glb_summary(path):
    """(triangles, material names by first use) of a .glb's default scene,
    read here independently of the page (header, JSON chunk, accessors)."""
    import struct
    with open(path, "rb") as f:
        data = f.read()
    length, kind = struct.unpack_from("<II", data, 12)
    assert kind == 0x4E4F534A
    g = json.loads(data[20:20 + length])
    triangles, names = 0, []

    def visit(i):
        nonlocal triangles
        node = g["nodes"][i]
        if "mesh" in node:
            for p in g["meshes"][node["mesh"]]["primitives"]:
                a = g["accessors"][p["indices"] if "indices" in p else p["attributes"]["POSITION"]]
                triangles += a["count"] // 3
                name = g["materials"][p["material"]]["name"] if "material" in p else "default"
                if name not in names:
                    names.append(name)
        for c in node.get("children", []):
            visit(c)
    for i in g["scenes"][g.get("scene", 0)]["nodes"]:
        visit(i)
    return triangles, names


def pick_file(page, path, timeout=40.0):
    """Hands `path` to the page's file input and waits for its frame;
    returns (asset, assetError)."""
    from selenium.webdriver.common.by import By
    page.driver.find_element(By.ID, "asset").send_keys(path)
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        r = page.driver.execute_script(
            "const g = window.glintlab; return {asset: g.asset, error: g.assetError, ready: g.ready};")
        if r["error"] or (r["asset"] and r["asset"]["name"] == os.path.basename(path) and r["ready"]):
            return r["asset"], r["error"]
        time.sleep(0.05)
    return None, f"no frame within {timeout} s"


def warm_and_blue(hdr):
    """Fractions of the covered, lit pixels whose colour is clearly warm
    (red over blue by 1.5) and clearly blue (blue over red by 1.5)."""
    import numpy as np
    rgb, cover = hdr[..., :3], hdr[..., 3] > 0.5
    lit = cover & (rgb.sum(axis=-1) > 1e-3)
    n = max(int(lit.sum()), 1)
    warm = lit & (rgb[..., 0] > 1.5 * rgb[..., 2])
    blue = lit & (rgb[..., 2] > 1.5 * rgb[..., 0])
    return warm.sum() / n, blue.sum() / n, lit.sum() / cover.size


# JavaScript for the scripts below: the .glb of `b64` as its JSON `json` and
# binary chunk `bin`, and glb(j), a .glb of JSON j with the same binary chunk.
GLB_PARTS = r"""
  const base = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
  const jlen = new DataView(base.buffer).getUint32(12, true);
  const json = JSON.parse(new TextDecoder().decode(base.subarray(20, 20 + jlen)));
  const bin = base.subarray(20 + jlen);
  const glb = (j) => {
    const t0 = new TextEncoder().encode(JSON.stringify(j));
    const t = new Uint8Array(t0.length + (4 - t0.length % 4) % 4).fill(32); t.set(t0);
    const out = new Uint8Array(20 + t.length + bin.length);
    const v = new DataView(out.buffer);
    v.setUint32(0, 0x46546c67, true); v.setUint32(4, 2, true); v.setUint32(8, out.length, true);
    v.setUint32(12, t.length, true); v.setUint32(16, 0x4e4f534a, true);
    out.set(t, 20); out.set(bin, 20 + t.length);
    return out.buffer;
  };
"""

# 600 mutations of a .glb (its bytes truncated or overwritten, or members of
# its JSON replaced by values of other types), each read by readGlb.
FUZZ_SCRIPT = r"""
const [b64, n, done] = arguments;
import('./gltf_asset.js').then(async ({readGlb, AssetError}) => {
""" + GLB_PARTS + r"""  let seed = 7;
  const rand = () => { seed = (seed * 1103515245 + 12345) & 0x7fffffff; return seed / 0x7fffffff; };
  const VALUES = [null, 5, -1, 'x', [], {}, 1e9, 0.5, [1, 2], true];
  const paths = (o, p = [], out = []) => {
    if (o && typeof o === 'object') for (const k of Object.keys(o)) { out.push([...p, k]); paths(o[k], [...p, k], out); }
    return out;
  };
  const all = paths(json);
  const r = {asset: 0, ok: 0, other: 0, examples: []};
  for (let it = 0; it < n; ++it) {
    let buf;
    if (it % 3 === 0) {
      buf = base.slice(0, Math.floor(rand() * base.length)).buffer;
    } else if (it % 3 === 1) {
      const bytes = base.slice();
      for (let k = 0; k < 8; ++k) bytes[Math.floor(rand() * bytes.length)] = Math.floor(rand() * 256);
      buf = bytes.buffer;
    } else {
      const j = JSON.parse(JSON.stringify(json));
      for (let k = 0; k < 3; ++k) {
        const p = all[Math.floor(rand() * all.length)];
        let o = j;
        for (let i = 0; i < p.length - 1 && o && typeof o === 'object'; ++i) o = o[p[i]];
        if (o && typeof o === 'object') o[p[p.length - 1]] = VALUES[Math.floor(rand() * VALUES.length)];
      }
      buf = glb(j);
    }
    try {
      await readGlb(buf, 'mutant.glb');
      r.ok++;
    } catch (e) {
      if (e instanceof AssetError && e.message.startsWith('mutant.glb: ')) r.asset++;
      else { r.other++; if (r.examples.length < 3) r.examples.push(`${e.constructor.name}: ${e.message}`); }
    }
  }
  done(r);
}, (e) => done({asset: 0, ok: 0, other: 1, examples: [String(e)]}));
"""


# The asset with its textures' sampler replaced: wrapS CLAMP_TO_EDGE and
# wrapT MIRRORED_REPEAT; wrapT 1234 (not a glTF mode); magFilter NEAREST;
# an index past the samplers. Returns the colour map's wraps and warnings.
WRAP_SCRIPT = r"""
const [b64, done] = arguments;
import('./gltf_asset.js').then(async ({readGlb}) => {
""" + GLB_PARTS + r"""  const read = async (sampler, index = 0) => {
    const j = JSON.parse(JSON.stringify(json));
    j.samplers = [sampler];
    for (const t of j.textures) t.sampler = index;
    return readGlb(glb(j), 'samplers.glb');
  };
  try {
    const apart = await read({wrapS: 33071, wrapT: 33648});
    const odd = await read({wrapS: 33071, wrapT: 1234});
    const nearest = await read({magFilter: 9728}), missing = await read({}, 9);
    const color = (a) => a.parts.map((p) => p.material).find((m) => m.maps.color)?.maps.color.wrap;
    done({wraps: [color(apart), color(odd), color(missing)], warnings: odd.warnings,
          nearest: nearest.warnings, missing: missing.warnings});
  } catch (e) {
    done({error: String(e)});
  }
}, (e) => done({error: String(e)}));
"""

def test_asset(page, export_dir):
    """scenes/gltf/glint_tiles.glb (scripts/make_gltf_asset.py: a plate whose
    base colour is a blue/orange checker, with roughness and normal maps,
    and a ball with factors only) loads through the file picker: the page
    draws the file's triangles with its two materials, names what it does
    not read, and the plate's colour map reaches the frame (blue pixels,
    which the page's own warm default colour cannot make), and matches the
    native render of the same view. 600 mutations of the file are each read
    or refused with an error naming the file; a truncated and a non-GLB file
    through the picker are errors naming the file and the page keeps
    drawing."""
    ok = True
    triangles, names = glb_summary(GLB)
    for model in ["smooth", "deliot2023"]:
        if model not in exported_models(export_dir):
            continue
        state, log = page.open(f"model={model}&w=256&h=192&env=1")
        if state["error"]:
            print(f"FAIL {model}: the page: {state['error']}")
            ok = False
            continue
        import numpy as np
        before = warm_and_blue(page.hdr())
        asset, error = pick_file(page, GLB)
        if error or not asset:
            print(f"FAIL {model}: {GLB}: {error}")
            ok = False
            continue
        after = warm_and_blue(page.hdr())
        got_names = [m["name"] for m in asset["materials"]]
        checks = [
            (asset["triangles"] == triangles, f"triangles {asset['triangles']}, the file has {triangles}"),
            (got_names == names, f"materials {got_names}, the file's {names}"),
            (asset["materials"][0]["maps"] == ["color", "alpha", "normal"] if names[0] == "Paint" else True,
             f"Paint's maps {asset['materials'][0]['maps']}, expected colour, roughness, normal"),
            (any("KHR_materials_sheen" in w for w in asset["warnings"]),
             f"warnings {asset['warnings']} do not name KHR_materials_sheen"),
            # The page's default colour (0.9, 0.85, 0.75) is warm: no blue
            # pixel before; the checker's blue cells give blue ones after.
            (before[1] < 0.01, f"blue fraction {before[1]:.3f} before the asset (expected none)"),
            (after[1] > 0.05, f"blue fraction {after[1]:.3f} with the asset's colour map (expected > 0.05)"),
            (after[2] > 0.05, f"the asset covers {after[2]:.3f} of the frame lit (expected > 0.05)"),
            (not errors_in(page.driver.get_log("browser")), "browser console errors"),
        ]
        # The same view natively: the file's materials turned into the page's
        # glint material by material_overrides (docs/SCENE_FORMAT.md, "glTF
        # materials"), the camera and the light the page chose, compared as
        # `compare` compares the page's own shapes (the same limits).
        import glintlab
        query = (f"model={model}&w={VIEW['w']}&h={VIEW['h']}&seed={VIEW['seed']}"
                 f"&log_density={VIEW['log_density']}&ndf={VIEW['ndf']}&fresnel=schlick"
                 f"&f0={','.join(map(str, VIEW['f0']))}&env=0&exposure=0&static=1")
        page.open(query)
        pick_file(page, GLB)
        st = page.driver.execute_script("return window.glintlab.state;")
        browser = page.hdr()
        glint = {"type": "glint", "model": model, "ndf": VIEW["ndf"],
                 "log_density": VIEW["log_density"], "seed": VIEW["seed"],
                 "fresnel": {"type": "schlick", "f0": VIEW["f0"]}}
        scene = {"film": {"width": VIEW["w"], "height": VIEW["h"], "exposure": 0.0},
                 "camera": {"eye": st["camera"]["eye"], "target": st["camera"]["target"],
                            "fov_deg": st["camera"]["fovDeg"]},
                 "render": {"integrator": "direct", "spp": 1, "seed": VIEW["seed"]},
                 "materials": [],
                 "shapes": [{"type": "gltf", "name": "tiles", "file": GLB,
                             "material_overrides": {n: glint for n in names}}],
                 "lights": [{"type": "directional", "direction": st["light"]["direction"],
                             "irradiance": st["light"]["irradiance"]}]}
        native = np.asarray(glintlab.render(scene, gpu=True, file="<the page's asset view>"),
                            dtype=np.float32)
        # The page draws no shadows (docs/WEB.md, "Limitations"); the native
        # renderer's ball shadows the plate. Its shadow is left out: pixels
        # lit on the page (luminance > 0.01) where the native image has less
        # than a tenth of it, at most a tenth of the frame (measured 3-5 %).
        lb, ln = luminance(browser[..., :3]), luminance(native)
        shadow = (lb > 0.01) & (ln < 0.1 * lb)
        r = compare(browser[..., :3], native, (~shadow).astype(np.float32))
        lim = LIMITS[model]
        checks.append((shadow.mean() <= 0.1, f"{100 * shadow.mean():.1f}% of the frame dark "
                       "natively and lit on the page (expected only the ball's shadow, <= 10%)"))
        checks.append((r["mean_rel"] <= lim[0] and r["smoothed_l1"] <= lim[1] and
                       r["mismatch"] <= lim[2],
                       f"against render --gpu: mean {r['mean_browser']:.5f} / {r['mean_native']:.5f} "
                       f"rel {r['mean_rel']:.4f} (<= {lim[0]}), smoothed {r['smoothed_l1']:.4f} "
                       f"(<= {lim[1]}), mismatching {100 * r['mismatch']:.2f}% (<= {100 * lim[2]:g}%)"))
        print(f"      asset {model} against render --gpu: rel {r['mean_rel']:.4f}, smoothed "
              f"{r['smoothed_l1']:.4f}, mismatching {100 * r['mismatch']:.2f}%, shadow "
              f"{100 * shadow.mean():.1f}%")
        failed = [m for good, m in checks if not good]
        print(f"{'FAIL' if failed else 'ok  '} asset {model}: {triangles} triangles, materials "
              f"{got_names}, warm/blue fractions before {before[0]:.3f}/{before[1]:.3f}, after "
              f"{after[0]:.3f}/{after[1]:.3f}" + (f": {'; '.join(failed)}" if failed else ""))
        ok = ok and not failed
    # Mutations of the asset, read by the page's reader in the browser: every
    # failure must be an AssetError naming the file (never a TypeError or a
    # RangeError, never a hang).
    page.open("model=smooth&w=64&h=64&env=0")
    page.driver.set_script_timeout(240)
    with open(GLB, "rb") as f:
        glb_b64 = base64.b64encode(f.read()).decode()
    r = page.driver.execute_async_script(FUZZ_SCRIPT, glb_b64, 600)
    page.driver.set_script_timeout(30)
    good = r["other"] == 0 and r["asset"] > 0
    print(f"{'ok  ' if good else 'FAIL'} asset mutations: {r['asset']} errors naming the file, "
          f"{r['ok']} read, {r['other']} other exceptions {r['examples']}")
    ok = ok and good
    # Samplers: wrapS and wrapT reach the maps apart (as the native loader
    # reads them); a value outside glTF's three is named and repeats.
    r = page.driver.execute_async_script(WRAP_SCRIPT, glb_b64)
    good = (r.get("wraps") == [[33071, 33648], [33071, 10497], [10497, 10497]]
            and sum("wrapT 1234 is not a glTF wrap mode" in w for w in r.get("warnings", [])) == 1
            and any("asks for nearest filtering" in w for w in r.get("nearest", []))
            and any("sampler 9 is not one of the file's samplers" in w for w in r.get("missing", [])))
    print(f"{'ok  ' if good else 'FAIL'} asset samplers: colour map wraps {r.get('wraps')}, "
          f"warnings {r.get('warnings')}, nearest {r.get('nearest')}, missing {r.get('missing')} "
          f"{r.get('error', '')}")
    ok = ok and good
    # The same file by URL (`asset=`): fetched as the page starts, kept in
    # the page's own URL; a missing file is an error naming the parameter
    # and the HTTP status, and the page keeps drawing its shape.
    url = "/gltf/" + os.path.basename(GLB)
    state, _ = page.open(f"model=smooth&w=128&h=96&env=0&asset={url}")
    time.sleep(0.5)  # the page writes its URL 200 ms after a change
    r = page.driver.execute_script(
        "const g = window.glintlab; return {asset: g.asset, error: g.assetError, "
        "search: decodeURIComponent(location.search), frames: g.frames};")
    good = (not state["error"] and not r["error"] and r["asset"] is not None
            and r["asset"]["triangles"] == triangles and f"asset={url}" in r["search"])
    print(f"{'ok  ' if good else 'FAIL'} asset by URL {url}: "
          f"{r['asset']['triangles'] if r['asset'] else None} triangles, error {r['error']}, "
          f"URL keeps it: {f'asset={url}' in r['search']}")
    ok = ok and good
    # The same file dropped on the image (a DataTransfer carrying it, as a
    # drag from the desktop delivers it).
    page.open("model=smooth&w=128&h=96&env=0")
    page.driver.execute_script(
        "const bytes = Uint8Array.from(atob(arguments[0]), (c) => c.charCodeAt(0));"
        "const dt = new DataTransfer();"
        "dt.items.add(new File([bytes], 'dropped.glb', {type: 'model/gltf-binary'}));"
        "document.getElementById('view').dispatchEvent("
        "  new DragEvent('drop', {dataTransfer: dt, bubbles: true, cancelable: true}));",
        glb_b64)
    deadline, r = time.monotonic() + 40.0, {}
    while time.monotonic() < deadline:
        r = page.driver.execute_script(
            "const g = window.glintlab; return {asset: g.asset, error: g.assetError, ready: g.ready};")
        if r["error"] or (r["asset"] and r["asset"]["name"] == "dropped.glb" and r["ready"]):
            break
        time.sleep(0.05)
    good = (not r.get("error") and r.get("asset") is not None
            and r["asset"]["name"] == "dropped.glb" and r["asset"]["triangles"] == triangles)
    print(f"{'ok  ' if good else 'FAIL'} asset dropped on the image: "
          f"{r['asset']['triangles'] if r.get('asset') else None} triangles, error {r.get('error')}")
    ok = ok and good
    state, _ = page.open("model=smooth&w=128&h=96&env=0&asset=/gltf/missing.glb")
    r = page.driver.execute_script(
        "const g = window.glintlab; return {asset: g.asset, error: g.assetError, frames: g.frames};")
    good = (r["asset"] is None and r["error"] is not None and "asset=/gltf/missing.glb" in r["error"]
            and "404" in r["error"] and not state["error"])
    print(f"{'ok  ' if good else 'FAIL'} asset by URL, missing: {r['error']} (frames {r['frames']})")
    ok = ok and good
    # Hostile files: the page names the file and the fault, and keeps its view.
    tmp = tempfile.mkdtemp(prefix="glintlab_asset_")
    try:
        with open(GLB, "rb") as f:
            data = f.read()
        cases = {"truncated.glb": (data[:len(data) // 2], "truncated"),
                 "not_a_glb.glb": (b"solid cube\nendsolid cube\n" * 4, "not a binary glTF")}
        for name, (content, expected) in cases.items():
            path = os.path.join(tmp, name)
            with open(path, "wb") as f:
                f.write(content)
            state, _ = page.open("model=smooth&w=128&h=96&env=0")
            asset, error = pick_file(page, path)
            frames = page.driver.execute_script("return window.glintlab.frames;")
            good = bool(error) and name in error and expected in error and asset is None
            print(f"{'ok  ' if good else 'FAIL'} asset {name}: {error} (frames {frames})")
            ok = ok and good
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return ok


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("what", choices=["load", "compare", "asset"])
    ap.add_argument("models", nargs="*")
    ap.add_argument("--export", required=True, help="directory written by scripts/export_web.sh")
    ap.add_argument("--env", default="", help="environment map the export used (kneiphof2025)")
    args = ap.parse_intermixed_args()
    if not os.path.isdir(args.export):
        print(f"FAIL: export directory {args.export} does not exist (run scripts/export_web.sh)")
        return 1
    page = Page(args.export)
    try:
        if args.what == "load":
            ok = test_load(page, args.export)
        elif args.what == "asset":
            ok = test_asset(page, args.export)
        else:
            models = args.models or [m for m in exported_models(args.export) if m in LIMITS]
            missing = [m for m in models if m not in exported_models(args.export)]
            if missing:
                print(f"FAIL: not exported: {missing}")
                return 1
            ok = test_compare(page, args.export, models, args.env)
    finally:
        page.close()
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
