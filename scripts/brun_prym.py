"""Brun's case on a level f = m.gamma != 0: the torus frequencies from the periods of the Prym
differentials of the spectral curve, against the frequencies measured on a numerical run.

The spectral curve Gamma: v^2 = P(u), xi^2 = N(u) + 2 sqrt(lambda) f v (docs/integrable.md, "Brun's
case, level f != 0") is of genus 3; the differentials du/(v xi), u du/(v xi) are odd under
xi -> -xi and span the holomorphic differentials of its Prym variety. On f = 0 they are
-+ i du/w, -+ i u du/w on w^2 = -P N, and the torus frequencies are
omega = 2 pi M^-1 (2/kappa, 0) with M the real periods. This script checks that the same rule on
the Prym of Gamma gives the frequencies of the motion on f != 0:

1. the periods of (du/(v xi), u du/(v xi)) over closed cycles of Gamma (loops around the branch
   points e1, e2, e3 and the roots of D = N^2 - 4 lambda f^2 P from one base point, the sheets
   (+-v, +-xi) continued along the path; every closed word of length 2 and 4), and the lattice
   Lambda they generate (rank 4 in C^2);
2. the time lattice of the real torus: the imaginary parts of the vectors of Lambda whose real
   part lies in 1/2 (Lambda n R^2) (on f = 0 this is the lattice of the real periods i M);
3. its dual basis omega = 2 pi M^-1 (2/kappa, 0): every frequency of the motion is an integer
   combination of omega;
4. the frequencies of u1(t) (the sphero-conic coordinate of gamma) measured on a run of the
   Python module (splitting6, step 0.005) by the peak of a windowed Fourier transform (C-infinity
   bump window), and each written as an integer combination of omega.

The library's brun_prym_frequencies (include/newtop/analysis/brun_prym_periods.hpp) finds the
torus lattice exactly, from the velocities of the flows of H and of Brun's integral on the Prym;
on the levels tried the basis of step 3 generates an index-2 submodule of its frequencies, which is
why halves of combinations appear below.

usage: PYTHONPATH=build/python python3 scripts/brun_prym.py [--lambda X] [f ...]
The level is the start of examples/analytic_brun.toml (lambda = -0.8 unless --lambda) with
m -> m + f gamma.
"""

import itertools
import sys
from fractions import Fraction

import numpy as np

INERTIA = np.array([1.0, 1.5, 2.2])
LAMBDA = -0.8  # replaced by --lambda X
OMEGA0 = np.array([0.5, 0.8, 0.340909090909091])
GAMMA0 = np.array([0.48, -0.6, 0.64])


class Level:
    def __init__(self, f):
        self.f = f
        self.kappa = INERTIA.prod()
        self.e = -self.kappa / INERTIA
        self.gamma = GAMMA0 / np.linalg.norm(GAMMA0)
        self.m = INERTIA * OMEGA0 + f * self.gamma
        self.h = 0.5 * np.sum(self.m**2 / INERTIA) + 0.5 * LAMBDA * np.sum(INERTIA * self.gamma**2)
        self.c = np.sum(self.m**2) - LAMBDA * self.kappa * np.sum(self.gamma**2 / INERTIA)
        self.N = np.array([LAMBDA, self.c - LAMBDA * self.e.sum(), 2 * self.kappa * self.h])
        self.P = np.poly(self.e)
        self.D = np.polysub(np.polymul(self.N, self.N), 4 * LAMBDA * f * f * self.P)
        self.sqrt_lambda = np.sqrt(complex(LAMBDA))


def continued(values):
    """Signs of a sampled square root made continuous along the path."""
    out = values.copy()
    for n in range(1, len(out)):
        if abs(out[n] - out[n - 1]) > abs(out[n] + out[n - 1]):
            out[n] = -out[n]
    return out


def path_integral(level, points, v0, xi0):
    """The integrals of (1, u) du/(v xi) along a polyline, v and xi continued from (v0, xi0)."""
    nodes, weights = np.polynomial.legendre.leggauss(8)
    us, ws = [points[0]], [0.0]
    branch = np.concatenate([level.e.astype(complex), np.roots(level.D)])
    for a, b in zip(points[:-1], points[1:]):
        # Sub-segments no longer than a tenth of the distance to the nearest branch point.
        near = max(min(np.abs(branch - a).min(), np.abs(branch - b).min()), 1e-12)
        k = max(1, int(np.ceil(10 * abs(b - a) / near)))
        for j in range(k):
            ua, ub = a + (b - a) * j / k, a + (b - a) * (j + 1) / k
            us.extend((ua + ub) / 2 + (ub - ua) / 2 * nodes)
            ws.extend(weights * (ub - ua) / 2)
        us.append(b)
        ws.append(0.0)
    us, ws = np.array(us), np.array(ws)
    v = np.sqrt(np.polyval(level.P, us).astype(complex))
    v[0] = v0
    v = continued(v)
    xi = np.sqrt(np.polyval(level.N, us) + 2 * level.sqrt_lambda * level.f * v)
    xi[0] = xi0
    xi = continued(xi)
    integrand = ws / (v * xi)
    return np.array([integrand.sum(), (integrand * us).sum()]), v[-1], xi[-1]


