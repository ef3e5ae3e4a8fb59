"""The analyses on Python objects: a ``Model`` (or an ``OrbitModel``) and a state, a ``Scenario``
(built in code or read from a file), or a scenario file's path.

Each function here is also ``newtop.NAME``. Whatever it is given, it calls the library in this
process and returns a typed result whose numeric fields are numpy arrays — the numbers of the
command line bit for bit. A path is read by the library's ``load_scenario`` (an orbit file gives an
``OrbitScenario``); a scenario's ``[integrate]`` settings are overridden by the keywords as the
command line's ``--t-end``, ``--method``, ``--step``, ``--tol`` and ``--split`` override them.
A command-line option with no native form here raises ``TypeError`` naming it
(``newtop.commands`` runs the command line itself and returns its JSON).
"""

import os

import numpy as np

from . import _newtop


def _load(obj):
    """A path read by the library (Scenario or OrbitScenario); any other object unchanged."""
    if isinstance(obj, (str, os.PathLike)):
        return _newtop.load_scenario(os.fspath(obj))
    return obj


def _no_options(name, options):
    """Options given (not None) that have no native form: TypeError naming the first."""
    given = sorted(k for k, v in options.items() if v is not None)
    if given:
        raise TypeError(f"{name}(): unexpected option '{given[0]}' (no native form; "
                        f"newtop.commands.{name}(path, {given[0]}=...) runs the command line)")


def _orbit(obj):
    """An OrbitModel or an OrbitScenario (docs/python.md, "Satellites on an orbit")."""
    return isinstance(obj, (_newtop.OrbitModel, _newtop.OrbitScenario))


def _refuse_orbit(name, obj):
    """The analyses of the fixed-point model only say so in one line."""
    if _orbit(obj):
        raise TypeError(f"{name}: expected a Model or a Scenario of the fixed-point model, found "
                        f"an orbit ({type(obj).__name__}): {name} has no orbit form")


def _model_state(obj, state):
    if isinstance(obj, _newtop.Scenario):
        return obj.model, (obj.initial if state is None else state)
    return obj, state


def _state(x):
    if x is None or isinstance(x, (_newtop.State, _newtop.OrbitState)):
        return x
    v = np.asarray(x, dtype=float)
    if v.shape != (6,):
        raise ValueError("state: expected a State or an array of 6 (m, gamma), found shape %s"
                         % (v.shape,))
    return _newtop.State(v[:3], v[3:])


def _orbit_scenario(obj, state, t0=None, t_end=None, method=None, step=None, tol=None,
                    max_steps=None):
    """An OrbitScenario of an orbit object: itself, or one with another state or start."""
    if isinstance(obj, _newtop.OrbitScenario) and state is None and t0 is None and max_steps is None:
        return obj
    if isinstance(obj, _newtop.OrbitScenario):
        sc = obj
        return _newtop.OrbitScenario(
            sc.model, sc.initial if state is None else state, t0=sc.t0 if t0 is None else t0,
            t_end=sc.t_end, method=sc.method, step=sc.step, tol=sc.tol,
            max_steps=sc.max_steps if max_steps is None else max_steps)
    if state is None:
        raise ValueError("state: missing: give the OrbitState to start from")
    return _newtop.OrbitScenario(obj, state, t0=0.0 if t0 is None else t0, t_end=t_end,
                                 method=method, step=step, tol=tol, max_steps=max_steps)


def _scenario_only(name, obj, **keys):
    """Keywords that a Scenario carries itself (t0, max_steps): set them on the Scenario."""
    given = sorted(k for k, v in keys.items() if v is not None)
    if isinstance(obj, _newtop.Scenario) and given:
        raise TypeError(f"{name}(scenario): unexpected option '{given[0]}' (a Scenario carries "
                        f"it: set scenario.{given[0]})")


def equilibria(model, **options):
    """Every equilibrium at rest (docs/model.md §7): ``Equilibria`` with ``gamma`` (K, 3),
    ``kappa``, ``potential`` (K), ``type``, ``hessian_eigenvalues`` (K, 2), ``minima`` ...
    On an orbit (circular), the relative equilibria: ``RelativeEquilibria``."""
    _no_options("equilibria", options)
    model = _load(model)
    if _orbit(model):
        return _newtop._orbit_equilibria(model.model if hasattr(model, "initial") else model)
    m, _ = _model_state(model, None)
    return _newtop._equilibria(m)


