"""Figures of the satellite on an orbit (docs/orbit.md) and of continued families' CSVs: an orbit
run (the attitude relative to LVLH against time, the integral's drift, ω), the DeBra–Delp diagram,
the periapsis section of ``newtop libration``, and the CSVs of ``newtop continue``."""

from __future__ import annotations

import numpy as np

from ._common import EPS, distinct_colours, new_figure
from .results import Result

#: The attitude columns of an orbit CSV, in the order they are looked for, with their labels:
#: roll/pitch/yaw (--euler 321), the 3-1-3 angles (--euler 313), q0..q3 (--attitude).
ATTITUDE_SETS = (
    (("roll", "pitch", "yaw"), "roll, pitch, yaw (rad), C(body←LVLH) = R1 R2 R3"),
    (("euler313_phi", "euler313_theta", "euler313_psi"), "3-1-3 angles φ, θ, ψ (rad)"),
    (("q0", "q1", "q2", "q3"), "q0..q3 of C(body←LVLH)"),
)
STABLE = ("stable", "lyapunov", "gyroscopic")
REGION_COLOURS = {"lagrange": "#4dac26", "debra_delp": "#2c7bb6", "unstable": "#d7191c"}


def _draw_attitude(ax, c):
    t = c["t"]
    for names, label in ATTITUDE_SETS:
        if all(n in c for n in names):
            for n in names:
                ax.plot(t, c[n], label=n, linewidth=1.0)
            ax.set_ylabel(label)
            ax.set_title("Attitude relative to LVLH")
            break
    else:  # no attitude columns: the orbital axes themselves, in body components
        for n in ("gamma1", "gamma2", "gamma3", "normal1", "normal2", "normal3"):
            ax.plot(t, c[n], label=n.replace("gamma", "γ").replace("normal", "n"), linewidth=1.0)
        ax.set_ylabel("components in body axes")
        ax.set_title("Radius γ and orbit normal n in body axes (run with --euler 321 for angles)")
    ax.set_xlabel("t")
    ax.legend(fontsize="small", loc="best")
    ax.grid(True, alpha=0.3)


def _draw_orbit_drift(ax, c):
    t = c["t"]
    name = "jacobi" if "jacobi" in c else "hamiltonian_nu"
    if name == "jacobi":
        v = c["jacobi"]
        d = np.abs(v - v[0]) / (abs(v[0]) if v[0] != 0 else 1.0)
        ax.plot(t, np.maximum(d, EPS / 2), label="Jacobi integral (relative)", linewidth=1.0)
    ax.plot(t, np.maximum(c["casimir_error"], EPS / 2), label="Casimir error", linewidth=1.0)
    ax.axhline(EPS, color="0.5", linestyle=":", linewidth=0.8, label="machine ε")
    ax.set_yscale("log")
    ax.set_xlabel("t")
    ax.set_ylabel("drift")
    ax.set_title("Drift of the conserved quantities" +
                 ("" if name == "jacobi" else " (H_ν is not conserved on an ellipse)"))
    ax.legend(fontsize="small", loc="best")


def orbit_trajectory_figure(res: Result):
    """``simulate --out`` on an orbit scenario: the attitude relative to LVLH against time (the
    angles or quaternion the run wrote; else γ and n in body axes), the drift of the Jacobi
    integral and the Casimirs, and ω in body axes."""
    c = res.columns
    fig = new_figure(16, 4.8)
    axes = fig.subplots(1, 3)
    _draw_attitude(axes[0], c)
    _draw_orbit_drift(axes[1], c)
    for i in (1, 2, 3):
        axes[2].plot(c["t"], c[f"omega{i}"], label=f"ω{i}", linewidth=1.0)
    axes[2].set_xlabel("t")
    axes[2].set_ylabel("ω (inertial, body axes)")
    axes[2].set_title("Angular velocity")
    axes[2].legend(fontsize="small", loc="best")
    kind = "elliptic" if "nu" in c else "circular"
    fig.suptitle(f"newtop simulate ({kind} orbit): {len(c['t'])} rows")
    return fig