def generators(level):
    """For each finite branch point: the loop from the base point around it, its permutation of
    the four sheets at the base point and its integrals from each sheet."""
    branch = list(level.e.astype(complex)) + list(np.roots(level.D))
    # The base point: the one of a few candidates whose rays to the branch points pass farthest
    # from the other branch points.
    def clearance(b):
        worst = np.inf
        for t in branch:
            for o in branch:
                if o is t:
                    continue
                s = np.clip(((o - b) * np.conj(t - b)).real / abs(t - b) ** 2, 0, 1)
                worst = min(worst, abs(b + s * (t - b) - o) / abs(t - o))
        return worst

    candidates = [complex(x, y) for x in np.linspace(-4, 1, 26) for y in (-0.05, -0.13, -0.31, -0.7)]
    base = max(candidates, key=clearance)
    sheets = []
    for sv in (1, -1):
        v = sv * np.sqrt(complex(np.polyval(level.P, base)))
        for sx in (1, -1):
            sheets.append((v, sx * np.sqrt(np.polyval(level.N, base) + 2 * level.sqrt_lambda * level.f * v)))

    def which(v, xi):
        for n, (v0, xi0) in enumerate(sheets):
            if abs(v - v0) < 1e-8 * abs(v0) and abs(xi - xi0) < 1e-8 * abs(xi0):
                return n
        raise RuntimeError("a loop ended off the sheets of the base point")

    out = []
    for t in branch:
        rho = 0.3 * min(abs(t - o) for o in branch if o is not t)
        d = (t - base) / abs(t - base)
        start = t - d * rho
        circle = [t - d * rho * np.exp(2j * np.pi * n / 96) for n in range(97)]
        loop = [base, start] + circle + [start, base]
        perm, ints = [], []
        for v0, xi0 in sheets:
            s, v, xi = path_integral(level, loop, v0, xi0)
            perm.append(which(v, xi))
            ints.append(s)
        out.append((perm, ints))
    return out


def periods(level):
    """The periods over every closed word of length 2 and 4 in the loops: vectors of R^4
    (Re, Re, Im, Im)."""
    gens = generators(level)
    vecs = []
    for length in (2, 4):
        for word in itertools.product(range(len(gens)), repeat=length):
            for s0 in range(4):
                s, total = s0, np.zeros(2, complex)
                for g in word:
                    total += gens[g][1][s]
                    s = gens[g][0][s]
                if s == s0 and np.abs(total).max() > 1e-9:
                    vecs.append(np.concatenate([total.real, total.imag]))
    return np.array(vecs)


def lattice_basis(vecs):
    """A basis (rows) of the lattice generated by vecs: coordinates in four independent vectors
    are rational with small denominators; integer row reduction (Euclid) of those."""
    basis = []
    for v in sorted(vecs, key=np.linalg.norm):
        if np.linalg.matrix_rank(np.array(basis + [v]), tol=1e-6 * np.linalg.norm(v)) > len(basis):
            basis.append(v)
        if len(basis) == 4:
            break
    B = np.array(basis).T
    coords = np.linalg.solve(B, vecs.T).T
    den = 1
    for x in coords.ravel():
        q = Fraction(x).limit_denominator(32)
        if abs(float(q) - x) > 1e-6:
            raise RuntimeError("period coordinates are not rational with small denominators")
        den = np.lcm(den, q.denominator)
    rows = [list(r) for r in np.round(coords * den).astype(np.int64)]
    # Echelon form by Euclid's algorithm, column by column.
    echelon = []
    for col in range(4):
        rows = [r for r in rows if any(r)]
        pivots = [r for r in rows if r[col] != 0]
        others = [r for r in rows if r[col] == 0]
        while len(pivots) > 1:
            pivots.sort(key=lambda r: abs(r[col]))
            p = pivots[0]
            rest = []
            for r in pivots[1:]:
                q = r[col] // p[col]
                r = [a - q * b for a, b in zip(r, p)]
                (rest if r[col] != 0 else others).append(r)
            pivots = [p] + rest
        if pivots:
            echelon.append(pivots[0])
        rows = others
    return (B @ (np.array(echelon, dtype=float).T / den)).T


def reduce2(u, w):
    """Lagrange–Gauss reduction of a basis of a lattice of R^2."""
    for _ in range(100):
        if np.linalg.norm(w) < np.linalg.norm(u):
            u, w = w, u
        k = round(np.dot(u, w) / np.dot(u, u))
        if k == 0:
            break
        w = w - k * u
    return u, w


