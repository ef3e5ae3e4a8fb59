#pragma once
// The base scenarios of the sweep harnesses (fuzz_sweep.cpp, fuzz_checkpoint.cpp), written next to
// the fuzzed sweep file: base.toml (Beletsky's problem, for stability and equilibria) and, one
// folder down, scenarios/heavy.toml (a heavy top, for the trajectory quantities). The seeds in
// tests/fuzz/corpus/sweep/ name them by these paths.

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

/// Writes `text` to `path` (creating its folder).
inline void write_file(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

/// Writes both bases into `dir`.
inline void write_sweep_bases(const std::filesystem::path& dir) {
  write_file(dir / "base.toml", kBeletskyBase);
  write_file(dir / "scenarios" / "heavy.toml", kHeavyTopBase);
}

}  // namespace newtop::fuzz
