"""The analyses on Python objects: a ``Model`` (or a ``Scenario`` built in code) and a ``State``.

Each function here is also ``newtop.NAME``: given a ``Model``, or a ``Scenario`` built in code, it
calls the library and returns a typed result whose numeric fields are numpy arrays (the numbers of
the command line, bit for bit); given a path (or a ``Scenario`` read from a file) it returns the
subcommand's JSON as a dict (``newtop.commands``), as before.
"""

import os

import numpy as np

from . import _newtop
from . import commands


def _is_native(obj):
    """A Model, or a Scenario that was not read from a file."""
    return isinstance(obj, _newtop.Model) or (
        isinstance(obj, _newtop.Scenario) and obj.source == "<python>")


def _orbit(obj):
    """An OrbitModel or an OrbitScenario (docs/python.md, "Satellites on an orbit")."""
    return isinstance(obj, (_newtop.OrbitModel, _newtop.OrbitScenario))


def _refuse_orbit(name, obj):
    """The analyses not yet bound for the orbit model say so in one line."""
    if _orbit(obj):
        raise TypeError(f"{name}: not available on an OrbitModel or OrbitScenario from Python "
                        f"yet; give the scenario file's path (newtop {name} on the command line)")


def _model_state(obj, state):
    if isinstance(obj, _newtop.Scenario):
        return obj.model, (obj.initial if state is None else state)
    return obj, state


def _state(x):
    if x is None or isinstance(x, _newtop.State):
        return x
    v = np.asarray(x, dtype=float)
    if v.shape != (6,):
        raise ValueError("state: expected a State or an array of 6 (m, gamma), found shape %s"
                         % (v.shape,))
    return _newtop.State(v[:3], v[3:])


def _run_keys(obj, t_end, method, step, tol):
    """[integrate] of a Scenario built in code, overridden by the keywords."""
    if isinstance(obj, _newtop.Scenario):
        if step is None and tol is None and method is None:
            method, step, tol = obj.method, obj.step, obj.tol
        if t_end is None:
            t_end = obj.t_end
    if t_end is None:
        raise ValueError("t_end: missing: give t_end")
    return t_end, method, step, tol


def equilibria(model, **options):
    """Every equilibrium at rest (docs/model.md §7): ``Equilibria`` with ``gamma`` (K, 3),
    ``kappa``, ``potential`` (K), ``type``, ``hessian_eigenvalues`` (K, 2), ``minima`` ...
    Given a path: ``newtop equilibria PATH --json`` as a dict."""
    if _orbit(model) and not options:
        return _newtop._orbit_equilibria(model.model if hasattr(model, "initial") else model)
    if not _is_native(model):
        return commands.equilibria(model, **options)
    if options:
        raise TypeError("equilibria(model): unexpected options %s" % sorted(options))
    m, _ = _model_state(model, None)
    return _newtop._equilibria(m)


def stability(model, *, equilibrium=None, state=None, axis=None, omega=None, **options):
    """Stability of one fixed point: ``equilibrium=K`` (1-based, as equilibria lists them),
    ``state=`` (polished by Newton's method) or ``axis='x'|'y'|'z'`` with ``omega=``. A
    ``StabilityReport``: ``eigenvalues`` (4,) complex, ``max_real_part``, ``linearly_stable``,
    ``lyapunov_stable``, ``threshold_omega_formula``/``_numeric``, ``axis``, ``gamma``, ...
    Given a path: ``newtop stability PATH --json [options]`` as a dict.
    On an orbit (``OrbitModel`` or ``OrbitScenario``, circular): ``equilibrium=K`` or
    ``state=OrbitState`` (a scenario's [initial] by default), a ``RelativeStability``."""
    if _orbit(model) and axis is None and omega is None and not options:
        if isinstance(model, _newtop.OrbitScenario):
            if equilibrium is None and state is None:
                state = model.initial
            model = model.model
        return _newtop._orbit_stability(model, equilibrium=equilibrium, state=state)
    if not _is_native(model):
        return commands.stability(model, equilibrium=equilibrium, axis=axis, omega=omega,
                                  **options)
    if options:
        raise TypeError("stability(model): unexpected options %s" % sorted(options))
    m, s = _model_state(model, None)
    if (isinstance(model, _newtop.Scenario) and equilibrium is None and state is None
            and axis is None):
        state = s
    return _newtop._stability(m, equilibrium=equilibrium, state=_state(state), axis=axis,
                              omega=omega)


