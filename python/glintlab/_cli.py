"""The `glintlab` command of an installed package: the C++ command-line
program installed beside the module (glintlab/bin/glintlab), run in place
of this process so that its exit status, signals and output are its own."""

import os
import sys


def executable():
    """Path of the installed command-line program."""
    return os.path.join(os.path.dirname(os.path.abspath(__file__)), "bin", "glintlab")


def main():
    exe = executable()
    if not os.access(exe, os.X_OK):
        sys.exit(f"glintlab: {exe} is missing: this glintlab package was not installed by "
                 "`pip install` (a build tree's python/ directory has no command; run "
                 "<build>/glintlab instead)")
    os.execv(exe, ["glintlab"] + sys.argv[1:])


if __name__ == "__main__":
    main()
