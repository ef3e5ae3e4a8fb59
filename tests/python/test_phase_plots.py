"""Pictures of the phase-space outputs (Poincaré sections, chaos indicators, sweeps), drawn from
small hand-made files in the formats of docs/cli.md (the gallery test draws the real outputs):
what each picture must show — log-scaled spectrum history, clipped MEGNO scale with 2 marked,
distinct orbit colours, levels and fixed parameters in the titles, unambiguous labels."""

from __future__ import annotations

import json

import numpy as np

from newtop import plot, results


def write_csv(path, header, rows):
    path.write_text(",".join(header) + "\n" +
                    "\n".join(",".join(str(x) for x in r) for r in rows) + "\n")
    return path


def test_section_csv_coloured_by_orbit(tmp_path):
    rows = []
    for orbit in range(3):
        for k in range(40):
            a = 2 * np.pi * k / 40
            rows.append([orbit, k, 0.1, 0.2, 0.3, 0.6, 0.0, 0.8, orbit + np.cos(a), np.sin(a)])
    p = write_csv(tmp_path / "s.csv", ["orbit", "t", "p", "q", "r", "gamma1", "gamma2", "gamma3",
                                       "l", "L_over_G"], rows)
    res = results.load(p)
    assert res.kind == "section"
    fig = plot.figure(res)
    ax = fig.axes[0]
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("ℓ = atan2(m1, m2), Andoyer angle (rad)",
                                                  "L/G = m3/|m|")
    assert len(ax.collections) == 3  # one colour per orbit
    assert "120 crossings, 3 orbits" in ax.get_title()


def test_section_json(tmp_path):
    cr = [{"orbit": k % 2, "t": k, "omega": [0, 0, 1], "gamma": [0.6, 0, 0.8], "m": [0, 0, 1],
           "coords": {"g": 0.1 * k, "G": 1.0}} for k in range(10)]
    p = tmp_path / "s.json"
    p.write_text(json.dumps({"surface": "gamma3 = 0", "direction": "up", "crossings": cr,
                             "count": 10, "stopped_by": "crossings"}))
    fig = plot.figure(results.load(p))
    assert fig.axes[0].get_xlabel() == "g, Andoyer angle about m (rad)"
    assert "gamma3 = 0" in fig.axes[0].get_title()


def test_chaos_history_csv(tmp_path):
    t = np.linspace(0, 100, 51)
    p = write_csv(tmp_path / "c.csv", ["t", "lyapunov_max", "megno", "fli"],
                  np.column_stack([t, 1 / (1 + t), 2 - 1 / (1 + t), np.log1p(t)]))
    res = results.load(p)
    assert res.kind == "chaos_history"
    fig = plot.figure(res)
    assert [ax.get_ylabel() for ax in fig.axes] == ["lyapunov_max", "megno", "fli"]
    assert fig.axes[-1].get_xlabel() == "t (log scale)"
    assert all(ax.get_xscale() == "log" for ax in fig.axes)


def test_sweep_map_masks_failed_points(tmp_path):
    rows = []
    for w in (0.0, 1.0, 2.0):
        for c in (1.7, 1.9, 2.1, 2.3):
            ok = not (w == 2.0 and c == 2.3)
            rows.append([w, c, w * c if ok else "", "ok" if ok else "non_finite"])
    p = write_csv(tmp_path / "w.csv", ["stability.omega", "body.inertia[2]", "megno", "status"],
                  rows)
    res = results.load(p)
    assert res.kind == "sweep"
    fig = plot.figure(res)
    ax = fig.axes[0]
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("stability.omega", "body.inertia[2]")
    assert "megno" in ax.get_title() and "1 failed" in ax.get_title()
    grid = ax.collections[0].get_array().reshape(4, 3)  # rows: body.inertia[2]; columns: omega
    assert np.ma.count_masked(grid) == 1 and np.ma.is_masked(grid[3, 2])
    assert grid[1, 2] == 2.0 * 1.9  # row: body.inertia[2] = 1.9, column: omega = 2


def test_sweep_over_one_key(tmp_path):
    p = write_csv(tmp_path / "w.csv", ["stability.omega", "linearly_stable", "lyapunov_stable",
                                       "max_real_part", "status"],
                  [[w, int(w > 1), "", max(0, 1 - w), "ok"] for w in np.linspace(0, 2, 9)])
    fig = plot.figure(results.load(p))
    assert fig.axes[0].get_ylabel() == "max_real_part"


SCENARIO = """[body]
inertia = [1.0, 1.5, 2.2]
mass = 1.0
center_of_mass = [0.3, 0.2, 0.1]

[field]
kind = "brun"
N = 0.8

[initial]
omega = [0.1, 0.2, 0.3]
gamma = [0.0, 0.6, 0.8]
"""


