"""Helpers shared by the figure modules (kept apart so that `python3 -m newtop.plot` imports no
module twice)."""

import numpy as np
from matplotlib.figure import Figure

#: Machine epsilon of double precision: relative drifts below it are drawn at it.
EPS = np.finfo(float).eps


def new_figure(width=7.0, height=5.0) -> Figure:
    return Figure(figsize=(width, height), layout="constrained")


def scenario_parameters(path, exclude=()) -> str:
    """The fixed parameters of a scenario file, for a title: "A = …, B = …, C = …; M = …; r0 = …;
    field: …" ("" without a file), leaving out the names in exclude (the scanned ones: A, B, C,
    g, lambda, …). Read with the standard library's TOML reader; the program has already checked
    the file when it wrote the result. Long titles are wrapped."""
    if not path:
        return ""
    import textwrap
    import tomllib

    with open(path, "rb") as f:
        doc = tomllib.load(f)
    fmt = lambda v: ("[" + ", ".join(f"{x:g}" for x in v) + "]" if isinstance(v, list)  # noqa: E731
                     else f"{v:g}" if isinstance(v, (int, float)) else str(v))
    skip = set(exclude)
    parts = []
    body = doc.get("body", {})
    if "inertia" in body and isinstance(body["inertia"], list) and len(body["inertia"]) == 3:
        moments = [f"{n} = {v:g}" for n, v in zip("ABC", body["inertia"]) if n not in skip]
        if moments:
            parts.append(", ".join(moments))
    elif "inertia" in body:
        parts.append(f"I = {fmt(body['inertia'])}")
    for key, label in (("mass", "M"), ("center_of_mass", "r0"), ("gyrostat", "k")):
        if key in body and key not in skip:
            parts.append(f"{label} = {fmt(body[key])}")
    field = doc.get("field", {})
    values = ", ".join(f"{'λ' if k == 'lambda' else k} = {fmt(v)}" for k, v in field.items()
                       if k != "kind" and k not in skip)
    if field:
        kind = f"{field['kind']} field" if "kind" in field else "field"
        parts.append(f"{kind}: {values}" if values else kind)
    if "mass_model" in doc:
        parts.append(f"mass model: {doc['mass_model'].get('kind', '?')}")
    return "\n".join(textwrap.wrap("; ".join(parts), 90))


def distinct_colours(n):
    """n colours that can be told apart: tab10 up to 10, beyond that evenly spaced hues of a
    perceptually ordered map (no colour repeats, unlike cycling a qualitative map)."""
    from matplotlib import colormaps

    if n <= 10:
        return [colormaps["tab10"](k) for k in range(n)]
    return [colormaps["turbo"](x) for x in np.linspace(0.05, 0.95, n)]
