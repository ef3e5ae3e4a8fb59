"""newtop sweep's HDF5 output (docs/sweep.md) read back with h5py: one dataset per column shaped
like the grid, the axes and the input files stored, the same numbers as the CSV, NaN (never a
number) and a status where a point's run failed, and the same bytes for any thread count."""

import os
import subprocess

import h5py
import numpy as np

EXE = os.environ["NEWTOP_EXE"]
ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))

BASE = """[body]
inertia = [2.0, 2.0, 1.0]
mass = 1.0
center_of_mass = [0.0, 0.0, 0.5]
[field]
kind = "uniform"
g = 9.81
[initial]
omega = [0.3, 0.0, 20.0]
gamma = [0.5, 0.0, 0.8660254037844386]
[integrate]
t_end = 1.0
step = 1e-2
max_steps = 200
"""

SWEEP = """scenario = "base.toml"
quantities = ["drift", "final_state"]
[[axes]]
key = "initial.omega[2]"
start = 1.0
stop = 100.0
count = 3
scale = "log"
[[axes]]
key = "integrate.step"
values = [1e-2, 1e-3]
"""


def sweep(tmp_path, out, threads):
    (tmp_path / "base.toml").write_text(BASE)
    (tmp_path / "sweep.toml").write_text(SWEEP)
    p = subprocess.run([EXE, "sweep", str(tmp_path / "sweep.toml"), "--quiet", "--threads",
                        str(threads), "--out", str(tmp_path / out)], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    return tmp_path / out


def test_hdf5_has_the_grid_the_axes_and_the_csvs_numbers(tmp_path):
    h5 = sweep(tmp_path, "map.h5", 2)
    csv = sweep(tmp_path, "map.csv", 1)
    header = csv.read_text().splitlines()[0].split(",")
    rows = [line.split(",") for line in csv.read_text().splitlines()[1:]]
    with h5py.File(h5) as f:
        spins = f["axes/initial.omega[2]"][:]  # log scale: the ends exact, the middle to round-off
        assert spins[0] == 1.0 and spins[2] == 100.0 and abs(spins[1] - 10.0) <= 4e-15
        assert np.array_equal(f["axes/integrate.step"][:], [1e-2, 1e-3])
        assert f.attrs["sweep"].decode() == SWEEP and f.attrs["scenario"].decode() == BASE
        status = f["status"][:].astype(str)
        assert status.shape == (3, 2)
        # 1 / 1e-3 = 1000 steps > max_steps = 200: the runs at the small step stop at the limit
        assert list(status[:, 0]) == ["ok"] * 3 and list(status[:, 1]) == ["step_limit"] * 3
        for column in ("drift_energy", "t", "p", "gamma3"):
            data = f[column][:]
            assert data.shape == (3, 2)
            assert np.isnan(data[:, 1]).all()  # a failed point is never a number
            for i in range(3):
                assert data[i, 0] == float(rows[2 * i][header.index(column)])
                assert rows[2 * i + 1][header.index(column)] == ""
                assert rows[2 * i + 1][header.index("status")] == "step_limit"


def test_hdf5_is_the_same_bytes_for_any_thread_count(tmp_path):
    one = sweep(tmp_path, "one.h5", 1).read_bytes()
    two = sweep(tmp_path, "two.h5", 2).read_bytes()
    assert one == two
