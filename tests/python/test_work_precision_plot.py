"""scripts/work_precision_plot.py: every finite run of the CSV is drawn, in the panel of its regime
and metric, in the order of its setting; runs with a non-finite error are left out; the committed
data of docs/performance.md plots a panel per regime and metric (read from the matplotlib objects,
not from pixels)."""

from __future__ import annotations

import os

from scripts_dir import ROOT, load_script

#: A PNG of a drawn figure is tens of kilobytes; an empty canvas compresses below this.
MIN_IMAGE_BYTES = 10_000


def test_runs_are_drawn_where_and_in_the_order_they_belong(tmp_path):
    csv = tmp_path / "wp.csv"
    csv.write_text(
        "regime,metric,method,setting,steps,error,cpu_s\n"
        'a,state,"splitting2 (axes)",0.01,4000,1.0e-6,2.0e-3\n'
        'a,state,"splitting2 (axes)",0.02,2000,4.0e-6,1.0e-3\n'
        'a,state,"splitting2 (axes)",0.04,1000,inf,5.0e-4\n'
        'a,state,"odeint rkf78 (peer)",1e-9,100,2.0e-7,3.0e-4\n'
        'c,energy,"splitting6 (spin)",0.1,100000,3.0e-10,5.0e-2\n')
    wp = load_script("work_precision_plot")
    out = tmp_path / "wp.png"
    fig = wp.plot(wp.read(str(csv)), str(out))
    assert os.path.getsize(out) > MIN_IMAGE_BYTES
    axes = fig.axes
    assert len(axes) == 4  # metrics (state, energy) × regimes (a, c)
    panels = {(ax.get_ylabel(), ax.get_title()): ax for ax in axes}
    state_a = panels[(wp.METRICS["state"], wp.REGIMES["a"])]
    lines = {l.get_label(): l for l in state_a.get_lines() if not l.get_label().startswith("_")}
    assert set(lines) == {"splitting2 (axes)", "odeint rkf78 (peer)"}
    s2 = lines["splitting2 (axes)"]
    assert list(s2.get_xdata()) == [2.0e-3, 1.0e-3]  # by setting 0.01, 0.02; the inf run dropped
    assert list(s2.get_ydata()) == [1.0e-6, 4.0e-6]
    energy_c = panels[(wp.METRICS["energy"], wp.REGIMES["c"])]
    (l,) = [l for l in energy_c.get_lines() if not l.get_label().startswith("_")]
    assert (l.get_label(), list(l.get_xdata()), list(l.get_ydata())) == (
        "splitting6 (spin)", [5.0e-2], [3.0e-10])
    for key in [(wp.METRICS["energy"], wp.REGIMES["a"]), (wp.METRICS["state"], wp.REGIMES["c"])]:
        assert not [l for l in panels[key].get_lines() if not l.get_label().startswith("_")]


def test_the_documented_data_plots_every_regime(tmp_path):
    wp = load_script("work_precision_plot")
    data = wp.read(os.path.join(ROOT, "docs", "data", "work_precision.csv"))
    fig = wp.plot(data, str(tmp_path / "wp.png"))
    titles = {ax.get_title() for ax in fig.axes}
    assert titles == set(wp.REGIMES.values())
    assert len(fig.axes) == len(wp.REGIMES) * len(wp.METRICS)
    docs = open(os.path.join(ROOT, "docs", "performance.md")).read()
    assert "img/work_precision.png" in docs and "data/work_precision.csv" in docs
