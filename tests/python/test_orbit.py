"""The satellite on an orbit from Python (docs/python.md, "Satellites on an orbit"): orbit
scenarios and models built in code integrate into the rows of `newtop simulate --euler 321`'s CSV
bit for bit (circular and elliptic, splitting and rkf78, every step and at output times); the LVLH
attitude against the triad built here from gamma and n; bad arguments refused with the library's
message (the command line's); the relative equilibria, the stability of one and the DeBra-Delp
diagram equal the command line's JSON numbers.

Run by ctest with NEWTOP_PYTHON_MODULE (build/python) and NEWTOP_EXE set
(tests/python/CMakeLists.txt)."""

import json
import os
import subprocess
import sys

import numpy as np
import pytest

sys.path.insert(0, os.environ["NEWTOP_PYTHON_MODULE"])
import newtop  # noqa: E402

EXE = os.environ["NEWTOP_EXE"]
EXAMPLES = os.path.join(os.path.dirname(__file__), "..", "..", "examples")

# Attitude check against an independent construction. The quaternion's matrix and the angles'
# R1 R2 R3 are products of a few rounded terms of unit-size numbers (a few eps each); a triad
# (gamma, n) that is not orthonormal by its Casimir error c (rkf78 drifts, ~1e-13 here) is
# represented only to ~c. 64 eps covers the rounding with a margin of ~10; the row's own c is
# added. The pitch comes from asin(-C13), whose rounding error grows as 1/|cos(pitch)| near the
# gimbal lock (pitch = ±pi/2, met by orbit_spin_orbit, whose pitch axis is body z): the angles'
# bound is divided by |cos(pitch)|.
ROUNDING = 64 * np.finfo(float).eps


def example(name):
    return os.path.join(EXAMPLES, name + ".toml")


def program(*words, ok=True):
    p = subprocess.run([EXE, *words], capture_output=True, text=True)
    if ok:
        assert p.returncode == 0, p.stderr
    return p


def csv_columns(path):
    table = np.genfromtxt(path, delimiter=",", names=True)
    return {name: table[name] for name in table.dtype.names}


# (example, t_end, extra options of simulate and of integrate)
RUNS = [
    ("satellite_700km", 2000.0, [], {}),
    ("orbit_elliptic_pitch", 3.0, [], {}),
    ("orbit_spin_orbit", 3.0, [], {}),  # rkf78 at 1e-12, elliptic
    ("orbit_leo_lagrange", 3000.0, ["--method", "splitting4"], {"method": "splitting4"}),
    ("satellite_700km", 2000.0, ["--tol", "1e-10"], {"tol": 1e-10}),  # rkf78 on a circle
]


@pytest.mark.parametrize("name,t_end,options,keywords", RUNS)
def test_every_step_equals_the_csv(tmp_path, name, t_end, options, keywords):
    out = str(tmp_path / "run.csv")
    program("simulate", example(name), "--t-end", repr(t_end), "--euler", "321", "--every", "1",
            "--out", out, *options)
    csv = csv_columns(out)
    sc = newtop.load_scenario(example(name))
    assert isinstance(sc, newtop.OrbitScenario)
    run = newtop.integrate(sc, t_end=t_end, **keywords)
    assert run["outcome"] == "finished"
    assert set(csv) <= set(run["columns"])
    for column, values in csv.items():
        assert np.array_equal(run[column], values), column
    assert run["normal"].base is run["table"]
    assert np.array_equal(run["roll_pitch_yaw"][:, 1], csv["pitch"])


@pytest.mark.parametrize("name", ["satellite_700km", "orbit_elliptic_pitch", "orbit_spin_orbit"])
def test_output_times_equal_the_csv(tmp_path, name):
    out = str(tmp_path / "run.csv")
    sc = newtop.load_scenario(example(name))
    dt = 100.0 if sc.kind == "circular" and sc.model.rate < 0.01 else 0.25
    program("simulate", example(name), "--t-end", repr(20 * dt), "--dt-out", repr(dt),
            "--euler", "321", "--out", out)
    csv = csv_columns(out)
    run = newtop.integrate(sc, t_end=20 * dt, t_eval=csv["t"])
    assert len(run["t"]) == 21
    for column, values in csv.items():
        assert np.array_equal(run[column], values), column