def chaos(model, state=None, t_end=None, *, spectrum=False, t0=0.0, method=None, step=None,
          tol=None, max_steps=None, history=False, **options):
    """Chaos indicators from the tangent map (docs/chaos.md): ``ChaosResult`` with
    ``lyapunov_max``, ``megno``, ``fli``, ``spectrum`` (6,) with spectrum=True, ``outcome``;
    ``history=True`` adds the indicators after every step as arrays.
    Given a path: ``newtop chaos PATH --json [options]`` as a dict."""
    _refuse_orbit("chaos", model)
    if not _is_native(model):
        return commands.chaos(model, t_end=t_end, spectrum=spectrum, method=method, step=step,
                              tol=tol, **options)
    m, s = _model_state(model, _state(state))
    t_end, method, step, tol = _run_keys(model, t_end, method, step, tol)
    return _newtop._chaos(m, s, t_end, t0=t0, method=method, step=step, tol=tol,
                          spectrum=spectrum, max_steps=max_steps, history=history)


def section(model, states=None, t_end=None, *, surface="gamma3 = 0", crossings=1000,
            direction="up", t0=0.0, method=None, step=None, tol=None, max_steps=None,
            **options):
    """Poincaré section (docs/section.md) of one orbit per state: ``Section`` with ``orbit``,
    ``t`` (N), ``omega``, ``gamma``, ``m`` (N, 3) in order of orbit and time, each orbit stopped
    after ``crossings`` crossings or at t_end.
    Given a path: ``newtop section PATH --surface ... --json`` as a dict."""
    _refuse_orbit("section", model)
    if not _is_native(model):
        return commands.section(model, surface=surface, crossings=crossings,
                                direction=direction, t_end=t_end, method=method, step=step,
                                tol=tol, **options)
    m, s = _model_state(model, None)
    if states is None:
        states = [s]
    elif isinstance(states, _newtop.State) or (
            not isinstance(states, _newtop.State) and len(states) == 6
            and all(isinstance(v, (int, float, np.floating)) for v in states)):
        states = [_state(states)]  # one state: a State or (m, gamma)
    else:
        states = [_state(x) for x in states]
    t_end, method, step, tol = _run_keys(model, t_end, method, step, tol)
    return _newtop._section(m, states, t_end, surface=surface, crossings=crossings,
                            direction=direction, t0=t0, method=method, step=step, tol=tol,
                            max_steps=max_steps)


def analytic(model, state=None, times=None, *, max_steps=None, **options):
    """The integrable case's closed form at ``times`` beside rkf78 at tol 1e-13:
    ``AnalyticResult`` with ``case``, ``t`` (N), ``omega``, ``gamma``, ``m`` (N, 3),
    ``numeric_omega``, ``numeric_gamma``, ``max_abs_error``, ``period``.
    Given a path: ``newtop analytic PATH --json [options]`` as a dict."""
    _refuse_orbit("analytic", model)
    if not _is_native(model):
        return commands.analytic(model, times=times, **options)
    m, s = _model_state(model, _state(state))
    if times is None:
        raise ValueError("times: missing: give the sample times")
    return _newtop._analytic(m, s, [float(t) for t in np.atleast_1d(times)],
                             max_steps=max_steps)


def rotations(model, *, samples=180, **options):
    """The families of permanent rotations (docs/model.md §8): ``RotationFamilies`` with
    ``principal_axes`` (K, 3), ``any_axis_omega``, ``cone_is_whole_sphere``, ``cone_gamma``
    (N, 3), ``cone_omega_squared`` (N), ``cone_admissible`` (N, bool).
    Given a path: ``newtop rotations PATH --json [options]`` as a dict."""
    if not _is_native(model):
        return commands.rotations(model, samples=samples if samples != 180 else None, **options)
    if options:
        raise TypeError("rotations(model): unexpected options %s" % sorted(options))
    m, _ = _model_state(model, None)
    return _newtop._rotations(m, samples=samples)


def find_integrals(model, *, degree=2, points=0, **options):
    """Numerical search for first integrals polynomial in (omega, gamma) up to ``degree``:
    ``IntegralSearch`` with ``monomials``, ``coefficients`` (K, monomials), ``names``, ``rank``,
    ``gap``, ``singular_values``. Given a path: ``newtop find-integrals PATH --json`` as a dict."""
    if not _is_native(model):
        return commands.find_integrals(model, degree=degree, points=points or None, **options)
    if options:
        raise TypeError("find_integrals(model): unexpected options %s" % sorted(options))
    m, _ = _model_state(model, None)
    return _newtop._find_integrals(m, degree=degree, points=points)


