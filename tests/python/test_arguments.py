"""The compiled module's argument checks under random arguments: numpy arrays of any shape and
dtype, with NaN, inf, huge and tiny values, Python scalars, lists and None, through every entry
point that takes numbers. The promise (docs/fuzzing.md): a result, or a clean ValueError
(newtop.InputError is one) or TypeError (pybind11's refusal of an argument it cannot convert);
never a crash, never another exception (an internal error).

The calls run in a child interpreter, each printed before it is made, so that a crash names its
call. Run by ctest with NEWTOP_PYTHON_MODULE (build/python) set (tests/python/CMakeLists.txt)."""

import os
import subprocess
import sys
import textwrap

import pytest

# Calls per entry point: a few thousand calls in all, a few seconds.
CASES = int(os.environ.get("NEWTOP_ARGUMENT_CASES", "150"))

WORKER = textwrap.dedent(
    r"""
    import sys
    import numpy as np
    sys.path.insert(0, sys.argv[1])
    import newtop

    CASES = int(sys.argv[2])
    rng = np.random.default_rng(int(sys.argv[3]))
    SPECIAL = [np.nan, np.inf, -np.inf, 0.0, -0.0, 1e-320, 1e308, -1e308, 1.0, 0.5, 2.2]
    DTYPES = [np.float64, np.float32, np.float16, np.int64, np.int32, np.uint8, np.bool_,
              np.complex128, object, "U3"]
    SHAPES = [(), (0,), (1,), (2,), (3,), (4,), (3, 1), (1, 3), (3, 3), (2, 3), (4, 3), (3, 4),
              (5, 3), (2, 3, 3), (0, 3)]

    def number():
        r = rng.random()
        if r < 0.4:
            return float(rng.choice(SPECIAL))
        if r < 0.8:
            return float(rng.normal() * 10.0 ** rng.integers(-12, 13))
        if r < 0.9:
            return int(rng.integers(-5, 10))
        return [None, "1.0", [1.0], True][int(rng.integers(0, 4))]

    def array(shape=None):
        if shape is None or rng.random() < 0.3:
            shape = SHAPES[int(rng.integers(0, len(SHAPES)))]
        n = int(np.prod(shape)) if shape else 1
        values = np.array([rng.choice(SPECIAL) if rng.random() < 0.2
                           else rng.normal() * 10.0 ** rng.integers(-3, 4) for _ in range(n)])
        dtype = DTYPES[int(rng.integers(0, len(DTYPES)))] if rng.random() < 0.4 else np.float64
        with np.errstate(all="ignore"):
            a = values.astype(dtype) if dtype not in (object, "U3") else values.astype(dtype)
        a = a.reshape(shape)
        r = rng.random()
        if r < 0.1:
            return a.tolist()
        if r < 0.15 and a.ndim >= 1 and a.shape[0] > 1:
            return a[::-1]  # a strided view
        if r < 0.2 and a.ndim == 2:
            return np.asfortranarray(a)
        return a

    def vec3():
        # Mostly three floats (with the special values), so that the calls reach the value checks
        # behind the conversion; otherwise any array.
        if rng.random() < 0.8:
            return np.array([number() if rng.random() < 0.3 else float(rng.normal()) + 1.5
                             for _ in range(3)], dtype=float) if rng.random() < 0.9 else array((3,))
        return array()

    def faces():
        n = int(rng.integers(0, 6))
        f = rng.integers(-2, 10, size=(n, 3))
        if rng.random() < 0.2:
            f = f.astype(rng.choice([np.int64, np.float64, np.uint8, np.int16]))
        return f if rng.random() < 0.9 else array()

    body = newtop.Body.from_principal([1.0, 1.5, 2.2], 1.0, [0.0, 0.0, 0.1])
    field = newtop.QuadraticField.coulomb(1.0, 1.0)
    model = newtop.Model(body, field)
    state = newtop.State.from_omega(body, [0.1, 0.2, 1.2], [0.48, -0.6, 0.64])
    box = newtop.MassModel.box([1.0, 2.0, 3.0], 1.0)
    methods = [None, "splitting6", "rk4", "dop853", "rkf78", "taylor", "bogus", ""]

    def scalar_or_array():
        r = rng.random()
        return float(rng.uniform(0.1, 3.0)) if r < 0.4 else number() if r < 0.9 else array()

    CALLS = {
        "Body.from_principal": lambda: newtop.Body.from_principal(
            vec3(), scalar_or_array(), vec3(), vec3()),
        "Body.from_tensor": lambda: newtop.Body.from_tensor(
            array((3, 3)), scalar_or_array(), vec3(), vec3()),
        "QuadraticField": lambda: [
            lambda: newtop.QuadraticField.coulomb(scalar_or_array(), scalar_or_array()),
            lambda: newtop.QuadraticField.from_g_R(scalar_or_array(), scalar_or_array()),
            lambda: newtop.QuadraticField.from_mu_R(scalar_or_array(), scalar_or_array()),
            lambda: newtop.QuadraticField.uniform(scalar_or_array()),
            lambda: newtop.QuadraticField.brun(scalar_or_array(), scalar_or_array())][
            int(rng.integers(0, 5))](),
        "State": lambda: newtop.State(vec3(), vec3()),
        "State.from_omega": lambda: newtop.State.from_omega(body, vec3(), vec3()),
        "State.omega": lambda: newtop.State(vec3(), vec3()).omega(body),
        "MassModel.point_masses": lambda: newtop.MassModel.point_masses(
            array((int(rng.integers(0, 4)),)), array((int(rng.integers(0, 4)), 3))),
        "MassModel.polyhedron": lambda: newtop.MassModel.polyhedron(
            array((int(rng.integers(0, 7)), 3)), faces(), scalar_or_array()),
        "MassModel.box": lambda: newtop.MassModel.box(vec3(), scalar_or_array(), vec3()),
        "MassModel.ellipsoid": lambda: newtop.MassModel.ellipsoid(
            vec3(), scalar_or_array(), vec3()),
        "Model": lambda: newtop.Model(
            newtop.Body.from_principal(vec3(), number(), vec3(), vec3()),
            newtop.QuadraticField.coulomb(number(), number())),
        "Model.potential": lambda: model.potential(vec3()),
        "Model.grad_gamma": lambda: model.grad_gamma(vec3()),
        "Model.hessian_gamma": lambda: model.hessian_gamma(vec3()),
        "Model.moment": lambda: model.moment(vec3()),
        "Model.rhs": lambda: model.rhs(newtop.State(vec3(), vec3())),
        "Model.exact": lambda: newtop.Model.exact(
            box, scalar_or_array(), scalar_or_array(), vec3()),
        "Model.multipole": lambda: newtop.Model.multipole(
            box, [int(rng.integers(-3, 9)), number()][int(rng.integers(0, 2))],
            scalar_or_array(), scalar_or_array(), vec3()),
        "Model.quadratic_on": lambda: newtop.Model.quadratic_on(box, field, vec3()),
        "integrals_at": lambda: newtop.integrals_at(model, newtop.State(vec3(), vec3())),
        "integrate": lambda: newtop.integrate(
            model, newtop.State(vec3(), vec3()) if rng.random() < 0.5 else state,
            scalar_or_array(), t0=scalar_or_array(),
            method=methods[int(rng.integers(0, len(methods)))],
            step=None if rng.random() < 0.3 else scalar_or_array(),
            tol=None if rng.random() < 0.6 else scalar_or_array(),
            max_steps=[1, 2, 50, 0, -1, -(2 ** 62)][int(rng.integers(0, 6))],
            quaternion=None if rng.random() < 0.5 else array((4,))),
        "integrate_ensemble": lambda: newtop.integrate_ensemble(
            [model, [model, model], [model] * 3][int(rng.integers(0, 3))],
            array((int(rng.integers(0, 4)), 6)) if rng.random() < 0.5 else [state] * 3,
            scalar_or_array(), tol=scalar_or_array(), t0=scalar_or_array(),
            max_steps=[1, 2, 50, 0, -1, -(2 ** 62)][int(rng.integers(0, 6))],
            t_eval=None if rng.random() < 0.5 else array((int(rng.integers(0, 4)),))),
        "chaos_ensemble": lambda: newtop.chaos_ensemble(
            [model, [model, model], [model] * 3][int(rng.integers(0, 3))],
            array((int(rng.integers(0, 4)), 6)) if rng.random() < 0.5 else [state] * 3,
            scalar_or_array(), tol=scalar_or_array(), t0=scalar_or_array(),
            max_steps=[1, 2, 50, 0, -1, -(2 ** 62)][int(rng.integers(0, 6))]),
    }

    for name in sorted(CALLS):
        call = CALLS[name]
        for i in range(CASES):
            print(f"{name} #{i}", file=sys.stderr, flush=True)
            try:
                call()
            except (ValueError, TypeError):
                pass
    print("all calls handled", file=sys.stderr, flush=True)
    """
)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_random_arguments_give_a_result_or_a_clean_error(seed):
    p = subprocess.run(
        [sys.executable, "-c", WORKER, os.environ["NEWTOP_PYTHON_MODULE"], str(CASES), str(seed)],
        capture_output=True,
        text=True,
        timeout=600,
    )
    tail = "\n".join(p.stderr.splitlines()[-12:])
    assert p.returncode == 0, f"exit {p.returncode}; the last calls and the error:\n{tail}"
    assert p.stderr.splitlines()[-1] == "all calls handled", tail
