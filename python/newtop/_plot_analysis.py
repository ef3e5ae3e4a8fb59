"""Figures of the qualitative analysis (docs/model.md §7–§9) and of the other one-shot subcommands:
equilibria over a map of V, the Staude cone, Beletsky's stability diagram, spectra, analytic
solutions, integral search, the exact field."""

from __future__ import annotations

import numpy as np

from . import _sphere, results
from ._common import EPS, new_figure, scenario_parameters
from .results import Result, UnrecognisedResult

QUADRATIC_NOTE = "V = M g r0·γ + ½ λ γ·Iγ (docs/model.md §3)"


def _model_is_quadratic(data):
    field = data.get("field")
    return not (isinstance(field, dict) and field.get("kind") not in (None, "quadratic"))


def _potential_map(fig, ax, model, title):
    lon, lat, g = _sphere.grid()
    V = _sphere.quadratic_potential(model, g)
    if np.ptp(V) > 0:
        cs = ax.contourf(lon, lat, V, levels=30, cmap="cividis")
        ax.contour(lon, lat, V, levels=cs.levels[::3], colors="w", linewidths=0.4, alpha=0.6)
        fig.colorbar(cs, ax=ax, label="V(γ)")
    ax.set_xlim(-180, 180)
    ax.set_ylim(-90, 90)
    ax.set_xticks(np.arange(-180, 181, 60))
    ax.set_yticks(np.arange(-90, 91, 30))
    ax.set_xlabel("longitude atan2(γ2, γ1) [deg]")
    ax.set_ylabel("latitude asin(γ3) [deg]")
    ax.set_title(title)


def _sphere_coloured_by_v(ax, model):
    from matplotlib import cm, colors

    u, v = np.linspace(-np.pi, np.pi, 73), np.linspace(-np.pi / 2, np.pi / 2, 37)
    U, W = np.meshgrid(u, v)
    g = np.stack([np.cos(W) * np.cos(U), np.cos(W) * np.sin(U), np.sin(W)], axis=-1)
    V = _sphere.quadratic_potential(model, g)
    norm = colors.Normalize(V.min(), V.max() if np.ptp(V) > 0 else V.min() + 1)
    ax.plot_surface(g[..., 0], g[..., 1], g[..., 2], facecolors=cm.cividis(norm(V)),
                    rstride=1, cstride=1, linewidth=0, antialiased=False, shade=False, alpha=0.85,
                    zorder=1)
    _sphere.set_equal_3d(ax, 1.1)


def equilibria_figure(eq: Result):
    """Equilibria with their types over a longitude–latitude map of V, and on the sphere."""
    d = eq.data
    fig = new_figure(14, 5.5)
    ax = fig.add_subplot(1, 2, 1)
    quadratic = _model_is_quadratic(d) and "model" in d
    counts = f"{d['minima']} minima, {d['saddles']} saddles, {d['maxima']} maxima"
    if quadratic:
        _potential_map(fig, ax, d["model"], f"Equilibria over the map of {QUADRATIC_NOTE}")
    else:
        _potential_map(fig, ax, {"inertia": [0, 0, 0], "mass": 0, "g": 0, "lambda": 0,
                                 "center_of_mass": [0, 0, 0]}, "Equilibria (field not quadratic: "
                                                               "no map of V)")
    _sphere.mark_equilibria(ax, d, three_d=False)
    if d.get("every_orientation"):
        ax.text(0, 0, "every orientation is an equilibrium (V constant)", ha="center")
    ax.legend(fontsize="small", loc="lower left")
    ax3 = fig.add_subplot(1, 2, 2, projection="3d")
    _sphere.draw_on_top(ax3)
    if quadratic:
        _sphere_coloured_by_v(ax3, d["model"])
    else:
        _sphere.draw_sphere(ax3)
    _sphere.mark_equilibria(ax3, d, three_d=True, size=90)
    ax3.set_xlabel("γ1")
    ax3.set_ylabel("γ2")
    ax3.set_zlabel("γ3")
    ax3.set_title("Equilibria on the Poisson sphere")
    rule = d["count_rule"]
    fig.suptitle(f"newtop equilibria: {counts}; minima − saddles + maxima = "
                 f"{rule['minima_minus_saddles_plus_maxima']} "
                 f"({'holds' if rule['holds'] else 'fails'})")
    return fig


