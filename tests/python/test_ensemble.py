"""newtop.integrate_ensemble (the Taylor ensemble): every trajectory of a batch of 1, 3, 8 or 17,
one model for all or one per trajectory, is the bits of newtop.integrate of that point alone with
method taylor at the same tolerance — the end of the run, and the states at t_eval; bad input
raises ValueError before any work. newtop.chaos_ensemble: each start's MEGNO, lambda_max and FLI
are the bits of newtop.chaos with method taylor.

Run by ctest with NEWTOP_PYTHON_MODULE (build/python) set (tests/python/CMakeLists.txt)."""

import os
import sys

import numpy as np
import pytest

sys.path.insert(0, os.environ["NEWTOP_PYTHON_MODULE"])
import newtop  # noqa: E402

TOL = 1e-10
T_END = 6.0


def models_and_states(n, rng):
    models, states = [], []
    for _ in range(n):
        a, b = rng.uniform(1.0, 1.6, 2)
        body = newtop.Body.from_principal([a, b, 2.0], mass=1.0,
                                          center_of_mass=list(rng.uniform(-0.3, 0.3, 3)),
                                          gyrostat=list(rng.uniform(-0.2, 0.2, 3)))
        model = newtop.Model(body, newtop.QuadraticField.coulomb(rng.uniform(-1, 1), rng.uniform(-1, 1)))
        gamma = rng.normal(size=3)
        models.append(model)
        states.append(newtop.State.from_omega(body, list(rng.uniform(-1.5, 1.5, 3)),
                                              list(gamma / np.linalg.norm(gamma))))
    return models, states


@pytest.mark.parametrize("n", [1, 3, 8, 17])
def test_each_trajectory_is_the_scalar_run(n):
    rng = np.random.default_rng(n)
    models, states = models_and_states(n, rng)
    run = newtop.integrate_ensemble(models, states, T_END, tol=TOL)
    assert run["m"].shape == (n, 3) and run["outcome"] == ["finished"] * n
    for i in range(n):
        one = newtop.integrate(models[i], states[i], T_END, tol=TOL, method="taylor")
        assert run["t"][i] == one["t"][-1]
        assert np.array_equal(run["m"][i], one["m"][-1])
        assert np.array_equal(run["omega"][i], one["omega"][-1])
        assert np.array_equal(run["gamma"][i], one["gamma"][-1])
        assert run["steps"][i] == one["steps"]


def test_t_eval_and_one_model_for_all():
    rng = np.random.default_rng(5)
    models, states = models_and_states(9, rng)
    rows = np.array([np.concatenate([s.m, s.gamma]) for s in states])
    times = [0.0, 0.3, 2.5, 6.0]
    run = newtop.integrate_ensemble(models[0], rows, T_END, tol=TOL, t_eval=times)
    assert np.array_equal(run["t"], times) and run["gamma"].shape == (9, 4, 3)
    for i, s in enumerate(states):
        one = newtop.integrate(models[0], s, T_END, tol=TOL, method="taylor", t_eval=times)
        assert np.array_equal(run["m"][i], one["m"])
        assert np.array_equal(run["gamma"][i], one["gamma"])
    # A run stopped by its step limit: its later times are NaN, never a number.
    short = newtop.integrate_ensemble(models[0], rows, T_END, tol=TOL, t_eval=times, max_steps=2)
    assert short["outcome"] == ["step_limit"] * 9
    assert np.all(np.isfinite(short["m"][:, 0])) and np.all(np.isnan(short["m"][:, -1]))


def test_chaos_ensemble_is_chaos_point_by_point():
    rng = np.random.default_rng(8)
    models, states = models_and_states(10, rng)
    many = newtop.chaos_ensemble(models, states, 20.0, tol=TOL)
    assert many["outcome"] == ["finished"] * 10
    for i in range(10):
        one = newtop.chaos(models[i], states[i], 20.0, tol=TOL, method="taylor")
        assert many["megno"][i] == one.megno
        assert many["lyapunov_max"][i] == one.lyapunov_max
        assert many["fli"][i] == one.fli


def test_bad_input_is_refused():
    rng = np.random.default_rng(1)
    models, states = models_and_states(3, rng)
    with pytest.raises(ValueError, match="models"):
        newtop.integrate_ensemble(models[:2], states, T_END, tol=TOL)
    with pytest.raises(ValueError, match="states"):
        newtop.integrate_ensemble(models[0], np.zeros((3, 5)), T_END, tol=TOL)
    with pytest.raises(ValueError, match="tol"):
        newtop.integrate_ensemble(models[0], states, T_END, tol=0.0)
    with pytest.raises(ValueError):
        newtop.integrate_ensemble(models[0], states, float("inf"), tol=TOL)


