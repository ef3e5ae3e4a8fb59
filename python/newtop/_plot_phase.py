"""Figures of phase-space results (issues 12 and 13): Poincaré sections coloured by orbit, chaos
indicators' histories, and maps of sweeps (MEGNO, stability) over one or two swept keys."""

from __future__ import annotations

import numpy as np

from ._common import distinct_colours, new_figure, scenario_parameters
from .results import SWEEP_QUANTITY_COLUMNS, TRAJECTORY_HEAD, Result, UnrecognisedResult

#: The column a sweep map shows unless asked otherwise: the first of these that the file has.
SWEEP_DEFAULT_QUANTITIES = ("megno", "lyapunov_max", "max_real_part", "linearly_stable",
                            "equilibria_count", "drift_energy")
SECTION_SKIP = set(TRAJECTORY_HEAD) | {"orbit", "m1", "m2", "m3"}
#: An orbit scenario's section (docs/orbit.md §10): the orbital-frame angle ψ (Beletsky's θ for the
#: planar pitch motion) against the relative rate about the normal's body axis.
ORBIT_SECTION_COLUMNS = ["psi", "omega_rel3"]
#: Axis labels of the section coordinates that cannot be misread (a bare `l` looks like `I` or 1).
SECTION_LABELS = {"psi": "ψ, 3-2-1 angle about the orbit normal (rad)",
                  "omega_rel3": "ω_rel,3 (rate relative to the orbital frame)",
                  "l": "ℓ = atan2(m1, m2), Andoyer angle (rad)", "L_over_G": "L/G = m3/|m|",
                  "g": "g, Andoyer angle about m (rad)", "G": "G = |m|"}
#: MEGNO maps: the colour scale is clipped to [0, MEGNO_CLIP] (⟨Y⟩ → 2 on regular orbits, grows
#: like λ t/2 on chaotic ones: the structure is between 0 and a few units; larger values saturate).
MEGNO_CLIP = (0.0, 8.0)
#: The value of ⟨Y⟩ on regular (quasi-periodic) orbits, marked on MEGNO plots.
MEGNO_REGULAR = 2.0


def _axis_label(name):
    if name in SECTION_LABELS:
        return SECTION_LABELS[name]
    if name.startswith("p_gamma"):
        return f"p_γ{name[7:]} (momentum of γ{name[7:]})"
    if name.startswith("gamma"):
        return f"γ{name[5:]}"
    return name


def _section_points(res: Result, columns=None):
    """(orbit, x, y, x name, y name) of a section CSV or JSON. The coordinates drawn are the
    first two after the raw state (the surface coordinates), or the two named in columns."""
    if res.kind == "section" and res.columns:
        c = res.columns
        orbit_section = all(n in c for n in ORBIT_SECTION_COLUMNS)
        names = columns or (ORBIT_SECTION_COLUMNS if orbit_section else
                            [n for n in c if n not in SECTION_SKIP][:2])
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


def section_levels(res: Result):
    """"h = …, f = …" from the JSON's levels (seeded portraits), or "" where the result has none."""
    lv = (res.data or {}).get("levels") if res.data else None
    if not lv or lv.get("empty"):
        return ""
    return f"h = {lv['energy']:.6g}, f = {lv['area']:.6g}"


def section_figure(res: Result, columns=None, scenario=None):
    """A Poincaré section: one colour per orbit, all distinct; the title gives the surface, the
    levels (h, f) and, with the scenario, the fixed parameters."""
    orbit, x, y, xn, yn = _section_points(res, columns)
    fig = new_figure(7, 6.5)
    ax = fig.add_subplot()
    orbits = np.unique(orbit)
    for colour, o in zip(distinct_colours(len(orbits)), orbits):
        sel = orbit == o
        ax.scatter(x[sel], y[sel], s=2, color=colour, linewidths=0)
    ax.set_xlabel(_axis_label(xn))
    ax.set_ylabel(_axis_label(yn))
    surface = res.data.get("surface", "") if res.data else ""
    lines = [f"Poincaré section {surface}: {len(x)} crossings, {len(orbits)} orbits".replace(
        "  ", " ")]
    levels = section_levels(res)
    lines.append(levels or "levels h, f: not in this file (seeded runs write them to the JSON)")
    params = scenario_parameters(scenario)
    if params:
        lines.append(params)
    ax.set_title("\n".join(lines), fontsize="medium")
    return fig


#: Titles of the panels of a chaos history.
PANEL_TITLES = {"lyapunov_max": "Largest Lyapunov exponent", "megno_y": "MEGNO Y(t) (instantaneous)",
                "megno": "MEGNO ⟨Y⟩ (mean)", "fli": "Fast Lyapunov indicator"}


