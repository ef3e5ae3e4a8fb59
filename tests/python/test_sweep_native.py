"""newtop.sweep on any Model built in code (no file on the Python side): the quadratic field on a
body of a full inertia tensor with a gyrostat, the exact field of point masses with a gyrostat,
the multipole field of an ellipsoid, each equal bit for bit to `newtop sweep --json` on the
equivalent sweep file; a mass model whose principal axes are not the frame's gives the program's
numbers on its scenario text; a polyhedron built in code is refused in one line.

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

GAMMA0 = [0.0, 0.6, 0.8]
OMEGA0 = [0.3, -0.2, 0.9]
GYROSTAT = [0.05, -0.1, 0.2]
# The three components of omega swept together (zip): every point's state is given by the sweep,
# so the base's omega (written back from m = I omega + k) takes no part.
W = {"initial.omega[0]": [0.3, -0.4, 0.1], "initial.omega[1]": [-0.2, 0.5, 0.0],
     "initial.omega[2]": [0.9, 0.2, -0.7]}
INTEGRATE = {"t_end": 5.0, "step": 0.01}


def toml(v):
    if isinstance(v, str):
        return '"%s"' % v
    if isinstance(v, (list, tuple, np.ndarray)):
        return "[" + ", ".join(toml(x) for x in v) + "]"
    if isinstance(v, int):
        return str(v)
    return repr(float(v))


def tables(**sections):
    return "".join("[%s]\n" % name + "".join("%s = %s\n" % (k, toml(v)) for k, v in keys.items())
                   for name, keys in sections.items())


def program_sweep(tmp_path, scenario_text, axes, quantities, combine="zip",
                  integrate=INTEGRATE):
    """The program's `newtop sweep --json` on the scenario text and a sweep file of these axes."""
    scenario = tmp_path / "scenario.toml"
    scenario.write_text(scenario_text)
    text = 'scenario = "%s"\nquantities = %s\ncombine = "%s"\n' % (
        scenario, toml(quantities), combine)
    text += tables(integrate=integrate)
    for key, values in axes.items():
        text += '[[axes]]\nkey = "%s"\nvalues = %s\n' % (key, toml(list(values)))
    sweep = tmp_path / "sweep.toml"
    sweep.write_text(text)
    p = subprocess.run([EXE, "sweep", str(sweep), "--json", "--quiet"], capture_output=True,
                       text=True)
    assert p.returncode == 0, p.stderr
    return json.loads(p.stdout)


def assert_same(r, j, columns):
    assert r["points"] == j["points"] and r["failed"] == j["failed"] == 0
    assert r["results"]["status"] == j["results"]["status"]
    for c in columns:
        assert np.array_equal(r["results"][c], np.asarray(j["results"][c], dtype=float)), c


def test_quadratic_field_on_a_body_of_a_full_inertia_tensor_with_a_gyrostat(tmp_path):
    tensor = [[1.2, 0.1, -0.05], [0.1, 1.5, 0.2], [-0.05, 0.2, 2.1]]
    body = newtop.Body.from_tensor(tensor, mass=1.0, center_of_mass=[0.1, 0.05, 0.2],
                                   gyrostat=GYROSTAT)
    assert not np.array_equal(np.asarray(body.principal_axes), np.eye(3))
    model = newtop.Model(body, newtop.QuadraticField.coulomb(1.0, 0.7))
    x0 = newtop.State.from_omega(body, OMEGA0, GAMMA0)
    r = newtop.sweep(model, W, ["megno", "final_state"], state=x0, combine="zip", threads=2,
                     integrate=INTEGRATE)
    # The equivalent file: the body in its principal axes (the dynamics are those axes').
    text = tables(body={"inertia": list(body.inertia), "mass": 1.0,
                        "center_of_mass": list(body.center_of_mass),
                        "gyrostat": list(body.gyrostat)},
                  field={"g": 1.0, "lambda": 0.7}, initial={"omega": OMEGA0, "gamma": GAMMA0})
    j = program_sweep(tmp_path, text, W, ["megno", "final_state"])
    assert_same(r, j, list(W) + ["megno", "t", "p", "q", "r", "gamma1", "gamma2", "gamma3"])


def point_masses():
    # Masses on the axes only: no products of inertia, so the principal axes are the frame's.
    masses = [1.0, 1.0, 0.7, 0.7, 0.4, 0.4, 0.3]
    positions = [[0.5, 0, 0], [-0.5, 0, 0], [0, 0.8, 0], [0, -0.8, 0], [0, 0, 1.1], [0, 0, -1.1],
                 [0, 0, 0.6]]
    return masses, positions