def section_rows(orbits, per_orbit=10):
    return [[o, k, 0.1, 0.2, 0.3, 0.6, 0.0, 0.8, o + np.cos(k), np.sin(k), 0.0, 1.0]
            for o in range(orbits) for k in range(per_orbit)]


SECTION_HEADER = ["orbit", "t", "p", "q", "r", "gamma1", "gamma2", "gamma3", "l", "L_over_G",
                  "g", "G"]


def test_chaos_spectrum_history_on_one_log_scaled_panel(tmp_path):
    # newtop chaos --spectrum --out: t,lyapunov_max,megno_y,megno,fli,lambda1..lambda6.
    t = np.linspace(0, 100, 101)
    lam = [0.05, 0.01, 1e-3, -1e-3, -0.01, -0.05]
    cols = [t, 0.05 + 1 / (1 + t), 1 + t / 50, 2 - 1 / (1 + t), np.log1p(t)] + \
        [np.full_like(t, x) for x in lam]
    p = write_csv(tmp_path / "c.csv", ["t", "lyapunov_max", "megno_y", "megno", "fli"] +
                  [f"lambda{i}" for i in range(1, 7)], np.column_stack(cols))
    fig = plot.figure(results.load(p))
    spectrum = fig.axes[0]
    labels = [line.get_label() for line in spectrum.get_lines()]
    assert [f"lambda{i}" for i in range(1, 7)] + ["lyapunov_max"] == \
        [x for x in labels if not x.startswith("_")]
    assert spectrum.get_xscale() == "log" and spectrum.get_ylabel() == "Lyapunov exponents"
    assert "spectrum" in spectrum.get_title()
    assert all(ax.get_title() and ax.get_xlabel() == "t (log scale)" for ax in fig.axes)
    # the start t = 0 has no place on a log axis and is left out; every other row is drawn
    assert len(spectrum.get_lines()[0].get_xdata()) == len(t) - 1
    megno = next(ax for ax in fig.axes if ax.get_ylabel() == "megno")
    assert any(list(line.get_ydata()) == [2.0, 2.0] for line in megno.get_lines())


def megno_map(tmp_path, top):
    rows = [[w, c, top * (w + c) / 4, "ok"] for w in (0.0, 1.0, 2.0) for c in (0.0, 1.0, 2.0)]
    return write_csv(tmp_path / "m.csv", ["initial.omega[0]", "initial.omega[1]", "megno",
                                          "status"], rows)


def test_megno_map_scale_is_clipped_with_the_regular_value_marked(tmp_path):
    fig = plot.figure(results.load(megno_map(tmp_path, 40.0)), quantity="megno")
    mesh = fig.axes[0].collections[0]
    assert mesh.get_clim() == (0.0, 8.0)  # a chaotic corner at 40 does not flatten the map
    bar = next(ax for ax in fig.axes if ax.get_label() == "<colorbar>")
    assert any(list(line.get_ydata()) == [2.0, 2.0] for line in bar.get_lines())
    assert 2.0 in list(bar.get_yticks())
    # another quantity keeps its own range
    p = write_csv(tmp_path / "s.csv", ["a", "b", "max_real_part", "status"],
                  [[a, b, 10.0 * a * b, "ok"] for a in (0.0, 1.0) for b in (0.0, 1.0)])
    assert plot.figure(results.load(p)).axes[0].collections[0].get_clim() == (0.0, 10.0)


def test_section_colours_stay_distinct_beyond_ten_and_twenty_orbits(tmp_path):
    for orbits in (3, 12, 25):
        p = write_csv(tmp_path / f"s{orbits}.csv", SECTION_HEADER, section_rows(orbits))
        ax = plot.figure(results.load(p)).axes[0]
        colours = {tuple(np.round(c.get_facecolor()[0], 6)) for c in ax.collections}
        assert len(ax.collections) == orbits and len(colours) == orbits


def test_section_title_gives_the_levels_and_the_fixed_parameters(tmp_path):
    cr = [{"orbit": k % 12, "t": k, "omega": [0, 0, 1], "gamma": [0.6, 0, 0.8], "m": [0, 0, 1],
           "coords": {"l": 0.1 * k, "L_over_G": 0.5}} for k in range(48)]
    p = tmp_path / "s.json"
    p.write_text(json.dumps({"surface": "gamma3 = 0", "direction": "up", "crossings": cr,
                             "count": 48, "stopped_by": "t_end",
                             "levels": {"energy": 0.53989, "area": -1.3132, "orbits": 12,
                                        "empty": False}}))
    sc = tmp_path / "sc.toml"
    sc.write_text(SCENARIO)
    ax = plot.figure(results.load(p), scenario=str(sc)).axes[0]
    title = ax.get_title()
    assert "h = 0.53989, f = -1.3132" in title
    assert "A = 1, B = 1.5, C = 2.2" in title and "r0 = [0.3, 0.2, 0.1]" in title
    assert "brun field: N = 0.8" in title
    assert ax.get_xlabel() != "l" and ax.get_xlabel().startswith("ℓ")
    # a CSV has no levels: the title says so instead of leaving them out silently
    csv = write_csv(tmp_path / "s.csv", SECTION_HEADER, section_rows(2))
    assert "levels h, f: not in this file" in plot.figure(results.load(csv)).axes[0].get_title()