def chaos_history_figure(res: Result):
    """Histories of the chaos indicators (newtop chaos --out) against log t: the Lyapunov
    spectrum (lambda1..lambda6, with --spectrum) and λ_max on one panel, MEGNO (the regular value 2
    marked) and the FLI each on their own."""
    c = res.columns
    t = np.asarray(c["t"], dtype=float)
    keep = t > 0  # log t: the start (t0 = 0) has no place on the axis
    spectrum = [n for n in c if n.startswith("lambda") and n[6:].isdigit()]
    lyap = spectrum + [n for n in ("lyapunov_max",) if n in c]
    others = [n for n in c if n != "t" and n not in lyap and not isinstance(c[n], list)]
    panels = ([lyap] if lyap else []) + [[n] for n in others]
    fig = new_figure(7.5, 2.6 * len(panels) + 0.6)
    axes = fig.subplots(len(panels), 1, sharex=True, squeeze=False)[:, 0]
    for ax, names in zip(axes, panels):
        for k, n in enumerate(names):
            style = ":" if n == "lyapunov_max" and spectrum else "-"
            ax.plot(t[keep], np.asarray(c[n], dtype=float)[keep], style, linewidth=1.0,
                    label=n, color="k" if style == ":" else f"C{k}")
        ax.set_xscale("log")
        if names is lyap:
            ax.axhline(0.0, color="0.5", linewidth=0.6)
            ax.set_ylabel("Lyapunov exponents" if spectrum else "lyapunov_max")
            if len(names) > 1:
                ax.legend(fontsize="x-small", ncol=4)
        else:
            ax.set_ylabel(names[0])
        if names[0].startswith("megno"):
            ax.axhline(MEGNO_REGULAR, color="0.4", linestyle="--", linewidth=0.8,
                       label="2 (regular, quasi-periodic)")
            ax.legend(fontsize="x-small")
        ax.grid(True, which="both", alpha=0.3)
        ax.set_xlabel("t (log scale)")
        ax.set_title(PANEL_TITLES.get(names[0], names[0]), fontsize="medium")
    if spectrum:
        axes[0].set_title("The Lyapunov spectrum's history (λ_max dotted)", fontsize="medium")
    fig.suptitle("Chaos indicators against time")
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
    """The swept keys: the columns before the first quantity column (issue 13's CSV layout). The
    program names a key `section.key` (docs/sweep.md): where the first column has a dot, the first
    column without one is a quantity, whatever its name (new quantities need no list here)."""
    names = list(res.columns)
    dotted = bool(names) and "." in names[0]
    axes = []
    for n in names:
        if n in SWEEP_QUANTITY_COLUMNS or n.startswith("drift_") or (dotted and "." not in n):
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
        if quantity.startswith("megno"):
            ax.axhline(MEGNO_REGULAR, color="#4dac26", linestyle="--", linewidth=1.0,
                       label="2 (regular)")
            ax.legend(fontsize="small")
    else:
        x, y = c[axes[0]], c[axes[1]]
        xs, ys = np.unique(x), np.unique(y)
        grid = np.full((len(ys), len(xs)), np.nan)
        grid[np.searchsorted(ys, y), np.searchsorted(xs, x)] = v
        megno = quantity.startswith("megno")
        clip = dict(vmin=MEGNO_CLIP[0], vmax=MEGNO_CLIP[1]) if megno else {}
        mesh = ax.pcolormesh(xs, ys, np.ma.masked_invalid(grid), shading="nearest",
                             cmap="magma" if megno else "viridis", **clip)
        ax.set_facecolor("0.75")  # failed points show the background
        if megno:
            bar = fig.colorbar(mesh, ax=ax, extend="max",
                               label=f"{quantity} (clipped to {MEGNO_CLIP[0]:g}–"
                                     f"{MEGNO_CLIP[1]:g}; 2 = regular)")
            bar.ax.axhline(MEGNO_REGULAR, color="#4dac26", linewidth=2.0)
            bar.set_ticks(sorted(set([0.0, MEGNO_REGULAR, 4.0, 6.0, 8.0])))
        else:
            fig.colorbar(mesh, ax=ax, label=quantity)
        ax.set_xlabel(axes[0])
        ax.set_ylabel(axes[1])
    failed = int((~ok).sum())
    ax.set_title(f"Sweep: {quantity} over {' × '.join(axes)}" +
                 (f" ({failed} failed points in grey)" if failed else ""))
    return fig