def test_exact_field_of_point_masses_with_a_gyrostat(tmp_path):
    masses, positions = point_masses()
    model = newtop.Model.exact(newtop.MassModel.point_masses(masses, positions), 5.0, 20.0,
                               gyrostat=GYROSTAT)
    assert np.array_equal(np.asarray(model.body.principal_axes), np.eye(3))
    x0 = newtop.State.from_omega(model.body, OMEGA0, GAMMA0)
    axes = dict(W, **{"field.R": [20.0, 25.0, 40.0]})
    r = newtop.sweep(model, axes, ["megno", "final_state"], state=x0, combine="zip",
                     integrate=INTEGRATE)
    text = tables(mass_model={"kind": "points",
                              "points": [[m] + p for m, p in zip(masses, positions)]},
                  body={"gyrostat": GYROSTAT}, field={"kind": "exact", "mu": 5.0, "R": 20.0},
                  initial={"omega": OMEGA0, "gamma": GAMMA0})
    j = program_sweep(tmp_path, text, axes, ["megno", "final_state"])
    assert_same(r, j, list(axes) + ["megno", "p", "q", "r", "gamma1", "gamma2", "gamma3"])


def test_multipole_field_of_an_ellipsoid(tmp_path):
    ellipsoid = newtop.MassModel.ellipsoid([1.0, 0.7, 0.4], 2.0)
    model = newtop.Model.multipole(ellipsoid, 4, 3.0, 10.0)
    x0 = newtop.State.from_omega(model.body, OMEGA0, GAMMA0)
    axes = {"field.mu": [1.0, 3.0], "initial.gamma[0]": [0.0, 0.6], "initial.gamma[1]": [0.6, 0.0]}
    r = newtop.sweep(model, axes, ["equilibria", "final_state"], state=x0, combine="zip",
                     integrate=INTEGRATE)
    text = tables(mass_model={"kind": "ellipsoid", "semi_axes": [1.0, 0.7, 0.4], "density": 2.0,
                              "center": [0.0, 0.0, 0.0]},
                  field={"kind": "multipole", "order": 4, "mu": 3.0, "R": 10.0},
                  initial={"omega": list(x0.omega(model.body)), "gamma": GAMMA0})
    j = program_sweep(tmp_path, text, axes, ["equilibria", "final_state"])
    assert_same(r, j, list(axes) + ["equilibria_count", "minima", "saddles", "maxima", "p", "q", "r",
                                    "gamma1", "gamma2", "gamma3"])


def test_mass_model_with_other_principal_axes_runs_on_its_scenario_text(tmp_path):
    masses = [1.0, 0.8, 0.5]
    positions = [[0.4, 0.3, 0.0], [-0.2, 0.5, 0.3], [0.1, -0.4, 0.6]]
    model = newtop.Model.exact(newtop.MassModel.point_masses(masses, positions), 5.0, 20.0,
                               gyrostat=GYROSTAT)
    assert not np.array_equal(np.asarray(model.body.principal_axes), np.eye(3))
    x0 = newtop.State.from_omega(model.body, OMEGA0, GAMMA0)
    text = newtop.analyses.scenario_text(model, x0)
    assert "[mass_model]" in text and 'kind = "exact"' in text
    r = newtop.sweep(model, W, ["megno"], state=x0, combine="zip", integrate=INTEGRATE)
    j = program_sweep(tmp_path, text, W, ["megno"])
    assert_same(r, j, list(W) + ["megno"])
    # Read back, the body is the model's to round-off (P v written for the frame's vectors).
    back = newtop.parse_scenario(text).model.body
    assert np.allclose(back.inertia, model.body.inertia, rtol=1e-14, atol=0)
    assert np.allclose(back.gyrostat, model.body.gyrostat, rtol=0, atol=1e-15)


def test_a_polyhedron_built_in_code_is_refused_in_one_line():
    box = newtop.MassModel.box([1.0, 0.8, 0.5], 1.0)
    model = newtop.Model.exact(box, 5.0, 20.0)
    x0 = newtop.State.from_omega(model.body, OMEGA0, GAMMA0)
    with pytest.raises(ValueError) as e:
        newtop.sweep(model, W, ["megno"], state=x0, combine="zip", integrate=INTEGRATE)
    assert str(e.value) == (
        "base: expected a model with a scenario text, found the field of a polyhedron built in "
        "code (a mesh is read from its file): give the scenario file that names its mesh")
