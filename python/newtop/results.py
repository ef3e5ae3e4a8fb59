"""Readers of the files that the ``newtop`` program writes, with the kind recognised from contents.

``load(path)`` returns a :class:`Result` whose ``kind`` names what wrote it (docs/cli.md):

============== ====================================================================================
kind           recognised by
============== ====================================================================================
trajectory     CSV header ``t,p,q,r,gamma1,gamma2,gamma3,...`` (``simulate --out``)
cone           CSV header ``gamma1,gamma2,gamma3,omega_squared,admissible`` (``rotations --out``)
omega_scan     CSV header ``omega,max_real_part,linearly_stable,energy_casimir_stable``
               (``stability --scan-omega --out``)
stability_map  CSV header ``P1,P2,max_real_part,verdict`` (``stability --scan ... --out``)
section        CSV header ``orbit,t,p,q,r,gamma1,gamma2,gamma3,...`` (``section --out``; on an
               orbit ``orbit,t[,nu],p,q,r,gamma1,...,normal1,...,psi,theta,phi,...``)
orbit_trajectory CSV header ``t[,nu],omega1,omega2,omega3,gamma1,gamma2,gamma3,normal1,...``
               (``simulate --out`` on an orbit scenario)
debra_delp     CSV header ``k_R,k_Y,region,closed_form,boundary,max_real_part``
               (``stability --diagram debra-delp --out``)
libration      CSV header ``start,orbit,theta,dtheta,spin,lyapunov,chaotic`` (``libration --out``)
continuation_family CSV ``parameter,...,stability`` (``continue --out``)
continuation_curves CSV ``curve,type,SECOND,PARAMETER,...`` (``continue --second ... --out``)
chaos_history  CSV with ``t`` and any of ``megno``, ``lyapunov_max``, ``fli`` (``chaos --out``)
sweep          CSV with a ``status`` column (``sweep --out FILE.csv``), or the HDF5 file of
               ``sweep --out FILE.h5`` (its axes and quantity grids read as the CSV's columns)
simulate, integrals, field, equilibria, rotations, stability, analytic, find_integrals, section,
chaos,
continuation, orbit_equilibria (``equilibria`` on an orbit), debra_delp (``stability --diagram``),
libration      JSON objects (``--json``), by their keys
============== ====================================================================================

Anything else raises :class:`UnrecognisedResult` with one line naming the file, what was expected
and what was found.
"""

from __future__ import annotations

import csv
import json
import math
import os
from dataclasses import dataclass, field

import numpy as np

TRAJECTORY_HEAD = ["t", "p", "q", "r", "gamma1", "gamma2", "gamma3"]
CONE_HEAD = ["gamma1", "gamma2", "gamma3", "omega_squared", "admissible"]
OMEGA_SCAN_HEAD = ["omega", "max_real_part", "linearly_stable", "energy_casimir_stable"]
SECTION_HEAD = ["orbit"] + TRAJECTORY_HEAD
CHAOS_COLUMNS = ("megno", "lyapunov_max", "fli")
ORBIT_HEAD = ["omega1", "omega2", "omega3", "gamma1", "gamma2", "gamma3", "normal1", "normal2",
              "normal3"]
DEBRA_DELP_HEAD = ["k_R", "k_Y", "region", "closed_form", "boundary", "max_real_part"]
LIBRATION_HEAD = ["start", "orbit", "theta", "dtheta", "spin", "lyapunov", "chaotic"]
ATTITUDE_COLUMNS = ["q0", "q1", "q2", "q3"]
#: The quantity columns of ``newtop sweep`` (issue 13); the swept keys' columns come before them.
SWEEP_QUANTITY_COLUMNS = (
    "linearly_stable", "lyapunov_stable", "max_real_part", "megno", "lyapunov_max",
    "equilibria_count", "minima", "saddles", "maxima", "t", "p", "q", "r",
    "gamma1", "gamma2", "gamma3", "status")

