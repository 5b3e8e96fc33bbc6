#!/usr/bin/env bash
# The documented Python install, as a test fixture: a fresh virtual
# environment that sees Debian's packages, then `pip install` of this
# source tree with the extension and the command taken from BUILD_DIR
# (already built by `make`; GLINTLAB_NO_BUILD: pip only packs them, so no
# build relinks the command while other tests run it). No network: every
# dependency is a Debian package (scripts/install-deps.sh).
#   scripts/install_python_venv.sh VENV_DIR BUILD_DIR SOURCE_DIR
set -euo pipefail
venv=$1 build=$2 source=$3
rm -rf "$venv"
/usr/bin/python3 -m venv --system-site-packages "$venv"
GLINTLAB_BUILD_DIR=$build GLINTLAB_NO_BUILD=1 "$venv/bin/pip" install --quiet --no-build-isolation --no-index \
    --no-deps --disable-pip-version-check "$source"
# The package imports from outside the source tree and agrees with its command.
cd "$venv"
module=$("$venv/bin/python" -c 'import glintlab; print(glintlab.__version__)')
command=$("$venv/bin/glintlab" --version)
if [ "glintlab $module" != "$command" ]; then
    echo "install_python_venv: glintlab.__version__ $module disagrees with '$command'" >&2
    exit 1
fi
echo "installed glintlab $module into $venv"
