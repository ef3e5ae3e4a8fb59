"""The bifurcation diagram of a continued family (``newtop continue --json``, docs/continuation.md):
a defining value against the parameter, stable and unstable stretches apart, the located events
marked; with ``--switch``, the branches from the flips and branch points dashed; with ``--second``,
the events' curves in the plane of the two keys (the stability chart)."""

from __future__ import annotations

import numpy as np

from ._common import new_figure
from .results import Result

EVENT_MARKERS = {"fold": "s", "flip": "o", "branch_point": "^", "krein": "D"}
STABLE = ("stable", "lyapunov", "gyroscopic")


def _value_name(points):
    """The value drawn: θ′(0) for periodic solutions, else the first one that varies."""
    names = list(points[0]["values"])
    if "dtheta0" in names:
        return "dtheta0"
    for n in names:
        if len({p["values"][n] for p in points}) > 1:
            return n
    return names[0]


def continuation_figure(res: Result):
    d = res.data
    points = d["points"]
    boundaries = d.get("boundaries")
    fig = new_figure(11.0 if boundaries else 7.0, 5.0)
    axes = fig.subplots(1, 2 if boundaries else 1, squeeze=False)[0]
    ax = axes[0]
    name = _value_name(points)
    p = np.array([q["parameter"] for q in points])
    v = np.array([q["values"][name] for q in points])
    stable = np.array([q["stability"] in STABLE for q in points])
    for mask, colour, label in ((stable, "C0", "stable"), (~stable, "C3", "unstable")):
        ax.plot(np.where(mask, p, np.nan), np.where(mask, v, np.nan), color=colour, label=label)
    for i, b in enumerate(d.get("branches", [])):
        bp = np.array([q["parameter"] for q in b["points"]])
        bv = np.array([q["values"][name] for q in b["points"]])
        bs = np.array([q["stability"] in STABLE for q in b["points"]])
        for mask, colour in ((bs, "C0"), (~bs, "C3")):
            ax.plot(np.where(mask, bp, np.nan), np.where(mask, bv, np.nan), color=colour,
                    linestyle="--", label=f"branch {i + 1} ({b['type']})" if mask is bs else None)
        for e in b["events"]:
            y = e["solution"].get(name, np.nan)
            ax.plot(e["value"], y, EVENT_MARKERS.get(e["type"], "x"), color="0.4", mfc="none")
    for e in d["events"]:
        y = e["solution"].get(name, np.nan)
        ax.plot(e["value"], y, EVENT_MARKERS.get(e["type"], "x"), color="k", mfc="none")
        ax.annotate(e["type"], (e["value"], y), textcoords="offset points", xytext=(4, 4),
                    fontsize=8)
    ax.set_xlabel(d["parameter"])
    ax.set_ylabel(name)
    ax.set_title(f"{d['family']} family ({len(d['events'])} events)")
    ax.legend(loc="best")
    if boundaries:
        bx = axes[1]
        for i, b in enumerate(boundaries):
            s = [q["second"] for q in b["points"]]
            t = [q["parameter"] for q in b["points"]]
            bx.plot(s, t, color=f"C{i % 10}", label=b["type"])
        bx.set_xlabel(d["second"])
        bx.set_ylabel(d["parameter"])
        bx.set_title("boundaries (events continued in two parameters)")
        bx.legend(loc="best")
    return fig