def integrals_figure(res: Result):
    """The integrals JSON: the map of V of its model, with the initial integrals in the title."""
    d = res.data
    fig = new_figure(8, 5)
    ax = fig.add_subplot()
    _potential_map(fig, ax, d["model"], f"Map of {QUADRATIC_NOTE}")
    vals = ", ".join(f"{k} = {v:.6g}" for k, v in d["integrals"].items())
    fig.suptitle(f"newtop integrals: {vals}", fontsize="small")
    return fig


def staude_cone_figure(cone: Result, rotations: Result | None = None):
    """The Staude cone γ·(Iγ × r0) = 0 on the sphere (docs/model.md §8): admissible axes (Ω² ≥ 0)
    coloured by Ω², the others grey; principal axes from a rotations JSON when given."""
    c = cone.columns
    g = np.column_stack([c["gamma1"], c["gamma2"], c["gamma3"]])
    ok = c["admissible"] > 0.5
    w2 = c["omega_squared"]
    fig = new_figure(14, 5.5)
    ax = fig.add_subplot(1, 2, 1)
    lon, lat = _sphere.lon_lat(g)
    ax.scatter(lon[~ok], lat[~ok], s=6, color="0.7", label="not admissible (Ω² < 0)")
    sc = ax.scatter(lon[ok], lat[ok], s=8, c=w2[ok], cmap="plasma", label="admissible (Ω² ≥ 0)")
    if ok.any():
        fig.colorbar(sc, ax=ax, label="Ω²")
    ax.set_xlim(-180, 180)
    ax.set_ylim(-90, 90)
    ax.set_xlabel("longitude atan2(γ2, γ1) [deg]")
    ax.set_ylabel("latitude asin(γ3) [deg]")
    ax.set_title("Staude cone γ·(Iγ × r0) = 0: axes of permanent rotation")
    ax3 = fig.add_subplot(1, 2, 2, projection="3d")
    _sphere.draw_sphere(ax3)
    ax3.scatter(*g[~ok].T, s=4, color="0.7", depthshade=False)
    ax3.scatter(*g[ok].T, s=6, c=w2[ok], cmap="plasma", depthshade=False)
    if rotations is not None:
        for a in rotations.data.get("principal_axes_any_omega", []):
            for sgn in (1, -1):
                p = sgn * np.asarray(a, dtype=float)
                ax3.scatter(*p, marker="*", s=120, color="k", depthshade=False)
                ax.scatter(*_sphere.lon_lat(p), marker="*", s=120, color="k")
    ax3.set_xlabel("γ1")
    ax3.set_ylabel("γ2")
    ax3.set_zlabel("γ3")
    ax3.set_title("Staude cone on the Poisson sphere")
    ax.legend(fontsize="small", loc="lower left")
    fig.suptitle(f"newtop rotations: {ok.sum()} of {len(ok)} sampled axes admissible")
    return fig


def rotations_figure(rot: Result):
    csv = results.companion_csv(rot)
    if not csv:
        raise UnrecognisedResult(f"{rot.path}: rotations JSON without its cone CSV: run newtop "
                                 "rotations with --out CONE.csv and plot that file (or keep it "
                                 "beside the JSON)")
    return staude_cone_figure(results.load(csv), rot)


def _omega_scan_arrays(res: Result):
    if res.kind == "omega_scan":
        c = res.columns
        linear = c["linearly_stable"] > 0.5
        # The CSV's 1/0: 1 proven stable; 0 with a stable spectrum is inconclusive (the JSON's null),
        # 0 with an unstable spectrum is unstable (the JSON's false).
        proven = c["energy_casimir_stable"] > 0.5
        lyap = np.where(proven, 1.0, np.where(linear, np.nan, 0.0))
        return c["omega"], c["max_real_part"], linear, lyap
    scan = res.data["scan"]
    lyap = [np.nan if p["lyapunov_stable"] is None else float(p["lyapunov_stable"]) for p in scan]
    return (np.array([p["omega"] for p in scan], dtype=float),
            np.array([p["max_real_part"] for p in scan], dtype=float),
            np.array([bool(p["linearly_stable"]) for p in scan]), np.array(lyap))


