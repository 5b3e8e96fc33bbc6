#!/usr/bin/env bash
# Runs the libFuzzer targets of the lean fuzzing build (docs/VALIDATION.md,
# "Fuzzing"); `make fuzz-ci` and `make fuzz-long` build that tree and call this.
#
#   scripts/fuzz.sh ci   [TARGET...]  each target FUZZ_SECONDS (default 60),
#                                     FUZZ_PARALLEL (default 2) at a time, from
#                                     a fresh corpus: seeds + fuzz/regressions,
#                                     with libFuzzer's random seed fixed
#                                     (FUZZ_SEED, default 1): CI explores the
#                                     same inputs every run (a slower machine a
#                                     prefix of them) instead of failing one run
#                                     in N on whatever a random seed meets
#   scripts/fuzz.sh long [TARGET...]  each target FUZZ_SECONDS (default 3600)
#                                     with FUZZ_JOBS (default nproc) workers,
#                                     one after the other, keeping the corpus
#                                     in BUILD_FUZZ/corpus/TARGET between runs
#
# Targets: scene gltf obj image (default: all). Every run is under
# AddressSanitizer + UndefinedBehaviorSanitizer; a crash, leak, UB report,
# out-of-memory (> 2 GiB) or an input slower than FUZZ_TIMEOUT seconds
# (default 30; wall-clock, so raise it for long runs on a loaded machine,
# where a niced worker can wait that long for a core) stops the target and
# leaves the input in BUILD_FUZZ/artifacts/TARGET/ (add it to
# fuzz/regressions/TARGET/ once fixed). The exit status is non-zero if any
# target failed. Per-target logs: BUILD_FUZZ/logs/TARGET.log.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:?usage: scripts/fuzz.sh ci|long [TARGET...]}
shift
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then targets=(scene gltf obj image); fi
build=${BUILD_FUZZ:-build/fuzz}
bin=$build/fuzz
case $mode in
    ci) seconds=${FUZZ_SECONDS:-60} parallel=${FUZZ_PARALLEL:-2} ;;
    long) seconds=${FUZZ_SECONDS:-3600} parallel=1 jobs=${FUZZ_JOBS:-$(nproc)} ;;
    *) echo "unknown mode '$mode' (ci or long)" >&2; exit 2 ;;
esac
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

run_target() {
    local t=$1 root
    root=$(pwd)
    local seeds=$build/seeds/$t corpus=$build/corpus/$t logs=$build/logs
    rm -rf "$seeds" "$build/artifacts/$t"
    [ "$mode" = ci ] && rm -rf "$corpus"
    mkdir -p "$corpus" "$logs" "$build/artifacts/$t"
    "$bin/glintlab_fuzz_seeds" "$t" "$seeds" "$root" > /dev/null
    local args=(-max_total_time="$seconds" -timeout="${FUZZ_TIMEOUT:-30}" -rss_limit_mb=2048 -print_final_stats=1
                -artifact_prefix="$root/$build/artifacts/$t/")
    [ "$t" = scene ] && args+=(-dict="$root/fuzz/scene.dict")
    [ "$mode" = ci ] && args+=(-seed="${FUZZ_SEED:-1}")
    local inputs=("$root/$corpus" "$root/$seeds")
    [ -d "fuzz/regressions/$t" ] && inputs+=("$root/fuzz/regressions/$t")
    if [ "$mode" = long ]; then
        # -jobs workers each write fuzz-N.log into the working directory.
        mkdir -p "$logs/$t"
        (cd "$logs/$t" && "$root/$bin/glintlab_fuzz_$t" "${args[@]}" -jobs="$jobs" \
            -workers="$jobs" "${inputs[@]}") > "$logs/$t.log" 2>&1
    else
        "$bin/glintlab_fuzz_$t" "${args[@]}" "${inputs[@]}" > "$logs/$t.log" 2>&1
    fi
}

declare -A pid
failed=0
start=$SECONDS
for t in "${targets[@]}"; do
    while [ "$(jobs -rp | wc -l)" -ge "$parallel" ]; do wait -n || true; done
    run_target "$t" &
    pid[$t]=$!
done
for t in "${targets[@]}"; do
    if wait "${pid[$t]}"; then status=ok; else status=FAILED; failed=1; fi
    # A long run's workers write their stats to fuzz-N.log, which libFuzzer's
    # parent process also copies into TARGET.log: count them once.
    if [ "$mode" = long ]; then stats=("$build"/logs/"$t"/fuzz-*.log); else stats=("$build"/logs/"$t".log); fi
    execs=$( (grep -ho 'stat::number_of_executed_units: *[0-9]*' "${stats[@]}" 2>/dev/null || true) |
                awk '{s += $2} END {print s + 0}')
    echo "fuzz $t: $status, $execs executions in ${seconds} s (log $build/logs/$t.log)"
    if [ $status = FAILED ]; then
        grep -h -A12 'ERROR:\|terminate called\|runtime error' "$build"/logs/"$t".log \
            "$build"/logs/"$t"/fuzz-*.log 2>/dev/null | head -40 || true
        ls "$build/artifacts/$t" || true
    fi
done
echo "fuzzing took $((SECONDS - start)) s"
exit $failed
