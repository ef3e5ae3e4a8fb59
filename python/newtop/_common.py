"""Helpers shared by the figure modules (kept apart so that `python3 -m newtop.plot` imports no
module twice)."""

import numpy as np
from matplotlib.figure import Figure

#: Machine epsilon of double precision: relative drifts below it are drawn at it.
EPS = np.finfo(float).eps


def new_figure(width=7.0, height=5.0) -> Figure:
    return Figure(figsize=(width, height), layout="constrained")
