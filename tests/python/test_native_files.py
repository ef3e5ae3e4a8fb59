"""The analyses on a scenario file: given a path, or a Scenario read from one, every function in
newtop's namespace runs the library natively and returns the typed result, the numbers of the
program's JSON on the same file bit for bit; the orbit's section and chaos likewise; command-line
options with no native form are refused by name, never ignored.

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


def example(name):
    return os.path.join(EXAMPLES, name)


def program_json(*words, ok=(0,)):
    p = subprocess.run([EXE, *words, "--json", "--quiet"], capture_output=True, text=True)
    assert p.returncode in ok, p.stderr
    return json.loads(p.stdout)


def both(path):
    """The path itself and the Scenario the library reads from it."""
    return [path, newtop.load_scenario(path)]


def pairs(rows):
    """[[re, im], ...] of the JSON as a complex array."""
    return np.array([complex(r[0], r[1]) for r in rows])


@pytest.mark.parametrize("form", ["path", "scenario"])
def test_equilibria_of_a_file(form):
    path = example("heavy_top.toml")
    eq = newtop.equilibria(both(path)[form == "scenario"])
    j = program_json("equilibria", path)
    assert isinstance(eq, newtop.Equilibria) and eq.count == j["count"] > 0
    assert np.array_equal(eq.gamma, [e["gamma"] for e in j["equilibria"]])
    assert np.array_equal(eq.potential, [e["potential"] for e in j["equilibria"]])
    assert eq.type == [e["type"] for e in j["equilibria"]]


@pytest.mark.parametrize("form", ["path", "scenario"])
def test_stability_of_a_file(form):
    path = example("stability_beletsky.toml")
    obj = both(path)[form == "scenario"]
    for r, j in ((newtop.stability(obj), program_json("stability", path)),
                 (newtop.stability(obj, axis="z", omega=1.3),
                  program_json("stability", path, "--axis", "z", "--omega", "1.3"))):
        assert isinstance(r, newtop.StabilityReport)
        assert np.array_equal(r.eigenvalues, pairs(j["eigenvalues"]))
        assert r.max_real_part == j["max_real_part"]
        assert r.linearly_stable == j["linearly_stable"]


@pytest.mark.parametrize("form", ["path", "scenario"])
def test_chaos_of_a_file_with_the_command_line_overrides(form):
    path = example("brun.toml")
    c = newtop.chaos(both(path)[form == "scenario"], t_end=50.0, step=0.01, spectrum=True)
    j = program_json("chaos", path, "--t-end", "50", "--step", "0.01", "--spectrum")
    assert isinstance(c, newtop.ChaosResult)
    assert (c.lyapunov_max, c.megno, c.fli, c.outcome, c.method) == (
        j["lyapunov_max"], j["megno"], j["fli"], j["outcome"], j["method"])
    assert np.array_equal(c.spectrum, j["spectrum"])
    # another split, as --split
    c = newtop.chaos(path, t_end=20.0, step=0.01, split="spin")
    j = program_json("chaos", path, "--t-end", "20", "--step", "0.01", "--split", "spin")
    assert c.megno == j["megno"] and c.lyapunov_max == j["lyapunov_max"]


def crossings_equal(s, j):
    assert s.count == j["count"]
    assert np.array_equal(s.t, [c["t"] for c in j["crossings"]])
    assert np.array_equal(s.gamma.reshape(-1, 3), np.reshape([c["gamma"] for c in j["crossings"]],
                                                            (-1, 3)))
    assert np.array_equal(s.omega.reshape(-1, 3), np.reshape([c["omega"] for c in j["crossings"]],
                                                            (-1, 3)))
    assert s.stopped_by == j["stopped_by"]
    assert s.max_surface_residual == j["max_surface_residual"]


@pytest.mark.parametrize("form", ["path", "scenario"])
def test_section_of_a_file(form):
    path = example("brun.toml")
    obj = both(path)[form == "scenario"]
    s = newtop.section(obj, surface="gamma1 = 0", crossings=40, t_end=500.0, step=0.01)
    j = program_json("section", path, "--surface", "gamma1 = 0", "--crossings", "40",
                     "--t-end", "500", "--step", "0.01")
    assert isinstance(s, newtop.Section) and s.count > 0
    crossings_equal(s, j)


def test_section_without_t_end_stops_at_its_crossings_and_seeds_orbits(tmp_path):
    # A scenario with no t_end: each orbit runs until its crossings (at most max_steps steps).
    text = open(example("brun.toml")).read()
    sc = newtop.parse_scenario(text)
    sc.t_end = None
    path = tmp_path / "no_t_end.toml"
    lines = [ln for ln in text.splitlines() if not ln.strip().startswith("t_end")]
    path.write_text("\n".join(lines) + "\n")
    s = newtop.section(str(path), surface="gamma3 = 0", crossings=25, step=0.01)
    j = program_json("section", str(path), "--surface", "gamma3 = 0", "--crossings", "25",
                     "--step", "0.01")
    assert s.count == 25 and s.stopped_by == "crossings"
    crossings_equal(s, j)
    s = newtop.section(str(path), surface="gamma3 = 0", crossings=5, step=0.01, orbits=4)
    j = program_json("section", str(path), "--surface", "gamma3 = 0", "--crossings", "5",
                     "--step", "0.01", "--orbits", "4")
    assert np.array_equal(s.orbit, [c["orbit"] for c in j["crossings"]]) and s.count > 5
    crossings_equal(s, j)


@pytest.mark.parametrize("form", ["path", "scenario"])
def test_analytic_rotations_find_integrals_of_a_file(form):
    path = example("heavy_top.toml")
    obj = both(path)[form == "scenario"]
    a = newtop.analytic(obj, samples=4, t_end=2.0)
    j = program_json("analytic", path, "--samples", "4", "--t-end", "2")
    assert a.case == j["case"]
    assert np.array_equal(a.t, [x["t"] for x in j["samples"]])
    assert np.array_equal(a.gamma, [x["analytic"]["gamma"] for x in j["samples"]])
    assert a.max_abs_error == j["max_abs_error"]
    r = newtop.rotations(obj, samples=60)
    j = program_json("rotations", path, "--samples", "60")
    assert r.any_axis_omega == j["any_axis_omega"] and len(r.cone_gamma) == j["cone_samples"]
    f = newtop.find_integrals(obj, degree=2)
    j = program_json("find-integrals", path, "--degree", "2")
    assert f.rank == j["rank"] and np.array_equal(f.singular_values, j["singular_values"])


def test_field_of_a_path_takes_the_scan_as_written():
    path = example("exact_box_multipole.toml")
    f = newtop.field(path, [0.3, 0.4, 1.0], scan_R="10:40:6")
    j = program_json("field", path, "--gamma", "0.3,0.4,1", "--scan-R", "10:40:6")
    assert f["exact"]["potential"] == j["exact"]["potential"]
    assert np.array_equal(f["scan"]["moment_error"], j["scan"]["moment_error"])


def test_orbit_section_equals_the_program():
    for name, extra in (("orbit_leo_lagrange.toml", ["--t-end", "20000"]),
                        ("orbit_elliptic_pitch.toml", ["--t-end", "60"])):
        path = example(name)
        kw = {"t_end": float(extra[1])}
        s = newtop.section(path, surface="gamma2 = 0", crossings=30, direction="both", **kw)
        j = program_json("section", path, "--surface", "gamma2 = 0", "--crossings", "30",
                         "--direction", "both", *extra, ok=(0, 3))
        assert isinstance(s, newtop.OrbitSection) and s.count == j["count"] > 0, name
        c = j["crossings"]
        assert np.array_equal(s.t, [x["t"] for x in c])
        assert np.array_equal(s.gamma, [x["gamma"] for x in c])
        assert np.array_equal(s.normal, [x["normal"] for x in c])
        assert np.array_equal(s.omega, [x["omega"] for x in c])
        assert np.array_equal(s.euler_321, [x["coords"]["euler_321"] for x in c])
        assert np.array_equal(s.omega_relative, [x["coords"]["omega_relative"] for x in c])
        assert np.array_equal(s.roll_pitch_yaw, [x["coords"]["roll_pitch_yaw"] for x in c])
        assert np.array_equal(s.lvlh_quaternion, [x["coords"]["lvlh_quaternion"] for x in c])
        if s.nu is not None:
            assert np.array_equal(s.nu, [x["nu"] for x in c])
        assert (s.stopped_by, s.outcome, s.method, s.orbit) == (
            j["stopped_by"], j["outcome"], j["method"], j["orbit"])
        assert s.max_surface_residual == j["max_surface_residual"]
        assert s.integrals_drift == j["integrals_drift"]


def test_orbit_chaos_equals_the_program():
    path = example("orbit_leo_lagrange.toml")
    sc = newtop.load_scenario(path)
    c = newtop.chaos(path, t_end=3000.0, tol=1e-10, spectrum=True)
    j = program_json("chaos", path, "--t-end", "3000", "--tol", "1e-10", "--spectrum")
    assert isinstance(c, newtop.OrbitChaosResult)
    assert (c.lyapunov_max, c.megno, c.fli, c.t_end, c.outcome, c.method, c.tol) == (
        j["lyapunov_max"], j["megno"], j["fli"], j["t_end"], j["outcome"], j["method"], j["tol"])
    assert np.array_equal(c.spectrum, j["spectrum"])
    # an OrbitModel and a state give the same numbers
    m = newtop.chaos(sc.model, sc.initial, 3000.0, tol=1e-10, spectrum=True)
    assert m.megno == c.megno and np.array_equal(m.spectrum, c.spectrum)
    with pytest.raises(ValueError, match="step: chaos on an orbit runs an embedded pair"):
        newtop.chaos(path, t_end=10.0, step=1.0)


def test_orbit_equilibria_and_stability_of_a_path():
    path = example("orbit_leo_lagrange.toml")
    eq = newtop.equilibria(path)
    j = program_json("equilibria", path)
    assert isinstance(eq, newtop.RelativeEquilibria) and eq.count == j["count"]
    path = example("orbit_leo_lagrange_rest.toml")  # [initial] at a relative equilibrium
    st = newtop.stability(path)
    j = program_json("stability", path)
    assert isinstance(st, newtop.RelativeStability) and st.max_real_part == j["max_real_part"]


def test_debra_delp_diagram_as_stability_diagram():
    d = newtop.stability(diagram="debra-delp", scan="k_R=-0.9:0.9:5,k_Y=-0.9:0.9:4")
    p = subprocess.run([EXE, "stability", "--diagram", "debra-delp", "--scan",
                        "k_R=-0.9:0.9:5,k_Y=-0.9:0.9:4", "--json"], capture_output=True,
                       text=True)
    assert p.returncode == 0, p.stderr
    j = json.loads(p.stdout)
    assert isinstance(d, newtop.DebraDelpDiagram)
    assert d.counts == j["counts"]
    assert np.array_equal(d.max_real_part, [x["max_real_part"] for x in j["points"]])


def test_a_sweep_file_runs_natively():
    path = example("sweep_megno.toml")
    r = newtop.sweep(path, threads=2)
    j = program_json("sweep", path)
    assert r["points"] == j["points"] and r["failed"] == j["failed"]
    for key in r["results"]:
        if key != "status":
            assert np.array_equal(r["results"][key], j["results"][key], equal_nan=True), key
    with pytest.raises(TypeError, match="'quantities'"):
        newtop.sweep(path, quantities=["megno"])


@pytest.mark.parametrize("call, option", [
    (lambda p: newtop.chaos(p, out="h.csv"), "out"),
    (lambda p: newtop.section(p, out="s.csv"), "out"),
    (lambda p: newtop.stability(p, scan_omega="0:3:61"), "scan_omega"),
    (lambda p: newtop.rotations(p, out="cone.csv"), "out"),
    (lambda p: newtop.analytic(p, dense=100), "dense"),
    (lambda p: newtop.find_integrals(p, potential="v.toml"), "potential"),
    (lambda p: newtop.equilibria(p, json=True), "json"),
])
def test_options_without_a_native_form_are_refused_by_name(call, option):
    with pytest.raises(TypeError, match="'%s'" % option):
        call(example("heavy_top.toml"))


def solutions_equal(sol, js):
    assert np.array_equal(sol["theta0"], [x["theta0"] for x in js])
    assert np.array_equal(sol["dtheta0"], [x["dtheta0"] for x in js])
    assert np.array_equal(sol["spin0"], [x["spin0"] for x in js])
    assert np.array_equal(sol["multipliers"].reshape(-1, 2),
                          np.reshape([pairs(x["multipliers"]) for x in js], (-1, 2)))
    assert np.array_equal(sol["trace"], [x["trace"] for x in js])
    assert sol["stability"] == [x["stability"] for x in js]
    for key in ("residual", "max_deviation", "symmetry_distance"):
        assert np.array_equal(sol[key], [x[key] for x in js]), key
    assert sol["symmetric"].tolist() == [x["symmetric"] for x in js]


@pytest.mark.parametrize("name", ["orbit_spin_orbit.toml", "libration_asymmetric.toml"])
def test_libration_equals_the_program(tmp_path, name):
    path = example(name)
    csv = tmp_path / "lib.csv"
    r = newtop.libration(path, resonances=[(1, 1), (3, 2)], spin=(0.5, 2.5, 3), iterates=30,
                         asymmetric=True, out=csv)
    prog = tmp_path / "prog.csv"
    j = program_json("libration", path, "--resonances", "1:1,3:2", "--spin", "0.5:2.5:3",
                     "--iterates", "30", "--asymmetric", "--out", str(prog))
    assert isinstance(r, newtop.LibrationReport)
    assert (r.eccentricity, r.k, r.iterates, r.chaos_threshold, r.chaotic_starts) == (
        j["eccentricity"], j["k"], j["iterates"], j["chaos_threshold"], j["chaotic_starts"])
    assert len(r.resonances) == len(j["resonances"]) == 2
    for x, jx in zip(r.resonances, j["resonances"]):
        for key in ("resonance", "spin_ratio", "periods", "half_turns", "strength",
                    "averaged_half_width"):
            assert x[key] == jx[key], key
        solutions_equal(x["solutions"], jx["solutions"])
        solutions_equal(x["asymmetric_solutions"], jx["asymmetric_solutions"])
    for key in ("theta0", "dtheta0", "spin0", "lyapunov"):
        assert np.array_equal(getattr(r, key), [s[key] for s in j["starts"]]), key
    assert r.chaotic.tolist() == [s["chaotic"] for s in j["starts"]]
    assert len(r.points) == 4 and r.points[0].shape == (30, 2)
    assert csv.read_bytes() == prog.read_bytes()  # the program's CSV, byte for byte
    rows = np.loadtxt(csv, delimiter=",", skiprows=1)
    assert np.array_equal(rows[:30, 2:4], r.points[0])
    # the defaults, on the scenario object
    d = newtop.libration(newtop.load_scenario(path), iterates=5)
    jd = program_json("libration", path, "--iterates", "5")
    assert [x["resonance"] for x in d.resonances] == [x["resonance"] for x in jd["resonances"]]
    assert d.resonances[0]["asymmetric_solutions"] is None
    assert np.array_equal(d.lyapunov, [s["lyapunov"] for s in jd["starts"]])
    with pytest.raises(ValueError, match="iterates: expected 1 to 100000, found 0"):
        newtop.libration(path, iterates=0)
    with pytest.raises(TypeError, match="expected an orbit scenario"):
        newtop.libration(example("brun.toml"))


SIMULATE_KEYS = ("outcome", "steps", "rejected_steps", "method", "step", "tolerance", "final",
                 "integrals", "casimir_drift", "conserved", "quadratic_comparison")


@pytest.mark.parametrize("name, words", [
    ("brun.toml", ["--t-end", "3", "--step", "0.01"]),
    ("brun.toml", ["--t-end", "3", "--tol", "1e-10"]),
    ("exact_box_multipole.toml", ["--t-end", "2"]),
    ("attitude_heavy_top.toml", ["--t-end", "2", "--every", "7", "--euler", "321"]),
])
def test_simulate_natively_equals_the_program(tmp_path, name, words):
    path = example(name)
    kw = {w[2:].replace("-", "_"): (int(v) if w in ("--every", "--euler") else float(v))
          for w, v in zip(words[::2], words[1::2])}
    csv, prog = tmp_path / "run.csv", tmp_path / "prog.csv"
    r = newtop.simulate(path, out=csv, **kw)
    j = program_json("simulate", path, *words, "--out", str(prog))
    assert csv.read_bytes() == prog.read_bytes()  # the program's CSV, byte for byte
    for key in SIMULATE_KEYS:
        assert (key in r) == (key in j), key
        if key in j:
            same(r[key], j[key], key)
    assert r["t"].shape == r["trajectory"]["t"].shape and r["gamma"] is r["trajectory"]["gamma"]
    sc = newtop.load_scenario(path)  # the Scenario read from the file: the same run
    assert np.array_equal(newtop.simulate(sc, **{k: v for k, v in kw.items()
                                                 if k in ("t_end", "step", "tol")})["gamma"],
                          r["gamma"])


def same(a, b, where=""):
    """Python's value against the JSON's, bit for bit (arrays against lists, dicts by key)."""
    if isinstance(b, dict):
        assert set(a) == set(b), where
        for k in b:
            same(a[k], b[k], where + "." + k)
    elif isinstance(b, list) and b and not isinstance(b[0], str):
        assert np.array_equal(np.asarray(a, dtype=float), np.asarray(b, dtype=float)), where
    else:
        assert a == b, where


def test_integrals_natively_equal_the_program():
    for name in ("brun.toml", "heavy_top.toml", "exact_box_multipole.toml"):
        path = example(name)
        r = newtop.integrals(path)
        j = program_json("integrals", path)
        same(r["integrals"], j["integrals"], name)
        assert r["conserved"] == j["conserved"]


def test_view_natively_writes_the_programs_page(tmp_path):
    path = example("brun.toml")
    csv = tmp_path / "run.csv"
    newtop.simulate(path, t_end=5.0, out=csv)
    for scenario in (None, path, newtop.load_scenario(path)):
        page, prog = tmp_path / "page.html", tmp_path / "prog.html"
        assert newtop.view(csv, page, scenario=scenario) == page
        words = [EXE, "view", str(csv), "-o", str(prog)]
        if scenario is not None:
            words += ["--scenario", path]
        assert subprocess.run(words, capture_output=True).returncode == 0
        assert page.read_bytes() == prog.read_bytes()
    with pytest.raises(ValueError, match="max_frames"):
        newtop.view(csv, tmp_path / "x.html", max_frames=1)


def test_the_command_line_runs_the_program_as_a_process(tmp_path, monkeypatch):
    # beside the package (build/python/newtop -> build/newtop), or NEWTOP_EXECUTABLE, else a clear
    # error; the module itself has no entry point into the program.
    assert not hasattr(newtop._newtop, "_run_command_line")
    monkeypatch.delenv("NEWTOP_EXECUTABLE", raising=False)
    assert os.path.samefile(newtop.commands.executable(), EXE)
    code, out, err = newtop.commands.run(["integrals", example("brun.toml"), "--json"])
    assert code == 0 and json.loads(out)["conserved"] == newtop.integrals(
        example("brun.toml"))["conserved"]
    assert newtop.commands.run(["integrals", str(tmp_path / "none.toml")])[0] == 2
    with pytest.raises(ValueError, match="none.toml"):
        newtop.commands.integrals(str(tmp_path / "none.toml"))
    monkeypatch.setenv("NEWTOP_EXECUTABLE", str(tmp_path / "no_such_program"))
    with pytest.raises(FileNotFoundError, match="NEWTOP_EXECUTABLE"):
        newtop.commands.run(["integrals", example("brun.toml")])
    monkeypatch.setenv("NEWTOP_EXECUTABLE", EXE)
    assert newtop.commands.equilibria(example("heavy_top.toml"))["count"] == newtop.equilibria(
        example("heavy_top.toml")).count
