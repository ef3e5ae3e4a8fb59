"""The command line from Python: one function per ``newtop`` subcommand.

``newtop.commands.simulate(scenario, t_end=..., step=...)`` runs ``newtop simulate SCENARIO
--t-end ... --step ... --json`` as a separate process and returns its JSON as a dict: the same
keys and the same numbers, bit for bit (the JSON carries 17 significant digits). Lists of numbers
become numpy arrays (vectors: shape (3,); tables: (N, k)). A keyword ``name=value`` is the option
``--name value`` (underscores become dashes); ``True`` is a flag, ``None`` and ``False`` leave it
out; a list or tuple is written comma-separated (``times=[1, 2]`` is ``--times 1,2``).
``run(words)`` runs ``newtop WORDS...`` and returns (exit code, stdout, stderr).

The program is found from the environment variable ``NEWTOP_EXECUTABLE``, else beside the
package (``build/newtop`` for the package in ``build/python/newtop``; ``PREFIX/bin/newtop`` for
one installed under ``PREFIX/lib/python3/dist-packages``), else on ``PATH``
(``FileNotFoundError`` naming the three places when none is there).

Errors: bad input raises ``ValueError`` with the command line's one-line message (without the
``newtop: error:`` prefix); an internal error raises ``RuntimeError``; an interrupted run raises
``KeyboardInterrupt``. A run that ended before ``t_end`` (exit code 3) returns its result: its
``outcome`` says why.

The analyses themselves, natively and with typed results, are ``newtop.NAME`` (docs/python.md).
"""

import json
import os
import shutil
import subprocess

import numpy as np

try:
    from . import _newtop
except ModuleNotFoundError:  # the command line needs no extension
    _newtop = None

_BAD_INPUT = 2
_INCOMPLETE = 3
_PREFIX = "newtop: error: "


def _option(name, value):
    flag = "--" + name.replace("_", "-")
    if value is None or value is False:
        return []
    if value is True:
        return [flag]
    if isinstance(value, (list, tuple, np.ndarray)):
        return [flag, ",".join(_number(v) for v in value)]
    return [flag, _number(value)]


def _number(v):
    if isinstance(v, float):
        return repr(v)  # the shortest form that reads back to the same double
    return str(v)


def _scenario_path(scenario):
    source = getattr(scenario, "source", None)  # a Scenario or OrbitScenario read from a file
    if isinstance(source, str):
        if source in ("<python>", "<string>") or not os.path.exists(source):
            raise ValueError("scenario: expected a file for the command line, found a scenario "
                             "built in code (%s): give its path" % source)
        return source
    return os.fspath(scenario)


def _arrays(value):
    """Lists of numbers (or of equal-length lists of numbers) to numpy arrays, recursively."""
    if isinstance(value, dict):
        return {k: _arrays(v) for k, v in value.items()}
    if isinstance(value, list):
        if value and all(_is_number(v) for v in value):
            return np.array(value, dtype=float)
        if (value and all(isinstance(v, list) and v and all(_is_number(x) for x in v)
                          for v in value) and len({len(v) for v in value}) == 1):
            return np.array(value, dtype=float)
        return [_arrays(v) for v in value]
    return value


def _is_number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


_PACKAGE = os.path.dirname(os.path.abspath(__file__))
# Where the build and the install put the program, relative to this package.
_BESIDE = (os.path.join(_PACKAGE, "..", "..", "newtop"),  # build/python/newtop -> build/newtop
           os.path.join(_PACKAGE, "..", "..", "..", "..", "bin", "newtop"))  # PREFIX/lib/python3/dist-packages


def executable():
    """The ``newtop`` program: $NEWTOP_EXECUTABLE, else beside the package, else on PATH."""
    given = os.environ.get("NEWTOP_EXECUTABLE")
    if given:
        if not (os.path.isfile(given) and os.access(given, os.X_OK)):
            raise FileNotFoundError("NEWTOP_EXECUTABLE: expected the newtop program, found no "
                                    "executable file at %s" % given)
        return given
    for path in _BESIDE:
        if os.path.isfile(path) and os.access(path, os.X_OK):
            return os.path.normpath(path)
    found = shutil.which("newtop")
    if found:
        return found
    raise FileNotFoundError("newtop: the program was not found: set NEWTOP_EXECUTABLE, or build "
                            "it beside the package (%s), or put it on PATH"
                            % os.path.normpath(_BESIDE[0]))


