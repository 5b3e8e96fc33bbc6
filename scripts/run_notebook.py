#!/usr/bin/env python3
"""Executes a notebook top to bottom in its own directory, as a reader
running it in Jupyter would, on the interpreter running this script (the
kernel is this Python's ipykernel). Fails on any cell's error, and when the
committed notebook stores more than 1 MiB of outputs.
    python3 scripts/run_notebook.py examples/tour.ipynb [--output executed.ipynb]"""

import argparse
import json
import os
import sys
import tempfile
import time

import nbformat
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError

MAX_STORED_OUTPUT_BYTES = 1 << 20


def stored_output_bytes(nb):
    """Bytes of the JSON text of every code cell's stored outputs."""
    return sum(len(json.dumps(c.get("outputs", []))) for c in nb.cells if c.cell_type == "code")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("notebook")
    parser.add_argument("--output", help="also write the executed notebook here")
    parser.add_argument("--timeout", type=int, default=240, help="seconds per cell (240)")
    args = parser.parse_args()
    nb = nbformat.read(args.notebook, as_version=4)
    stored = stored_output_bytes(nb)
    if stored > MAX_STORED_OUTPUT_BYTES:
        print(f"{args.notebook}: stores {stored} bytes of outputs (at most "
              f"{MAX_STORED_OUTPUT_BYTES}); clear them before committing", file=sys.stderr)
        return 1
    # Debian's kernelspec "python3" runs /usr/bin/python3, which does not
    # see a virtual environment's packages; a spec of the same name first
    # on JUPYTER_PATH runs this interpreter, so the notebook sees the
    # glintlab installed where this script runs.
    spec_root = tempfile.mkdtemp(prefix="glintlab_kernel_")
    os.makedirs(os.path.join(spec_root, "kernels", "python3"))
    with open(os.path.join(spec_root, "kernels", "python3", "kernel.json"), "w") as f:
        json.dump({"argv": [sys.executable, "-Xfrozen_modules=off", "-m", "ipykernel_launcher",
                            "-f", "{connection_file}"],
                   "display_name": "Python 3", "language": "python"}, f)
    os.environ["JUPYTER_PATH"] = os.pathsep.join(
        [spec_root] + [p for p in os.environ.get("JUPYTER_PATH", "").split(os.pathsep) if p])
    os.environ.setdefault("PYDEVD_DISABLE_FILE_VALIDATION", "1")
    client = NotebookClient(nb, timeout=args.timeout, kernel_name="python3",
                            resources={"metadata": {"path": os.path.dirname(
                                os.path.abspath(args.notebook))}})
    start = time.perf_counter()
    try:
        client.execute()
    except CellExecutionError as e:
        print(f"{args.notebook}: a cell failed:\n{e}", file=sys.stderr)
        return 1
    cells = sum(c.cell_type == "code" for c in nb.cells)
    print(f"{args.notebook}: {cells} code cells ran in {time.perf_counter() - start:.1f} s "
          f"on {sys.executable}")
    if args.output:
        os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
        nbformat.write(nb, args.output)
        print(f"wrote {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