def test_model_built_in_code_equals_the_scenario(tmp_path):
    """OrbitModel.circular(body, mu=, radius=) and OrbitState.from_lvlh give the run of
    examples/satellite_700km.toml; OrbitModel.elliptic that of orbit_elliptic_pitch from the
    scenario's initial state."""
    sc = newtop.load_scenario(example("satellite_700km"))
    body = newtop.Body.from_principal([1200.0, 1500.0, 900.0], mass=1.0)
    model = newtop.OrbitModel.circular(body, mu=3.986004418e14, radius=7.078137e6)
    assert model.kind == "circular" and model.rate == sc.model.rate
    x0 = newtop.OrbitState.from_lvlh(model, roll_pitch_yaw=[0.0, 0.08726646259971647, 0.0])
    assert np.array_equal(x0.m, sc.initial.m) and np.array_equal(x0.gamma, sc.initial.gamma)
    a = newtop.integrate(model, x0, 500.0, step=10.0)
    b = newtop.integrate(sc, t_end=500.0)
    assert np.array_equal(a["table"], b["table"])

    el = newtop.load_scenario(example("orbit_elliptic_pitch"))
    body = newtop.Body.from_principal([1.0, 1.6, 2.1], mass=1.0)
    model = newtop.OrbitModel.elliptic(body, mu=1.0, a=1.0, e=0.1)
    assert model.kind == "elliptic" and model.eccentricity == 0.1
    a = newtop.integrate(model, el.initial, 2.0, step=0.01)
    b = newtop.integrate(el, t_end=2.0)
    assert np.array_equal(a["table"], b["table"])
    assert list(a)[:2] == ["t", "nu"] and "hamiltonian_nu" in a


@pytest.mark.parametrize("name", ["orbit_leo_lagrange", "orbit_spin_orbit"])
def test_lvlh_attitude_against_the_triad_from_gamma_and_normal(name):
    """C(body<-LVLH) has the columns n x gamma, -n, -gamma (docs/orbit.md §11): built here from
    each row's gamma and n, against the row's quaternion and R1(roll) R2(pitch) R3(yaw)."""
    sc = newtop.load_scenario(example(name))
    run = newtop.integrate(sc, t_end=3.0 if sc.kind == "elliptic" else 3000.0)
    g, n = run["gamma"], run["normal"]
    C = np.stack([np.cross(n, g), -n, -g], axis=2)  # rows: body components; columns: LVLH axes

    def R(axis, a):
        c, s = np.cos(a), np.sin(a)
        m = np.zeros((len(a), 3, 3))
        i, j = [(1, 2), (2, 0), (0, 1)][axis]
        m[:, axis, axis] = 1
        m[:, i, i] = m[:, j, j] = c
        m[:, i, j], m[:, j, i] = s, -s
        return m

    rpy = run["roll_pitch_yaw"]
    from_angles = R(0, rpy[:, 0]) @ R(1, rpy[:, 1]) @ R(2, rpy[:, 2])
    bound = ROUNDING + 4 * run["casimir_error"]
    err = np.max(np.abs(from_angles - C), axis=(1, 2))
    assert np.all(err * np.abs(np.cos(rpy[:, 1])) <= bound)
    q0, q = run["lvlh_quaternion"][:, 0], run["lvlh_quaternion"][:, 1:]
    assert np.all(q0 >= 0)
    cross = np.zeros((len(q0), 3, 3))
    cross[:, 0, 1], cross[:, 0, 2], cross[:, 1, 2] = -q[:, 2], q[:, 1], -q[:, 0]
    cross -= np.transpose(cross, (0, 2, 1))
    from_q = ((q0 ** 2 - np.sum(q * q, axis=1))[:, None, None] * np.eye(3)
              + 2 * q[:, :, None] * q[:, None, :] - 2 * q0[:, None, None] * cross)
    assert np.all(np.max(np.abs(from_q - C), axis=(1, 2)) <= bound)


def scenario_text(orbit, initial="roll_pitch_yaw = [0.0, 0.1, 0.0]", integrate="step = 10.0"):
    return ("[body]\ninertia = [1200.0, 1500.0, 900.0]\n[orbit]\n%s\n[initial]\n%s\n"
            "[integrate]\n%s\nt_end = 100.0\n" % (orbit, initial, integrate))


BAD = [
    # (keywords of OrbitModel.circular/elliptic, [orbit] of the same)
    ({"mu": -1.0, "radius": 7e6}, 'kind = "circular"\nmu = -1.0\nradius = 7e6'),
    ({"mu": 4e14, "radius": 0.0}, 'kind = "circular"\nmu = 4e14\nradius = 0.0'),
    ({"mu": 1.0, "a": 1.0, "e": 1.2}, 'kind = "elliptic"\nmu = 1.0\nsemi_major_axis = 1.0\n'
                                      'eccentricity = 1.2'),
    ({"mu": 1.0, "a": 0.0, "e": 0.1}, 'kind = "elliptic"\nmu = 1.0\nsemi_major_axis = 0.0\n'
                                      'eccentricity = 0.1'),
]


