// newtop sweep SWEEP.toml: quantities over a grid (or zip) of parameters and initial conditions,
// on every core, checkpointed and resumable (docs/sweep.md).

#include "newtop/sweep/sweep.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "cli.hpp"
#include "command.hpp"
#include "interrupt.hpp"
#include "newtop/io/json.hpp"
#include "newtop/io/output.hpp"
#include "newtop/orbit/orbit.hpp"
#include "summary.hpp"
#include "sweep_hdf5.hpp"
#include "sweep_mpi.hpp"

namespace newtop::app {
namespace {

struct SweepArgs {
  std::string sweep;
  std::optional<int> threads;
  std::optional<std::string> out;
  bool resume = false, json = false;
};

/// A cell: empty for a failed point or an inconclusive verdict (never a number for them).
std::string cell(const sweep::PointResult& r, std::size_t k) {
  if (r.status != "ok" || std::isnan(r.values[k])) return "";
  return format_number(r.values[k]);
}

void write_csv(std::ostream& os, const sweep::SweepFile& s, const sweep::SweepRun& run) {
  const std::vector<std::string> columns = sweep::quantity_columns(s);
  std::string line;
  for (const auto& a : s.axes) line += a.key + ",";
  for (const auto& c : columns) line += c + ",";
  os << line << "status\n";
  for (std::size_t i = 0; i < run.results.size(); ++i) {
    line.clear();
    for (const double v : sweep::point_values(s, i)) line += format_number(v) + ",";
    for (std::size_t k = 0; k < columns.size(); ++k) line += cell(run.results[i], k) + ",";
    os << line << run.results[i].status << '\n';
  }
}

io::Json results_json(const sweep::SweepFile& s, const sweep::SweepRun& run) {
  io::Json cols = io::Json::object();
  for (std::size_t k = 0; k < s.axes.size(); ++k) {
    io::Json v = io::Json::array();
    for (std::size_t i = 0; i < run.results.size(); ++i) v.push_back(sweep::point_values(s, i)[k]);
    cols[s.axes[k].key] = v;
  }
  const std::vector<std::string> columns = sweep::quantity_columns(s);
  for (std::size_t k = 0; k < columns.size(); ++k) {
    io::Json v = io::Json::array();
    for (const auto& r : run.results) {
      if (r.status != "ok" || std::isnan(r.values[k])) {
        v.push_back(nullptr);
      } else {
        v.push_back(r.values[k]);
      }
    }
    cols[columns[k]] = v;
  }
  io::Json status = io::Json::array();
  for (const auto& r : run.results) status.push_back(r.status);
  cols["status"] = status;
  return cols;
}

/// Sends std::cout and std::cerr nowhere while it lives (the ranks other than 0).
class Silence {
 public:
  Silence() : out_(std::cout.rdbuf(nullptr)), err_(std::cerr.rdbuf(nullptr)) {}
  ~Silence() {
    std::cout.rdbuf(out_);
    std::cerr.rdbuf(err_);
  }
  Silence(const Silence&) = delete;
  Silence& operator=(const Silence&) = delete;

 private:
  std::streambuf* out_;
  std::streambuf* err_;
};

/// Progress on stderr: a bar that rewrites itself on a terminal, a line every 5 s otherwise.
class Progress {
 public:
  explicit Progress(bool quiet) : quiet_(quiet), tty_(isatty(STDERR_FILENO) != 0) {}
  void operator()(std::size_t done, std::size_t total) {
    if (quiet_) return;
    const auto now = std::chrono::steady_clock::now();
    const double since = std::chrono::duration<double>(now - last_).count();
    if (done < total && since < (tty_ ? 0.2 : 5.0)) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double rate = static_cast<double>(done - first_) / std::max(elapsed, 1e-9);
    const double left = rate > 0 ? static_cast<double>(total - done) / rate : 0.0;
    char buf[160];
    std::snprintf(buf, sizeof buf, "sweep: %zu/%zu points (%.1f%%), %.3g points/s, %.0f s left",
                  done, total, 100.0 * static_cast<double>(done) / static_cast<double>(total), rate,
                  left);
    std::cerr << (tty_ ? "\r" : "") << buf << (tty_ && done < total ? "" : "\n") << std::flush;
  }
  void start(std::size_t first) {
    first_ = first;
    start_ = last_ = std::chrono::steady_clock::now();
  }

