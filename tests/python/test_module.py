"""The compiled module newtop._newtop and the per-subcommand functions: the same numbers, bit for
bit, as the newtop program (its JSON and CSV), numpy arrays of the documented shapes viewing one
buffer, and bad input raised as ValueError with the program's message.

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

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
EXAMPLES = os.path.join(ROOT, "examples")
EXE = os.environ["NEWTOP_EXE"]


def example(name):
    return os.path.join(EXAMPLES, name)


def program(*words):
    p = subprocess.run([EXE, *words], capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def program_json(*words):
    code, out, err = program(*words, "--json")
    assert code == 0, err
    return json.loads(out)


# Measurements, not results: they differ from run to run (docs/cli.md).
MEASURED = {"seconds_per_sample"}


def same(python_value, json_value):
    """Equal to the bit: numpy arrays against JSON lists, dicts key by key (measured times aside)."""
    if isinstance(json_value, dict):
        assert set(python_value) >= set(json_value)
        for k, v in json_value.items():
            if k not in MEASURED:
                same(python_value[k], v)
    elif isinstance(json_value, list):
        assert len(python_value) == len(json_value)
        for a, b in zip(python_value, json_value):
            same(a, b)
    elif isinstance(json_value, float):
        assert float(python_value) == json_value or (np.isnan(python_value) and np.isnan(json_value))
    else:
        assert python_value == json_value


def test_extension_is_loaded():
    assert newtop.HAVE_EXTENSION


@pytest.mark.parametrize("name", ["integrals", "equilibria", "rotations", "analytic"])
@pytest.mark.parametrize("scenario", ["brun.toml", "heavy_top.toml", "exact_box_multipole.toml"])
def test_commands_give_the_programs_json(name, scenario):
    if name == "analytic" and scenario != "brun.toml":
        pytest.skip("analytic needs an integrable case")
    result = getattr(newtop.commands, name)(example(scenario))  # the command line from Python
    same(result, program_json(name, example(scenario)))


def test_simulate_json_and_trajectory_match_the_program_bit_for_bit(tmp_path):
    csv = tmp_path / "run.csv"
    result = newtop.commands.simulate(example("brun.toml"), t_end=3.0, step=0.01, out=str(csv))
    cli = program_json("simulate", example("brun.toml"), "--t-end", "3", "--step", "0.01",
                       "--out", str(tmp_path / "cli.csv"))
    assert (tmp_path / "cli.csv").read_text() == csv.read_text()
    paths = [k for k, v in cli.items() if v == str(tmp_path / "cli.csv")]
    assert len(paths) == 1 and result[paths[0]] == str(csv)  # the one key that differs
    same({k: v for k, v in result.items() if k not in ["trajectory", *paths]},
         {k: v for k, v in cli.items() if k not in paths})
    header = csv.read_text().splitlines()[0].split(",")
    table = np.loadtxt(csv, delimiter=",", skiprows=1)
    tr = result["trajectory"]
    assert tr["t"].shape == (table.shape[0],)
    assert np.array_equal(tr["t"], table[:, header.index("t")])
    assert np.array_equal(tr["omega"], table[:, [header.index(c) for c in ("p", "q", "r")]])
    assert np.array_equal(tr["gamma"],
                          table[:, [header.index("gamma%d" % i) for i in (1, 2, 3)]])
    for name in ("energy", "area", "geometric", "brun"):
        assert np.array_equal(tr[name], table[:, header.index(name)]), name
    assert np.array_equal(tr["m"][-1], result["final"]["m"])
    for name in ("t", "omega", "gamma", "m", "energy", "area", "geometric", "brun"):
        assert result[name] is tr[name], name  # the same arrays at the top level
    assert tr["outcome"] == result["outcome"]


def test_integrate_gives_arrays_of_one_buffer():
    body = newtop.Body.from_principal([1.0, 2.0, 2.5], 1.0, [0.0, 0.0, 0.1])
    model = newtop.Model(body, newtop.QuadraticField.from_mu_R(1.0, 2.0))
    x0 = newtop.State.from_omega(body, [0.1, 0.2, 0.3], [0.0, 0.6, 0.8])
    r = newtop.integrate(model, x0, 10.0, step=0.01)
    n = 1001  # t0 and the 1000 steps
    assert r["t"].shape == (n,) and r["t"].dtype == np.float64
    for k in ("omega", "gamma", "m"):
        assert r[k].shape == (n, 3) and r[k].dtype == np.float64
    for k in ("energy", "area", "geometric"):
        assert r[k].shape == (n,)
    assert "brun" not in r and "lagrange" not in r  # neither holds for this body
    table = r["table"]
    assert table.shape == (n, 13) and table.flags.c_contiguous
    for k in ("t", "omega", "gamma", "m", "energy", "area", "geometric"):
        assert r[k].base is table, k  # views, not copies
    assert r["t"][-1] == 10.0 and r["outcome"] == "finished" and r["steps"] == 1000
    # the library's integrals at the last state, and omega = I^-1 m
    last = newtop.State(r["m"][-1], r["gamma"][-1])
    assert newtop.integrals_at(model, last)["energy"] == r["energy"][-1]
    assert np.array_equal(last.omega(body), r["omega"][-1])


def test_model_functions_against_the_formulas_of_spec_section_3():
    inertia, r0, mass = np.array([1.0, 2.0, 2.5]), np.array([0.3, -0.2, 0.1]), 2.0
    body = newtop.Body.from_principal(inertia, mass, r0)
    f = newtop.QuadraticField.from_mu_R(3.0, 2.0)
    model = newtop.Model(body, f)
    assert f.g == 3.0 / 4.0 and f.lambda_ == 9.0 / 8.0
    gamma = np.array([0.48, 0.6, 0.64])
    v = mass * f.g * r0 @ gamma + 0.5 * f.lambda_ * gamma @ (inertia * gamma)
    grad = mass * f.g * r0 + f.lambda_ * inertia * gamma
    assert model.potential(gamma) == pytest.approx(v, rel=4e-16)
    assert np.allclose(model.grad_gamma(gamma), grad, rtol=4e-16, atol=0)
    assert np.allclose(model.hessian_gamma(gamma), f.lambda_ * np.diag(inertia), rtol=0, atol=0)
    assert np.allclose(model.moment(gamma), np.cross(gamma, grad), rtol=1e-15, atol=1e-16)


def test_scenario_loads_into_the_same_objects():
    sc = newtop.load_scenario(example("exact_box_multipole.toml"))
    assert sc.model.kind in ("exact", "multipole")
    r = newtop.integrate(sc, t_end=0.5)
    cli = program_json("simulate", example("exact_box_multipole.toml"), "--t-end", "0.5")
    assert np.array_equal(r["m"][-1], cli["final"]["m"])
    assert np.array_equal(r["gamma"][-1], cli["final"]["gamma"])


BAD = {
    "malformed.toml": "[body\ninertia = [1, 2, 3]\n",
    "unknown.toml": "[body]\ninertia = [1, 2, 2.5]\nmass = 1\ncolour = 3\n",
    "nonphysical.toml": "[body]\ninertia = [1, 2, 4.5]\nmass = 1\n",
    "nan.toml": "[body]\ninertia = [1, 2, 2.5]\nmass = nan\n",
    "length.toml": "[body]\ninertia = [1, 2]\nmass = 1\n",
}


@pytest.mark.parametrize("name", sorted(BAD))
def test_bad_input_raises_value_error_with_the_programs_message(tmp_path, name):
    path = tmp_path / name
    path.write_text(BAD[name])
    code, _, err = program("integrals", str(path), "--json")
    assert code == 2
    message = err.strip().removeprefix("newtop: error: ")
    for integrals in (newtop.integrals, newtop.commands.integrals):  # native, the command line
        with pytest.raises(ValueError) as e:
            integrals(str(path))
        assert str(e.value) == message
    with pytest.raises(ValueError) as e:
        newtop.load_scenario(str(path))
    assert str(e.value) == message


def test_bad_options_raise_value_error():
    for simulate in (newtop.simulate, newtop.commands.simulate):
        with pytest.raises(ValueError, match="step"):
            simulate(example("brun.toml"), step=-1.0)
        with pytest.raises(ValueError, match="t_end"):
            simulate(example("brun.toml"), t_end=float("inf"))
    with pytest.raises(ValueError, match="inertia"):
        newtop.Body.from_principal([1.0, 2.0, 4.5], 1.0)
    body = newtop.Body.from_principal([1.0, 2.0, 2.5], 1.0)
    model = newtop.Model(body, newtop.QuadraticField.uniform(1.0))
    x0 = newtop.State([0.1, 0.2, 0.3], [0.0, 0.0, 1.0])
    with pytest.raises(ValueError, match="method"):
        newtop.integrate(model, x0, 1.0, method="euler", step=0.1)
    with pytest.raises(ValueError, match="step, tol"):
        newtop.integrate(model, x0, 1.0)


def test_every_snippet_of_docs_python_md_runs(tmp_path, monkeypatch):
    text = open(os.path.join(ROOT, "docs", "python.md")).read()
    snippets = [block.split("```", 1)[0] for block in text.split("```python\n")[1:]]
    assert len(snippets) >= 2
    os.symlink(EXAMPLES, tmp_path / "examples")
    monkeypatch.chdir(tmp_path)
    namespace = {}  # the snippets follow one another, as in a session
    for code in snippets:
        exec(compile(code, "docs/python.md", "exec"), namespace)
    assert (tmp_path / "run.html").stat().st_size > 0
    for picture in ("heavy_top.png", "beletsky.png"):  # the tutorial's figures
        assert (tmp_path / picture).stat().st_size > 10_000, picture


def test_sweep_gives_one_array_per_column():
    r = newtop.commands.sweep(example("sweep_beletsky.toml"), quiet=True)
    cli = program_json("sweep", example("sweep_beletsky.toml"), "--quiet")
    same(r, cli)
    native = newtop.sweep(example("sweep_beletsky.toml"))  # the sweep file natively
    for key, column in native["results"].items():  # NaN where the JSON has null
        same(column, [np.nan if v is None else v for v in cli["results"][key]])
    assert r["results"]["linearly_stable"].shape == (124,)
    assert set(r["results"]["linearly_stable"]) == {0.0, 1.0}


def test_mass_models_from_python_are_the_scenarios():
    box = newtop.MassModel.box([1.0, 2.0, 3.0], 100.0, [0.2, 0.1, 1.0])
    model = newtop.Model.multipole(box, 5, 50.0, 8.0)  # examples/exact_box_multipole.toml
    sc = newtop.load_scenario(example("exact_box_multipole.toml"))
    assert model.kind == sc.model.kind == "multipole"
    for gamma in ([0.0, 0.6, 0.8], [0.48, 0.6, 0.64], [1.0, 0.0, 0.0]):
        assert model.potential(gamma) == sc.model.potential(gamma)
        assert np.array_equal(model.moment(gamma), sc.model.moment(gamma))
    assert np.array_equal(model.body.inertia, sc.model.body.inertia)


def test_mass_properties_against_closed_forms():
    a, b, c, rho = 1.0, 2.0, 3.0, 7.0
    e = newtop.MassModel.ellipsoid([a, b, c], rho)
    mass = 4.0 / 3.0 * np.pi * a * b * c * rho
    assert e.kind == "ellipsoid" and e.mass == pytest.approx(mass, rel=4e-16)
    expected = mass / 5.0 * np.diag([b * b + c * c, a * a + c * c, a * a + b * b])
    assert np.allclose(e.inertia_tensor, expected, rtol=1e-15, atol=0)
    p = newtop.MassModel.point_masses([1.0, 3.0], [[0.0, 0.0, 1.0], [2.0, 0.0, 0.0]])
    assert p.kind == "points" and p.mass == 4.0
    assert np.array_equal(p.center_of_mass, [1.5, 0.0, 0.25])
    assert p.max_radius == 2.0
    # The exact field of point masses (docs/model.md §2): V(gamma) = -mu sum m_i / |R gamma + rho_i|,
    # rho_i in the body's principal axes (P^T rho in the user's frame), summed here independently.
    masses = [1.0, 2.0, 1.5]
    rho = np.array([[1.0, 0.0, 0.0], [0.0, -0.5, 0.3], [0.2, 0.4, -0.7]])
    mu, R = 3.0, 5.0
    exact = newtop.Model.exact(newtop.MassModel.point_masses(masses, rho), mu, R)
    P = exact.body.principal_axes
    for gamma in (np.array([0.48, 0.6, 0.64]), np.array([1.0, 0.0, 0.0])):
        v = -mu * sum(m / np.linalg.norm(R * gamma + P.T @ r) for m, r in zip(masses, rho))
        assert exact.potential(gamma) == pytest.approx(v, rel=1e-15)


def test_bad_mass_models_raise_value_error():
    with pytest.raises(ValueError, match="density"):
        newtop.MassModel.box([1.0, 2.0, 3.0], -1.0)
    with pytest.raises(ValueError, match="points"):
        newtop.MassModel.point_masses([1.0, -1.0], [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]])
    with pytest.raises(ValueError, match="mesh"):
        newtop.MassModel.polyhedron([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
                                    [[0, 1, 2]], 1.0)  # one triangle: not closed
    with pytest.raises(ValueError):
        newtop.MassModel.polyhedron_file(os.path.join(EXAMPLES, "no_such_mesh.off"), 1.0)


def test_section_and_chaos_give_the_programs_json():
    brun = example("section_brun.toml")
    r = newtop.commands.section(brun, surface="gamma3 = 0", crossings=20)
    same(r, program_json("section", brun, "--surface", "gamma3 = 0", "--crossings", "20"))
    assert r["count"] == len(r["crossings"]) == 20
    assert r["crossings"][0]["gamma"].shape == (3,)
    c = newtop.commands.chaos(brun, t_end=100.0)
    same(c, program_json("chaos", brun, "--t-end", "100"))
    for section in (newtop.section, newtop.commands.section):
        with pytest.raises(ValueError, match="surface"):
            section(brun, surface="gamma4 = 0")


def test_simulate_with_an_attitude_gives_the_programs_quaternion_columns(tmp_path):
    csv = tmp_path / "run.csv"
    scenario = example("attitude_heavy_top.toml")
    result = newtop.commands.simulate(scenario, t_end=2.0, out=str(csv))
    header = csv.read_text().splitlines()[0].split(",")
    table = np.loadtxt(csv, delimiter=",", skiprows=1)
    q = result["quaternion"]
    assert q.shape == (table.shape[0], 4)
    assert q is result["trajectory"]["quaternion"]
    assert np.array_equal(q, table[:, [header.index("q%d" % i) for i in range(4)]])
    assert np.array_equal(q[-1], result["final"]["quaternion"])
    sc = newtop.load_scenario(scenario)
    assert np.array_equal(q[0], sc.attitude)
    # the same run from a model, a state and the quaternion
    direct = newtop.integrate(sc.model, sc.initial, 2.0, step=sc.step, method=sc.method,
                              quaternion=sc.attitude)
    assert np.array_equal(direct["quaternion"], q)
    assert "quaternion" not in newtop.integrate(sc.model, sc.initial, 2.0, step=0.01)
    with pytest.raises(ValueError, match="quaternion: expected a finite unit quaternion"):
        newtop.integrate(sc.model, sc.initial, 1.0, step=0.01, quaternion=[1.0, 0.1, 0, 0])


def test_integrate_takes_the_split_of_the_command_line():
    sc = newtop.load_scenario(example("brun.toml"))
    run = newtop.integrate(sc, t_end=3.0, split="spin")
    cli = program_json("simulate", example("brun.toml"), "--t-end", "3", "--split", "spin")
    assert cli["split"] == "spin"
    assert run["gamma"][-1].tolist() == cli["final"]["gamma"]  # the same run, bit for bit
    assert run["gamma"][-1].tolist() != newtop.integrate(sc, t_end=3.0)["gamma"][-1].tolist()
    with pytest.raises(ValueError, match="split"):
        newtop.integrate(sc, t_end=1.0, tol=1e-9, split="spin")


def test_integrate_runs_dop853_as_the_command_line_does():
    sc = newtop.load_scenario(example("brun.toml"))
    run = newtop.integrate(sc, t_end=3.0, method="dop853", tol=1e-11)
    cli = program_json("simulate", example("brun.toml"), "--t-end", "3", "--method", "dop853",
                       "--tol", "1e-11")
    assert run["method"] == cli["method"] == "dop853"
    assert run["gamma"][-1].tolist() == cli["final"]["gamma"]  # the same run, bit for bit
    # against Fehlberg 7(8) at 1e-13: both within 1e-9 of the motion over t = 3
    ref = newtop.integrate(sc, t_end=3.0, method="rkf78", tol=1e-13)
    assert np.max(np.abs(run["gamma"][-1] - ref["gamma"][-1])) < 1e-9


def test_integrate_runs_taylor_as_the_command_line_does():
    sc = newtop.load_scenario(example("brun.toml"))
    run = newtop.integrate(sc, t_end=3.0, tol=1e-11)  # the default with a tolerance here
    cli = program_json("simulate", example("brun.toml"), "--t-end", "3", "--tol", "1e-11")
    assert run["method"] == cli["method"] == "taylor"
    assert run["gamma"][-1].tolist() == cli["final"]["gamma"]  # the same run, bit for bit
    ref = newtop.integrate(sc, t_end=3.0, method="rkf78", tol=1e-13)
    assert np.max(np.abs(run["gamma"][-1] - ref["gamma"][-1])) < 1e-9
