#!/usr/bin/env bash
# Exports the glint models for the WebGL2 page (web/, docs/WEB.md):
#     scripts/export_web.sh [GLINTLAB_CLI] [OUT_DIR]
# runs `glintlab export MODEL --lang glsles -o OUT_DIR` for every model the
# exporter accepts (kneiphof2025 and wang2020 with `--env` the environment
# map, so the page has their prefiltered maps / tables) and writes OUT_DIR/models.json
# (`glintlab info --json`: the parameters' ranges for the sliders) and
# OUT_DIR/index.json (the exported models, the page's model list).
# Defaults: build/release/glintlab, web/export (gitignored). The map is
# $GLINTLAB_WEB_ENV, default Blender's CC0 studio light forest.exr (Debian
# blender-data).
set -euo pipefail
cli="${1:-build/release/glintlab}"
out="${2:-web/export}"
env_map="${GLINTLAB_WEB_ENV:-/usr/share/blender/datafiles/studiolights/world/forest.exr}"
models=(smooth zirr2016 chermain2020 deliot2023 kneiphof2025 wang2020)

if [[ ! -x "$cli" ]]; then
    echo "export_web.sh: $cli is not an executable glintlab (build it: make build)" >&2
    exit 1
fi
if [[ ! -f "$env_map" ]]; then
    echo "export_web.sh: environment map $env_map not found (GLINTLAB_WEB_ENV, or install blender-data)" >&2
    exit 1
fi
mkdir -p "$out"
"$cli" info --json > "$out/models.json.tmp"
mv "$out/models.json.tmp" "$out/models.json"
for model in "${models[@]}"; do
    args=(export "$model" --lang glsles -o "$out")
    [[ "$model" == kneiphof2025 || "$model" == wang2020 ]] && args+=(--env "$env_map")
    "$cli" "${args[@]}"
done
names=$(printf '"%s", ' "${models[@]}")
printf '{"models": [%s]}\n' "${names%, }" > "$out/index.json"
echo "export_web.sh: ${models[*]} exported to $out; serve the repository root with" \
     "\`python3 -m http.server\` and open http://localhost:8000/web/"