def _debra_delp_columns(res: Result):
    """The points of the CSV, or of the JSON's `points` as columns."""
    if res.columns:
        return res.columns
    pts = res.data["points"]
    c = {n: np.array([p[n] for p in pts], dtype=float) for n in ("k_R", "k_Y", "max_real_part")}
    c["region"] = [p["region"] for p in pts]
    c["boundary"] = np.array([float(p["boundary"]) for p in pts])
    return c


def debra_delp_figure(res: Result):
    """The DeBra–Delp diagram (CSV or JSON): each point coloured by the region of the model's
    linearisation, boundary points hollow, the closed-form boundaries (k_R = k_Y, k_R k_Y = 0 and
    1 + 3k_R + k_R k_Y = 4√(k_R k_Y)) drawn."""
    c = _debra_delp_columns(res)
    fig = new_figure(6.5, 6)
    ax = fig.add_subplot()
    region = np.array(c["region"])
    boundary = np.asarray(c["boundary"], dtype=float) > 0
    for name, colour in REGION_COLOURS.items():
        sel = (region == name) & ~boundary
        ax.scatter(c["k_R"][sel], c["k_Y"][sel], s=14, color=colour, label=name, linewidths=0)
    ax.scatter(c["k_R"][boundary], c["k_Y"][boundary], s=14, facecolors="none",
               edgecolors="0.3", label="boundary", linewidths=0.6)
    k = np.linspace(-1, 1, 801)
    ax.plot(k, k, color="k", linewidth=0.8)
    ax.axhline(0, color="k", linewidth=0.8)
    ax.axvline(0, color="k", linewidth=0.8)
    kr, ky = np.meshgrid(k, k)
    with np.errstate(invalid="ignore"):
        f = 1 + 3 * kr + kr * ky - 4 * np.sqrt(kr * ky)
    ax.contour(kr, ky, np.where(kr * ky > 0, f, np.nan), levels=[0], colors="k",
               linewidths=0.8)
    ax.set_xlim(-1, 1)
    ax.set_ylim(-1, 1)
    ax.set_xlabel("k_R = (B − C)/A")
    ax.set_ylabel("k_Y = (B − A)/C")
    ax.set_title(f"DeBra–Delp diagram: {len(region)} points")
    ax.legend(fontsize="small", loc="lower right")
    return fig


def libration_starts_figure(res: Result):
    """``newtop libration --json``: each start's finite-time Lyapunov exponent against its spin at
    periapsis, the chaos threshold drawn, and the periodic solutions' spins marked."""
    d = res.data
    fig = new_figure(7, 5)
    ax = fig.add_subplot()
    starts = d["starts"]
    spin = np.array([s["spin0"] for s in starts], dtype=float)
    lyap = np.array([s["lyapunov"] for s in starts], dtype=float)
    chaotic = np.array([bool(s["chaotic"]) for s in starts])
    ax.scatter(spin[~chaotic], lyap[~chaotic], color="C0", label="regular start")
    ax.scatter(spin[chaotic], lyap[chaotic], color="C3", label="chaotic start")
    ax.axhline(d["chaos_threshold"], color="0.4", linestyle="--", linewidth=0.8,
               label="chaos threshold")
    for r in d["resonances"]:
        for sol in r["solutions"]:
            ax.axvline(sol["spin0"], color="C2" if sol["stability"] == "stable" else "0.7",
                       linewidth=0.6)
    ax.set_xlabel("spin θ̇/n at periapsis")
    ax.set_ylabel("Lyapunov exponent per orbit")
    ax.set_title(f"Libration: e = {d['eccentricity']:g}, k = {d['k']:.4g}; resonances' spins "
                 "as lines (green: stable)")
    ax.legend(fontsize="small", loc="best")
    return fig


