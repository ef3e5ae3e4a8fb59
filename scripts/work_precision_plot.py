#!/usr/bin/python3
"""Plots the data of bench/work_precision (error against CPU time, a panel per regime and metric).

    build/bench/work_precision abc 5 wp.csv
    /usr/bin/python3 scripts/work_precision_plot.py wp.csv --out docs/img/work_precision.png

Each point is one run of the harness's search (its setting, its error, its CPU time, timed once);
the points of a method are joined in the order of its step or tolerance. The tables of
docs/performance.md give the interleaved median timings of the best setting per target."""

from __future__ import annotations

import argparse
import csv
import math
import os
import sys
from collections import defaultdict

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

REGIMES = {
    "a": "(a) generic, T = 40",
    "b3": "(b) fast spin, λ/Ω² = 1e-3, T = 1e4",
    "b5": "(b) fast spin, λ/Ω² = 1e-5, T = 1e4",
    "c": "(c) slow libration, T = 1e4",
}
METRICS = {"state": "final state error |Δm| + |Δγ|", "energy": "max relative energy error"}


def read(path):
    """{(regime, metric): {method: [(setting, error, cpu_s)]}} with finite errors only."""
    data = defaultdict(lambda: defaultdict(list))
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            err, cpu = float(row["error"]), float(row["cpu_s"])
            if math.isfinite(err) and err > 0 and cpu > 0:
                data[(row["regime"], row["metric"])][row["method"]].append(
                    (float(row["setting"]), err, cpu))
    return data


def style(method):
    """Peers black/grey and thick, taylor red and dop853 blue; newtop's splittings coloured by
    table, the split by dash."""
    if method.startswith("odeint rkf78"):
        return dict(color="black", lw=2.2, ls="-", marker="s")
    if method.startswith("odeint dopri5"):
        return dict(color="0.5", lw=2.2, ls="-", marker="s")
    if method.startswith("newtop rkf78"):
        return dict(color="black", lw=1.0, ls=":", marker="x")
    if method == "newtop taylor":
        return dict(color="tab:red", lw=2.2, ls="-", marker="o")
    if method == "newtop dop853":
        return dict(color="tab:blue", lw=1.8, ls="-", marker="d")
    ls = "--" if "(spin)" in method else (":" if "exact" in method else "-")
    return dict(ls=ls, lw=1.0, marker=".")


def plot(data, out):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    regimes = [r for r in REGIMES if any((r, m) in data for m in METRICS)]
    metrics = [m for m in METRICS if any((r, m) in data for r in regimes)]
    if not regimes:
        raise SystemExit("no data")
    fig, axes = plt.subplots(len(metrics), len(regimes), squeeze=False,
                             figsize=(4.2 * len(regimes), 4.0 * len(metrics) + 1.6))
    methods = sorted({m for d in data.values() for m in d})
    cmap = plt.get_cmap("tab20")
    colour = {m: cmap(i % 20) for i, m in enumerate(x for x in methods if "odeint" not in x)}
    handles = {}
    for i, metric in enumerate(metrics):
        for j, regime in enumerate(regimes):
            ax = axes[i][j]
            for method, pts in sorted(data.get((regime, metric), {}).items()):
                pts.sort()
                s = style(method)
                s.setdefault("color", colour.get(method))
                (line,) = ax.plot([p[2] for p in pts], [p[1] for p in pts], ms=4, label=method, **s)
                handles[method] = line
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_title(REGIMES[regime], fontsize=9)
            ax.set_xlabel("CPU s per run")
            ax.set_ylabel(METRICS[metric])
            for target in (1e-6, 1e-9, 1e-12):
                ax.axhline(target, color="0.8", lw=0.6, zorder=0)
            ax.grid(True, which="major", lw=0.3)
    fig.legend([handles[m] for m in methods if m in handles],
               [m for m in methods if m in handles], loc="lower center", ncol=4, fontsize=7)
    fig.tight_layout(rect=(0, 1.6 / (4.0 * len(metrics) + 1.6), 1, 1))
    fig.savefig(out, dpi=90, metadata={"Software": "scripts/work_precision_plot.py"})
    return fig


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("csv", help="the data file written by bench/work_precision")
    p.add_argument("--out", default=os.path.join(ROOT, "docs", "img", "work_precision.png"))
    a = p.parse_args(argv)
    plot(read(a.csv), a.out)
    print(a.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