def _axis_range(text, name):
    lo, hi, n = text.split(":")
    return (float(lo), float(hi), int(n))


def _debra_delp(scan):
    """``stability --diagram debra-delp [--scan k_R=LO:HI:N,k_Y=LO:HI:M]`` natively."""
    axes = {}
    for part in ([] if scan is None else str(scan).split(",")):
        key, _, value = part.partition("=")
        key = key.strip()
        if key not in ("k_R", "k_Y") or not value:
            raise ValueError("scan: expected k_R=LO:HI:N,k_Y=LO:HI:M, found '%s'" % scan)
        axes[key] = _axis_range(value, "scan")
    return _newtop.debra_delp(**axes)


def stability(model=None, *, equilibrium=None, state=None, axis=None, omega=None, diagram=None,
              scan=None, **options):
    """Stability of one fixed point: ``equilibrium=K`` (1-based, as equilibria lists them),
    ``state=`` (polished by Newton's method) or ``axis='x'|'y'|'z'`` with ``omega=``; a
    scenario's [initial] by default. A ``StabilityReport``: ``eigenvalues`` (4,) complex,
    ``max_real_part``, ``linearly_stable``, ``lyapunov_stable``, ``threshold_omega_formula``/
    ``_numeric``, ``axis``, ``gamma``, ...
    On an orbit (``OrbitModel`` or ``OrbitScenario``, circular): ``equilibrium=K`` or
    ``state=OrbitState`` (a scenario's [initial] by default), a ``RelativeStability``.
    ``diagram="debra-delp"`` (no model) with ``scan="k_R=LO:HI:N,k_Y=LO:HI:M"``: the
    ``DebraDelpDiagram`` of ``newtop.debra_delp``."""
    _no_options("stability", options)
    if diagram is not None:
        if diagram != "debra-delp":
            raise ValueError("diagram: expected debra-delp, found %s" % diagram)
        if model is not None:
            raise TypeError("stability(diagram=...): the diagram takes no model")
        return _debra_delp(scan)
    if scan is not None:
        raise TypeError("stability(): unexpected option 'scan' (no native form; "
                        "newtop.commands.stability(path, scan=...) runs the command line)")
    if model is None:
        raise TypeError("stability(): missing the model (a Model, a Scenario or a path)")
    model = _load(model)
    if _orbit(model) and axis is None and omega is None:
        if isinstance(model, _newtop.OrbitScenario):
            if equilibrium is None and state is None:
                state = model.initial
            model = model.model
        return _newtop._orbit_stability(model, equilibrium=equilibrium, state=state)
    m, s = _model_state(model, None)
    if (isinstance(model, _newtop.Scenario) and equilibrium is None and state is None
            and axis is None):
        state = s
    return _newtop._stability(m, equilibrium=equilibrium, state=_state(state), axis=axis,
                              omega=omega)


def chaos(model, state=None, t_end=None, *, spectrum=False, t0=None, method=None, step=None,
          tol=None, max_steps=None, history=False, split=None, **options):
    """Chaos indicators from the tangent map (docs/chaos.md): ``ChaosResult`` with
    ``lyapunov_max``, ``megno``, ``fli``, ``spectrum`` (6,) with spectrum=True, ``outcome``;
    ``history=True`` adds the indicators after every step as arrays. On an orbit
    (docs/orbit.md §13): ``OrbitChaosResult`` (an embedded pair: ``tol=``, not ``step=``)."""
    _no_options("chaos", options)
    model = _load(model)
    if _orbit(model):
        if split is not None:
            raise ValueError("split: the free body's split applies to the fixed-point model, "
                             "not to an orbit scenario")
        if step is not None:
            raise ValueError("step: chaos on an orbit runs an embedded pair (tol), not a fixed "
                             "step")
        sc = _orbit_scenario(model, state, t0=t0, method=method, tol=tol, max_steps=max_steps)
        return _newtop._orbit_chaos(sc, t_end=t_end, method=method, tol=tol, spectrum=spectrum,
                                    history=history)
    if isinstance(model, _newtop.Scenario):
        _scenario_only("chaos", model, t0=t0, max_steps=max_steps)
        return _newtop._chaos_scenario(model, state=_state(state), t_end=t_end, method=method,
                                       step=step, tol=tol, split=split, spectrum=spectrum,
                                       history=history)
    if split is not None:
        raise TypeError("chaos(model): unexpected option 'split' (give a Scenario)")
    if t_end is None:
        raise ValueError("t_end: missing: give t_end")
    return _newtop._chaos(model, _state(state), t_end, t0=0.0 if t0 is None else t0,
                          method=method, step=step, tol=tol, spectrum=spectrum,
                          max_steps=max_steps, history=history)


