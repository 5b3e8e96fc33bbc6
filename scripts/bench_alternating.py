#!/usr/bin/env python3
"""Times glintlab binaries against each other on a shared, noisy machine
(docs/BENCHMARKS.md): runs `BIN bench --gpu --json ARGS` for each binary in
turn, ROUNDS times (so slow phases of the machine hit every binary alike),
and prints, per binary, scene and model, the minimum over the rounds of the
frame time (render + glFinish, ms) at each point of the density sweep.

Usage: scripts/bench_alternating.py ROUNDS "BENCH ARGS" BIN [BIN...]
e.g.   scripts/bench_alternating.py 3 "--res 480x270 --frames 7 --warmup 2 \\
           --scene PLANE_25 --model smooth deliot2023 --log-density 8 20" \\
           old/glintlab build/release/glintlab
"""
import json
import shlex
import subprocess
import sys


def frame_times(binary, args):
    """{(scene, model): [frame ms per density]} of one `bench --gpu --json` run."""
    run = subprocess.run([binary, "bench", "--gpu", "--json"] + args, capture_output=True,
                         text=True)
    if run.returncode != 0:
        sys.exit(f"bench_alternating: {binary} failed ({run.returncode}):\n{run.stderr.strip()}")
    # Warnings (e.g. clamped environment texels) precede the JSON on stdout.
    start = run.stdout.find("{")
    if start < 0:
        sys.exit(f"bench_alternating: {binary} printed no JSON")
    doc = json.loads(run.stdout[start:])
    return {(r["scene"], r["model"]): r["frame_ms_per_density"] for r in doc["results"]}


def main(argv):
    if len(argv) < 4 or not argv[1].isdigit() or int(argv[1]) < 1:
        sys.exit(__doc__)
    rounds, args, binaries = int(argv[1]), shlex.split(argv[2]), argv[3:]
    best = {}
    for _ in range(rounds):
        for binary in binaries:
            for key, times in frame_times(binary, args).items():
                old = best.get((binary, key))
                best[(binary, key)] = times if old is None else [min(a, b) for a, b in zip(old, times)]
    for (binary, (scene, model)), times in best.items():
        print(f"{binary}\t{scene}\t{model}\t" + " ".join(f"{t:.1f}" for t in times))


if __name__ == "__main__":
    main(sys.argv)
