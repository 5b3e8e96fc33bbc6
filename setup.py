"""Builds the glintlab wheel from the project's CMake build.

The build directory is GLINTLAB_BUILD_DIR (default build/release, the one
`make` uses, so an install after `make demo` only packs what is built). A
directory without a CMake cache is configured as the Makefile does
(Ninja, Release). Only the extension and the command-line program are
built; the wheel holds them beside python/glintlab/*.py. GLINTLAB_NO_BUILD=1
packs the build directory's files without building."""

import os
import re
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py
from setuptools.dist import Distribution

ROOT = Path(__file__).resolve().parent


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text(encoding="utf-8")
    match = re.search(r"project\(glintlab VERSION ([0-9]+\.[0-9]+\.[0-9]+)", text)
    if not match:
        sys.exit("setup.py: CMakeLists.txt has no `project(glintlab VERSION x.y.z)`")
    return match.group(1)


def run(command):
    print("+ " + " ".join(str(c) for c in command), flush=True)
    subprocess.run([str(c) for c in command], check=True)


class CMakeBuildPy(build_py):
    """build_py, plus the CMake targets `glintlab_python` (the extension)
    and `glintlab_cli`, copied into the package."""

    def run(self):
        super().run()
        build_dir = Path(os.environ.get("GLINTLAB_BUILD_DIR", "build/release"))
        if not build_dir.is_absolute():
            build_dir = ROOT / build_dir
        # GLINTLAB_NO_BUILD=1: pack what the build directory holds (ctest's
        # install fixture: a build started while other tests run the
        # command could relink it under them).
        if os.environ.get("GLINTLAB_NO_BUILD") != "1":
            if not (build_dir / "CMakeCache.txt").exists():
                run(["cmake", "-S", ROOT, "-B", build_dir, "-G", "Ninja",
                     "-DCMAKE_BUILD_TYPE=Release"])
            run(["cmake", "--build", build_dir, "--target", "glintlab_python", "glintlab_cli",
                 "-j", str(os.cpu_count() or 1)])
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        extension = build_dir / "python" / "glintlab" / f"_glintlab{suffix}"
        if not extension.exists():
            found = sorted(p.name for p in (build_dir / "python" / "glintlab").glob("_glintlab*"))
            sys.exit(f"setup.py: {extension} is missing (found {found or 'none'}): the build in "
                     f"{build_dir} is for another Python than {sys.executable} "
                     f"(set GLINTLAB_BUILD_DIR to a new directory)")
        program = build_dir / "glintlab"
        if not program.exists():
            sys.exit(f"setup.py: {program} is missing: build it first (make build)")
        package = Path(self.build_lib) / "glintlab"
        shutil.copy2(extension, package / extension.name)
        (package / "bin").mkdir(exist_ok=True)
        shutil.copy2(program, package / "bin" / "glintlab")


class BinaryDistribution(Distribution):
    """The wheel holds compiled code: tag it for this platform and Python."""

    def has_ext_modules(self):
        return True


(ROOT / "build" / "setuptools").mkdir(parents=True, exist_ok=True)
setup(
    version=project_version(),
    package_dir={"": "python"},
    packages=["glintlab"],
    cmdclass={"build_py": CMakeBuildPy},
    distclass=BinaryDistribution,
    options={"build": {"build_base": "build/setuptools"},
             "egg_info": {"egg_base": "build/setuptools"}},
    zip_safe=False,
)