#: JSON kinds and the keys that identify them, most specific first.
JSON_KINDS = [
    ("simulate", ("method", "outcome", "final", "integrals")),
    ("continuation", ("family", "points", "events")),
    ("field", ("mass_properties", "exact", "approx")),
    ("equilibria", ("equilibria", "count_rule")),
    ("orbit_equilibria", ("equilibria", "count", "lyapunov", "gyroscopic", "unstable")),
    ("debra_delp", ("diagram", "points", "counts")),
    ("libration", ("resonances", "starts", "chaos_threshold")),
    ("rotations", ("principal_axes_any_omega", "cone_samples")),
    ("stability", ("eigenvalues", "max_real_part", "linearly_stable")),
    ("analytic", ("case", "samples", "max_abs_error")),
    ("find_integrals", ("monomials", "singular_values", "rank")),
    ("section", ("surface", "crossings")),
    ("chaos", ("lyapunov_max", "megno", "fli")),
    ("integrals", ("integrals", "conserved")),
]


class UnrecognisedResult(ValueError):
    """A file that is not (or not a well-formed) newtop result; the message is one line."""


@dataclass
class Result:
    """A newtop result: ``kind`` (see the module's table), ``path``, and either ``columns`` (CSV:
    name -> numpy array; text columns stay lists of str) or ``data`` (JSON object)."""

    kind: str
    path: str
    columns: dict = field(default_factory=dict)
    data: dict = field(default_factory=dict)

    @property
    def header(self):
        return list(self.columns)


def load(path) -> Result:
    """Reads a newtop CSV or JSON file and recognises its kind from its contents."""
    path = os.fspath(path)
    if path.lower().endswith(".h5"):
        return _load_hdf5(path)
    try:
        with open(path, "r", encoding="utf-8") as f:
            text = f.read()
    except (OSError, UnicodeDecodeError) as e:
        raise UnrecognisedResult(f"{path}: cannot read: {e}") from None
    stripped = text.lstrip()
    if stripped.startswith("{"):
        try:
            data = json.loads(text)
        except json.JSONDecodeError as e:
            raise UnrecognisedResult(f"{path}: malformed JSON: {e}") from None
        return Result(json_kind(data, path), path, data=data)
    return _load_csv(text, path)


def json_kind(data, path="JSON") -> str:
    if not isinstance(data, dict):
        raise UnrecognisedResult(f"{path}: expected a JSON object written by newtop, found "
                                 f"{type(data).__name__}")
    for kind, keys in JSON_KINDS:
        if all(k in data for k in keys):
            return kind
    found = ", ".join(list(data)[:6]) or "no keys"
    raise UnrecognisedResult(f"{path}: not a newtop result: expected the keys of a subcommand's "
                             f"--json (docs/cli.md), found {found}")


def csv_kind(header, path="CSV") -> str:
    h = list(header)
    if h[: len(SECTION_HEAD)] == SECTION_HEAD or (h[:3] == ["orbit", "t", "nu"]
                                                   and h[3:6] == ["p", "q", "r"]):
        return "section"
    if h[:1] == ["t"] and (h[1:10] == ORBIT_HEAD or h[1:2] == ["nu"] and h[2:11] == ORBIT_HEAD):
        return "orbit_trajectory"
    if h == DEBRA_DELP_HEAD:
        return "debra_delp"
    if h == LIBRATION_HEAD:
        return "libration"
    if len(h) >= 3 and h[0] == "parameter" and h[-1] == "stability":
        return "continuation_family"
    if len(h) >= 5 and h[:2] == ["curve", "type"] and h[-1] == "stability":
        return "continuation_curves"
    if h[: len(TRAJECTORY_HEAD)] == TRAJECTORY_HEAD:
        return "trajectory"
    if h == CONE_HEAD:
        return "cone"
    if h == OMEGA_SCAN_HEAD:
        return "omega_scan"
    if len(h) == 4 and h[2:] == ["max_real_part", "verdict"]:
        return "stability_map"
    if "status" in h:
        return "sweep"
    if "t" in h and any(c in h for c in CHAOS_COLUMNS):
        return "chaos_history"
    shown = ",".join(h[:8]) + (",..." if len(h) > 8 else "")
    raise UnrecognisedResult(f"{path}: not a newtop result: expected the header of a newtop CSV "
                             f"(e.g. {','.join(TRAJECTORY_HEAD)},...; docs/cli.md), found '{shown}'")


