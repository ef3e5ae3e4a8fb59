"""Pictures of newtop's results (matplotlib).

Command line::

    python3 -m newtop.plot RESULT -o FIG.png|svg|pdf [--equilibria EQ.json]
                           [--panel all|drift|gamma|omega] [--quantity NAME]
                           [--scenario SCENARIO.toml]

RESULT is any CSV, JSON or HDF5 (``sweep --out FILE.h5``) that ``newtop`` writes; its kind is recognised from its contents
(``newtop.results``). A file that is not one gives one line on stderr and exit status 2.

From Python every function returns a ``matplotlib.figure.Figure`` (no pyplot state)::

    from newtop import plot, results
    fig = plot.figure(results.load("run.csv"), equilibria=results.load("eq.json"))
    fig.savefig("run.png")
"""

from __future__ import annotations

import argparse
import os
import sys

import numpy as np
from matplotlib.figure import Figure

from . import _sphere, results
from ._common import EPS, new_figure  # noqa: F401 (EPS is part of the interface)
from .results import Result, UnrecognisedResult

#: Points drawn along a path at most (a stride keeps the first and last rows).
MAX_PATH_POINTS = 20000
#: Time bins of the drift plot at most; each bin shows its largest drift, so no spike is hidden.
MAX_DRIFT_BINS = 4000
FORMATS = (".png", ".svg", ".pdf")


# --- trajectories (simulate --out) -------------------------------------------------------------

