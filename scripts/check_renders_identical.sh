#!/usr/bin/env bash
# Behaviour-preservation check for refactors: renders every scene of scenes/
# on the CPU with fixed settings and compares the pixels with references
# rendered by an earlier build (a previous commit).
#
#   scripts/check_renders_identical.sh write   REF_DIR [GLINTLAB_BIN]   # references (old build)
#   scripts/check_renders_identical.sh compare REF_DIR [GLINTLAB_BIN]   # new build vs references
#
# Typical use: build the previous commit, `write /tmp/ref build-old/glintlab`,
# then after the change `compare /tmp/ref build/release/glintlab`. Exit status
# is 0 only when every scene's image is bit-identical (`glintlab diff` is not
# needed: the EXR is written deterministically, so the files must be equal byte
# for byte). The settings keep it quick on 2 cores: 96×64, 2 spp, seed 7,
# direct integrator as each scene says. Set SCENES to a subset to speed up.
set -euo pipefail
cd "$(dirname "$0")/.."

mode=${1:?usage: $0 write|compare REF_DIR [GLINTLAB_BIN]}
ref=${2:?usage: $0 write|compare REF_DIR [GLINTLAB_BIN]}
bin=${3:-build/release/glintlab}
[ -x "$bin" ] || { echo "check_renders_identical: no executable $bin" >&2; exit 2; }

scenes=${SCENES:-$(ls scenes/*.json)}
case "$mode" in
write) mkdir -p "$ref" ;;
compare) [ -d "$ref" ] || { echo "check_renders_identical: no reference dir $ref" >&2; exit 2; } ;;
*) echo "check_renders_identical: mode must be write or compare" >&2; exit 2 ;;
esac

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=0
for scene in $scenes; do
    name=$(basename "$scene" .json)
    out="$tmp/$name.exr"
    "$bin" render "$scene" -o "$out" --res 96x64 --spp 2 --seed 7 --threads 2 --quiet >/dev/null
    if [ "$mode" = write ]; then
        cp "$out" "$ref/$name.exr"
        echo "wrote $ref/$name.exr"
    elif cmp -s "$out" "$ref/$name.exr"; then
        echo "identical  $name"
    else
        echo "DIFFERENT  $name"
        failed=1
    fi
done
exit $failed
