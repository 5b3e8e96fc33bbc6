"""Parameter sweeps: the product of axes of scene overrides, one render per
point, run as Dask distributed tasks (docs/PYTHON.md "Sweeps").

Every point's task is pure and keyed by the sweep's content and the point's
index, and its seed is derived from the point's values only, so a retried
task (a killed worker) recomputes exactly the same row and the table has
each point once."""

import hashlib
import itertools
import json
import os
import re
import time

import numpy as np

# Rec. 709 luminance weights, as core/image.h luminance().
_Y = np.array([0.2126, 0.7152, 0.0722])


def _mean_luminance(image):
    return float(np.mean(image.astype(np.float64) @ _Y))


def mean_luminance(image, reference=None):
    """Image mean of the Rec. 709 luminance."""
    return _mean_luminance(image)


def mean_r(image, reference=None):
    return float(np.mean(image[..., 0], dtype=np.float64))


def mean_g(image, reference=None):
    return float(np.mean(image[..., 1], dtype=np.float64))


def mean_b(image, reference=None):
    return float(np.mean(image[..., 2], dtype=np.float64))


def rel_error(image, reference):
    """|mean luminance − the reference's| / the reference's (the image-mean
    relative error of the glint papers' convergence plots)."""
    ref = _mean_luminance(reference)
    return abs(_mean_luminance(image) - ref) / ref if ref > 0 else float("nan")


def rel_rmse(image, reference):
    """Per-pixel RMS difference of luminance over the reference's mean."""
    d = (image.astype(np.float64) - reference.astype(np.float64)) @ _Y
    ref = _mean_luminance(reference)
    return float(np.sqrt(np.mean(d * d)) / ref) if ref > 0 else float("nan")


METRICS = {"mean_luminance": mean_luminance, "mean_r": mean_r, "mean_g": mean_g,
           "mean_b": mean_b, "rel_error": rel_error, "rel_rmse": rel_rmse}
_NEEDS_REFERENCE = {"rel_error", "rel_rmse"}


def point_seed(base_seed, values):
    """The render seed of a point: a hash of the base seed and the point's
    axis values (32 bits), the same on any worker and in any order."""
    text = json.dumps([int(base_seed), values], sort_keys=True, separators=(",", ":"))
    return int.from_bytes(hashlib.sha256(text.encode()).digest()[:4], "little")


def realization_seed(base_seed, values, realization):
    """The render seed of realization r of a point: point_seed for r = 0
    (a sweep of one realization renders what it always did), a hash of the
    point and r otherwise."""
    if realization == 0:
        return point_seed(base_seed, values)
    return point_seed(base_seed, {"point": values, "realization": int(realization)})


def _shift_glint_seeds(doc, realization):
    """Realization r renders another microstructure: every glint material's
    `seed` (the facets' placement, default 0) plus r, modulo 2^32."""
    for m in doc.get("materials", []):
        if isinstance(m, dict) and m.get("type") == "glint":
            m["seed"] = (int(m.get("seed", 0)) + int(realization)) % (1 << 32)


def _render_task(doc_text, file, values, seed, res, spp, threads, realization=0):
    """One render: the point's model (axis "model" switches every glint
    material's model), then its overrides, on the base document, as
    glintlab.render applies them; then realization r's glint seeds.
    Returns (image, seconds)."""
    import glintlab
    doc = json.loads(doc_text)
    if values.get("model") is not None:
        glintlab.set_model(doc, values["model"])
    glintlab.apply_overrides(doc, {k: v for k, v in values.items() if k != "model"})
    if realization:
        _shift_glint_seeds(doc, realization)
    start = time.perf_counter()
    image = glintlab.render(doc, spp=spp, seed=seed, res=res, threads=threads, file=file,
                            progress=False)
    return image, time.perf_counter() - start


def _row_task(index, values, rendered, references, metric_names, custom):
    """A point's row: each metric's mean over the realizations (each against
    the reference of the same realization) and its standard error (sample
    standard deviation / sqrt(R); NaN for one realization)."""
    row = {"point": index}
    row.update({k: _cell(v) for k, v in values.items()})
    for name in metric_names:
        fn = custom.get(name) or METRICS[name]
        samples = np.array([float(fn(image, None if references is None else references[r][0]))
                            for r, (image, _) in enumerate(rendered)])
        row[name] = float(np.mean(samples))
        row[name + "_se"] = (float(np.std(samples, ddof=1) / np.sqrt(samples.size))
                             if samples.size > 1 else float("nan"))
    row["render_s"] = float(np.mean([seconds for _, seconds in rendered]))
    return row


