"""Pictures of the phase-space outputs (Poincaré sections, chaos indicators, sweeps), drawn from
synthetic files in the formats of docs/cli.md (issues 12 and 13) until those commands exist."""

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
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("l", "L_over_G")
    assert len(ax.collections) == 3  # one colour per orbit
    assert "120 crossings, 3 orbits" in ax.get_title()


def test_section_json(tmp_path):
    cr = [{"orbit": k % 2, "t": k, "omega": [0, 0, 1], "gamma": [0.6, 0, 0.8], "m": [0, 0, 1],
           "coords": {"g": 0.1 * k, "G": 1.0}} for k in range(10)]
    p = tmp_path / "s.json"
    p.write_text(json.dumps({"surface": "gamma3 = 0", "direction": "up", "crossings": cr,
                             "count": 10, "stopped_by": "crossings"}))
    fig = plot.figure(results.load(p))
    assert fig.axes[0].get_xlabel() == "g" and "gamma3 = 0" in fig.axes[0].get_title()


def test_chaos_history_csv(tmp_path):
    t = np.linspace(0, 100, 51)
    p = write_csv(tmp_path / "c.csv", ["t", "lyapunov_max", "megno", "fli"],
                  np.column_stack([t, 1 / (1 + t), 2 - 1 / (1 + t), np.log1p(t)]))
    res = results.load(p)
    assert res.kind == "chaos_history"
    fig = plot.figure(res)
    assert [ax.get_ylabel() for ax in fig.axes] == ["lyapunov_max", "megno", "fli"]
    assert fig.axes[-1].get_xlabel() == "t"


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