def _parse_value(s):
    """A number (nan/inf kept as such), a boolean as 1.0/0.0, an empty cell as nan; else None."""
    s = s.strip()
    if s == "":
        return math.nan
    if s in ("true", "false"):
        return 1.0 if s == "true" else 0.0
    try:
        return float(s)
    except ValueError:
        return None


def _load_csv(text, path) -> Result:
    rows = [r for r in csv.reader(text.splitlines()) if r and not r[0].startswith("#")]
    if not rows:
        raise UnrecognisedResult(f"{path}: not a newtop result: expected a CSV header, found an "
                                 "empty file")
    header = [h.strip() for h in rows[0]]
    kind = csv_kind(header, path)
    body = rows[1:]
    if not body:
        raise UnrecognisedResult(f"{path}: expected at least one data row after the header, "
                                 "found none")
    columns = {}
    for i, name in enumerate(header):
        cells = []
        for n, r in enumerate(body, start=2):
            if len(r) != len(header):
                raise UnrecognisedResult(f"{path}:{n}: expected {len(header)} fields as in the "
                                         f"header, found {len(r)}")
            cells.append(r[i].strip())
        values = [_parse_value(c) for c in cells]
        columns[name] = cells if any(v is None for v in values) else np.array(values, dtype=float)
    text_ok = {"verdict", "status", "region", "closed_form", "type", "stability"}
    for name, col in columns.items():
        if isinstance(col, list) and name not in text_ok:
            bad = next(c for c in col if _parse_value(c) is None)
            raise UnrecognisedResult(f"{path}: column {name}: expected numbers, found '{bad}'")
    return Result(kind, path, columns=columns)


def _load_hdf5(path) -> Result:
    """The HDF5 file of ``newtop sweep --out FILE.h5``: the group ``axes`` holds one dataset per
    swept key, every other dataset a grid over them (first key outermost, as the CSV's rows)."""
    try:
        import h5py
    except ImportError:
        raise UnrecognisedResult(f"{path}: reading HDF5 needs h5py (python3-h5py, "
                                 "scripts/install-deps.sh)") from None
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        raise UnrecognisedResult(f"{path}: cannot read as HDF5: {e}") from None
    with f:
        if "axes" not in f or "status" not in f:
            raise UnrecognisedResult(f"{path}: not a newtop result: expected the HDF5 of newtop "
                                     f"sweep (groups axes, status), found {', '.join(f) or 'none'}")
        names = _hdf5_axis_order(f)
        values = [np.asarray(f["axes"][n], dtype=float) for n in names]
        if np.asarray(f["status"]).ndim == 1 and len(names) > 1:  # a zip: one point per row
            columns = dict(zip(names, values))
        else:
            columns = {n: g.ravel() for n, g in zip(names, np.meshgrid(*values, indexing="ij"))}
        for n in f:
            if n == "axes":
                continue
            v = np.asarray(f[n]).ravel()
            columns[n] = ([x.decode() if isinstance(x, bytes) else str(x) for x in v]
                          if v.dtype.kind in "OSU" else v.astype(float))
    status = columns.pop("status")
    columns["status"] = status  # last, as in the CSV
    return Result("sweep", path, columns=columns)


def _hdf5_axis_order(f):
    """The swept keys in the order of the sweep file (the grid's dimensions), read from the file's
    `sweep` attribute (the sweep file's text); HDF5 lists a group's members alphabetically."""
    names = list(f["axes"])
    text = f.attrs.get("sweep")
    try:
        import tomllib

        doc = tomllib.loads(text.decode() if isinstance(text, bytes) else str(text))
        keys = [a["key"] for a in doc["axes"]]
    except Exception:  # no readable sweep text: the group's order
        return names
    return keys if sorted(keys) == sorted(names) else names


def integral_columns(res: Result):
    """The integral columns of a trajectory CSV (everything after the state, except q0..q3)."""
    skip = set(TRAJECTORY_HEAD) | set(ATTITUDE_COLUMNS)
    return [c for c in res.columns if c not in skip]


def companion_csv(res: Result):
    """The CSV that a JSON result names in its "csv" key (relative to the current directory as the
    program wrote it, or to the JSON file's folder), or None."""
    name = res.data.get("csv")
    if not name:
        return None
    for p in (name, os.path.join(os.path.dirname(res.path), os.path.basename(name))):
        if os.path.isfile(p):
            return p
    return None