def _states(states):
    if states is None:
        return None
    if isinstance(states, (_newtop.State, _newtop.OrbitState)) or (
            len(states) == 6 and all(isinstance(v, (int, float, np.floating)) for v in states)):
        return [_state(states)]  # one state: a State or (m, gamma)
    return [_state(x) for x in states]


def section(model, states=None, t_end=None, *, surface="gamma3 = 0", crossings=1000,
            direction="up", t0=None, method=None, step=None, tol=None, max_steps=None,
            split=None, orbits=None, energy=None, area=None, **options):
    """Poincaré section (docs/section.md) of one orbit per state: ``Section`` with ``orbit``,
    ``t`` (N), ``omega``, ``gamma``, ``m`` (N, 3) in order of orbit and time, each orbit stopped
    after ``crossings`` crossings or at t_end (a scenario without t_end: at its crossings, at
    most max_steps steps). ``orbits=K`` seeds K starts on the surface at the scenario's energy
    and area levels (or ``energy=``, ``area=``). On an orbit: ``OrbitSection``."""
    _no_options("section", options)
    model = _load(model)
    if _orbit(model):
        if orbits is not None:
            raise ValueError("orbits: expected a body scenario, found an orbit scenario "
                             "([orbit]): seeded portraits on the Jacobi level are not "
                             "available; run one scenario per start")
        if split is not None:
            raise ValueError("split: the free body's split applies to the fixed-point model, "
                             "not to an orbit scenario")
        one = _states(states)
        if one is not None and len(one) != 1:
            raise TypeError("section(orbit): expected one OrbitState, found %d" % len(one))
        sc = _orbit_scenario(model, None if one is None else one[0], t0=t0, method=method,
                             step=step, tol=tol, max_steps=max_steps)
        return _newtop._orbit_section(sc, t_end=t_end, surface=surface, crossings=crossings,
                                      direction=direction, method=method, step=step, tol=tol)
    if isinstance(model, _newtop.Model):
        m = model
        if orbits is not None or split is not None:
            raise TypeError("section(model): unexpected option '%s' (give a Scenario)"
                            % ("orbits" if orbits is not None else "split"))
        if t_end is None:
            raise ValueError("t_end: missing: give t_end")
        return _newtop._section(m, _states(states), t_end, surface=surface, crossings=crossings,
                                direction=direction, t0=0.0 if t0 is None else t0,
                                method=method, step=step, tol=tol, max_steps=max_steps)
    _scenario_only("section", model, t0=t0, max_steps=max_steps)
    return _newtop._section_scenario(model, states=_states(states), t_end=t_end, surface=surface,
                                     crossings=crossings, direction=direction, method=method,
                                     step=step, tol=tol, split=split, orbits=orbits,
                                     energy=energy, area=area)


_DEFAULT_SAMPLES = 20  # as `newtop analytic` without --samples


