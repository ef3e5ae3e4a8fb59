"""The analyses on Python objects: a ``Model`` (or a ``Scenario`` built in code) and a ``State``.

Each function here is also ``newtop.NAME``: given a ``Model``, or a ``Scenario`` built in code, it
calls the library and returns a typed result whose numeric fields are numpy arrays (the numbers of
the command line, bit for bit); given a path (or a ``Scenario`` read from a file) it returns the
subcommand's JSON as a dict (``newtop.commands``), as before.
"""

import numpy as np

from . import _newtop
from . import commands


def _is_native(obj):
    """A Model, or a Scenario that was not read from a file."""
    return isinstance(obj, _newtop.Model) or (
        isinstance(obj, _newtop.Scenario) and obj.source == "<python>")


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
    Given a path: ``newtop stability PATH --json [options]`` as a dict."""
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
        scan = None if scan_R is None else "%r:%r:%d" % (float(scan_R[0]), float(scan_R[1]),
                                                         int(scan_R[2]))
        return commands.field(model, gamma=gamma, R=R, scan_R=scan, **options)
    if options:
        raise TypeError("field(model): unexpected options %s" % sorted(options))
    if gamma is None:
        raise ValueError("gamma: missing: give the direction of the centre")
    m, _ = _model_state(model, None)
    scan = None if scan_R is None else (float(scan_R[0]), float(scan_R[1]), int(scan_R[2]))
    return _newtop._field(m, np.asarray(gamma, dtype=float), R=R, scan_R=scan)


__all__ = ["analytic", "chaos", "equilibria", "field", "find_integrals", "rotations", "section",
           "stability"]