def field(model, gamma=None, *, R=None, scan_R=None, **options):
    """The exact field of the model's mass model against its quadratic model at ``gamma`` (the
    mass model's frame, normalised): a dict with ``mu``, ``R``, ``gamma`` (principal axes),
    ``exact``, ``approx``, ``difference`` (each ``potential``, ``grad_gamma``, ``dV_dR``,
    ``moment``, ``force``, ``hessian_gamma``), ``approx_truncation_error``, ``input_frame``, and
    with ``scan_R=(R1, R2, N)`` the ``scan`` of the quadratic model's error over R (arrays).
    Given a path: ``newtop field PATH --gamma ... --json [options]`` as a dict."""
    if not _is_native(model):
        scan = scan_R if scan_R is None or isinstance(scan_R, str) else "%r:%r:%d" % (
            float(scan_R[0]), float(scan_R[1]), int(scan_R[2]))
        return commands.field(model, gamma=gamma, R=R, scan_R=scan, **options)
    if options:
        raise TypeError("field(model): unexpected options %s" % sorted(options))
    if gamma is None:
        raise ValueError("gamma: missing: give the direction of the centre")
    m, _ = _model_state(model, None)
    scan = None if scan_R is None else (float(scan_R[0]), float(scan_R[1]), int(scan_R[2]))
    return _newtop._field(m, np.asarray(gamma, dtype=float), R=R, scan_R=scan)


def _toml(value):
    """A TOML value: numbers in their shortest round-trip form, strings quoted, lists."""
    if isinstance(value, str):
        return '"' + value.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (list, tuple, np.ndarray)):
        return "[" + ", ".join(_toml(v) for v in value) + "]"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    return repr(float(value))


def _table(name, keys):
    lines = ["[%s]" % name]
    lines += ["%s = %s" % (k, _toml(v)) for k, v in keys.items() if v is not None]
    return "\n".join(lines) + "\n"


def scenario_text(model, state=None, *, t0=0.0, t_end=None, method=None, step=None, tol=None):
    """The scenario file of a Model built in code (the quadratic field on any body, the exact and
    multipole fields of point masses or an ellipsoid, a gyrostat) and a state, as TOML text: what
    newtop.sweep runs a Model or a Scenario built in code on (docs/sweep.md). The state is
    written as (omega, gamma); a polyhedron built in code is refused (its mesh is a file)."""
    if isinstance(model, _newtop.Scenario):
        sc = model
        model, state = sc.model, sc.initial if state is None else state
        t0 = sc.t0 if hasattr(sc, "t0") else t0
        t_end = sc.t_end if t_end is None else t_end
        if method is None and step is None and tol is None:
            method, step, tol = sc.method, sc.step, sc.tol
    if state is None:
        raise ValueError("base: a Model needs state= (the initial state of every point)")
    text = _newtop._scenario_text(model, _state(state))
    integrate = {"t0": t0 if t0 else None, "t_end": t_end, "method": method, "step": step,
                 "tol": tol}
    if any(v is not None for v in integrate.values()):
        text += _table("integrate", integrate)
    return text


def sweep(base, axes=None, quantities=None, *, threads=0, state=None, combine="grid",
          stability=None, integrate=None, **options):
    """Quantities over a grid (or zip) of values of scenario keys, with no sweep file:
    ``axes={key: values}`` (``initial.omega[0]``, ``field.lambda``, ``stability.omega``, ...),
    ``quantities=[...]`` (docs/sweep.md), ``threads`` (0: all cores); ``base`` a Scenario or a
    Model built in code (with ``state=``), a Scenario read from a file or a scenario path;
    ``stability={"axis": "z", "omega": 1.0}`` and ``integrate={"t_end": ..., "step": ...}``
    as a sweep file's tables. A dict with ``points``, ``failed``, ``off_level``, ``threads``,
    ``quantities`` and ``results``: one numpy array per axis and column in point order (the last
    axis fastest; NaN where a point failed or a verdict is inconclusive) and ``status``.
    Without ``axes``, ``base`` is a sweep file: ``newtop sweep PATH --json`` as a dict."""
    if axes is None:
        return commands.sweep(base, **options)
    if options:
        raise TypeError("sweep(base, axes=...): unexpected options %s" % sorted(options))
    if not quantities:
        raise ValueError("quantities: expected at least one quantity, found none")
    if isinstance(base, _newtop.Scenario) and base.source != "<python>":
        base = base.source
    if isinstance(base, (str, os.PathLike)):
        source = os.fspath(base)
        with open(source, encoding="utf-8") as f:
            base_text = f.read()
    else:
        source, base_text = "<python>", scenario_text(base, state)
    text = "scenario = %s\nquantities = %s\ncombine = %s\n" % (
        _toml(source), _toml(list(quantities)), _toml(combine))
    if stability:
        text += _table("stability", dict(stability))
    if integrate:
        text += _table("integrate", dict(integrate))
    for key, values in axes.items():
        text += "[[axes]]\nkey = %s\nvalues = %s\n" % (
            _toml(key), _toml([float(v) for v in np.atleast_1d(values)]))
    return _newtop._sweep(text, source, base_text, threads=threads)


__all__ = ["analytic", "chaos", "equilibria", "field", "find_integrals", "rotations", "scenario_text",
           "section", "stability", "sweep"]