def analytic(model, state=None, times=None, *, max_steps=None, t_end=None, samples=None,
             **options):
    """The integrable case's closed form at ``times`` beside rkf78 at tol 1e-13:
    ``AnalyticResult`` with ``case``, ``t`` (N), ``omega``, ``gamma``, ``m`` (N, 3),
    ``numeric_omega``, ``numeric_gamma``, ``max_abs_error``, ``period``. Without ``times``:
    ``samples`` + 1 times (20 by default) evenly over [0, t_end] (the scenario's t_end, else
    one period), as ``newtop analytic``."""
    _no_options("analytic", options)
    model = _load(model)
    _refuse_orbit("analytic", model)
    m, s = _model_state(model, _state(state))
    if isinstance(model, _newtop.Scenario):
        _scenario_only("analytic", model, max_steps=max_steps)
        max_steps = model.max_steps
    if times is None:
        if t_end is None and isinstance(model, _newtop.Scenario):
            t_end = model.t_end
        if t_end is None:
            t_end = _newtop._analytic(m, s, [], max_steps=max_steps).period
        if t_end is None:
            raise ValueError("times: missing: give the sample times or t_end")
        if not (np.isfinite(t_end) and t_end > 0):
            raise ValueError("t_end: expected a time > 0, found %r" % t_end)
        n = _DEFAULT_SAMPLES if samples is None else int(samples)
        if n < 1:
            raise ValueError("samples: expected an integer >= 1, found %d" % n)
        times = [t_end if i == n else t_end * i / n for i in range(n + 1)]
    elif t_end is not None or samples is not None:
        raise TypeError("analytic(): times= excludes %s" % ("t_end" if t_end is not None
                                                            else "samples"))
    return _newtop._analytic(m, s, [float(t) for t in np.atleast_1d(times)],
                             max_steps=max_steps)


def rotations(model, *, samples=180, **options):
    """The families of permanent rotations (docs/model.md §8): ``RotationFamilies`` with
    ``principal_axes`` (K, 3), ``any_axis_omega``, ``cone_is_whole_sphere``, ``cone_gamma``
    (N, 3), ``cone_omega_squared`` (N), ``cone_admissible`` (N, bool)."""
    _no_options("rotations", options)
    model = _load(model)
    _refuse_orbit("rotations", model)
    m, _ = _model_state(model, None)
    return _newtop._rotations(m, samples=samples)


def find_integrals(model, *, degree=2, points=0, **options):
    """Numerical search for first integrals polynomial in (omega, gamma) up to ``degree``:
    ``IntegralSearch`` with ``monomials``, ``coefficients`` (K, monomials), ``names``, ``rank``,
    ``gap``, ``singular_values``."""
    _no_options("find_integrals", options)
    model = _load(model)
    _refuse_orbit("find_integrals", model)
    m, _ = _model_state(model, None)
    return _newtop._find_integrals(m, degree=degree, points=points)


def field(model, gamma=None, *, R=None, scan_R=None, **options):
    """The exact field of the model's mass model against its quadratic model at ``gamma`` (the
    mass model's frame, normalised): a dict with ``mu``, ``R``, ``gamma`` (principal axes),
    ``exact``, ``approx``, ``difference`` (each ``potential``, ``grad_gamma``, ``dV_dR``,
    ``moment``, ``force``, ``hessian_gamma``), ``approx_truncation_error``, ``input_frame``, and
    with ``scan_R=(R1, R2, N)`` (or ``"R1:R2:N"``) the ``scan`` of the quadratic model's error
    over R (arrays)."""
    _no_options("field", options)
    model = _load(model)
    _refuse_orbit("field", model)
    if gamma is None:
        raise ValueError("gamma: missing: give the direction of the centre")
    m, _ = _model_state(model, None)
    if isinstance(scan_R, str):
        scan_R = _axis_range(scan_R, "scan_R")
    scan = None if scan_R is None else (float(scan_R[0]), float(scan_R[1]), int(scan_R[2]))
    return _newtop._field(m, np.asarray(gamma, dtype=float), R=R, scan_R=scan)