def test_stability_map_title_gives_the_values_held_fixed(tmp_path):
    p = write_csv(tmp_path / "map.csv", ["omega", "C", "max_real_part", "verdict"],
                  [[w, c, 0.0, "stable"] for w in (0.0, 1.0) for c in (1.0, 2.0)])
    sc = tmp_path / "sc.toml"
    sc.write_text(SCENARIO)
    title = plot.figure(results.load(p), scenario=str(sc)).axes[0].get_title()
    assert "fixed: A = 1, B = 1.5; M = 1" in title and "C = 2.2" not in title
    assert "brun field: N = 0.8" in title


def test_plot_command_line_refuses_a_missing_scenario(tmp_path, capsys):
    p = write_csv(tmp_path / "s.csv", SECTION_HEADER, section_rows(2))
    assert plot.main([str(p), "-o", str(tmp_path / "s.png"), "--scenario",
                      str(tmp_path / "none.toml")]) == 2
    assert "--scenario" in capsys.readouterr().err


def analytic_json(tmp_path, samples):
    # a spin of rate 20 about e3 with γ turning in the xy plane: γ1 = cos 20t, γ2 = −sin 20t
    t = np.linspace(0.0, 2.0, samples)
    rows = [{"t": x, "analytic": {"omega": [0, 0, 20.0], "gamma": [np.cos(20 * x), -np.sin(20 * x),
                                                                    0.0]},
             "numeric": {"omega": [0, 0, 20.0], "gamma": [np.cos(20 * x), -np.sin(20 * x), 0.0]}}
            for x in t]
    p = tmp_path / f"a{samples}.json"
    p.write_text(json.dumps({"case": "lagrange", "samples": rows, "max_abs_error": 0.0}))
    return p


def test_analytic_closed_form_is_a_curve_only_where_the_samples_resolve_it(tmp_path):
    # 2 time units at |ω| = 20: 40 rad; a curve needs a sample every 0.2 rad, 201 samples.
    sparse = plot.figure(results.load(analytic_json(tmp_path, 50)))
    ax = sparse.axes[1]
    closed = [ln for ln in ax.get_lines() if ln.get_label().endswith("closed form")]
    assert closed and all(ln.get_linestyle() == "None" for ln in closed)  # markers, no zig-zag
    assert "circles" in ax.get_title() and "--dense 201 or --samples 201" in sparse._suptitle.get_text()
    dense = plot.figure(results.load(analytic_json(tmp_path, 201)))
    ax = dense.axes[1]
    closed = [ln for ln in ax.get_lines() if ln.get_label().endswith("closed form")]
    assert closed and all(ln.get_linestyle() == "-" for ln in closed)
    assert "(lines)" in ax.get_title() and "too sparse" not in dense._suptitle.get_text()


def test_lagrange_figure_draws_the_euler_angles_and_the_axis_trace(tmp_path):
    p = analytic_json(tmp_path, 201)
    d = json.loads(p.read_text())
    t = np.array([x["t"] for x in d["samples"]])
    theta, phi, psi = 0.5 + 0.1 * np.sin(3 * t), 0.7 * t, 20 * t
    d["euler_angles"] = [{"t": x, "phi": f, "theta": th, "psi": s,
                          "axis": [np.sin(th) * np.sin(f), -np.sin(th) * np.cos(f), np.cos(th)]}
                         for x, th, f, s in zip(t, theta, phi, psi)]
    p.write_text(json.dumps(d))
    fig = plot.figure(results.load(p))
    titles = [ax.get_title() for ax in fig.axes]
    assert "Nutation θ (cos θ = γ3)" in titles
    assert "Precession φ and spin ψ (Euler 3-1-3)" in titles
    assert "Trace of the symmetry axis e3" in titles
    nutation = fig.axes[titles.index("Nutation θ (cos θ = γ3)")]
    assert np.allclose(nutation.get_lines()[0].get_ydata(), np.degrees(theta))
    # without the key (other cases) the figure keeps its one row
    assert len(plot.figure(results.load(analytic_json(tmp_path, 50))).axes) == 3