def _cell(v):
    return v if isinstance(v, (int, float, str, bool)) or v is None else json.dumps(v)


def _slug(axis):
    return re.sub(r"[^A-Za-z0-9]+", "_", axis).strip("_") or "axis"


class _Dep(str):
    """An argument (or an element of a list argument) that is the result of
    the task with this key."""


def _resolve(arg, results):
    if isinstance(arg, _Dep):
        return results[arg]
    if isinstance(arg, list):
        return [_resolve(a, results) for a in arg]
    return arg


def _run_serial(tasks, row_keys, bar):
    """Runs the tasks in this process, in order (client="serial")."""
    results, rows = {}, set(row_keys)
    for key, fn, args in tasks:
        results[key] = fn(*[_resolve(a, results) for a in args])
        if key in rows:
            bar.update(sum(k in results for k in row_keys) / len(row_keys))
    return results


def _run_dask(client, tasks, row_keys, bar):
    from distributed import as_completed
    futures = {}
    for key, fn, args in tasks:
        futures[key] = client.submit(fn, *[_resolve(a, futures) for a in args], key=key, pure=True)
    done = 0
    for _ in as_completed([futures[k] for k in row_keys]):
        done += 1
        bar.update(done / len(row_keys))
    rows = client.gather([futures[k] for k in row_keys])
    return dict(zip(row_keys, rows))


