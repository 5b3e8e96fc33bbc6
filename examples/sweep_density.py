"""Image-mean relative error against log_density, one line per glint model,
against the `explicit` ground truth (the convergence plots of the glint
papers: at high densities every model tends to its smooth limit).

    PYTHONPATH=build/release/python /usr/bin/python3 examples/sweep_density.py [--scheduler ADDR]

Reads examples/sweep_density.json (scene, axes, reference) and writes
out/sweep_density/{sweep.csv, plot_*.png, rel_error_vs_density.png}.
"""

import argparse
import json
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import glintlab  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scheduler", help="Dask scheduler address (default: local cluster)")
    parser.add_argument("-o", "--output", default=None)
    args = parser.parse_args()
    with open(os.path.join(HERE, "sweep_density.json"), encoding="utf-8") as f:
        spec = json.load(f)
    output = args.output or os.path.join(HERE, spec["output"])
    table = glintlab.sweep(os.path.join(HERE, spec["scene"]), spec["axes"],
                           metrics=spec["metrics"], reference=spec["reference"], res=spec["res"],
                           seed=spec["seed"], client=args.scheduler, output=output)
    axis = "/materials/0/log_density"
    fig, ax = plt.subplots(figsize=(6, 4))
    for model, group in table.groupby("model", sort=False):
        g = group.sort_values(axis)
        ax.semilogy(g[axis], g["rel_error"].clip(lower=1e-6), marker="o", label=model)
    ax.set_xlabel("log_density (ln facets per unit uv area)")
    ax.set_ylabel("|mean − mean_explicit| / mean_explicit")
    ax.set_title("Image-mean relative error vs the explicit ground truth")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    path = os.path.join(output, "rel_error_vs_density.png")
    fig.savefig(path, dpi=120)
    print(table.pivot(index=axis, columns="model", values="rel_error").to_string())
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
