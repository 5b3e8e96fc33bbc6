#!/usr/bin/env python3
"""Static instruction counts of the GPU forward shader per glint model
(docs/BENCHMARKS.md "Where the time goes on a GPU").

Assembles the forward fragment shader as realtime/forward_shaders.cpp does
(prelude, light-count defines, the model's GLSL glue, forward.frag.glsl; each
#include "glintlab/..." expanded once from src/), compiles it to SPIR-V with
glslangValidator, optimises it with spirv-opt -O (inlining, constant folding,
CSE: close to what a driver's front end keeps) and counts the instructions of
the optimised module: all of them, and by kind (extended GLSL.std.450 calls
such as Log/Exp/Sqrt, texture reads, loops/branches, arithmetic).

Usage: scripts/shader_instruction_counts.py [--point N] [--directional N]
       [--environment] [--define NAME[=VALUE]]... [--src DIR] GLUE.glsl...
GLUE is a path under src/, e.g. glintlab/glints/deliot2023/deliot2023_gpu.glsl.
Requires glslangValidator, spirv-opt and spirv-dis (Debian: glslang-tools,
spirv-tools).
"""
import argparse
import collections
import os
import re
import subprocess
import sys
import tempfile

SRC = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "src")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"\s*$')


def expand(text, seen):
    global SRC
    out = []
    for line in text.splitlines():
        m = INCLUDE.match(line)
        if m:
            path = m.group(1)
            if path not in seen:
                seen.add(path)
                with open(os.path.join(SRC, path)) as f:
                    out.append(expand(f.read(), seen))
            continue
        out.append(line)
    return "\n".join(out)


def assemble(glue, point, directional, environment, defines):
    text = "#version 450 core\n#define INOUT(T) inout T\n#define OUT(T) out T\n#define GLINTLAB_GLSL 1\n"
    for d in defines:
        name, _, value = d.partition("=")
        text += f"#define {name} {value or 1}\n"
    text += (f"#define GLINTLAB_POINT_LIGHTS {point}\n#define GLINTLAB_DIRECTIONAL_LIGHTS {directional}\n"
             f"#define GLINTLAB_ENVIRONMENT {1 if environment else 0}\n"
             "#define GLINTLAB_ENV_SPECULAR_SAMPLES 32\n#define GLINTLAB_ENV_DIFFUSE_SAMPLES 16\n")
    root = f'#include "{glue}"\n#include "glintlab/realtime/shaders/forward.frag.glsl"\n'
    return text + expand(root, set())


KINDS = {
    "ext (log/exp/sqrt/trig/pow...)": re.compile(r"OpExtInst "),
    "texture reads": re.compile(r"OpImage(Sample|Fetch|Gather|Read)"),
    "branches": re.compile(r"Op(BranchConditional|Switch)\b"),
    "loops": re.compile(r"OpLoopMerge\b"),
    "float arithmetic": re.compile(r"Op(FAdd|FSub|FMul|FDiv|FMod|FNegate|VectorTimesScalar|Dot)\b"),
    "integer/bit ops": re.compile(r"Op(IAdd|ISub|IMul|ShiftRightLogical|ShiftLeftLogical|BitwiseXor|BitwiseOr|BitwiseAnd|UMod|SMod|SDiv|UDiv)\b"),
    "selects": re.compile(r"OpSelect\b"),
}


def counts(glsl):
    with tempfile.TemporaryDirectory() as d:
        src = os.path.join(d, "s.frag")
        with open(src, "w") as f:
            f.write(glsl)
        spv = os.path.join(d, "s.spv")
        opt = os.path.join(d, "o.spv")
        r = subprocess.run(["glslangValidator", "-G", "--auto-map-locations", "--auto-map-bindings",
                            "-S", "frag", src, "-o", spv], capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit(r.stdout + r.stderr)
        subprocess.run(["spirv-opt", "--skip-validation", "-O", spv, "-o", opt], check=True)
        dis = subprocess.run(["spirv-dis", "--raw-id", opt], check=True, capture_output=True,
                             text=True).stdout
    body = [l for l in dis.splitlines() if l.strip() and not l.lstrip().startswith(";")]
    # Instructions inside functions only (after the first OpFunction).
    start = next(i for i, l in enumerate(body) if "OpFunction " in l)
    code = [l for l in body[start:] if not re.search(r"Op(Function|FunctionEnd|Label|Phi)\b", l)]
    c = collections.OrderedDict(total=len(code))
    for k, rx in KINDS.items():
        c[k] = sum(1 for l in code if rx.search(l))
    return c


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("glue", nargs="+")
    ap.add_argument("--point", type=int, default=0)
    ap.add_argument("--directional", type=int, default=1)
    ap.add_argument("--environment", action="store_true")
    ap.add_argument("--define", action="append", default=[])
    ap.add_argument("--src", help="source tree (default: this checkout's src/)")
    a = ap.parse_args()
    if a.src:
        global SRC
        SRC = a.src
    for g in a.glue:
        c = counts(assemble(g, a.point, a.directional, a.environment, a.define))
        print(g + ": " + ", ".join(f"{k} {v}" for k, v in c.items()))


if __name__ == "__main__":
    main()