@pytest.mark.parametrize("keywords,orbit", BAD)
def test_bad_orbits_are_refused_with_the_library_message(tmp_path, keywords, orbit):
    body = newtop.Body.from_principal([1200.0, 1500.0, 900.0])
    make = newtop.OrbitModel.elliptic if "e" in keywords else newtop.OrbitModel.circular
    with pytest.raises(newtop.InputError) as e:
        make(body, **keywords)
    path = tmp_path / "bad.toml"
    path.write_text(scenario_text(orbit))
    p = program("simulate", str(path), ok=False)
    assert p.returncode == 2 and str(e.value) in p.stderr, (str(e.value), p.stderr)


def test_bad_states_methods_and_times_are_refused(tmp_path):
    body = newtop.Body.from_principal([1200.0, 1500.0, 900.0])
    model = newtop.OrbitModel.circular(body, mu=3.986004418e14, radius=7.078137e6)
    with pytest.raises(newtop.InputError, match="gamma"):
        newtop.OrbitState([0, 0, 0], [0, 0.6, 0.9], [1, 0, 0])
    with pytest.raises(newtop.InputError, match="normal"):
        newtop.OrbitState([0, 0, 0], [0, 0.6, 0.8], [0, 1, 0])
    x0 = newtop.OrbitState.from_lvlh(model, roll_pitch_yaw=[0, 0.1, 0])
    with pytest.raises(newtop.InputError) as e:
        newtop.integrate(model, x0, 100.0, method="rk4", step=1.0)
    path = tmp_path / "s.toml"
    path.write_text(scenario_text('kind = "circular"\nmu = 3.986004418e14\nradius = 7.078137e6'))
    p = program("simulate", str(path), "--method", "rk4", "--step", "1", ok=False)
    assert p.returncode == 2 and str(e.value) in p.stderr, (str(e.value), p.stderr)
    with pytest.raises(newtop.InputError, match="t_end"):
        newtop.integrate(model, x0, -1.0, step=1.0)
    with pytest.raises(newtop.InputError):
        newtop.integrate(model, x0, 100.0, step=1.0, t_eval=[50.0, 10.0])
    with pytest.raises(newtop.InputError, match="step, tol"):
        newtop.integrate(model, x0, 100.0)
    sc = newtop.load_scenario(str(path))
    with pytest.raises(newtop.InputError) as e:
        newtop.integrate(sc, method="dop853")
    p = program("simulate", str(path), "--method", "dop853", ok=False)
    assert p.returncode == 2 and str(e.value) in p.stderr


def test_parse_scenario_reads_orbits():
    text = scenario_text('kind = "circular"\nrate = 0.001')
    sc = newtop.parse_scenario(text)
    assert isinstance(sc, newtop.OrbitScenario) and sc.model.rate == 0.001
    assert isinstance(newtop.load_scenario(example("heavy_top")), newtop.Scenario)


def test_relative_equilibria_equal_the_program():
    j = json.loads(program("equilibria", example("satellite_700km"), "--json").stdout)
    eq = newtop.equilibria(newtop.load_scenario(example("satellite_700km")))
    assert isinstance(eq, newtop.RelativeEquilibria) and eq.count == j["count"] == 24
    rows = j["equilibria"]
    for key in ("gamma", "normal", "lvlh_quaternion", "roll_pitch_yaw"):
        assert np.array_equal(getattr(eq, key), [r[key] for r in rows]), key
    for key in ("jacobi", "residual", "max_real_part"):
        assert np.array_equal(getattr(eq, key), [r[key] for r in rows]), key
    assert np.array_equal(eq.eigenvalues, [[complex(*z) for z in r["eigenvalues"]] for r in rows])
    assert list(eq.linearly_stable) == [r["linearly_stable"] for r in rows]
    assert eq.lyapunov_stable == [r["lyapunov_stable"] for r in rows]
    assert eq.verdict == [r["verdict"] for r in rows]
    assert (eq.lyapunov, eq.gyroscopic, eq.unstable) == (j["lyapunov"], j["gyroscopic"],
                                                         j["unstable"])


