#!/usr/bin/env bash
# Packs a built glintlab binary with the shared libraries it needs (all but
# glibc and the GL/EGL dispatch, which the GPU machine's driver provides) and
# the environment maps the benchmarks read, so that `glintlab bench --gpu` can
# run on a bare machine with an NVIDIA driver and no Debian packages
# (docs/BENCHMARKS.md, "On an NVIDIA GPU").
#
#   scripts/gpu_bundle.sh build/release/glintlab BUNDLE_DIR [build/release/glintlab_tests]
#   # on the GPU machine:
#   LD_LIBRARY_PATH=BUNDLE_DIR/lib BUNDLE_DIR/glintlab bench --gpu ...
#   scripts/gpu_session.sh BUNDLE_DIR OUT_DIR    # or every check in one go
#
# With the test binary too, the bundle records the source tree it was built
# from (BUNDLE_DIR/source_dir), which the tests have compiled in, so that
# gpu_session.sh can link it to the checkout there.
#
# The target must have the GL vendor-neutral dispatch (libglvnd: libEGL.so.1
# and friends) beside its driver. A machine with only the NVIDIA driver's own
# libraries answers "no EGL library found"; unpack Debian's libegl1,
# libglvnd0, libopengl0, libgl1, libglx0 and libgles2 there
# (`apt-get download` here, `dpkg -x PKG.deb /` and `ldconfig` there). The
# benchmarks read environment maps from Blender's path: copy BUNDLE_DIR/world/*
# to /usr/share/blender/datafiles/studiolights/world/ on the target.
set -euo pipefail
bin=${1:?usage: gpu_bundle.sh GLINTLAB_BINARY BUNDLE_DIR [TEST_BINARY]}
out=${2:?usage: gpu_bundle.sh GLINTLAB_BINARY BUNDLE_DIR [TEST_BINARY]}
tests=${3:-}
mkdir -p "$out/lib" "$out/world"
cp "$bin" "$out/glintlab"
strip "$out/glintlab"
if [[ -n $tests ]]; then
    cp "$tests" "$out/glintlab_tests"
    strip "$out/glintlab_tests"
    # The source tree the test binary was configured from (its CMakeCache).
    sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$(dirname "$tests")/CMakeCache.txt" \
        > "$out/source_dir"
fi
# glibc and the GL vendor-neutral dispatch stay the target's own: the first
# must match its loader, the second must reach its driver.
skip='^(linux-vdso|ld-linux|libc\.|libm\.|libdl\.|librt\.|libpthread\.|libEGL\.|libGL|libOpenGL\.|libGLX|libGLdispatch\.)'
ldd "$bin" ${tests:+"$tests"} | awk '/=> \//{print $1, $3}' | sort -u | while read -r name path; do
    if [[ ! $name =~ $skip && ! -e $out/lib/$name ]]; then
        cp -L "$path" "$out/lib/$name"
        strip --strip-unneeded "$out/lib/$name" 2>/dev/null || true
    fi
done
world=/usr/share/blender/datafiles/studiolights/world
[[ -d $world ]] && cp "$world"/*.exr "$out/world/"
du -sh "$out"
