#pragma once
/// \file
/// Sweeps (docs/sweep.md): one base scenario, swept keys and the quantities computed at every point
/// of a grid (or zip) of their values. A point is evaluated from its own scenario, independently
/// of every other point, so the results do not depend on the order or the thread that computed
/// them.

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/scenario.hpp"

namespace newtop::sweep {

/// One swept key and its values: a scenario key (`body.inertia[2]`, `field.lambda`) or an option
/// of a quantity (`stability.omega`).
struct Axis {
  std::string key;
  std::vector<double> values;
};

enum class Combine { grid, zip };

/// Options of the `stability` quantity, as `newtop stability --axis --omega`.
struct StabilityOptions {
  std::optional<int> axis;  ///< 0, 1, 2 for x, y, z; none: the scenario's own state
  double omega = 0.0;
};

/// `[level]`: every point's initial state moved onto one energy level by solving the energy
/// equation for one component of ω (in the body's principal axes), with the sign asked for.
struct EnergyLevel {
  double energy = 0.0;
  int component = 2;  ///< ω_1, ω_2, ω_3 → 0, 1, 2
  double sign = 1.0;
};

/// The model of the base scenario: a body about a fixed point (docs/model.md), or a satellite on a
/// circular or elliptic orbit (an [orbit] scenario, docs/orbit.md).
enum class BaseModel { fixed_point, circular_orbit, elliptic_orbit };

/// "fixed point", "circular orbit" or "elliptic orbit".
const char* to_string(BaseModel m);

/// A sweep file, read and checked: every point's scenario has been built once (bad input at any
/// point is reported before any work).
struct SweepFile {
  std::string source;                        ///< the sweep file
  std::string base_source;                   ///< the base scenario file
  std::string base_text;                     ///< its text, as read
  std::string text;                          ///< the sweep file's text, as read
  BaseModel model = BaseModel::fixed_point;  ///< from the base scenario's [orbit] kind
  std::vector<std::string> quantities;
  Combine combine = Combine::grid;
  std::vector<Axis> axes;
  StabilityOptions stability;
  io::IntegrateOverrides integrate;
  std::optional<EnergyLevel> level;
  std::vector<std::string> input_files;  ///< the sweep file, the base and its mesh files
};

/// The quantities a sweep can compute.
const std::vector<std::string>& known_quantities();

/// Reads and checks a sweep file (and the scenario of every point). Throws InputError with one
/// line naming the key, what was expected and what was found.
SweepFile load_sweep(const std::string& path);

/// The first part of load_sweep: reads and checks the sweep file itself and reads the base
/// scenario's text, without building the points' scenarios (input_files stays empty).
SweepFile read_sweep(const std::string& path);

/// The sweep file's own part of read_sweep on its text (`path` names it in messages): base_source
/// is the `scenario` key as written, base_text stays empty.
SweepFile parse_sweep(const std::string& text, const std::string& path);

/// A sweep without files: the sweep's text (as a sweep file's, its `scenario` key naming the base
/// in messages only) over the base scenario's text, every point checked as load_sweep does.
SweepFile make_sweep(const std::string& text, const std::string& base_source,
                     const std::string& base_text);

/// The number of points: the product of the axes' lengths (grid) or their common length (zip).
std::size_t point_count(const SweepFile& s);

/// The swept values of point `index` (grid order: the last axis varies fastest).
std::vector<double> point_values(const SweepFile& s, std::size_t index);

/// The columns of the quantities, in the order of SweepFile::quantities.
std::vector<std::string> quantity_columns(const SweepFile& s);

/// One point's result: `status` "ok" or the outcome that ended its run (then `values` is empty:
/// a failed run is never recorded as a number). Booleans are 1 and 0; an inconclusive verdict
/// (lyapunov_stable) is NaN, written as an empty cell.
struct PointResult {
  std::string status;
  std::vector<double> values;
};

/// Computes the quantities at point `index`.
PointResult evaluate_point(const SweepFile& s, std::size_t index);

/// The scenario of point `index` (the base with the swept scenario keys set) and its stability
/// options. Throws InputError naming the point for a value the scenario rejects.
io::Scenario point_scenario(const SweepFile& s, std::size_t index,
                            StabilityOptions* options = nullptr);

/// The same for a sweep over an orbit scenario (SweepFile::model not fixed_point; point_scenario
/// refuses those): the base with the swept keys set, the inertia ratios body.k_R and body.k_Y
/// written as the moments (A, B, C) = B (1 − k_Y, 1 − k_R k_Y, 1 − k_R)/(1 − k_R k_Y).
io::OrbitScenario orbit_point_scenario(const SweepFile& s, std::size_t index);

/// How to run a sweep: threads, the checkpoint file, progress and stop requests.
struct RunOptions {
  int threads = 0;         ///< 0: OpenMP's default (all cores)
  std::string checkpoint;  ///< a file the finished points are appended to; empty: none
  bool resume = false;     ///< read the checkpoint's finished points and compute only the others
  /// Called (under a lock, from any thread) after each point with (done, total).
  std::function<void(std::size_t, std::size_t)> progress;
  /// Polled before each point: true stops the sweep (the points done stay in the checkpoint).
  std::function<bool()> stop;
};

struct SweepRun {
  std::vector<PointResult> results;  ///< by point index
  std::size_t resumed = 0;           ///< points read back from the checkpoint
  bool complete = true;              ///< false when stop() ended it early
  int threads = 1;
};

/// Evaluates every point (dynamic schedule over the threads). Each point's result depends only on
/// the point, so the results are the same bits for any thread count, and read back from a
/// checkpoint (17 significant digits) they are the same bits as computed. Throws InputError when
/// the checkpoint exists without `resume`, or belongs to another sweep.
SweepRun run_sweep(const SweepFile& s, const RunOptions& o);

/// The bookkeeping of a run, for any driver (the threads of run_sweep, the ranks of MPI): the
/// points still to compute (after reading the checkpoint back), and the results as they come, each
/// appended to the checkpoint. record() may be called from any thread.
class SweepLedger {
 public:
  /// Reads the checkpoint back when resuming (InputError as run_sweep).
  SweepLedger(const SweepFile& s, const RunOptions& o);
  const std::vector<std::size_t>& todo() const { return todo_; }
  void record(std::size_t index, PointResult r);
  /// The results by index ("not_run" where none came), with the count of workers.
  SweepRun finish(bool complete, int workers);

 private:
  RunOptions options_;
  std::string key_;  ///< the sweep's fingerprint, which every checkpoint line's check covers
  std::vector<std::optional<PointResult>> done_;
  std::vector<std::size_t> todo_;
  std::size_t resumed_ = 0, finished_ = 0;
  std::ofstream checkpoint_;
  std::mutex lock_;
};

/// evaluate_point, with any exception turned into the status `error: …` (one CSV cell).
PointResult evaluate_point_safely(const SweepFile& s, std::size_t index);

/// One result as one line of text (the checkpoint's format: index, status, the values in shortest
/// round-trip form and a check of the line) and back (nullopt for a line that is not whole, whose
/// check does not match or whose values are not `width` numbers); `width` is the number of
/// quantity columns.
std::string encode_result(std::size_t index, const PointResult& r);
std::optional<std::pair<std::size_t, PointResult>> decode_result(const std::string& line,
                                                                 std::size_t width);

}  // namespace newtop::sweep