@pytest.mark.parametrize("k", [1, 7, 24])
def test_stability_of_an_equilibrium_equals_the_program(k):
    path = example("satellite_700km")
    j = json.loads(program("stability", path, "--equilibrium", str(k), "--json").stdout)
    st = newtop.stability(newtop.load_scenario(path), equilibrium=k)
    assert isinstance(st, newtop.RelativeStability)
    assert np.array_equal(st.eigenvalues, [complex(*z) for z in j["eigenvalues"]])
    assert np.array_equal(st.characteristic_polynomial, j["characteristic_polynomial"])
    for key in ("omega", "gamma", "normal"):
        assert np.array_equal(getattr(st, key), j[key]), key
    for key in ("jacobi", "residual", "max_real_part", "linearly_stable", "lyapunov_stable",
                "verdict"):
        assert getattr(st, key) == j[key], key
    with pytest.raises(newtop.InputError, match=r"equilibrium: expected 1 to 24 \(.*\), found 25"):
        newtop.stability(newtop.load_scenario(path), equilibrium=25)


def test_stability_of_the_initial_state_equals_the_program():
    path = example("orbit_leo_lagrange_rest")
    j = json.loads(program("stability", path, "--json").stdout)
    st = newtop.stability(newtop.load_scenario(path))
    assert np.array_equal(st.eigenvalues, [complex(*z) for z in j["eigenvalues"]])
    assert st.verdict == j["verdict"]
    with pytest.raises(newtop.InputError, match="relative equilibrium"):
        newtop.stability(newtop.load_scenario(example("satellite_700km")))


def test_debra_delp_equals_the_program():
    j = json.loads(program("stability", "--diagram", "debra-delp", "--scan",
                           "k_R=-0.9:0.9:7,k_Y=-0.95:0.95:9", "--json").stdout)
    d = newtop.debra_delp(k_R=(-0.9, 0.9, 7), k_Y=(-0.95, 0.95, 9))
    assert isinstance(d, newtop.DebraDelpDiagram) and len(d) == len(j["points"]) == 63
    for key in ("k_R", "k_Y", "max_real_part"):
        assert np.array_equal(getattr(d, key), [p[key] for p in j["points"]]), key
    for key in ("region", "closed_form"):
        assert getattr(d, key) == [p[key] for p in j["points"]], key
    assert list(d.boundary) == [p["boundary"] for p in j["points"]]
    assert d.counts == j["counts"]
    assert d.disagreements_with_closed_form == j["disagreements_with_closed_form"]
    with pytest.raises(newtop.InputError, match="k_R"):
        newtop.debra_delp(k_R=(-1.5, 0.5, 3))


def test_the_docs_section_runs(monkeypatch):
    """The code of docs/python.md's section "Satellites on an orbit" runs as written."""
    import re

    root = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
    text = open(os.path.join(root, "docs", "python.md"), encoding="utf-8").read()
    body = text.split("## Satellites on an orbit\n", 1)[1].split("\n## ", 1)[0]
    blocks = re.findall(r"```python\n(.*?)```", body, re.S)
    assert blocks
    monkeypatch.chdir(root)
    for code in blocks:
        namespace = {}
        exec(compile(code, "docs/python.md", "exec"), namespace)
        assert namespace["eq"].count == 24 and namespace["ell"]["t"].shape == (3,)
        assert namespace["run"]["roll_pitch_yaw"].shape == (601, 3)


def test_analyses_of_the_fixed_point_model_only_say_so_on_an_orbit():
    # section and chaos have orbit forms (test_native_files.py); analytic, rotations,
    # find_integrals and field are of the fixed-point model alone.
    sc = newtop.load_scenario(example("satellite_700km"))
    for f in (newtop.analytic, newtop.rotations, newtop.find_integrals):
        with pytest.raises(TypeError, match="has no orbit form"):
            f(sc)


def test_taylor_runs_on_an_orbit_and_agrees_with_rkf78():
    # Taylor's method on the orbit (docs/orbit.md §5) against Fehlberg 7(8), both near round-off:
    # the two final states agree to the runs' errors (1e-10 of the O(1) numbers after 3000 s).
    body = newtop.Body.from_principal([1200.0, 1500.0, 900.0])
    model = newtop.OrbitModel.circular(body, mu=3.986004418e14, radius=7.078137e6)
    x0 = newtop.OrbitState.from_lvlh(model, roll_pitch_yaw=[0.2, 0.1, -0.3])
    a = newtop.integrate(model, x0, 3000.0, method="taylor", tol=1e-13)
    b = newtop.integrate(model, x0, 3000.0, method="rkf78", tol=1e-13)
    assert a["outcome"] == "finished" and a["method"] == "taylor" and a["tol"] == 1e-13
    assert a["steps"] < b["steps"]
    for key in ("gamma", "normal"):
        assert np.max(np.abs(a[key][-1] - b[key][-1])) < 1e-10, key
    scale = np.max(np.abs(b["m"][-1]))
    assert np.max(np.abs(a["m"][-1] - b["m"][-1])) < 1e-10 * scale