def omega_scan_figure(res: Result):
    """Beletsky's diagram along Ω (docs/model.md §9): max Re s against Ω, stable ranges shaded, with the
    thresholds Ω* (formula and numeric, from the stability JSON) and Ω = √λ."""
    w, re, stable, lyap = _omega_scan_arrays(res)
    fig = new_figure(8, 4.5)
    ax = fig.add_subplot()
    ax.plot(w, np.maximum(re, 0.0), color="k", linewidth=1.2, marker=".", markersize=3,
            label="max Re s")
    top = max(float(np.nanmax(re)) if len(re) else 0.0, 1e-3) * 1.1
    half = 0.5 * (np.diff(w).min() if len(w) > 1 else 1.0)
    for wi, si, li in zip(w, stable, lyap):
        colour = "#1a9850" if si and li == 1 else ("#a6d96a" if si else "#f46d43")
        ax.axvspan(wi - half, wi + half, color=colour, alpha=0.35, linewidth=0)
    ax.plot([], [], color="#1a9850", linewidth=8, alpha=0.5, label="Lyapunov stable")
    ax.plot([], [], color="#a6d96a", linewidth=8, alpha=0.5, label="linearly stable")
    ax.plot([], [], color="#f46d43", linewidth=8, alpha=0.5, label="unstable")
    d = res.data
    model = d.get("model", {})
    if d.get("threshold_omega_formula") is not None:
        ax.axvline(d["threshold_omega_formula"], color="#2166ac", linestyle="--",
                   label=f"Ω* (Beletsky) = {d['threshold_omega_formula']:.6g}")
    if d.get("threshold_omega_numeric") is not None:
        ax.axvline(d["threshold_omega_numeric"], color="#762a83", linestyle=":",
                   label=f"Ω* (numeric) = {d['threshold_omega_numeric']:.6g}")
    if model.get("lambda", 0) > 0:
        ax.axvline(np.sqrt(model["lambda"]), color="0.4", linewidth=0.8, label="Ω = √λ")
    ax.set_ylim(0, top)
    ax.set_xlabel("Ω")
    ax.set_ylabel("max Re s")
    axis = d.get("axis")
    ax.set_title("Beletsky's diagram: spin about the radius vector" +
                 (f" (axis {axis}, {d.get('axis_class')} moment)" if axis else ""))
    ax.legend(fontsize="small", loc="upper right")
    return fig


def stability_map_figure(res: Result, scenario=None):
    """The two-parameter diagram of ``stability --scan P1=..,P2=..``: the verdict at each point;
    with the scenario, the title gives the values of the parameters that are held fixed."""
    names = list(res.columns)
    x, y, verdict = res.columns[names[0]], res.columns[names[1]], res.columns["verdict"]
    xs, ys = np.unique(x), np.unique(y)
    code = {"stable": 0, "unstable": 1, "nonphysical": 2}
    grid = np.full((len(ys), len(xs)), np.nan)
    for xi, yi, v in zip(x, y, verdict):
        if v not in code:
            raise UnrecognisedResult(f"{res.path}: verdict: expected stable, unstable or "
                                     f"nonphysical, found '{v}'")
        grid[np.searchsorted(ys, yi), np.searchsorted(xs, xi)] = code[v]
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch

    fig = new_figure(7, 5.5)
    ax = fig.add_subplot()
    ax.pcolormesh(xs, ys, grid, cmap=ListedColormap(["#1a9850", "#f46d43", "#bdbdbd"]),
                  vmin=-0.5, vmax=2.5, shading="nearest")
    ax.legend(handles=[Patch(color="#1a9850", label="linearly stable"),
                       Patch(color="#f46d43", label="unstable"),
                       Patch(color="#bdbdbd", label="nonphysical (triangle inequality)")],
              fontsize="small", loc="upper left")
    ax.set_xlabel(names[0])
    ax.set_ylabel(names[1])
    title = f"Stability of the spin about the radius vector over ({names[0]}, {names[1]})"
    fixed = scenario_parameters(scenario, exclude=(names[0], names[1]))
    ax.set_title(title + (f"\nfixed: {fixed}" if fixed else ""), fontsize="medium")
    return fig


def stability_figure(res: Result):
    """A stability JSON: its Ω scan if it has one, else the spectrum in the complex plane."""
    if res.data.get("scan"):
        return omega_scan_figure(res)
    ev = np.array(res.data["eigenvalues"], dtype=float).reshape(-1, 2)
    fig = new_figure(5.5, 5)
    ax = fig.add_subplot()
    ax.axvline(0, color="0.5", linewidth=0.8)
    ax.axhline(0, color="0.5", linewidth=0.8)
    ax.scatter(ev[:, 0], ev[:, 1], s=50, color="#b2182b", zorder=3)
    ax.set_xlabel("Re s")
    ax.set_ylabel("Im s")
    verdict = "linearly stable" if res.data["linearly_stable"] else "unstable"
    ax.set_title(f"Spectrum on the symplectic leaf: {verdict}")
    return fig