def orbit_equilibria_figure(res: Result):
    """``newtop equilibria --json`` on an orbit: the Jacobi integral of each relative equilibrium
    (numbered as listed), coloured by its verdict, with its roll, pitch and yaw beside."""
    eq = res.data["equilibria"]
    number = np.array([e["number"] for e in eq])
    fig = new_figure(12, 4.8)
    a, b = fig.subplots(1, 2)
    colours = {"lyapunov": "#4dac26", "gyroscopic": "#2c7bb6", "unstable": "#d7191c"}
    for verdict, colour in colours.items():
        sel = np.array([e["verdict"] == verdict for e in eq])
        a.scatter(number[sel], [e["jacobi"] for e, s in zip(eq, sel) if s], color=colour,
                  label=verdict)
    a.set_xlabel("equilibrium (number)")
    a.set_ylabel("Jacobi integral")
    a.set_title(f"{len(eq)} relative equilibria")
    a.legend(fontsize="small", loc="best")
    rpy = np.array([e["roll_pitch_yaw"] for e in eq], dtype=float)
    for i, name in enumerate(("roll", "pitch", "yaw")):
        b.plot(number, np.degrees(rpy[:, i]), "o", label=name, markersize=4)
    b.set_xlabel("equilibrium (number)")
    b.set_ylabel("angle relative to LVLH (degrees)")
    b.set_title("Roll, pitch, yaw of each equilibrium")
    b.legend(fontsize="small", loc="best")
    return fig


def libration_figure(res: Result):
    """The periapsis section of Beletsky's equation (``newtop libration --out``): θ mod π against
    θ′ at each periapsis, one colour per start, chaotic starts marked in the legend; from the
    JSON, libration_starts_figure."""
    if not res.columns:
        return libration_starts_figure(res)
    c = res.columns
    fig = new_figure(7, 6.5)
    ax = fig.add_subplot()
    starts = np.unique(c["start"])
    for colour, s in zip(distinct_colours(len(starts)), starts):
        sel = c["start"] == s
        chaotic = bool(np.any(np.asarray(c["chaotic"])[sel] > 0))
        ax.scatter(c["theta"][sel], c["dtheta"][sel], s=3, color=colour, linewidths=0,
                   label=f"start {int(s)}" + (" (chaotic)" if chaotic else ""))
    ax.set_xlabel("θ mod π (rad), at periapsis")
    ax.set_ylabel("θ′ = dθ/dν")
    ax.set_title(f"Periapsis section of Beletsky's equation: {len(starts)} starts")
    if len(starts) <= 12:
        ax.legend(fontsize="x-small", loc="best", markerscale=3)
    return fig


def _stable(c):
    return np.array([s in STABLE for s in c["stability"]])


def continuation_family_figure(res: Result):
    """``newtop continue --out``: the defining value (θ′(0) for periodic solutions, else the first
    that varies) against the parameter, stable and unstable stretches apart; the period beside."""
    c = res.columns
    skip = {"parameter", "period", "stability"}
    values = [n for n in c if n not in skip and not n.startswith("multiplier")]
    name = "dtheta0" if "dtheta0" in values else next(
        (n for n in values if np.ptp(c[n]) > 0), values[0] if values else "parameter")
    stable = _stable(c)
    fig = new_figure(11 if "period" in c else 7, 4.8)
    axes = fig.subplots(1, 2 if "period" in c else 1, squeeze=False)[0]
    for ax, y, label in zip(axes, (name, "period"), (name, "period")):
        for mask, colour, what in ((stable, "C0", "stable"), (~stable, "C3", "unstable")):
            ax.plot(np.where(mask, c["parameter"], np.nan), np.where(mask, c[y], np.nan),
                    color=colour, label=what)
        ax.set_xlabel("parameter")
        ax.set_ylabel(label)
        ax.set_title(f"Continued family: {label}")
        ax.legend(fontsize="small", loc="best")
    return fig


def continuation_curves_figure(res: Result):
    """``newtop continue --second KEY --out``: each event's curve in the plane of the two keys."""
    c = res.columns
    names = list(c)
    second, parameter = names[2], names[3]
    fig = new_figure(7, 5.5)
    ax = fig.add_subplot()
    curves = np.unique(c["curve"])
    for colour, k in zip(distinct_colours(len(curves)), curves):
        sel = c["curve"] == k
        kind = np.array(c["type"])[sel][0]
        ax.plot(c[second][sel], c[parameter][sel], color=colour, label=f"{int(k)}: {kind}")
    ax.set_xlabel(second)
    ax.set_ylabel(parameter)
    ax.set_title(f"Events continued in two parameters: {len(curves)} curves")
    ax.legend(fontsize="small", loc="best")
    return fig
