#pragma once
// The base scenarios of the sweep harnesses (fuzz_sweep.cpp, fuzz_checkpoint.cpp), written next to
// the fuzzed sweep file: base.toml (Beletsky's problem, for stability and equilibria), one
// folder down scenarios/heavy.toml (a heavy top, for the trajectory quantities), and the orbit
// scenarios orbit.toml (circular: debra_delp, the ratio keys) and ellipse.toml
// (synchronous_odd). The seeds in tests/fuzz/corpus/sweep/ name them by these paths.

#include <filesystem>
#include <fstream>
#include <string>

namespace newtop::fuzz {

inline constexpr const char* kBeletskyBase = R"([body]
inertia = [1.0, 1.5, 2.2]
mass = 1.0

[field]
g = 1.0
lambda = 1.0

[initial]
omega = [0.0, 0.0, 1.2]
gamma = [0.0, 0.0, 1.0]

[integrate]
t_end = 20.0
step = 1e-2
)";

inline constexpr const char* kHeavyTopBase = R"([body]
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
t_end = 0.5
step = 1e-2
max_steps = 1000
)";

inline constexpr const char* kCircularOrbitBase = R"([body]
inertia = [1200.0, 1500.0, 900.0]

[orbit]
kind = "circular"
mu = 1.0
radius = 1.0

[initial]
roll_pitch_yaw = [0.0, 0.05, 0.0]
omega_relative = [0.0, 0.0, 0.0]

[integrate]
step = 0.1
t_end = 1.0
)";

inline constexpr const char* kEllipticOrbitBase = R"([body]
inertia = [0.1, 1.0, 1.0]

[orbit]
kind = "elliptic"
mu = 1.0
semi_major_axis = 1.0
eccentricity = 0.1

[initial]
euler_321 = [0.0, 0.0, 0.0]

[integrate]
method = "rkf78"
tol = 1e-10
t_end = 1.0
)";

/// Writes `text` to `path` (creating its folder).
inline void write_file(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

/// Writes the bases into `dir`.
inline void write_sweep_bases(const std::filesystem::path& dir) {
  write_file(dir / "base.toml", kBeletskyBase);
  write_file(dir / "scenarios" / "heavy.toml", kHeavyTopBase);
  write_file(dir / "orbit.toml", kCircularOrbitBase);
  write_file(dir / "ellipse.toml", kEllipticOrbitBase);
}

}  // namespace newtop::fuzz