def sweep(base_scene, axes, metrics=None, client=None, seed=1, reference=None, res=None,
          spp=None, threads=1, output=None, n_workers=2, file=None, plots=True, realizations=1,
          progress=None):
    """Renders every point of the product of `axes` and returns a pandas
    DataFrame with one row per point (sorted by "point", the point's index
    in the product): the axis values, each metric's mean over the
    realizations with its standard error beside it ("<metric>_se"; NaN for
    one realization), and "render_s" (mean seconds per render).

    base_scene: dict or path. axes: {pointer or "model": [values, ...]},
      pointers as in glintlab.apply_overrides; the product runs in the
      order given (last axis fastest).
    metrics: names from METRICS and/or {name: fn(image, reference) -> float}
      (a module-level function, so workers can import it); default every
      built-in metric that applies.
    reference: None, or the overrides (same keys as axes) that turn a point
      into its reference render, e.g. {"model": "explicit"}: each distinct
      reference is rendered once, with the seed of its own values.
    seed: base seed; each point renders with point_seed(seed, values).
    client: None (a LocalCluster of `n_workers` worker threads in this
      process, closed afterwards: renders release the GIL, and no process
      is spawned, so a script without `if __name__ == "__main__":` works),
      a distributed.Client (e.g. of a process cluster), a scheduler address
      ("tcp://host:8786") or "serial" (this process, no Dask).
    output: a directory for sweep.csv (+ sweep.parquet when pyarrow or
      fastparquet is importable) and one PNG per metric and axis (error
      bars of one standard error when realizations > 1).
    realizations: R renders per point, realization r with the render seed
      realization_seed(seed, values, r) and every glint material's `seed`
      plus r (another microstructure); a reference is rendered per
      realization too, so each point's error compares like with like.
    progress: None (a bar after a second, see glintlab.set_progress), True,
      False or a callable(fraction), over the points.
    """
    import pandas as pd
    import glintlab

    if not axes:
        raise ValueError("axes: give at least one axis {pointer: [values]}")
    axis_names = list(axes)
    for name in axis_names:
        if name != "model":
            glintlab._pointer_tokens(name)  # raises OverrideError for a malformed pointer
        if not isinstance(axes[name], (list, tuple)) or not axes[name]:
            raise ValueError(f"axes[{name!r}]: expected a non-empty list of values")
    doc, name = glintlab.load_document(base_scene, file)
    doc_text = json.dumps(doc, sort_keys=True)
    custom = {}
    if metrics is None:
        metric_names = [m for m in METRICS if reference is not None or m not in _NEEDS_REFERENCE]
    elif isinstance(metrics, dict):
        custom = dict(metrics)
        metric_names = list(metrics)
    else:
        metric_names = list(metrics)
    for m in metric_names:
        if m not in METRICS and m not in custom:
            raise ValueError(f"metrics: unknown metric {m!r} (built in: {', '.join(METRICS)})")
        if m in _NEEDS_REFERENCE and m not in custom and reference is None:
            raise ValueError(f"metrics: {m} needs a reference (reference={{...}})")
    res = None if res is None else glintlab._resolution(res)
    if isinstance(realizations, bool) or not isinstance(realizations, (int, np.integer)) or \
            not 1 <= realizations <= 1024:
        raise ValueError(f"realizations: expected an integer in [1, 1024], got {realizations!r}")
    realizations = int(realizations)

    points = [dict(zip(axis_names, combo)) for combo in itertools.product(*(axes[a] for a in axis_names))]
    # Validate every point's overrides here, where an error names the point,
    # rather than in a worker.
    for i, values in enumerate(points):
        glintlab.parse_scene(doc, file=name, model=values.get("model"),
                             overrides={k: v for k, v in values.items() if k != "model"})

    # Keys: the sweep's content, then the role and index, so retries and
    # repeated sweeps reuse results and distinct sweeps never collide.
    digest = hashlib.sha256(json.dumps([doc_text, name, res, spp, seed, threads, metric_names,
                                        sorted(custom), realizations],
                                       default=str).encode()).hexdigest()[:16]
    tasks, row_keys, ref_keys = [], [], {}
    for i, values in enumerate(points):
        ref_deps = None
        if reference is not None:
            ref_values = dict(values)
            ref_values.update(reference)
            ref_id = json.dumps(ref_values, sort_keys=True)
            if ref_id not in ref_keys:
                ref_keys[ref_id] = [f"glintlab-ref-{digest}-{len(ref_keys)}-{r}"
                                    for r in range(realizations)]
                for r, key in enumerate(ref_keys[ref_id]):
                    tasks.append((key, _render_task,
                                  (doc_text, name, ref_values,
                                   realization_seed(seed, ref_values, r), res, spp, threads, r)))
            ref_deps = [_Dep(k) for k in ref_keys[ref_id]]
        render_deps = []
        for r in range(realizations):
            render_key = f"glintlab-render-{digest}-{i}-{r}"
            tasks.append((render_key, _render_task,
                          (doc_text, name, values, realization_seed(seed, values, r), res, spp,
                           threads, r)))
            render_deps.append(_Dep(render_key))
        row_key = f"glintlab-row-{digest}-{i}"
        tasks.append((row_key, _row_task, (i, values, render_deps, ref_deps, metric_names,
                                           custom)))
        row_keys.append(row_key)

    with glintlab._Bar(progress, "sweep") as bar:
        if isinstance(client, str) and client == "serial":
            results = _run_serial(tasks, row_keys, bar)
        elif client is None:
            from distributed import Client, LocalCluster
            # Threads, not processes: a process cluster spawns interpreters
            # that re-run the user's script, and one without a main guard
            # then starts a cluster in every worker (it hung for 15 minutes).
            # Renders release the GIL, so the threads render in parallel.
            with LocalCluster(n_workers=n_workers, threads_per_worker=1, processes=False,
                              dashboard_address=None) as cluster, \
                    Client(cluster) as own:
                results = _run_dask(own, tasks, row_keys, bar)
        elif isinstance(client, str):
            from distributed import Client
            with Client(client) as own:
                results = _run_dask(own, tasks, row_keys, bar)
        else:
            results = _run_dask(client, tasks, row_keys, bar)

    table = pd.DataFrame([results[k] for k in row_keys]).sort_values("point").reset_index(drop=True)
    if not table["point"].is_unique or len(table) != len(points):
        raise RuntimeError("sweep: the gathered table does not have each point exactly once")
    if output is not None:
        write_outputs(table, axis_names, metric_names, output, plots=plots)
    return table