#: rkf78's samples drawn at most (every k-th beyond), so that its dots do not hide the curves.
MAX_REFERENCE_DOTS = 100
#: Largest turn |ω| Δt between two samples (rad) for which a line through the samples shows the
#: motion: γ and the body axes move by at most |ω| Δt between them, and a chord of a circle of
#: angle 0.2 rad departs from the arc by 1 − cos(0.1) = 0.5% of the radius.
ANALYTIC_MAX_TURN = 0.2


def analytic_sampling(samples):
    """(dense, needed): whether the samples are close enough for lines (the body turns by at most
    ANALYTIC_MAX_TURN between two of them), and the number of samples over the same span that
    would be."""
    t = np.array([x["t"] for x in samples], dtype=float)
    w = max(float(np.linalg.norm(x["analytic"]["omega"])) for x in samples)
    if len(t) < 2:
        return False, 2
    turn = float(np.max(np.diff(t))) * w
    slack = 1 + 1e-9  # sample times written to 17 digits: their spacing is exact to round-off
    needed = int(np.ceil((t[-1] - t[0]) * w / ANALYTIC_MAX_TURN / slack)) + 1
    return turn <= ANALYTIC_MAX_TURN * slack, needed


def analytic_figure(res: Result):
    """Closed-form solution against rkf78 at the samples (newtop analytic)."""
    d = res.data
    s = d["samples"]
    if not s:
        raise UnrecognisedResult(f"{res.path}: analytic result for case '{d['case']}' has no "
                                 "samples to draw (quadratures not implemented for this case)")
    t = np.array([x["t"] for x in s])
    dense, needed = analytic_sampling(s)
    curve = d.get("dense")  # newtop analytic --dense N: the closed form alone, densely
    if curve:
        dense = True
    dots = np.arange(0, len(t), max(1, -(-len(t) // MAX_REFERENCE_DOTS)))  # the curves stay visible
    source = (curve or {}).get("euler_angles") or d.get("euler_angles") or []
    euler = [e for e in source if e.get("theta") is not None]
    rows = 2 if euler else 1
    fig = new_figure(13, 4.5 * rows)
    for k, (key, names) in enumerate((("omega", "pqr"), ("gamma", ("γ1", "γ2", "γ3")))):
        ax = fig.add_subplot(rows, 3, k + 1)
        a = np.array([x["analytic"][key] for x in s])
        n = np.array([x["numeric"][key] for x in s])
        for i, nm in enumerate(names):
            if curve:
                line, = ax.plot(curve["t"], np.array(curve[key])[:, i],
                                label=f"{nm} closed form", linewidth=1.0)
                ax.plot(t, a[:, i], "o", markersize=3, color=line.get_color())
            elif dense:
                ax.plot(t, a[:, i], label=f"{nm} closed form", linewidth=1.2)
            else:  # a line between samples a spin apart would draw a zig-zag that is not there
                ax.plot(t, a[:, i], "o", markersize=3.5, label=f"{nm} closed form")
            ax.plot(t[dots], n[dots, i], "k.", markersize=3)
        ax.set_xlabel("t")
        ax.set_ylabel("ω" if key == "omega" else "γ")
        how = "lines" if dense else "circles"
        ax.set_title(f"{'ω' if key == 'omega' else 'γ'}: closed form ({how}), rkf78 (dots)",
                     fontsize="medium")
        ax.legend(fontsize="x-small")
    ax = fig.add_subplot(rows, 3, 3)
    err = [max(np.max(np.abs(np.subtract(x["analytic"][k], x["numeric"][k])))
               for k in ("omega", "gamma")) for x in s]
    ax.semilogy(t, np.maximum(err, EPS / 2), "o-", markersize=3)
    ax.set_xlabel("t")
    ax.set_ylabel("max |closed form − rkf78|")
    ax.set_title("Difference")
    if euler:
        draw_euler_angles(fig, euler, "-" if dense else "o")
    fig.suptitle(f"newtop analytic: case {d['case']}" + (
        "" if dense else f" (samples too sparse for a curve: ask --dense {needed} or --samples "
        f"{needed})"))
    return fig


def draw_euler_angles(fig, euler, style):
    """The Lagrange top's Euler angles against t (nutation θ; precession φ and spin ψ, unwrapped)
    and the trace of its symmetry axis on the unit sphere, from the JSON's "euler_angles"."""
    t = np.array([e["t"] for e in euler], dtype=float)
    theta, phi, psi = (np.array([e[k] for e in euler], dtype=float) for k in ("theta", "phi", "psi"))
    kw = dict(markersize=3) if style == "o" else dict(linewidth=1.2)
    ax = fig.add_subplot(2, 3, 4)
    ax.plot(t, np.degrees(theta), style, color="C2", **kw)
    ax.set_xlabel("t")
    ax.set_ylabel("θ (deg)")
    ax.set_title("Nutation θ (cos θ = γ3)", fontsize="medium")
    ax = fig.add_subplot(2, 3, 5)
    ax.plot(t, np.unwrap(phi), style, label="precession φ", **kw)
    ax.plot(t, np.unwrap(psi), style, label="spin ψ", **kw)
    ax.set_xlabel("t")
    ax.set_ylabel("angle (rad, unwrapped)")
    ax.set_title("Precession φ and spin ψ (Euler 3-1-3)", fontsize="medium")
    ax.legend(fontsize="x-small")
    ax = fig.add_subplot(2, 3, 6, projection="3d")
    axis = np.array([e["axis"] for e in euler], dtype=float)
    _sphere.draw_sphere(ax)
    ax.plot(axis[:, 0], axis[:, 1], axis[:, 2], style, color="#b2182b", **kw)
    ax.set_xlabel("x (node at t = 0)")
    ax.set_ylabel("y")
    ax.set_zlabel("z (fixed direction e)")
    ax.set_title("Trace of the symmetry axis e3", fontsize="medium")


def find_integrals_figure(res: Result):
    """Singular values of the condition matrix with the rank decision (newtop find-integrals)."""
    d = res.data
    sv = np.maximum(np.array(d["singular_values"], dtype=float), EPS / 2)
    fig = new_figure(7, 4.5)
    ax = fig.add_subplot()
    colours = ["#4575b4" if i < d["rank"] else "#d73027" for i in range(len(sv))]
    ax.bar(np.arange(1, len(sv) + 1), sv, color=colours)
    ax.set_yscale("log")
    ax.axvline(d["rank"] + 0.5, color="k", linestyle="--", label=f"rank {d['rank']}")
    ax.set_xlabel("index of singular value")
    ax.set_ylabel("singular value / largest")
    ax.set_title(f"Integral search, degree {d['degree']}: {d['independent_integrals']} "
                 "independent integrals (red: null space)")
    ax.legend(fontsize="small")
    return fig


def field_figure(res: Result):
    """newtop field: with --scan-R the error of the quadratic model against R (log–log, fitted
    slopes); otherwise exact against approximate potential and moment."""
    d = res.data
    fig = new_figure(7, 4.5)
    ax = fig.add_subplot()
    if "scan" in d:
        s = d["scan"]
        ax.loglog(s["R"], s["potential_error"], "o-", markersize=3,
                  label=f"|ΔV| (slope {d['scan']['slope_potential']:.3f})")
        ax.loglog(s["R"], s["moment_error"], "s-", markersize=3,
                  label=f"|ΔL| (slope {d['scan']['slope_moment']:.3f})")
        ax.set_xlabel("R")
        ax.set_ylabel("|exact − quadratic model|")
        ax.set_title("Error of the quadratic model against the distance R")
        ax.legend(fontsize="small")
        return fig
    names = ["potential", "|moment|", "|force|"]
    ex = [d["exact"]["potential"], np.linalg.norm(d["exact"]["moment"]),
          np.linalg.norm(d["exact"]["force"])]
    ap = [d["approx"]["potential"], np.linalg.norm(d["approx"]["moment"]),
          np.linalg.norm(d["approx"]["force"])]
    x = np.arange(3)
    ax.bar(x - 0.2, np.abs(ex), 0.4, label="exact")
    ax.bar(x + 0.2, np.abs(ap), 0.4, label="approx (through 1/R³)")
    ax.set_xticks(x, names)
    ax.set_yscale("log")
    ax.set_xlabel("quantity")
    ax.set_ylabel("magnitude")
    ax.set_title(f"Exact field and its expansion at R = {d['R']:.6g}")
    ax.legend(fontsize="small")
    return fig