def _stride(n, limit=MAX_PATH_POINTS):
    idx = np.arange(0, n, max(1, -(-n // limit)))
    return idx if idx[-1] == n - 1 else np.append(idx, n - 1)


def relative_drift(values):
    """|I(t) − I(0)| / |I(0)| (absolute when I(0) = 0), and whether it is relative."""
    v = np.asarray(values, dtype=float)
    d = np.abs(v - v[0])
    return (d / abs(v[0]), True) if v[0] != 0.0 else (d, False)


def _binned_max(t, d, bins=MAX_DRIFT_BINS):
    if len(t) <= bins:
        return t, d
    edges = np.linspace(0, len(t), bins + 1).astype(int)
    tb = np.array([t[b - 1] for b in edges[1:]])
    db = np.array([np.nanmax(d[a:b]) for a, b in zip(edges[:-1], edges[1:])])
    return tb, db


def draw_drift(ax, traj: Result):
    t = traj.columns["t"]
    for name in results.integral_columns(traj):
        d, relative = relative_drift(traj.columns[name])
        tb, db = _binned_max(t, d)
        label = name if relative else f"{name} (absolute: I(0) = 0)"
        ax.plot(tb, np.maximum(db, EPS / 2), label=label, linewidth=1.0)
    ax.axhline(EPS, color="0.5", linestyle=":", linewidth=0.8, label="machine ε")
    ax.set_yscale("log")
    ax.set_xlabel("t")
    ax.set_ylabel("|I(t) − I(0)| / |I(0)|")
    ax.set_title("Drift of the first integrals")
    ax.legend(fontsize="small", loc="best")
    ax.grid(True, which="major", alpha=0.3)


def _coloured_path_3d(fig, ax, xyz, t, label):
    from mpl_toolkits.mplot3d.art3d import Line3DCollection

    pts = xyz.reshape(-1, 1, 3)
    seg = np.concatenate([pts[:-1], pts[1:]], axis=1)
    lc = Line3DCollection(seg, cmap="viridis", linewidth=1.2)
    lc.set_array(0.5 * (t[:-1] + t[1:]))
    ax.add_collection(lc)
    ax.scatter(*xyz[0], color="k", s=25, label=f"{label} at t0", depthshade=False)
    ax.scatter(*xyz[-1], color="#e7298a", s=25, label=f"{label} at t_end", depthshade=False)
    fig.colorbar(lc, ax=ax, shrink=0.6, pad=0.08, label="t")


def draw_gamma_path(fig, ax, traj: Result, equilibria: Result | None = None):
    i = _stride(len(traj.columns["t"]))
    g = np.column_stack([traj.columns[c][i] for c in ("gamma1", "gamma2", "gamma3")])
    _sphere.draw_sphere(ax)
    _coloured_path_3d(fig, ax, g, traj.columns["t"][i], "γ")
    if equilibria is not None:
        _sphere.mark_equilibria(ax, equilibria.data, three_d=True)
    ax.set_xlabel("γ1")
    ax.set_ylabel("γ2")
    ax.set_zlabel("γ3")
    ax.set_title("Path of γ on the Poisson sphere")
    ax.legend(fontsize="x-small", loc="upper left")


def draw_omega_path(fig, ax, traj: Result):
    i = _stride(len(traj.columns["t"]))
    w = np.column_stack([traj.columns[c][i] for c in ("p", "q", "r")])
    _coloured_path_3d(fig, ax, w, traj.columns["t"][i], "ω")
    lo, hi = np.nanmin(w, axis=0), np.nanmax(w, axis=0)
    half = 0.55 * max(np.max(hi - lo), 1e-12)
    mid = 0.5 * (lo + hi)
    ax.set_xlim(mid[0] - half, mid[0] + half)
    ax.set_ylim(mid[1] - half, mid[1] + half)
    ax.set_zlim(mid[2] - half, mid[2] + half)
    ax.set_xlabel("p")
    ax.set_ylabel("q")
    ax.set_zlabel("r")
    ax.set_title("Path of ω in the body frame")
    ax.legend(fontsize="x-small", loc="upper left")


def trajectory_figure(traj: Result, equilibria: Result | None = None, panel="all") -> Figure:
    """Drift of the integrals, path of γ on the Poisson sphere (equilibria marked when given) and
    path of ω, from a ``simulate --out`` CSV; panel selects one of them."""
    if equilibria is not None and equilibria.kind != "equilibria":
        raise UnrecognisedResult(f"{equilibria.path}: --equilibria: expected the JSON of newtop "
                                 f"equilibria --json, found a {equilibria.kind} result")
    if panel == "drift":
        fig = new_figure(7, 4.5)
        draw_drift(fig.add_subplot(), traj)
        return fig
    if panel in ("gamma", "omega"):
        fig = new_figure(6, 5.5)
        ax = fig.add_subplot(projection="3d")
        if panel == "gamma":
            draw_gamma_path(fig, ax, traj, equilibria)
        else:
            draw_omega_path(fig, ax, traj)
        return fig
    fig = new_figure(17, 5.2)
    draw_drift(fig.add_subplot(1, 3, 1), traj)
    draw_gamma_path(fig, fig.add_subplot(1, 3, 2, projection="3d"), traj, equilibria)
    draw_omega_path(fig, fig.add_subplot(1, 3, 3, projection="3d"), traj)
    fig.suptitle(f"newtop simulate: {os.path.basename(traj.path)}")
    return fig


def simulate_figure(sim: Result, equilibria=None, panel="all") -> Figure:
    """A simulate JSON: its trajectory CSV when the file named in "csv" exists, otherwise the
    largest drift of each integral as bars."""
    csv_path = results.companion_csv(sim)
    if csv_path:
        traj = results.load(csv_path)
        if traj.kind == "orbit_trajectory":
            from ._plot_orbit import orbit_trajectory_figure

            return orbit_trajectory_figure(traj)
        return trajectory_figure(traj, equilibria, panel)
    drift = sim.data["integrals"]["max_abs_drift"]
    names = list(drift)
    fig = new_figure(6, 4)
    ax = fig.add_subplot()
    ax.bar(names, [max(abs(drift[n]), EPS / 2) for n in names], color="#4575b4")
    ax.set_yscale("log")
    ax.set_xlabel("integral")
    ax.set_ylabel("max |I(t) − I(0)|")
    ax.set_title(f"Largest drift: {sim.data['method']}, {sim.data['outcome']}")
    return fig


# --- dispatch and command line -----------------------------------------------------------------

def _continuation_figure(res: Result) -> Figure:
    from ._plot_continuation import continuation_figure

    return continuation_figure(res)


def figure(res: Result, equilibria: Result | None = None, panel="all", quantity=None,
           scenario=None) -> Figure:
    """The figure for any newtop result (the kind decides). scenario: the scenario file the result
    was computed from, whose fixed parameters the titles of sections and stability maps give."""
    from . import _plot_analysis as an
    from . import _plot_orbit as orb
    from . import _plot_phase as ph

    makers = {
        "trajectory": lambda: trajectory_figure(res, equilibria, panel),
        "simulate": lambda: simulate_figure(res, equilibria, panel),
        "equilibria": lambda: an.equilibria_figure(res),
        "integrals": lambda: an.integrals_figure(res),
        "cone": lambda: an.staude_cone_figure(res),
        "rotations": lambda: an.rotations_figure(res),
        "omega_scan": lambda: an.omega_scan_figure(res),
        "stability": lambda: an.stability_figure(res),
        "stability_map": lambda: an.stability_map_figure(res, scenario),
        "analytic": lambda: an.analytic_figure(res),
        "find_integrals": lambda: an.find_integrals_figure(res),
        "field": lambda: an.field_figure(res),
        "section": lambda: ph.section_figure(res, scenario=scenario),
        "sweep": lambda: ph.sweep_figure(res, quantity),
        "chaos_history": lambda: ph.chaos_history_figure(res),
        "chaos": lambda: ph.chaos_figure(res),
        "continuation": lambda: _continuation_figure(res),
        "orbit_trajectory": lambda: orb.orbit_trajectory_figure(res),
        "debra_delp": lambda: orb.debra_delp_figure(res),
        "libration": lambda: orb.libration_figure(res),
        "orbit_equilibria": lambda: orb.orbit_equilibria_figure(res),
        "continuation_family": lambda: orb.continuation_family_figure(res),
        "continuation_curves": lambda: orb.continuation_curves_figure(res),
    }
    return makers[res.kind]()


def save(fig: Figure, path):
    """Writes PNG, SVG or PDF (by extension) without a time stamp, so reruns give the same file."""
    ext = os.path.splitext(os.fspath(path))[1].lower()
    if ext not in FORMATS:
        raise UnrecognisedResult(f"-o {path}: expected a file name ending in .png, .svg or .pdf, "
                                 f"found '{ext or 'no extension'}'")
    meta = {".png": {"Software": None}, ".svg": {"Date": None},
            ".pdf": {"CreationDate": None, "ModDate": None}}[ext]
    fig.savefig(path, dpi=110, metadata=meta)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python3 -m newtop.plot",
                                description="Draw a figure from any CSV or JSON that newtop writes.")
    p.add_argument("result", help="a newtop CSV or JSON (the kind is recognised from its contents)")
    p.add_argument("-o", "--output", required=True, help="figure file: .png, .svg or .pdf")
    p.add_argument("--equilibria", help="newtop equilibria --json output, marked on the sphere")
    p.add_argument("--panel", choices=("all", "drift", "gamma", "omega"), default="all",
                   help="for a trajectory: all panels (default) or one of them")
    p.add_argument("--quantity", help="for a sweep: the column to map (default: the first of "
                                      "megno, lyapunov_max, max_real_part, ...)")
    p.add_argument("--scenario", help="the scenario file of a section or a stability map: its "
                                      "fixed parameters go into the title")
    a = p.parse_args(argv)
    try:
        if os.path.splitext(a.output)[1].lower() not in FORMATS:
            raise UnrecognisedResult(f"-o {a.output}: expected a file name ending in .png, .svg "
                                     "or .pdf")
        res = results.load(a.result)
        eq = results.load(a.equilibria) if a.equilibria else None
        if a.scenario and not os.path.isfile(a.scenario):
            raise UnrecognisedResult(f"--scenario {a.scenario}: expected a scenario file, found "
                                     "no such file")
        fig = figure(res, eq, a.panel, a.quantity, a.scenario)
        tmp = a.output + ".tmp" + os.path.splitext(a.output)[1]
        try:
            save(fig, tmp)
            os.replace(tmp, a.output)  # the figure appears whole or not at all
        finally:
            if os.path.exists(tmp):
                os.remove(tmp)
    except (UnrecognisedResult, KeyError, IndexError, TypeError, ValueError) as e:
        if isinstance(e, UnrecognisedResult):
            msg = str(e)
        else:
            msg = f"{a.result}: malformed newtop result: missing or wrong field {e}"
        print(f"newtop.plot: error: {msg}", file=sys.stderr)
        return 2
    print(f"{a.output}: {res.kind} figure")
    return 0


# The figures of the other kinds, importable from here (they need the helpers above).
from ._plot_analysis import (analytic_figure, equilibria_figure, field_figure,  # noqa: E402
                             find_integrals_figure, integrals_figure, omega_scan_figure,
                             rotations_figure, stability_figure, stability_map_figure,
                             staude_cone_figure)
from ._plot_orbit import (continuation_curves_figure, continuation_family_figure,  # noqa: E402
                          debra_delp_figure, libration_figure, orbit_trajectory_figure)
from ._plot_phase import (chaos_figure, chaos_history_figure, section_figure,  # noqa: E402
                          sweep_figure)

if __name__ == "__main__":
    sys.exit(main())
