"""Figures of phase-space results (issues 12 and 13): Poincaré sections coloured by orbit, chaos
indicators' histories, and maps of sweeps (MEGNO, stability) over one or two swept keys."""

from __future__ import annotations

import numpy as np

from ._common import new_figure
from .results import SWEEP_QUANTITY_COLUMNS, TRAJECTORY_HEAD, Result, UnrecognisedResult

#: The column a sweep map shows unless asked otherwise: the first of these that the file has.
SWEEP_DEFAULT_QUANTITIES = ("megno", "lyapunov_max", "max_real_part", "linearly_stable",
                            "equilibria_count", "drift_energy")
SECTION_SKIP = set(TRAJECTORY_HEAD) | {"orbit", "m1", "m2", "m3"}


def _section_points(res: Result, columns=None):
    """(orbit, x, y, x name, y name) of a section CSV or JSON. The coordinates drawn are the
    first two after the raw state (the surface coordinates), or the two named in columns."""
    if res.kind == "section" and res.columns:
        c = res.columns
        names = columns or [n for n in c if n not in SECTION_SKIP][:2]
        if len(names) < 2:
            names = ["gamma1", "gamma2"]
        missing = [n for n in names if n not in c]
        if missing:
            raise UnrecognisedResult(f"{res.path}: section column {missing[0]}: not in the "
                                     f"header ({','.join(c)})")
        return c["orbit"], c[names[0]], c[names[1]], names[0], names[1]
    cr = res.data["crossings"]
    if not cr:
        raise UnrecognisedResult(f"{res.path}: section with no crossings: nothing to draw")
    names = columns or list(cr[0].get("coords", {}))[:2]
    if len(names) < 2:
        g = np.array([x["gamma"] for x in cr], dtype=float)
        return np.array([x["orbit"] for x in cr]), g[:, 0], g[:, 1], "γ1", "γ2"
    get = lambda n: np.array([x["coords"][n] for x in cr], dtype=float)  # noqa: E731
    return np.array([x["orbit"] for x in cr]), get(names[0]), get(names[1]), names[0], names[1]


def section_figure(res: Result, columns=None):
    """A Poincaré section: one colour per orbit."""
    orbit, x, y, xn, yn = _section_points(res, columns)
    fig = new_figure(6.5, 6)
    ax = fig.add_subplot()
    orbits = np.unique(orbit)
    from matplotlib import colormaps

    cmap = colormaps["tab20"]
    for k, o in enumerate(orbits):
        sel = orbit == o
        ax.scatter(x[sel], y[sel], s=2, color=cmap(k % 20), linewidths=0)
    ax.set_xlabel(xn)
    ax.set_ylabel(yn)
    surface = res.data.get("surface", "") if res.data else ""
    ax.set_title(f"Poincaré section {surface}: {len(x)} crossings, {len(orbits)} orbits".replace(
        "  ", " "))
    return fig


def chaos_history_figure(res: Result):
    """Histories of the chaos indicators (newtop chaos --out), one panel each."""
    c = res.columns
    names = [n for n in c if n != "t" and not isinstance(c[n], list)]
    fig = new_figure(7, 2.2 * len(names) + 0.6)
    axes = fig.subplots(len(names), 1, sharex=True, squeeze=False)[:, 0]
    for ax, n in zip(axes, names):
        ax.plot(c["t"], c[n], linewidth=1.0)
        ax.set_ylabel(n)
        if n.startswith("megno"):
            ax.axhline(2.0, color="0.4", linestyle="--", linewidth=0.8, label="2 (quasi-periodic)")
            ax.legend(fontsize="x-small")
        ax.grid(True, alpha=0.3)
    axes[-1].set_xlabel("t")
    axes[0].set_title("Chaos indicators against time")
    return fig


def chaos_figure(res: Result):
    d = res.data
    names = ["lyapunov_max", "megno", "fli"]
    fig = new_figure(6, 4)
    ax = fig.add_subplot()
    ax.bar(names, [d[n] for n in names], color="#4575b4")
    ax.axhline(2.0, color="0.4", linestyle="--", linewidth=0.8, label="MEGNO 2 (quasi-periodic)")
    ax.set_xlabel("indicator")
    ax.set_ylabel("value at t_end")
    ax.set_title(f"Chaos indicators at t = {d.get('t_end')}: {d.get('outcome', '')}")
    ax.legend(fontsize="small")
    return fig


def sweep_axes(res: Result):
    """The swept keys: the columns before the first quantity column (issue 13's CSV layout)."""
    names = list(res.columns)
    axes = []
    for n in names:
        if n in SWEEP_QUANTITY_COLUMNS or n.startswith("drift_"):
            break
        axes.append(n)
    return axes


def sweep_figure(res: Result, quantity=None):
    """A sweep over one key (a curve) or two (a map); points whose status is not ok are grey."""
    axes = sweep_axes(res)
    c = res.columns
    if quantity is None:
        quantity = next((q for q in SWEEP_DEFAULT_QUANTITIES if q in c), None)
        quantity = quantity or next((n for n in c if n not in axes and n != "status"
                                     and not isinstance(c[n], list)), None)
    if quantity not in c or isinstance(c[quantity], list):
        raise UnrecognisedResult(f"{res.path}: --quantity: expected a numeric column of the sweep "
                                 f"({','.join(n for n in c if n not in axes)}), found "
                                 f"'{quantity}'")
    if len(axes) not in (1, 2):
        raise UnrecognisedResult(f"{res.path}: sweep: expected 1 or 2 swept keys to draw, found "
                                 f"{len(axes)} ({','.join(axes)})")
    ok = np.array([s == "ok" for s in c["status"]])
    v = np.where(ok, c[quantity], np.nan)
    fig = new_figure(7, 5.5 if len(axes) == 2 else 4.5)
    ax = fig.add_subplot()
    if len(axes) == 1:
        x = c[axes[0]]
        ax.plot(x, v, "o-", markersize=3)
        ax.plot(x[~ok], np.zeros((~ok).sum()), "x", color="0.5", label="failed point")
        ax.set_xlabel(axes[0])
        ax.set_ylabel(quantity)
    else:
        x, y = c[axes[0]], c[axes[1]]
        xs, ys = np.unique(x), np.unique(y)
        grid = np.full((len(ys), len(xs)), np.nan)
        grid[np.searchsorted(ys, y), np.searchsorted(xs, x)] = v
        mesh = ax.pcolormesh(xs, ys, np.ma.masked_invalid(grid), shading="nearest",
                             cmap="magma" if quantity.startswith("megno") else "viridis")
        ax.set_facecolor("0.75")  # failed points show the background
        fig.colorbar(mesh, ax=ax, label=quantity)
        ax.set_xlabel(axes[0])
        ax.set_ylabel(axes[1])
    failed = int((~ok).sum())
    ax.set_title(f"Sweep: {quantity} over {' × '.join(axes)}" +
                 (f" ({failed} failed points in grey)" if failed else ""))
    return fig
