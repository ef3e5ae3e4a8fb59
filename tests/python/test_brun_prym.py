"""scripts/brun_prym.py: on Brun levels f = m.gamma != 0, the dual basis of the time lattice of the
real torus computed from the periods of the Prym differentials du/(v xi), u du/(v xi) of the
spectral curve (with the time normalisation of f = 0, (kappa/2) sum int du/(v xi) = t) predicts the
frequencies of the motion: the strongest peaks of the windowed spectrum of u1(t), measured on a run
of the compiled module, are integer combinations of it or halves of one (the sphero-conic u1 is not
a function on the torus of the Prym: it takes the discrete data along, as the 4 pi period of the
state in the angles of f = 0) (docs/integrable.md, "Brun's case, level f != 0").

Run by ctest with NEWTOP_PYTHON_MODULE (build/python) set (tests/python/CMakeLists.txt)."""

import os
import sys

import numpy as np
import pytest

from scripts_dir import load_script

sys.path.insert(0, os.environ["NEWTOP_PYTHON_MODULE"])

#: The peaks are located to 1e-8 .. 1e-11 (C-infinity window over T = 1500, measured by the script
#: on these levels); a wrong lattice or time normalisation moves a predicted frequency by 1e-4 or
#: more (the f = 0 rule on w^2 = -P N misses by 1e-2), and with |coefficients| <= 16 a random number
#: falls within this bound of some combination or half of one with probability ~1e-3.
PEAK_TOLERANCE = 1e-6
#: Halves are accepted, so the test checks the lattice up to a sublattice or superlattice of index
#: 2 (the purely imaginary periods alone also pass); it checks the curve, the differentials and the
#: time normalisation (a velocity 2.001/kappa instead of 2/kappa fails on both levels).
#: Coefficients searched: the main peaks use |i|, |j| <= 7 on these levels.
COEFFICIENTS = range(-16, 17)


@pytest.mark.parametrize("lam, f", [(-0.8, 0.3), (0.8, 0.6)])
def test_prym_frequencies_are_the_frequencies_of_the_motion(lam, f):
    mod = load_script("brun_prym")
    mod.LAMBDA = lam
    level = mod.Level(f)
    u, w = mod.torus_lattice(mod.lattice_basis(mod.periods(level)))
    omega = 2 * np.pi * np.linalg.solve(np.column_stack([u, w]), [2 / level.kappa, 0])
    peaks = mod.measured_frequencies(level, count=3)
    for nu, _ in peaks:
        miss = min(
            abs(abs(i * omega[0] + j * omega[1]) / d - nu)
            for i in COEFFICIENTS
            for j in COEFFICIENTS
            for d in (1, 2)
        )
        assert miss < PEAK_TOLERANCE, (nu, omega, miss)
