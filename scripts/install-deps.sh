#!/usr/bin/env bash
# Installs every Debian 12 package glintlab needs to build, test and run.
# Idempotent and non-interactive: when everything is already installed it
# returns at once; otherwise it runs `apt-get update` and installs what is missing.
set -euo pipefail

packages=(
    build-essential cmake ninja-build pkg-config git
    libembree-dev libtbb-dev libglm-dev libopenexr-dev libstb-dev
    nlohmann-json3-dev libcli11-dev libfmt-dev libboost-math-dev
    libtinygltf-dev libtinyobjloader-dev libdraco-dev libjpeg-dev
    libgtest-dev libgmock-dev libbenchmark-dev
    glslang-tools spirv-cross
    clang libclang-rt-14-dev
    chromium chromium-driver python3-selenium
    blender-data
    libepoxy-dev libglfw3-dev libimgui-dev libegl-dev libegl-mesa0 libgl1-mesa-dri
    xvfb xauth
    python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest
    python3-pandas python3-matplotlib python3-distributed
    python3-venv python3-pip python3-setuptools python3-wheel python3-tqdm
    jupyter-nbconvert python3-nbclient python3-nbformat python3-ipykernel
)

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done

if [ ${#missing[@]} -eq 0 ]; then
    echo "install-deps: all ${#packages[@]} packages present"
    exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
    SUDO="sudo"
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