def torus_lattice(L):
    """The time lattice of the real torus (rows of L: a basis of Lambda in R^4)."""
    span = range(-6, 7)
    X = np.array(list(itertools.product(span, repeat=4)), dtype=float) @ L  # rows: L.T @ n
    imag = np.abs(X[:, 2:]).max(axis=1)
    real = X[(imag < 1e-7 * np.abs(L).max()) & (np.abs(X).max(axis=1) > 0)][:, :2]
    # x is kept when its real part is 0 or half a real vector of the lattice (within 1e-6).
    half_real = np.abs(X[:, :2]).max(axis=1) < 1e-9
    chunk = max(1, 2**22 // max(1, len(real)))
    for k in range(0, len(X), chunk):
        d = np.abs(2 * X[k : k + chunk, None, :2] - real[None, :, :]).max(axis=2)
        half_real[k : k + chunk] |= (d < 1e-6).any(axis=1)
    found = list(X[half_real & (imag > 1e-9)][:, 2:])
    found.sort(key=np.linalg.norm)
    u = found[0]
    w = next(x for x in found if abs(u[0] * x[1] - u[1] * x[0]) > 1e-6 * np.linalg.norm(u) * np.linalg.norm(x))
    for x in found:  # extend to the whole set
        c = np.linalg.solve(np.column_stack([u, w]), x)
        if np.abs(c - np.round(c)).max() > 1e-6:
            raise RuntimeError("the torus lattice needs a finer basis than the search found")
    return reduce2(u, w)


def measured_frequencies(level, t_end=1500.0, count=6):
    """Peaks of the windowed Fourier transform of u1(t) on a numerical run."""
    import newtop

    body = newtop.Body.from_principal(list(INERTIA), mass=1.0)
    model = newtop.Model(body, newtop.QuadraticField.brun(-LAMBDA, 0.0))
    run = newtop.integrate(model, newtop.State(level.m, level.gamma), t_end, step=0.005)
    t, g = run["t"], run["gamma"]
    e = level.e
    # u1: the smaller root of sum gamma_i^2 / (u - e_i) = 0.
    a = g[:, 0] ** 2 + g[:, 1] ** 2 + g[:, 2] ** 2
    b = -(g[:, 0] ** 2 * (e[1] + e[2]) + g[:, 1] ** 2 * (e[0] + e[2]) + g[:, 2] ** 2 * (e[0] + e[1]))
    c = g[:, 0] ** 2 * e[1] * e[2] + g[:, 1] ** 2 * e[0] * e[2] + g[:, 2] ** 2 * e[0] * e[1]
    u1 = (-b - np.sqrt(b * b - 4 * a * c)) / (2 * a)
    s = np.clip(t / t[-1], 1e-12, 1 - 1e-12)
    window = np.exp(-1.0 / (s * (1 - s)))
    x = (u1 - np.sum(window * u1) / np.sum(window)) * window

    def power(om):
        return abs(np.sum(x * np.exp(-1j * om * t)))

    # Coarse peaks from a zero-padded FFT (uniform steps), refined below.
    dt = t[1] - t[0]
    spectrum = np.abs(np.fft.rfft(x, 8 * len(x)))
    grid = 2 * np.pi * np.fft.rfftfreq(8 * len(x), dt)
    keep = (grid > 0.05) & (grid < 5.0)
    grid, p = grid[keep], spectrum[keep]
    peaks = [i for i in range(1, len(grid) - 1) if p[i] > p[i - 1] and p[i] >= p[i + 1]]
    peaks = sorted(peaks, key=lambda i: -p[i])[:count]
    out = []
    for i in peaks:  # golden-section refinement of each peak (one new power per iteration)
        lo, hi = grid[i - 1], grid[i + 1]
        r = (np.sqrt(5) - 1) / 2
        m1, m2 = hi - r * (hi - lo), lo + r * (hi - lo)
        p1, p2 = power(m1), power(m2)
        for _ in range(60):
            if p1 > p2:
                hi, m2, p2 = m2, m1, p1
                m1 = hi - r * (hi - lo)
                p1 = power(m1)
            else:
                lo, m1, p1 = m1, m2, p2
                m2 = lo + r * (hi - lo)
                p2 = power(m2)
        out.append((0.5 * (lo + hi), p[i]))
    return out


def main(fs):
    for f in fs:
        level = Level(f)
        L = lattice_basis(periods(level))
        u, w = torus_lattice(L)
        M = np.column_stack([u, w])
        omega = 2 * np.pi * np.linalg.solve(M, [2 / level.kappa, 0])
        print(f"f = {f}: h = {level.h:.12g}, c = {level.c:.12g}; roots of D {np.round(np.roots(level.D), 6)}")
        print(f"  torus time lattice (rows): {np.round(M.T, 9).tolist()}")
        print(f"  frequency basis omega = {omega.tolist()}")
        try:
            peaks = measured_frequencies(level)
        except ImportError:
            print("  (no Python module on PYTHONPATH: no measurement)")
            continue
        for nu, amplitude in peaks:
            best = min(
                (abs(abs(i * omega[0] + j * omega[1]) - nu), i, j)
                for i in range(-16, 17)
                for j in range(-16, 17)
            )
            print(f"  measured peak {nu:.10f} (amplitude {amplitude:.3g}) = |{best[1]} omega1 + {best[2]} omega2| "
                  f"to {best[0]:.2e}")


if __name__ == "__main__":
    args = sys.argv[1:]
    if "--lambda" in args:
        i = args.index("--lambda")
        LAMBDA = float(args[i + 1])
        del args[i : i + 2]
    main([float(a) for a in args] or [0.3])
