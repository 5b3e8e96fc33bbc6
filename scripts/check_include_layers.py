#!/usr/bin/env python3
"""Checks that every include between folders of src/glintlab runs along an
arrow of docs/ARCHITECTURE.md's table ("every folder's includes (arrows)").

Usage: check_include_layers.py REPO_ROOT

Tests (*_test.cpp, *_test_util.h), benchmarks (*_bench.cpp) and the fuzz
tree are left out, as the table leaves them out; research files (CMake's
GLINTLAB_RESEARCH_SOURCE_REGEX) get the research library's arrows. Exits 1
naming each include that runs against the table.
"""
import pathlib
import re
import sys

# The runtime library's arrows (docs/ARCHITECTURE.md).
RUNTIME = {
    "realtime": {"glints", "gl", "scene", "microfacet", "core"},
    "export": {"loader", "glints", "scene", "core"},
    "render": {"glints", "scene", "microfacet", "core"},
    "loader": {"glints", "scene", "microfacet", "core"},
    "glints": {"gl", "scene", "counting", "microfacet", "core"},
    # scene/ reaches glints/ only for the material description (below).
    "scene": {"glints", "microfacet", "core"},
    "counting": {"microfacet", "core"},
    "microfacet": {"core"},
    "gl": {"core"},
    "core": set(),
}
# The research library's: its own folders, and the research files of the
# runtime folders (experiments and validation suites), which also reach validate/.
RESEARCH = {
    "bench": {"realtime", "gl", "render", "loader", "glints", "scene", "core"},
    "compare": {"realtime", "gl", "render", "loader", "glints", "scene", "core", "validate"},
    "validate": {"loader", "glints", "scene", "core"},
    "fuzz": {"loader", "scene", "core"},
}
RESEARCH_FILE = re.compile(
    r"_experiments\.(cpp|h)$|/validate_[a-z0-9_]*\.(cpp|h)$|/validation_suites\.(cpp|h)$"
    r"|/counting/(lod_blend_experiment|pow_accuracy|robustness)\.cpp$")
LEFT_OUT = re.compile(r"_test\.cpp$|_test_util\.h$|_bench\.cpp$")
INCLUDE = re.compile(r'^\s*#\s*include\s+"glintlab/(([a-z0-9_]+)/[^"]*)"', re.M)
# The material description: the glint material (glint_desc.h), the list of
# models and each model's parameter struct (in its own folder, one model one
# folder). It is the one part of glints/ below scene/: scene/ includes it
# (a material holds a GlintDesc), it includes only core/, microfacet/ and
# itself, and the rest of glints/ sits above scene/.
DESCRIPTION = re.compile(
    r"^glints/(glint_desc|model_list|model_params|model_headers)\.h$"
    r"|^glints/([a-z0-9]+)/\2_params\.h$")
DESCRIPTION_ARROWS = {"core", "microfacet"}


def allowed(folder: str, rel: str) -> set:
    if folder in RESEARCH:
        return RESEARCH[folder] | {folder}
    arrows = set(RUNTIME.get(folder, set())) | {folder}
    if RESEARCH_FILE.search("/" + rel):
        arrows |= {"validate"}
        if "validation_suites." in rel:
            arrows |= {"compare"}
    return arrows


def main() -> int:
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    src = root / "src" / "glintlab"
    against = []
    files = 0
    for path in sorted(src.rglob("*")):
        if path.suffix not in (".h", ".cpp", ".glsl") or not path.is_file():
            continue
        rel = path.relative_to(src).as_posix()
        if LEFT_OUT.search(rel):
            continue
        folder = rel.split("/", 1)[0]
        if folder not in RUNTIME and folder not in RESEARCH:
            against.append(f"{rel}: folder {folder}/ is not in the table")
            continue
        files += 1
        ok = allowed(folder, rel)
        described = DESCRIPTION.search(rel)
        for path_included, target in INCLUDE.findall(path.read_text(encoding="utf-8")):
            if described:
                if target not in DESCRIPTION_ARROWS and not DESCRIPTION.search(path_included):
                    against.append(f"{rel} (the material description) includes {path_included} "
                                   f"(allowed: core, microfacet and the description itself)")
                continue
            if target not in ok:
                against.append(f"{rel} includes {target}/ (allowed from {folder}/: "
                               f"{', '.join(sorted(ok - {folder})) or 'nothing'})")
            elif folder == "scene" and target == "glints" and not DESCRIPTION.search(path_included):
                against.append(f"{rel} includes {path_included}: scene/ reaches glints/ only for "
                               f"the material description (glint_desc.h, model_list.h, "
                               f"model_params.h, model_headers.h, <model>/<model>_params.h)")
    for line in against:
        print(line)
    if against:
        print(f"{len(against)} include(s) against docs/ARCHITECTURE.md's arrows")
        return 1
    print(f"{files} files: every include runs along an arrow of docs/ARCHITECTURE.md")
    return 0


if __name__ == "__main__":
    sys.exit(main())
