"""Image-mean relative error against log_density, one line per glint model,
against the `explicit` ground truth, with standard errors (the convergence
plots of the glint papers: at high densities every model tends to its
smooth limit).

    env/bin/python examples/sweep_density.py [--scheduler ADDR] [--realizations R]

Reads examples/sweep_density.json (scene, axes, reference). Every point is
rendered with R material seeds (realizations), each against the truth of
the same seed, so that the error of a point is the difference of two means
over R realizations, with its standard error; one realization of a sparse
truth is a rare-event estimate (at ln 10 it put every model ~70 % off).
Points whose truth is black (no glint reached the camera in any
realization) have no relative error: they are listed, not dropped.
Writes out/sweep_density/{sweep.csv, rel_error_vs_density.png}.
"""

import argparse
import json
import math
import os

import numpy as np

import glintlab

HERE = os.path.dirname(os.path.abspath(__file__))
SEED_AXIS = "/materials/0/seed"
DENSITY_AXIS = "/materials/0/log_density"


def reference_mean(image, reference):
    """The reference render's image-mean luminance (a sweep metric)."""
    return glintlab._sweep.mean_luminance(reference)


def summarize(table):
    """Per (model, density): mean error of the R realizations' means and its
    standard error (delta method on the ratio of two independent means)."""
    rows = []
    for (model, density), g in table.groupby(["model", DENSITY_AXIS], sort=False):
        m, t = g["mean_luminance"].to_numpy(), g["reference_mean"].to_numpy()
        r = len(g)
        mm, tm = m.mean(), t.mean()
        if not tm > 0.0:
            rows.append({"model": model, "log_density": density, "rel_error": math.nan,
                         "se": math.nan, "realizations": r})
            continue
        var = m.var(ddof=1) / r + (mm / tm) ** 2 * t.var(ddof=1) / r
        rows.append({"model": model, "log_density": density, "rel_error": (mm - tm) / tm,
                     "se": math.sqrt(var) / tm, "realizations": r})
    import pandas as pd
    return pd.DataFrame(rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scheduler", help="Dask scheduler address (default: local threads)")
    parser.add_argument("--realizations", type=int, default=8, help="material seeds per point (8)")
    parser.add_argument("-o", "--output", default=None)
    args = parser.parse_args()
    if args.realizations < 2:
        parser.error("--realizations: at least 2 (a standard error needs two)")
    with open(os.path.join(HERE, "sweep_density.json"), encoding="utf-8") as f:
        spec = json.load(f)
    output = args.output or os.path.join(HERE, spec["output"])
    axes = dict(spec["axes"])
    axes[SEED_AXIS] = list(range(1, args.realizations + 1))
    table = glintlab.sweep(os.path.join(HERE, spec["scene"]), axes,
                           metrics={"mean_luminance": glintlab._sweep.mean_luminance,
                                    "reference_mean": reference_mean},
                           reference=spec["reference"], res=spec["res"], seed=spec["seed"],
                           client=args.scheduler, output=output, plots=False)
    summary = summarize(table)
    black = summary[~np.isfinite(summary["rel_error"])]
    for _, row in black.iterrows():
        print(f"no relative error at {row['model']} ln {row['log_density']}: the truth is black "
              f"in all {row['realizations']} realizations")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    shown = summary[np.isfinite(summary["rel_error"])]
    for model, g in shown.groupby("model", sort=False):
        g = g.sort_values("log_density")
        ax.errorbar(g["log_density"], 100 * g["rel_error"], yerr=100 * g["se"], marker="o",
                    capsize=3, label=model)
    ax.axhline(0.0, color="k", lw=0.8)
    ax.set_xlabel("log_density (ln facets per unit uv area)")
    ax.set_ylabel("(mean − mean_explicit) / mean_explicit  [%]")
    ax.set_title(f"Image-mean error vs explicit, ±1 s.e. over {args.realizations} seeds")
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    path = os.path.join(output, "rel_error_vs_density.png")
    fig.savefig(path, dpi=120)
    print(summary.to_string(index=False, float_format=lambda x: f"{x:.4f}"))
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