def libration(model, state=None, *, resonances=None, spin=None, iterates=200, asymmetric=False,
              out=None, **options):
    """Planar pitch on a Kepler orbit (docs/orbit.md §9): ``LibrationReport`` with
    ``eccentricity``, ``k``, ``iterates``, ``chaos_threshold``, ``resonances`` (one dict each,
    the solutions as arrays), the periapsis section's starts ``theta0``, ``dtheta0``, ``spin0``,
    ``lyapunov``, ``chaotic`` (arrays) and ``points`` (per start, (iterates, 2)),
    ``chaotic_starts``. ``resonances`` as "p:q,..." or [(p, q), ...] (default 1:2, 1:1, 3:2, 2:1,
    5:2); ``spin=(LO, HI, N)`` or "LO:HI:N" adds N starts at periapsis; ``out=`` writes the
    section CSV of ``newtop libration --out``. On an OrbitScenario (or its path), or an
    OrbitModel with an OrbitState."""
    _no_options("libration", options)
    model = _load(model)
    if not _orbit(model):
        raise TypeError("libration: expected an orbit scenario (a file with [orbit], an "
                        "OrbitScenario or an OrbitModel), found %s" % type(model).__name__)
    sc = _orbit_scenario(model, state)
    if resonances is None:
        resonances = "1:2,1:1,3:2,2:1,5:2"
    elif not isinstance(resonances, str):
        resonances = ",".join("%d:%d" % (int(p), int(q)) for p, q in resonances)
    if spin is not None and not isinstance(spin, str):
        spin = "%r:%r:%d" % (float(spin[0]), float(spin[1]), int(spin[2]))
    return _newtop._libration(sc, resonances=resonances, spin=spin, iterates=iterates,
                              asymmetric=asymmetric,
                              out=None if out is None else os.fspath(out))


def integrals(model, state=None, **options):
    """The first integrals at the initial state (or ``state``) and which are conserved for the
    model: a dict with ``integrals`` (``energy``, ``area``, ``geometric``, and ``brun``,
    ``lagrange`` where they hold) and ``conserved`` (their names), the numbers of
    ``newtop integrals --json``."""
    _no_options("integrals", options)
    model = _load(model)
    if _orbit(model):
        raise TypeError("integrals: no native form on an orbit yet (the Jacobi integral is "
                        "OrbitModel.integral(state)); newtop.commands.integrals(path) runs the "
                        "command line")
    m, s = _model_state(model, _state(state))
    if s is None:
        raise ValueError("state: missing: give the state")
    return {"integrals": _newtop.integrals(m, s), "conserved": _newtop.conserved_integrals(m)}


_RUN_ARRAYS = ("t", "omega", "gamma", "m", "energy", "area", "geometric", "brun", "lagrange",
               "quaternion")


def _vector_norm(v):
    return float(np.sqrt(np.dot(v, v)))