def write_outputs(table, axis_names, metric_names, output, plots=True):
    """sweep.csv, sweep.parquet (when an engine is importable) and
    plot_<metric>__<axis>.png per metric and axis in `output`. Returns the
    paths written."""
    os.makedirs(output, exist_ok=True)
    written = [os.path.join(output, "sweep.csv")]
    table.to_csv(written[0], index=False)
    try:
        import pyarrow  # noqa: F401
        engine = "pyarrow"
    except ImportError:
        try:
            import fastparquet  # noqa: F401
            engine = "fastparquet"
        except ImportError:
            engine = None
    if engine:
        written.append(os.path.join(output, "sweep.parquet"))
        table.to_parquet(written[-1], engine=engine, index=False)
    if not plots:
        return written
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    for metric in list(metric_names) + ["render_s"]:
        for axis in axis_names:
            others = [a for a in axis_names if a != axis]
            fig, ax = plt.subplots(figsize=(6, 4))
            if not others:
                groups = [((), table)]
            else:  # a single grouper as a name, not a list (pandas yields scalars for it)
                groups = table.groupby(others if len(others) > 1 else others[0], sort=False)
            for key, group in groups:
                key = key if isinstance(key, tuple) else (key,)
                label = ", ".join(f"{a}={v}" for a, v in zip(others, key)) or None
                xs = group[axis]
                se_col = metric + "_se"
                if all(isinstance(x, (int, float)) for x in xs):
                    g = group.sort_values(axis)
                    x_values = g[axis]
                else:
                    g = group
                    x_values = [str(x) for x in xs]
                se = g[se_col] if se_col in g and g[se_col].notna().any() else None
                ax.errorbar(x_values, g[metric], yerr=se, marker="o", capsize=3, label=label)
            ax.set_xlabel(axis)
            ax.set_ylabel(metric)
            if others:
                ax.legend(fontsize=7)
            ax.grid(True, alpha=0.3)
            fig.tight_layout()
            path = os.path.join(output, f"plot_{_slug(metric)}__{_slug(axis)}.png")
            fig.savefig(path, dpi=100)
            plt.close(fig)
            written.append(path)
    return written


def main(argv=None):
    """python3 -m glintlab.sweep SWEEP.json [--scheduler ADDR] [-o DIR]"""
    import argparse
    import glintlab

    parser = argparse.ArgumentParser(
        prog="python3 -m glintlab.sweep",
        description="Sweep scene parameters on Dask distributed (docs/PYTHON.md)")
    parser.add_argument("sweep", help="SWEEP.json: scene, axes, metrics, reference, res, spp, "
                                      "seed, output")
    parser.add_argument("--scheduler", help="Dask scheduler address (default: a local cluster)")
    parser.add_argument("--workers", type=int, default=2, help="local cluster workers (2)")
    parser.add_argument("-o", "--output", help="output directory (overrides the file's)")
    parser.add_argument("--realizations", type=int,
                        help="renders per point, each another microstructure (overrides the "
                             "file's; default 1)")
    args = parser.parse_args(argv)
    with open(args.sweep, encoding="utf-8") as f:
        spec = json.load(f)
    known = {"comment", "scene", "axes", "metrics", "reference", "res", "spp", "seed", "output",
             "threads", "realizations"}
    unknown = sorted(set(spec) - known)
    if unknown:
        raise SystemExit(f"{args.sweep}: unknown keys {unknown} (known: {sorted(known)})")
    base = os.path.dirname(os.path.abspath(args.sweep))
    scene = spec.get("scene")
    if isinstance(scene, str):
        scene = os.path.join(base, scene)
    elif not isinstance(scene, dict):
        raise SystemExit(f"{args.sweep}: /scene: expected a scene path or an inline scene")
    output = args.output or os.path.join(base, spec.get("output", "sweep_out"))
    try:
        table = sweep(scene, spec.get("axes"), metrics=spec.get("metrics"),
                      client=args.scheduler, seed=spec.get("seed", 1),
                      reference=spec.get("reference"), res=spec.get("res"), spp=spec.get("spp"),
                      threads=spec.get("threads", 1), output=output, n_workers=args.workers,
                      realizations=args.realizations or spec.get("realizations", 1),
                      file=None if isinstance(scene, str) else args.sweep)
    except (glintlab.Error, ValueError) as e:
        raise SystemExit(f"glintlab.sweep: error: {e}")
    print(table.to_string(index=False))
    print(f"wrote {output}")
