"""The continued families from Python (docs/continuation.md): the same events, bit for bit, as
`newtop continue`, and Beletsky's threshold from the rotation family.

Run by ctest with NEWTOP_PYTHON_MODULE (build/python) and NEWTOP_EXE set
(tests/python/CMakeLists.txt)."""

import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

sys.path.insert(0, os.environ["NEWTOP_PYTHON_MODULE"])
import newtop  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
EXE = os.environ["NEWTOP_EXE"]


def test_resonance_family_is_the_programs():
    f = newtop.resonance_family(0.0, 0.9, "eccentricity", 0.6)
    p = subprocess.run([EXE, "continue", os.path.join(ROOT, "examples", "continue_synchronous.toml"),
                        "--family", "resonance", "--parameter", "orbit.eccentricity",
                        "--range", "0:0.6", "--json"], capture_output=True, text=True, check=True)
    j = json.loads(p.stdout)
    assert f["end"] == j["end"]
    assert f["values"].shape == (len(j["points"]), 2)
    assert f["multipliers"].shape == (len(j["points"]), 2)
    assert [e["type"] for e in f["events"]] == [e["type"] for e in j["events"]]
    assert [e["value"] for e in f["events"]] == [e["value"] for e in j["events"]]
    assert list(f["parameter"]) == [q["parameter"] for q in j["points"]]


def test_switch_gives_the_programs_branches(tmp_path):
    f = newtop.resonance_family(0.25, 0.9, "eccentricity", 0.35, switch=True)
    p = subprocess.run([EXE, "continue", os.path.join(ROOT, "examples", "continue_synchronous.toml"),
                        "--family", "resonance", "--parameter", "orbit.eccentricity",
                        "--range", "0.25:0.35", "--switch", "--json"],
                       capture_output=True, text=True, check=True)
    j = json.loads(p.stdout)
    assert [b["event"] for b in f["branches"]] == [b["event"] for b in j["branches"]]
    for b, jb in zip(f["branches"], j["branches"]):
        assert b["type"] == jb["type"] == "flip"
        assert list(b["parameter"]) == [q["parameter"] for q in jb["points"]]
        assert np.all(b["period"] == 4 * math.pi)
    from newtop import plot, results

    out = tmp_path / "switch.json"
    out.write_text(p.stdout)
    fig = plot.figure(results.load(out))
    labels = [ln.get_label() for ln in fig.axes[0].get_lines()]
    assert "branch 1 (flip)" in labels and "branch 2 (flip)" in labels


def test_rotation_family_finds_beletskys_threshold():
    body = newtop.Body.from_principal([1.0, 1.5, 2.2], 1.0, [0.0, 0.0, 0.0])
    r = newtop.rotation_family(body, 1.0, 0.1, 3.0)
    a, b = (2.2 - 1.5) / 1.0, (2.2 - 1.0) / 1.5
    star = (math.sqrt(a) + math.sqrt(b)) / (1 + math.sqrt(a * b))
    assert [e["type"] for e in r["events"]] == ["krein"]
    assert r["events"][0]["value"] == pytest.approx(star, abs=1e-10)
    assert np.all(np.iscomplexobj(r["multipliers"]))


def test_rest_family_is_the_programs():
    body = newtop.Body.from_principal([1.0, 1.5, 2.2], 1.0, [0.1, 0.0, 0.0])
    f = newtop.rest_family(body, 1.0, 1.0, "body.center_of_mass[0]", 0.1, 2.0, [1.0, 0.0, 0.0])
    p = subprocess.run([EXE, "continue", os.path.join(ROOT, "examples", "continue_rest.toml"),
                        "--family", "equilibrium", "--parameter", "body.center_of_mass[0]",
                        "--range", "0.1:2", "--json"], capture_output=True, text=True, check=True)
    j = json.loads(p.stdout)
    assert [e["value"] for e in f["events"]] == [e["value"] for e in j["events"]]
    assert f["values"].shape == (len(j["points"]), 4)
    assert f["events"][0]["value"] == pytest.approx(0.5, abs=1e-10)
    assert f["stability"][0] == "minimum"


def test_lyapunov_family_is_the_programs():
    body = newtop.Body.from_principal([1.0, 1.5, 2.2], 1.0, [0.1, 0.0, 0.0])
    f = newtop.lyapunov_family(body, 1.0, 1.0, [1.0, 0.0, 0.0], 1, 1e-4, 0.3)
    p = subprocess.run([EXE, "continue", os.path.join(ROOT, "examples", "continue_rest.toml"),
                        "--family", "periodic", "--parameter", "energy", "--range", "1e-4:0.3",
                        "--mode", "2", "--json"], capture_output=True, text=True, check=True)
    j = json.loads(p.stdout)
    assert list(f["period"]) == [q["period"] for q in j["points"]]
    assert f["multipliers"].shape == (len(j["points"]), 6)


def test_bad_input_is_value_error():
    with pytest.raises(ValueError, match="parameter"):
        newtop.resonance_family(0.0, 0.9, "omega", 0.6)


def test_bifurcation_diagram_is_drawn(tmp_path):
    from newtop import plot, results

    out = tmp_path / "family.json"
    p = subprocess.run([EXE, "continue", os.path.join(ROOT, "examples", "continue_synchronous.toml"),
                        "--family", "resonance", "--parameter", "orbit.eccentricity",
                        "--range", "0.3:0.6", "--second", "body.inertia[0]",
                        "--second-range", "0.05:0.2", "--json"],
                       capture_output=True, text=True, check=True)
    out.write_text(p.stdout)
    res = results.load(out)
    assert res.kind == "continuation"
    fig = plot.figure(res)
    family, chart = fig.axes[:2]
    assert family.get_xlabel() == "orbit.eccentricity"
    assert chart.get_xlabel() == "body.inertia[0]"
    assert len(chart.get_lines()) == len(json.loads(p.stdout)["boundaries"])
    plot.save(fig, tmp_path / "family.png")
    assert (tmp_path / "family.png").stat().st_size > 0
