#!/usr/bin/env bash
# The checks a lent GPU machine runs in one go (docs/BENCHMARKS.md, "On an
# NVIDIA GPU"), each stage under its own time limit so that a stage that
# hangs (a driver compiling a program for minutes) costs its limit, not the
# lease. Run from the repository root on the GPU machine:
#
#   scripts/gpu_bundle.sh build/release/glintlab BUNDLE      # here, then
#   tar -cJf bundle.tar.xz BUNDLE                            # (fits a 64 MiB transfer)
#   scripts/gpu_session.sh BUNDLE_OR_TARBALL OUT_DIR [STAGE...]   # there
#
# Stages (default: all, in this order): compile, textured, normal_maps,
# lights, tests, table1. OUT_DIR gets one JSON line per bench call
# (STAGE.jsonl), tests.log and stages.txt. The glintlab_tests binary is read
# from the bundle when scripts/gpu_bundle.sh was given it as well (second
# binary argument), else the tests stage is skipped. RES (1920x1080), FRAMES
# (20), WARMUP (5), ROUNDS (3) and STAGE_SECONDS (100, after which a stage
# makes no more calls; each call has its own limit of 45-120 s) override
# the defaults. About 5 min when nothing hangs, 16 at most: name the stages
# a lease has time for.
set -uo pipefail
bundle=${1:?usage: gpu_session.sh BUNDLE_DIR|BUNDLE.tar.xz OUT_DIR [STAGE...]}
out=${2:?usage: gpu_session.sh BUNDLE_DIR|BUNDLE.tar.xz OUT_DIR [STAGE...]}
shift 2
stages=("$@")
[[ ${#stages[@]} -eq 0 ]] && stages=(compile textured normal_maps lights tests table1)
mkdir -p "$out"
if [[ -f $bundle ]]; then
    tar -xJf "$bundle" -C /tmp
    bundle=/tmp/$(tar -tJf "$bundle" | head -1 | cut -d/ -f1)
fi
G=$bundle/glintlab
export LD_LIBRARY_PATH=$bundle/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
world=/usr/share/blender/datafiles/studiolights/world
if [[ -d $bundle/world && ! -d $world ]]; then
    mkdir -p "$world" && cp "$bundle"/world/*.exr "$world"/
fi
RES=${RES:-1920x1080} FRAMES=${FRAMES:-20} WARMUP=${WARMUP:-5} ROUNDS=${ROUNDS:-3}
t0=$(date +%s)
{
    nvidia-smi --query-gpu=name,driver_version --format=csv,noheader 2>/dev/null || true
    "$G" info 2>&1 | head -3
} > "$out/device.txt"
log() { echo "$(($(date +%s) - t0)) s: $*" | tee -a "$out/stages.txt"; }
# One bench call as one JSON line tagged with the variant: {"error": ...}
# when it fails, passes its limit, or comes after STAGE_SECONDS.
bench() {
    local file=$1 tag=$2 limit=$3
    shift 3
    local json
    if (($(date +%s) - stage_t0 > ${STAGE_SECONDS:-100})); then
        echo "{\"variant\":\"$tag\",\"result\":{\"error\":\"skipped: the stage's time is spent\"}}" \
            >> "$out/$file.jsonl"
        return
    fi
    json=$(timeout "$limit" "$G" bench --gpu --json "$@" 2>&1 | tr -d '\n')
    [[ $json == '{'* ]] || json="{\"error\":$(printf '%s' "${json:-no output: a failure or the limit of $limit s}" |
        python3 -c 'import json,sys; print(json.dumps(sys.stdin.read()))')}"
    echo "{\"variant\":\"$tag\",\"result\":$json}" >> "$out/$file.jsonl"
}
NM='/materials/0/normal_map={"texture":"scenes/compare/textures/bumps.exr","encoding":"signed","uv_transform":{"scale":4}}'
MIX='/materials/0/normal_map/filtering="lean_mixture"'
POINT='/lights/-={"type":"point","position":[0.6,1.2,1.8],"intensity":3.0}'
for stage in "${stages[@]}"; do
    log "$stage"
    stage_t0=$(date +%s)
    case $stage in
    compile)
        # Cold compile + link + first draw of each program, the driver's disk
        # cache off (first_frame_ms_per_density).
        export __GL_SHADER_DISK_CACHE=0 MESA_SHADER_CACHE_DISABLE=true
        small=(--res 64x36 --frames 1 --warmup 0 --scene PLANE_25 --log-density 12)
        for m in smooth deliot2023 zirr2016 chermain2020 wang2020 kneiphof2025; do
            # kneiphof2025 takes GGX only (PLANE_25's material is Beckmann).
            X=(--model "$m")
            [[ $m == kneiphof2025 ]] && X+=(--set '/materials/0/ndf="ggx"')
            bench compile "$m" 45 "${small[@]}" "${X[@]}"
            bench compile "$m+1 light" 45 "${small[@]}" "${X[@]}" --set "$POINT"
            bench compile "$m+3 lights" 45 "${small[@]}" "${X[@]}" --set "$POINT" \
                --set "$POINT" --set "$POINT"
        done
        for m in deliot2023 chermain2020; do
            bench compile "$m lean" 45 "${small[@]}" --model "$m" --set "$NM"
            for k in 2 4; do
                bench compile "$m lean_mixture $k" 45 "${small[@]}" --model "$m" --set "$NM" \
                    --set "$MIX" --set "/materials/0/normal_map/mixture=$k"
            done
        done
        unset __GL_SHADER_DISK_CACHE MESA_SHADER_CACHE_DISABLE
        ;;
    textured)
        # A density and a roughness map of the material's own constants (a
        # white grey PNG scaled to ln N 12 and alpha 0.3) against the numbers.
        python3 -c '
import struct, zlib, sys
w = h = 256
raw = b"".join(b"\x00" + b"\xff" * w for _ in range(h))
def chunk(t, d): return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d))
sys.stdout.buffer.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 0, 0, 0, 0))
                        + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))' > /tmp/white.png
        maps=(--set '/materials/0/log_density={"texture":"/tmp/white.png","colorspace":"linear","scale":12}'
            --set '/materials/0/roughness={"texture":"/tmp/white.png","colorspace":"linear","scale":0.3}')
        for r in $(seq "$ROUNDS"); do
            for v in numbers maps; do
                X=()
                [[ $v == maps ]] && X=("${maps[@]}")
                bench textured "$v" 60 --res "$RES" --frames "$FRAMES" --warmup "$WARMUP" \
                    --scene PLANE_25 --model deliot2023 chermain2020 zirr2016 --log-density 12 "${X[@]}"
            done
        done
        ;;
    normal_maps)
        for r in $(seq "$ROUNDS"); do
            for v in nomap none lean; do
                X=()
                [[ $v != nomap ]] && X=(--set "$NM")
                [[ $v == none ]] && X+=(--set '/materials/0/normal_map/filtering="none"')
                bench normal_maps "$v" 60 --res "$RES" --frames "$FRAMES" --warmup "$WARMUP" \
                    --scene PLANE_25 --model smooth deliot2023 chermain2020 zirr2016 wang2020 \
                    --log-density 12 "${X[@]}"
            done
        done
        ;;
    lights)
        for r in $(seq "$ROUNDS"); do
            for v in 1 2; do
                X=()
                [[ $v == 2 ]] && X=(--set "$POINT")
                bench lights "$v" 60 --res "$RES" --frames "$FRAMES" --warmup "$WARMUP" \
                    --scene SPHERE PLANE_25 --model smooth deliot2023 wang2020 \
                    --log-density 8 12 "${X[@]}"
            done
        done
        ;;
    tests)
        if [[ ! -x $bundle/glintlab_tests ]]; then
            log "no glintlab_tests in the bundle: skipped"
            continue
        fi
        # The tests read GLINTLAB_SOURCE_DIR and the CLI's path, compiled in:
        # this checkout must be found there (a link on a bare machine).
        src=$(cat "$bundle/source_dir" 2>/dev/null)
        if [[ -n $src && ! -e $src ]]; then
            mkdir -p "$(dirname "$src")" && ln -s "$PWD" "$src"
        fi
        if [[ ! -e build/release/glintlab ]]; then
            mkdir -p build/release && ln -s "$G" build/release/glintlab
        fi
        filter='*Gpu*:Wang2020Tables*:*Export*'
        timeout 180 "$bundle/glintlab_tests" --gtest_filter="$filter" > "$out/tests.log" 2>&1
        log "tests: exit $?"
        ;;
    table1)
        bench table1 000 120 --res "$RES" --frames "$FRAMES" --warmup "$WARMUP" \
            --scene PLANE_25 PLANE_90 SPHERE
        bench table1 003 60 --table 003 --res "$RES" --frames "$FRAMES" --warmup "$WARMUP" \
            --log-density 8 20
        ;;
    *) log "unknown stage $stage (compile textured normal_maps lights tests table1)" ;;
    esac
done
log done
