"""The analyses on Python objects (newtop.analyses): a body, a field and a state built in code give
the same numbers, bit for bit, as the newtop program on the equivalent scenario file — equilibria,
the stability of equilibrium 1, a Poincaré section of 200 crossings, MEGNO and lambda_max, and the
analytic solution of a heavy top at 5 times — without the Python side writing a file; the library's
check of gamma, integrate's t_eval and model.rhs as an array.

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

INERTIA = [1.0, 1.5, 2.2]
R0 = [0.1, 0.05, 0.2]
G, LAMBDA = 1.0, 0.7
OMEGA0 = [0.3, -0.2, 0.9]
GAMMA0 = [0.0, 0.6, 0.8]


def body_field_state():
    body = newtop.Body.from_principal(INERTIA, mass=1.0, center_of_mass=R0)
    model = newtop.Model(body, newtop.QuadraticField.coulomb(G, LAMBDA))
    return model, newtop.State.from_omega(body, OMEGA0, GAMMA0)


def vec(v):
    return "[" + ", ".join(repr(float(x)) for x in v) + "]"


def scenario_file(tmp_path, inertia=INERTIA, r0=R0, g=G, lam=LAMBDA, omega=OMEGA0, gamma=GAMMA0):
    """The same body, field and state as a scenario file, for the program."""
    path = tmp_path / "scenario.toml"
    path.write_text("[body]\ninertia = %s\nmass = 1.0\ncenter_of_mass = %s\n"
                    "[field]\ng = %r\nlambda = %r\n[initial]\nomega = %s\ngamma = %s\n"
                    % (vec(inertia), vec(r0), float(g), float(lam), vec(omega), vec(gamma)))
    return str(path)


def program_json(*words):
    p = subprocess.run([EXE, *words, "--json"], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    return json.loads(p.stdout)


def test_equilibria_equal_the_program(tmp_path):
    model, _ = body_field_state()
    eq = newtop.equilibria(model)
    j = program_json("equilibria", scenario_file(tmp_path))
    assert isinstance(eq, newtop.Equilibria) and eq.count == j["count"] > 0
    assert eq.gamma.shape == (eq.count, 3)
    assert np.array_equal(eq.gamma, [e["gamma"] for e in j["equilibria"]])
    assert np.array_equal(eq.kappa, [e["kappa"] for e in j["equilibria"]])
    assert np.array_equal(eq.potential, [e["potential"] for e in j["equilibria"]])
    assert np.array_equal(eq.hessian_eigenvalues, [e["hessian_eigenvalues"] for e in j["equilibria"]])
    assert eq.type == [e["type"] for e in j["equilibria"]]
    assert (eq.minima, eq.saddles, eq.maxima) == (j["minima"], j["saddles"], j["maxima"])


def test_stability_of_equilibrium_1_equals_the_program(tmp_path):
    model, _ = body_field_state()
    r = newtop.stability(model, equilibrium=1)
    j = program_json("stability", scenario_file(tmp_path), "--equilibrium", "1")
    assert np.array_equal(r.eigenvalues.real, [z[0] for z in j["eigenvalues"]])
    assert np.array_equal(r.eigenvalues.imag, [z[1] for z in j["eigenvalues"]])
    assert r.max_real_part == j["max_real_part"]
    assert r.linearly_stable == j["linearly_stable"] and r.lyapunov_stable == j["lyapunov_stable"]
    assert np.array_equal(r.gamma, j["gamma"]) and r.residual == j["residual"]


def test_stability_of_an_axis_equals_the_program(tmp_path):
    body = newtop.Body.from_principal([1.0, 1.5, 2.2], mass=1.0)
    model = newtop.Model(body, newtop.QuadraticField.coulomb(1.0, 0.7))
    r = newtop.stability(model, axis="z", omega=1.3)
    j = program_json("stability", scenario_file(tmp_path, r0=[0, 0, 0]), "--axis", "z",
                     "--omega", "1.3")
    assert r.axis == j["axis"] == "z"
    assert r.threshold_omega_formula == j["threshold_omega_formula"]
    assert r.threshold_omega_numeric == j["threshold_omega_numeric"]
    assert np.array_equal(r.eigenvalues.real, [z[0] for z in j["eigenvalues"]])


def test_section_of_200_crossings_equals_the_program(tmp_path):
    model, x0 = body_field_state()
    s = newtop.section(model, [x0], 1e4, surface="gamma1 = 0", crossings=200, step=0.01)
    j = program_json("section", scenario_file(tmp_path), "--surface", "gamma1 = 0",
                     "--crossings", "200", "--t-end", "1e4", "--step", "0.01")
    assert s.count == j["count"] == 200
    assert s.t.shape == (200,) and s.gamma.shape == (200, 3)
    assert np.array_equal(s.t, [c["t"] for c in j["crossings"]])
    assert np.array_equal(s.gamma, [c["gamma"] for c in j["crossings"]])
    assert np.array_equal(s.omega, [c["omega"] for c in j["crossings"]])
    assert np.array_equal(s.m, [c["m"] for c in j["crossings"]])


def test_chaos_equals_the_program(tmp_path):
    model, x0 = body_field_state()
    c = newtop.chaos(model, x0, 200.0, step=0.01, spectrum=True)
    j = program_json("chaos", scenario_file(tmp_path), "--t-end", "200", "--step", "0.01",
                     "--spectrum")
    assert c.lyapunov_max == j["lyapunov_max"] and c.megno == j["megno"] and c.fli == j["fli"]
    assert np.array_equal(c.spectrum, j["spectrum"]) and c.outcome == j["outcome"]


def test_analytic_heavy_top_at_5_times_equals_the_program(tmp_path):
    # A heavy symmetric top (A = B, centre of mass on the axis, uniform gravity): Lagrange's case.
    body = newtop.Body.from_principal([2.0, 2.0, 1.0], mass=1.0, center_of_mass=[0, 0, 0.5])
    model = newtop.Model(body, newtop.QuadraticField.uniform(9.81))
    x0 = newtop.State.from_omega(body, [0.3, 0.0, 20.0], [0.6, 0.0, 0.8])
    times = [0.5, 1.0, 1.5, 2.0, 2.5]
    a = newtop.analytic(model, x0, times)
    j = program_json("analytic", scenario_file(tmp_path, inertia=[2.0, 2.0, 1.0], r0=[0, 0, 0.5],
                                               g=9.81, lam=0.0, omega=[0.3, 0.0, 20.0],
                                               gamma=[0.6, 0.0, 0.8]),
                     "--times", "0.5,1,1.5,2,2.5")
    assert a.case == j["case"] == "lagrange"
    assert np.array_equal(a.t, times)
    assert np.array_equal(a.omega, [s["analytic"]["omega"] for s in j["samples"]])
    assert np.array_equal(a.gamma, [s["analytic"]["gamma"] for s in j["samples"]])
    assert np.array_equal(a.numeric_gamma, [s["numeric"]["gamma"] for s in j["samples"]])
    assert a.max_abs_error == j["max_abs_error"]


def test_a_scenario_built_in_code_is_accepted_where_a_model_is(tmp_path):
    model, x0 = body_field_state()
    sc = newtop.Scenario(model, x0, t_end=200.0, step=0.01)
    sc.t_end = 100.0  # editable
    assert newtop.chaos(sc).megno == newtop.chaos(model, x0, 100.0, step=0.01).megno
    assert np.array_equal(newtop.equilibria(sc).gamma, newtop.equilibria(model).gamma)


def test_a_non_unit_gamma_is_refused_as_on_the_command_line(tmp_path):
    body = newtop.Body.from_principal(INERTIA, mass=1.0, center_of_mass=R0)
    with pytest.raises(newtop.InputError, match=r"gamma: expected a unit vector \(\|gamma\| = 1 to "
                                                r"1e-12\), found \|gamma\| = 1\.08"):
        newtop.State.from_omega(body, OMEGA0, [0.0, 0.6, 0.9])
    p = subprocess.run([EXE, "simulate", scenario_file(tmp_path, gamma=[0.0, 0.6, 0.9]),
                        "--t-end", "1", "--step", "0.1"], capture_output=True, text=True)
    assert p.returncode == 2
    assert "gamma: expected a unit vector (|gamma| = 1 to 1e-12), found |gamma| = 1.08" in p.stderr
    x = newtop.State.from_omega(body, OMEGA0, [0.0, 0.6, 0.9], normalize=True)
    assert abs(np.linalg.norm(x.gamma) - 1.0) < 1e-15
    with pytest.raises(newtop.InputError, match="m: expected finite numbers"):
        newtop.State([np.nan, 0, 0], [0, 0, 1])


def test_integrate_t_eval_is_the_dense_output_of_simulate_times(tmp_path):
    model, x0 = body_field_state()
    times = [0.25, 1.0, 3.5, 7.0]
    run = newtop.integrate(model, x0, 10.0, tol=1e-10, t_eval=times)
    assert np.array_equal(run["t"], times) and run["gamma"].shape == (4, 3)
    out = tmp_path / "run.csv"
    p = subprocess.run([EXE, "simulate", scenario_file(tmp_path), "--t-end", "10", "--tol",
                        "1e-10", "--times", "0.25,1,3.5,7", "--out", str(out)],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    rows = np.loadtxt(out, delimiter=",", skiprows=1, ndmin=2)
    assert np.array_equal(rows[:, 0], times)
    assert np.array_equal(rows[:, 4:7], run["gamma"])


def test_rhs_is_an_array():
    model, x0 = body_field_state()
    d = model.rhs(x0)
    assert d.shape == (6,)
    assert np.array_equal(d, model.rhs(np.concatenate([x0.m, x0.gamma])))
    # dgamma/dt = gamma x omega
    assert np.allclose(d[3:], np.cross(x0.gamma, x0.omega(model.body)), rtol=0, atol=1e-15)


# Brun's inversion on a level f != 0 (docs/integrable.md) against rkf78 at tol 1e-14: the same bar
# as tests/integrable/test_brun_prym_inversion.cpp, 1e-9 in the state (measured 3e-13 at t = 7.5).
BRUN_AGREEMENT = 1e-9


def test_brun_state_at_agrees_with_integration():
    sc = newtop.load_scenario(os.path.join(os.path.dirname(__file__), "..", "..", "examples",
                                          "analytic_brun_f.toml"))
    for t in (2.0, 7.5):
        x = newtop.brun_state_at(sc.model, sc.initial, t)
        r = newtop.integrate(sc.model, sc.initial, t, method="rkf78", tol=1e-14)
        assert np.abs(np.asarray(x.gamma) - r["gamma"][-1]).max() < BRUN_AGREEMENT
        assert np.abs(np.asarray(x.m) - r["m"][-1]).max() < BRUN_AGREEMENT
    with pytest.raises(newtop.InputError):
        newtop.brun_state_at(sc.model, newtop.State([0.5, 1.2, 0.75], [0.0, 0.0, 2.0]), 1.0)


EXAMPLES = os.path.join(os.path.dirname(__file__), "..", "..", "examples")


def test_rotations_equal_the_program(tmp_path):
    model, _ = body_field_state()
    r = newtop.rotations(model, samples=90)
    out = tmp_path / "cone.csv"
    j = program_json("rotations", scenario_file(tmp_path), "--samples", "90", "--out", str(out))
    assert isinstance(r, newtop.RotationFamilies)
    assert np.array_equal(r.principal_axes.reshape(-1, 3),
                          np.reshape(j["principal_axes_any_omega"], (-1, 3)))
    assert r.any_axis_omega == j["any_axis_omega"]
    assert r.cone_is_whole_sphere == j["cone_is_whole_sphere"]
    assert len(r.cone_omega_squared) == j["cone_samples"] > 0
    assert int(r.cone_admissible.sum()) == j["cone_admissible_samples"]
    rows = np.loadtxt(out, delimiter=",", skiprows=1, ndmin=2)
    assert np.array_equal(rows[:, 0:3], r.cone_gamma)
    assert np.array_equal(rows[:, 3], r.cone_omega_squared)
    assert np.array_equal(rows[:, 4] == 1, r.cone_admissible)


def test_field_and_its_R_scan_equal_the_program():
    path = os.path.join(EXAMPLES, "exact_box_multipole.toml")
    model = newtop.load_scenario(path).model
    f = newtop.field(model, [0.3, 0.4, 1.0], scan_R=(10.0, 40.0, 6))
    j = program_json("field", path, "--gamma", "0.3,0.4,1", "--scan-R", "10:40:6")
    assert f["mu"] == j["mu"] and f["R"] == j["R"]
    assert np.array_equal(f["gamma"], j["gamma"])
    for part in ("exact", "approx", "difference"):
        for key in ("potential", "dV_dR"):
            assert f[part][key] == j[part][key], (part, key)
        for key in ("grad_gamma", "moment", "force", "hessian_gamma"):
            assert np.array_equal(f[part][key], j[part][key]), (part, key)
        assert np.array_equal(f["input_frame"][part]["moment"], j["input_frame"][part]["moment"])
    assert np.array_equal(f["input_frame"]["gamma"], j["input_frame"]["gamma"])
    assert f["approx_truncation_error"] == j["approx_truncation_error"]
    for key in ("R", "potential_error", "moment_error", "moment_relative_error"):
        assert np.array_equal(f["scan"][key], j["scan"][key]), key
    assert f["scan"]["slope_moment"] == j["scan"]["slope_moment"]
    with pytest.raises(newtop.InputError, match="mass model"):
        newtop.field(body_field_state()[0], [0, 0, 1], R=5.0)


def test_find_integrals_equal_the_program(tmp_path):
    model, _ = body_field_state()
    s = newtop.find_integrals(model, degree=2)
    j = program_json("find-integrals", scenario_file(tmp_path), "--degree", "2")
    assert isinstance(s, newtop.IntegralSearch)
    assert s.degree == j["degree"] and len(s.monomials) == j["monomials"]
    assert s.rank == j["rank"]
    assert (s.gap if np.isfinite(s.gap) else None) == j["gap"]  # no gap: inf here, null in JSON
    assert np.array_equal(s.singular_values, j["singular_values"])
    assert len(s.names) == j["independent_integrals"] > 0
    for name, row, found in zip(s.names, s.coefficients, j["integrals"]):
        assert name == found["name"]
        nonzero = {m: c for m, c in zip(s.monomials, row) if c != 0.0}
        assert nonzero == found["coefficients"]
    with pytest.raises(newtop.InputError, match="points: expected 0"):
        newtop.find_integrals(model, points=-1)  # refused, never taken for the default


def test_sweep_of_a_model_built_in_code_equals_the_program(tmp_path):
    # A 4 x 3 MEGNO and final-state sweep over two initial components, no file written here; the
    # program runs the same sweep from files.
    model, x0 = body_field_state()
    w0 = [-0.5, 0.0, 0.25, 0.5]
    w1 = [-0.2, 0.1, 0.4]
    r = newtop.sweep(model, {"initial.omega[0]": w0, "initial.omega[1]": w1},
                     ["megno", "final_state"], state=x0, threads=2,
                     integrate={"t_end": 20.0, "step": 0.01})
    scenario = scenario_file(tmp_path)
    sweep_file = tmp_path / "sweep.toml"
    sweep_file.write_text('scenario = "%s"\nquantities = ["megno", "final_state"]\n'
                          "[integrate]\nt_end = 20.0\nstep = 0.01\n"
                          '[[axes]]\nkey = "initial.omega[0]"\nvalues = %s\n'
                          '[[axes]]\nkey = "initial.omega[1]"\nvalues = %s\n'
                          % (scenario, vec(w0), vec(w1)))
    j = program_json("sweep", str(sweep_file), "--quiet")
    assert r["points"] == j["points"] == 12 and r["failed"] == j["failed"] == 0
    for key in ("initial.omega[0]", "initial.omega[1]", "megno", "t", "p", "q", "r", "gamma1",
                "gamma2", "gamma3"):
        assert isinstance(r["results"][key], np.ndarray)
        assert np.array_equal(r["results"][key], j["results"][key]), key
    assert r["results"]["status"] == j["results"]["status"]
    # The same bits for one thread, and a base Scenario built in code gives the same sweep.
    sc = newtop.Scenario(model, x0, t_end=20.0, step=0.01)
    one = newtop.sweep(sc, {"initial.omega[0]": w0, "initial.omega[1]": w1}, ["megno"], threads=1)
    assert np.array_equal(one["results"]["megno"], r["results"]["megno"])
