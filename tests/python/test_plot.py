"""newtop.plot: every kind of newtop output is recognised from its contents and drawn with the
titles and axis labels that say what it shows; the command line writes the figure or, for a file
that is not a newtop result, prints one line and exits with 2 leaving no figure."""

from __future__ import annotations

import os
import subprocess
import sys

import numpy as np
import pytest

from newtop import _sphere, plot, results

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
EXE = os.environ.get("NEWTOP_EXE", os.path.join(ROOT, "build", "newtop"))
#: V from the model block against V reported by newtop at its equilibria: the same formula
#: evaluated in another order, a few roundings of numbers of order 1.
POTENTIAL_TOLERANCE = 64 * np.finfo(float).eps


def newtop(tmp_path, *args, json_name=None):
    args = [*map(str, args)] + (["--json"] if json_name else [])
    r = subprocess.run([EXE, *args], capture_output=True, text=True, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    if json_name:
        (tmp_path / json_name).write_text(r.stdout)
        return tmp_path / json_name
    return None


def example(name):
    return os.path.join(ROOT, "examples", name)


def plot_cli(*args):
    return subprocess.run([sys.executable, "-m", "newtop.plot", *map(str, args)],
                          capture_output=True, text=True,
                          env=dict(os.environ, PYTHONPATH=os.path.join(ROOT, "python")))


def titles(fig):
    return [ax.get_title() for ax in fig.axes] + [fig._suptitle.get_text() if fig._suptitle
                                                  else ""]


def labelled(fig):
    """Every plotting axes (colour bars aside) has a title and an x label."""
    for ax in fig.axes:
        if ax.get_label() == "<colorbar>":
            assert ax.get_ylabel() or ax.get_xlabel(), "colour bar without a label"
            continue
        assert ax.get_title(), f"axes without a title in {titles(fig)}"
        assert ax.get_xlabel(), f"axes '{ax.get_title()}' without an x label"


@pytest.fixture(scope="module")
def outputs(tmp_path_factory):
    d = tmp_path_factory.mktemp("outputs")
    newtop(d, "simulate", example("brun.toml"), "--t-end", 5, "--out", "brun.csv",
           json_name="brun_simulate.json")
    newtop(d, "equilibria", example("equilibria_newtonian.toml"), json_name="eq.json")
    newtop(d, "stability", example("stability_beletsky.toml"), "--scan-omega", "0:3:31",
           "--out", "scan.csv", json_name="stability.json")
    newtop(d, "stability", example("stability_beletsky.toml"), "--axis", "z", "--scan",
           "omega=0:3:7,C=0.5:2.5:5", "--out", "map.csv")
    newtop(d, "rotations", example("rotation_staude_cone.toml"), "--out", "cone.csv",
           json_name="rotations.json")
    newtop(d, "integrals", example("heavy_top.toml"), json_name="integrals.json")
    newtop(d, "analytic", example("analytic_lagrange.toml"), "--samples", 10,
           json_name="analytic.json")
    newtop(d, "find-integrals", example("brun.toml"), json_name="find.json")
    newtop(d, "field", example("exact_box_multipole.toml"), "--gamma", "0,0.6,0.8",
           json_name="field.json")
    return d


KINDS = {
    "brun.csv": ("trajectory", "Drift of the first integrals"),
    "brun_simulate.json": ("simulate", "Path of γ on the Poisson sphere"),
    "eq.json": ("equilibria", "Equilibria over the map of V"),
    "stability.json": ("stability", "Beletsky's diagram"),
    "scan.csv": ("omega_scan", "Beletsky's diagram"),
    "map.csv": ("stability_map", "Stability of the spin about the radius vector"),
    "cone.csv": ("cone", "Staude cone"),
    "rotations.json": ("rotations", "Staude cone"),
    "integrals.json": ("integrals", "Map of V"),
    "analytic.json": ("analytic", "closed form"),
    "find.json": ("find_integrals", "Integral search"),
    "field.json": ("field", "Exact field and its expansion"),
}


@pytest.mark.parametrize("name", sorted(KINDS))
def test_every_output_is_recognised_and_drawn(outputs, name, monkeypatch):
    monkeypatch.chdir(outputs)  # JSON files name their CSV relative to where newtop ran
    kind, title = KINDS[name]
    res = results.load(outputs / name)
    assert res.kind == kind
    fig = plot.figure(res)
    assert any(title in t for t in titles(fig)), titles(fig)
    labelled(fig)


def test_drift_curves_are_the_integrals_relative_drift(outputs):
    res = results.load(outputs / "brun.csv")
    fig = plot.trajectory_figure(res, panel="drift")
    ax = fig.axes[0]
    assert ax.get_yscale() == "log" and ax.get_xlabel() == "t"
    curves = {ln.get_label(): ln for ln in ax.get_lines()}
    assert set(results.integral_columns(res)) <= set(curves)  # one curve per integral
    e = res.columns["energy"]
    expected = np.maximum(np.abs(e - e[0]) / abs(e[0]), plot.EPS / 2)
    np.testing.assert_array_equal(curves["energy"].get_ydata(), expected)


def test_equilibria_sit_where_newtop_says_and_v_matches(outputs):
    eq = results.load(outputs / "eq.json")
    for e in eq.data["equilibria"]:
        v = _sphere.quadratic_potential(eq.data["model"], np.array(e["gamma"]))
        assert abs(v - e["potential"]) <= POTENTIAL_TOLERANCE * max(1.0, abs(v))
    fig = plot.figure(eq)
    marked = np.concatenate([c.get_offsets() for c in fig.axes[0].collections
                             if c.get_gid() == "equilibrium"])
    lon, lat = _sphere.lon_lat(np.array([e["gamma"] for e in eq.data["equilibria"]]))
    assert len(marked) == len(eq.data["equilibria"])
    np.testing.assert_allclose(sorted(marked[:, 0]), sorted(lon))
    np.testing.assert_allclose(sorted(marked[:, 1]), sorted(lat))


def test_beletsky_threshold_is_drawn_from_the_json(outputs):
    res = results.load(outputs / "stability.json")
    fig = plot.figure(res)
    xs = [ln.get_xdata()[0] for ln in fig.axes[0].get_lines() if "Ω*" in ln.get_label()]
    assert res.data["threshold_omega_formula"] in xs


def test_cli_writes_each_format(outputs, tmp_path):
    for ext in ("png", "svg", "pdf"):
        out = tmp_path / f"fig.{ext}"
        r = plot_cli(outputs / "brun.csv", "-o", out, "--equilibria", outputs / "eq.json")
        assert r.returncode == 0, r.stderr
        assert out.stat().st_size > 1000
    assert sorted(os.listdir(tmp_path)) == ["fig.pdf", "fig.png", "fig.svg"]  # no temporaries


BAD = {
    "notes.txt": ("hello, world\n1,2\n", "not a newtop result"),
    "other.json": ('{"answer": 42}\n', "not a newtop result"),
    "broken.json": ('{"method": ', "malformed JSON"),
    "header_only.csv": ("t,p,q,r,gamma1,gamma2,gamma3,energy\n", "at least one data row"),
    "words.csv": ("t,p,q,r,gamma1,gamma2,gamma3\n0,a,0,0,0,0,1\n", "column p: expected numbers"),
    "ragged.csv": ("t,p,q,r,gamma1,gamma2,gamma3\n0,0,0\n", "expected 7 fields"),
    "empty.csv": ("", "empty file"),
}


@pytest.mark.parametrize("name", sorted(BAD))
def test_cli_rejects_what_is_not_a_newtop_result(tmp_path, name):
    text, message = BAD[name]
    (tmp_path / name).write_text(text)
    out = tmp_path / "fig.png"
    r = plot_cli(tmp_path / name, "-o", out)
    assert r.returncode == 2
    assert r.stderr.count("\n") == 1 and r.stderr.startswith("newtop.plot: error: ")
    assert message in r.stderr, r.stderr
    assert not out.exists()


def test_cli_rejects_an_unknown_figure_format(outputs, tmp_path):
    r = plot_cli(outputs / "brun.csv", "-o", tmp_path / "fig.bmp")
    assert r.returncode == 2 and ".png, .svg or .pdf" in r.stderr


def test_import_without_the_compiled_extension():
    import newtop

    assert newtop.HAVE_EXTENSION is False  # not built yet; the pictures work without it