def orbit_satellites(kind, n, rng):
    """n satellites on one kind of orbit, a body each (one orbit for all on an ellipse but for the
    last two, started at another true anomaly: their own group in nu), each turned from the rest
    orientation of the orbital frame and spinning off the orbit's rate."""
    models, states = [], []
    for i in range(n):
        a = rng.uniform(1.0, 1.3)
        body = newtop.Body.from_principal([a, 1.6, 2.1], mass=1.0)
        if kind == "circular":
            model = newtop.OrbitModel.circular(body, mu=1.0, radius=rng.uniform(1.0, 1.5))
        else:
            model = newtop.OrbitModel.elliptic(body, mu=1.0, a=1.0, e=0.1,
                                               true_anomaly=0.0 if i < n - 2 else 0.5)
        models.append(model)
        states.append(newtop.OrbitState.from_lvlh(
            model, roll_pitch_yaw=list(rng.uniform(-0.2, 0.2, 3)),
            omega_relative=list(rng.uniform(-0.3, 0.3, 3))))
    return models, states


@pytest.mark.parametrize("kind", ["circular", "elliptic"])
@pytest.mark.parametrize("n", [1, 5, 11])
def test_each_satellite_is_the_scalar_run(kind, n):
    rng = np.random.default_rng(100 + n)
    models, states = orbit_satellites(kind, n, rng)
    out = newtop.integrate_ensemble(models, states, 9.0, tol=TOL)
    assert out["m"].shape == (n, 3) and out["normal"].shape == (n, 3)
    assert ("nu" in out) == (kind == "elliptic")
    for i in range(n):
        one = newtop.integrate(models[i], states[i], 9.0, tol=TOL, method="taylor")
        assert out["outcome"][i] == one["outcome"] == "finished"
        assert out["steps"][i] == one["steps"] > 10
        assert out["t"][i] == one["t"][-1]
        for key in ("m", "omega", "gamma", "normal"):
            assert np.array_equal(out[key][i], one[key][-1]), (kind, i, key)
    # One model for all, the states as an (N x 9) array: the same bits as that model per state.
    rows = np.array([np.concatenate([s.m, s.gamma, s.normal]) for s in states])
    shared = newtop.integrate_ensemble(models[0], rows, 9.0, tol=TOL)
    each = newtop.integrate_ensemble([models[0]] * n, states, 9.0, tol=TOL)
    assert np.array_equal(shared["m"], each["m"]) and np.array_equal(shared["t"], each["t"])


def test_orbit_ensemble_refuses_bad_input():
    rng = np.random.default_rng(7)
    circ, states = orbit_satellites("circular", 3, rng)
    ell, _ = orbit_satellites("elliptic", 3, rng)
    with pytest.raises(ValueError, match="t_eval"):
        newtop.integrate_ensemble(circ, states, 1.0, tol=TOL, t_eval=[0.5])
    with pytest.raises(ValueError, match="one kind"):
        newtop.integrate_ensemble([circ[0], ell[1], circ[2]], states, 1.0, tol=TOL)
    with pytest.raises(ValueError, match="model_or_models"):
        newtop.integrate_ensemble(circ[:2], states, 1.0, tol=TOL)
    with pytest.raises(ValueError, match="N x 9"):
        newtop.integrate_ensemble(circ[0], np.zeros((3, 6)), 1.0, tol=TOL)
    with pytest.raises(ValueError, match="t_end"):
        newtop.integrate_ensemble(circ[0], states, -1.0, tol=TOL)
    with pytest.raises(ValueError, match="tol"):
        newtop.integrate_ensemble(circ[0], states, 1.0, tol=0.0)


@pytest.mark.parametrize("kind", ["circular", "elliptic"])
def test_each_satellites_chaos_is_the_scalar_run(kind):
    rng = np.random.default_rng(300)
    models, states = orbit_satellites(kind, 6, rng)
    out = newtop.chaos_ensemble(models, states, 12.0, tol=TOL)
    for i in range(6):
        one = newtop.chaos(models[i], states[i], 12.0, tol=TOL, method="taylor")
        assert out["outcome"][i] == one.outcome == "finished"
        assert out["megno"][i] == one.megno, (kind, i)
        assert out["lyapunov_max"][i] == one.lyapunov_max and out["fli"][i] == one.fli
    assert np.all(np.isfinite(out["megno"]))