def simulate(model, state=None, t_end=None, *, t0=None, method=None, step=None, tol=None,
             split=None, max_steps=None, out=None, every=None, euler=None, **options):
    """One run with its summary, as ``newtop simulate --json``: a dict with the run's arrays
    (``t`` (N), ``omega``, ``gamma``, ``m`` (N, 3), the integrals (N), ``quaternion`` (N, 4)
    with an attitude; also the whole ``newtop.integrate`` dict as ``trajectory``), ``outcome``,
    ``steps``, ``rejected_steps``, ``method``, ``step`` or ``tolerance``, ``final`` (``t``,
    ``omega``, ``gamma``, ``m``[, ``quaternion``]), ``integrals`` (``initial``, ``final``,
    ``max_abs_drift``), ``casimir_drift``, ``conserved``; on an exact or multipole field
    ``quadratic_comparison`` (the same method on the quadratic model). ``out=`` (or the
    scenario's [output] file) writes the CSV of ``newtop simulate --out`` (every ``every``-th
    step and the last; ``euler=321`` or ``313`` adds Euler angles), the same bytes."""
    _no_options("simulate", options)
    model = _load(model)
    if _orbit(model):
        raise TypeError("simulate: no native summary on an orbit yet; newtop.integrate(orbit) "
                        "gives its rows, newtop.commands.simulate(path) the command line's JSON")
    inputs = []
    if isinstance(model, _newtop.Scenario):
        _scenario_only("simulate", model, t0=t0, max_steps=max_steps)
        if state is not None:
            raise TypeError("simulate(scenario): unexpected option 'state' (set "
                            "scenario.initial)")
        output = model.output
        if output["dt"] is not None and out is None and every is None:
            raise ValueError("[output] dt: rows at output times have no native form here; "
                             "newtop.commands.simulate(path) runs the command line")
        if out is None and every is None:
            out, every = output["file"], output["every"]
        inputs = list(model.input_files)
        run = _newtop.integrate(model, t_end=t_end, method=method, step=step, tol=tol,
                                split=split)
        m, x0 = model.model, model.initial
    else:
        if split is not None:
            raise TypeError("simulate(model): unexpected option 'split' (give a Scenario)")
        if t_end is None:
            raise ValueError("t_end: missing: give t_end")
        m, x0 = model, _state(state)
        run = _newtop.integrate(m, x0, t_end, t0=0.0 if t0 is None else t0, method=method,
                                step=step, tol=tol, max_steps=max_steps)
    if euler is not None and "quaternion" not in run:
        raise ValueError("euler: expected a scenario with an attitude ([initial] quaternion, "
                         "rotation_matrix, euler_321 or euler_313), found none")
    r = {"trajectory": run}
    for name in _RUN_ARRAYS:
        if name in run:
            r[name] = run[name]
    r["method"] = run["method"]
    if "tolerance" in run:
        r["tolerance"] = run["tolerance"]
    else:
        r["step"] = run["step"]
    r["outcome"], r["steps"], r["rejected_steps"] = run["outcome"], run["steps"], run["rejected"]
    body = m.body
    last = _newtop.State(run["m"][-1], run["gamma"][-1])
    r["final"] = {"t": float(run["t"][-1]), "omega": last.omega(body), "gamma": run["gamma"][-1],
                  "m": run["m"][-1]}
    if "quaternion" in run:
        r["final"]["quaternion"] = run["quaternion"][-1]
    s = _newtop._simulation_summary(m, run["t"], run["m"], run["gamma"])
    r["integrals"] = {k: s[k] for k in ("initial", "final", "max_abs_drift")}
    r["casimir_drift"] = s["casimir_drift"]
    r["conserved"] = _newtop.conserved_integrals(m)
    if m.kind != "quadratic":
        keys = ({"tol": run["tolerance"]["abs"]} if "tolerance" in run
                else {"step": run["step"]})
        q = _newtop.integrate(m.quadratic_approximation(), x0, float(run["t"][-1]),
                              t0=float(run["t"][0]), method=run["method"], **keys)
        qs = _newtop.State(q["m"][-1], q["gamma"][-1])
        r["quadratic_comparison"] = {
            "outcome": q["outcome"], "gamma": q["gamma"][-1], "omega": qs.omega(body),
            "difference_gamma": _vector_norm(run["gamma"][-1] - q["gamma"][-1]),
            "difference_omega": _vector_norm(last.omega(body) - qs.omega(body))}
    if out is not None:
        _newtop._write_trajectory_csv(os.fspath(out), m, run["t"], run["m"], run["gamma"],
                                      quaternion=run.get("quaternion"),
                                      every=1 if every is None else every,
                                      euler=0 if euler is None else euler, inputs=inputs)
        r["csv"] = os.fspath(out)
    return r


def view(csv, out, scenario=None, *, max_frames=5000):
    """The self-contained HTML page that plays a trajectory CSV in 3D (``newtop view``): the
    scenario (a path, a Scenario or an OrbitScenario) draws the body. Writes ``out`` (the bytes
    of ``newtop view CSV -o OUT [--scenario S]``) and returns it."""
    scenario = _load(scenario) if scenario is not None else None
    _newtop._view(os.fspath(csv), os.fspath(out), scenario, max_frames=max_frames)
    return out


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
    Without ``axes``, ``base`` is a sweep file (read as ``newtop sweep PATH`` reads it), the
    same dict."""
    _no_options("sweep", options)
    if axes is None:
        extra = {"quantities": quantities, "state": state, "stability": stability,
                 "integrate": integrate, "combine": None if combine == "grid" else combine}
        given = sorted(k for k, v in extra.items() if v is not None)
        if given:
            raise TypeError("sweep(sweep_file): unexpected option '%s' (the sweep file sets it; "
                            "with axes= a base scenario takes it)" % given[0])
        return _newtop._sweep_file(os.fspath(base), threads=threads)
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


__all__ = ["analytic", "chaos", "equilibria", "field", "find_integrals", "integrals", "libration",
           "rotations", "scenario_text", "section", "simulate", "stability", "sweep", "view"]
