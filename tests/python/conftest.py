"""pytest set-up for newtop's Python tests: the package from python/, matplotlib without a
display, and the newtop program from NEWTOP_EXE (set by ctest, tests/python/CMakeLists.txt)."""

import os
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "python"))

import matplotlib  # noqa: E402

matplotlib.use("Agg")