def run(words):
    """Runs ``newtop WORDS...`` as a separate process; returns (exit code, stdout, stderr) as
    text. An exit by a signal is 128 + the signal, as a shell reports it."""
    p = subprocess.run([executable(), *[str(w) for w in words]], capture_output=True)
    code = p.returncode if p.returncode >= 0 else 128 - p.returncode
    return code, p.stdout.decode("utf-8"), p.stderr.decode("utf-8")


def _check(code, err):
    line = err.strip().splitlines()[-1] if err.strip() else ""
    if code == _BAD_INPUT:
        raise ValueError(line[len(_PREFIX):] if line.startswith(_PREFIX) else line)
    if code > 128:
        raise KeyboardInterrupt(line)
    if code not in (0, _INCOMPLETE):
        raise RuntimeError(line or "newtop exited with code %d" % code)


def command(name, scenario, **options):
    """The JSON of ``newtop NAME SCENARIO --json [options]`` as a dict (see the module's doc)."""
    words = [name]
    if scenario is not None:
        words.append(_scenario_path(scenario))
    for key, value in options.items():
        words += _option(key, value)
    words.append("--json")
    code, out, err = run(words)
    _check(code, err)
    return _arrays(json.loads(out))


def _make(name, doc):
    def fn(scenario, **options):
        return command(name, scenario, **options)

    fn.__name__ = name.replace("-", "_")
    fn.__qualname__ = fn.__name__
    fn.__doc__ = doc + "\n\nOptions as for `newtop %s --help` (see newtop.commands)." % name
    return fn


chaos = _make("chaos", "Chaos indicators: lambda_max, spectrum, MEGNO and FLI (docs/chaos.md).")
section = _make("section", "Poincare section of the scenario's motion (docs/section.md); "
                "'crossings' is a list of dicts.")
analytic = _make("analytic", "Integrable case detected and its closed form against the numerics.")
equilibria = _make("equilibria", "Every equilibrium at rest, its type and the count rule (docs/model.md §7).")
field = _make("field", "Exact and quadratic field of a mass model: V, dV/dgamma, moment, force.")
find_integrals = _make("find-integrals", "Numerical search for polynomial first integrals.")
integrals = _make("integrals", "First integrals at the initial state and which are conserved.")
libration = _make("libration", "Planar pitch on an elliptic orbit: resonances, Floquet, section.")
rotations = _make("rotations", "Families of permanent rotations (docs/model.md §8).")
stability = _make("stability", "Linear and energy-Casimir stability; diagrams and scans.")
sweep = _make("sweep", "Quantities over a grid of parameters (a sweep file, docs/sweep.md); "
              "'results' holds one array per column.")


def simulate(scenario, **options):
    """``newtop simulate SCENARIO --json [options]`` as a dict, with the trajectory.

    Adds ``trajectory``: the dict of ``newtop.integrate`` for the same scenario and options (t,
    omega, gamma, m and the integrals at every accepted step, numpy views of one buffer), and the
    same arrays at the top level: ``t`` (N), ``omega``, ``gamma``, ``m`` (N x 3), ``energy``,
    ``area``, ``geometric`` (and ``brun``, ``lagrange`` where they hold) (N), and with an
    attitude in the scenario ``quaternion`` (N x 4, body to inertial, scalar first). The
    options ``t_end``, ``method``, ``step`` and ``tol`` apply to both; ``out``, ``every``,
    ``dt_out`` and ``times`` only to the CSV file the command writes.
    """
    result = command("simulate", scenario, **options)
    path = _scenario_path(scenario)
    # orbit scenarios: the JSON only
    if _newtop is not None and not _newtop.is_orbit_scenario(path):
        sc = scenario if isinstance(scenario, _newtop.Scenario) else _newtop.load_scenario(path)
        keys = {k: options.get(k) for k in ("t_end", "method", "step", "tol", "split")}
        trajectory = _newtop.integrate(sc, **keys)
        result["trajectory"] = trajectory
        # the trajectory's arrays also at the top level (views of the same buffer)
        for name in ("t", "omega", "gamma", "m", "energy", "area", "geometric", "brun",
                     "lagrange", "quaternion"):
            if name in trajectory:
                result[name] = trajectory[name]
    return result


def view(csv, out, scenario=None):
    """``newtop view CSV -o OUT [--scenario S]``: a self-contained HTML page; returns OUT."""
    words = ["view", os.fspath(csv), "-o", os.fspath(out)]
    if scenario is not None:
        words += ["--scenario", _scenario_path(scenario)]
    code, _, err = run(words)
    _check(code, err)
    return out


__all__ = ["analytic", "chaos", "command", "equilibria", "executable", "field", "find_integrals", "integrals",
           "libration", "rotations", "run", "section", "simulate", "stability", "sweep", "view"]