 private:
  bool quiet_, tty_;
  std::size_t first_ = 0;
  std::chrono::steady_clock::time_point start_, last_;
};

int run_rank(const SweepArgs& a, const MpiSession& mpi) {
  const bool hdf5 = a.out && a.out->size() >= 3 && a.out->substr(a.out->size() - 3) == ".h5";
  if (hdf5 && !hdf5_available()) {
    throw InputError(
        "--out: this build has no HDF5 (install libhdf5-dev and rebuild); give FILE.csv");
  }
  if (a.resume && !a.out)
    throw InputError("--resume: needs --out (the checkpoint is OUT.checkpoint)");
  if (a.threads && *a.threads < 1) {
    throw InputError("--threads: expected an integer >= 1, found " + std::to_string(*a.threads));
  }
  const sweep::SweepFile s = sweep::load_sweep(a.sweep);
  if (s.model != sweep::BaseModel::fixed_point) {  // the units the orbit's μ implies (point 1's)
    const io::OrbitScenario first = sweep::orbit_point_scenario(s, 0);
    set_units(first.mu ? orbit_units(*first.mu)
                       : "those of the scenario (rate in rad per time unit)");
  }
  // Opened (and so checked) before any work; it appears only when the sweep is complete.
  std::unique_ptr<io::AtomicFile> file;
  std::string error;
  if (a.out && mpi.rank() == 0) {
    try {
      file = std::make_unique<io::AtomicFile>(*a.out, s.input_files);
    } catch (const InputError& e) {
      error = e.what();
    }
  }
  if (!mpi.confirm(error.empty())) throw InputError(error);
  // Checked, then closed at once: a sweep killed while it runs (SIGKILL, or a rank lost under
  // mpirun) leaves its checkpoint and no temporary beside it; the file is opened again, under a
  // fresh temporary, only to write the results.
  const bool write_out = file != nullptr;
  file.reset();
  const InterruptGuard guard;
  Progress progress(quiet());
  sweep::RunOptions o;
  o.threads = a.threads.value_or(0);
  o.resume = a.resume;
  if (a.out) o.checkpoint = *a.out + ".checkpoint";
  o.stop = [] { return pending_signal() != 0; };
  o.progress = [&](std::size_t done, std::size_t total) { progress(done, total); };
  progress.start(0);
  sweep::SweepRun run;
  if (mpi.size() > 1) {
    std::optional<sweep::SweepRun> r = run_sweep_ranks(mpi, s, o);
    if (!r) return kExitOk;  // a worker: rank 0 reports
    run = std::move(*r);
  } else {
    run = sweep::run_sweep(s, o);
  }
  if (!run.complete) {
    std::cerr << "newtop: interrupted by " << signal_name(pending_signal()) << "; "
              << (a.out ? "the finished points are in " + o.checkpoint +
                              " (newtop sweep --resume completes the sweep)"
                        : std::string("nothing was written"))
              << '\n';
    return 128 + pending_signal();
  }
  std::size_t failed = 0, off_level = 0;  // off the energy level: no run, not a failure
  for (const auto& r : run.results) {
    off_level += r.status == "off_level";
    failed += r.status != "ok" && r.status != "off_level";
  }
  if (write_out && hdf5) {
    write_hdf5(*a.out, s, run);  // HDF5 writes its own temporary and renames it
    std::remove(o.checkpoint.c_str());
  } else if (write_out) {
    io::AtomicFile out(*a.out, s.input_files);
    write_csv(out.stream(), s, run);
    out.commit();
    std::remove(o.checkpoint.c_str());
  }
  if (a.json) {
    io::Json j;
    j["sweep"] = s.source;
    j["scenario"] = s.base_source;
    j["points"] = run.results.size();
    j["failed"] = failed;
    j["off_level"] = off_level;
    j["resumed"] = run.resumed;
    j["threads"] = run.threads;
    j["quantities"] = s.quantities;
    j["out"] = a.out ? io::Json(*a.out) : io::Json(nullptr);
    j["results"] = results_json(s, run);
    print_json(std::cout, j);
    return kExitOk;
  }
  std::cout << "newtop sweep " << s.source << " (scenario " << s.base_source << ")\n"
            << run.results.size() << " points on " << run.threads
            << (mpi.size() > 1     ? (run.threads == 1 ? " worker rank" : " worker ranks")
                : run.threads == 1 ? " thread"
                                   : " threads");
  if (run.resumed) std::cout << " (" << run.resumed << " read back from the checkpoint)";
  std::cout << "; " << failed << " failed";
  if (off_level) std::cout << ", " << off_level << " off the energy level";
  std::cout << "\n";
  if (a.out) std::cout << "results: " << *a.out << "\n";
  if (!a.out) {
    print_units_line(std::cout);  // before the table, so that the table ends the output
    write_csv(std::cout, s, run);
  }
  return kExitOk;
}

int run(const SweepArgs& a) {
  const MpiSession mpi;
  if (mpi.rank() == 0) {
    // Said before the session ends (MPI_Finalize): the other ranks, done at once with the same
    // verdict, then end the job, and could take rank 0's line with it.
    try {
      return run_rank(a, mpi);
    } catch (const InputError& e) {
      return bad_input(e.what());
    }
  }
  // Every rank reads the sweep (the same files, the same verdict); only rank 0 speaks and writes.
  const Silence silent;
  try {
    return run_rank(a, mpi);
  } catch (const InputError&) {
    return kExitBadInput;  // rank 0 says why
  }
}

const RegisterCommand reg_sweep{Command{
    "sweep", "Quantities over a grid of parameters and initial conditions, on every core",
    [](CLI::App& sub) -> std::function<int()> {
      auto a = std::make_shared<SweepArgs>();
      sub.add_option("sweep", a->sweep, "sweep file (TOML, docs/sweep.md)")->required();
      sub.add_option("--threads", a->threads, "threads (default: all cores)");
      sub.add_option("--out", a->out, "write the results to this CSV or HDF5 (.h5) file");
      sub.add_flag("--resume", a->resume, "complete an interrupted sweep from OUT.checkpoint");
      sub.add_flag("--json", a->json, "print one JSON object (with every column)");
      return [a] { return run(*a); };
    }}};

}  // namespace
}  // namespace newtop::app
