// Running a sweep: points over OpenMP threads (dynamic schedule), results by index, and a
// checkpoint of the finished points that survives SIGKILL (docs/sweep.md).

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>

#include "newtop/sweep/sweep.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace newtop::sweep {
namespace {

constexpr const char* kMagic = "newtop-sweep-checkpoint 1";

/// FNV-1a of the sweep file, the base scenario and the columns: a checkpoint of another sweep is
/// refused.
std::string fingerprint(const SweepFile& s) {
  std::uint64_t h = 14695981039346656037ull;
  auto add = [&](const std::string& text) {
    for (const unsigned char c : text) {
      h ^= c;
      h *= 1099511628211ull;
    }
    h ^= 0xff;
    h *= 1099511628211ull;
  };
  add(s.text);
  add(s.base_text);
  for (const auto& c : quantity_columns(s)) add(c);
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

/// One finished point: `index<TAB>status<TAB>v1,v2,…` (shortest round-trip numbers).
std::string checkpoint_line(std::size_t index, const PointResult& r) {
  std::string line = std::to_string(index) + '\t' + r.status + '\t';
  for (std::size_t k = 0; k < r.values.size(); ++k) {
    line += (k ? "," : "") +
            (std::isnan(r.values[k]) ? std::string("nan") : format_number(r.values[k]));
  }
  return line + '\n';
}

/// Reads the finished points back; a last line cut short by a kill is ignored.
std::size_t read_checkpoint(const SweepFile& s, const std::string& path,
                            std::vector<std::optional<PointResult>>& done) {
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::istringstream lines(text);
  std::string line;
  if (!std::getline(lines, line) || line != std::string(kMagic) + ' ' + fingerprint(s)) {
    throw InputError("--resume: " + path +
                     " is the checkpoint of another sweep (or not one); "
                     "delete it to start again");
  }
  const std::size_t width = quantity_columns(s).size();
  std::size_t count = 0;
  std::size_t pos = line.size() + 1;
  while (std::getline(lines, line)) {
    pos += line.size() + 1;
    if (pos > text.size() + 1 || text[pos - 1] != '\n') break;  // no newline: cut by the kill
    std::istringstream f(line);
    std::string index_text, status, values;
    if (!std::getline(f, index_text, '\t') || !std::getline(f, status, '\t')) break;
    std::getline(f, values);
    PointResult r{status, {}};
    std::istringstream v(values);
    std::string cell;
    while (std::getline(v, cell, ',')) r.values.push_back(std::strtod(cell.c_str(), nullptr));
    const std::size_t index = std::stoul(index_text);
    if (index >= done.size() || (status == "ok" && r.values.size() != width)) break;
    if (!done[index]) ++count;
    done[index] = std::move(r);
  }
  return count;
}

}  // namespace

SweepRun run_sweep(const SweepFile& s, const RunOptions& o) {
  const std::size_t n = point_count(s);
  std::vector<std::optional<PointResult>> done(n);
  SweepRun out;
  std::ofstream checkpoint;
  if (!o.checkpoint.empty()) {
    const bool exists = std::filesystem::exists(o.checkpoint);
    if (exists && !o.resume) {
      throw InputError(
          "--out: " + o.checkpoint +
          " exists (an interrupted sweep): give --resume to complete it, or delete it");
    }
    if (exists) out.resumed = read_checkpoint(s, o.checkpoint, done);
    // Rewritten whole (header and the points read), then appended to.
    checkpoint.open(o.checkpoint, std::ios::trunc);
    checkpoint << kMagic << ' ' << fingerprint(s) << '\n';
    for (std::size_t i = 0; i < n; ++i) {
      if (done[i]) checkpoint << checkpoint_line(i, *done[i]);
    }
    checkpoint.flush();
  }
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < n; ++i) {
    if (!done[i]) todo.push_back(i);
  }
  std::mutex lock;
  std::size_t finished = n - todo.size();
  std::atomic<bool> stopped{false};
  const auto count = static_cast<std::int64_t>(todo.size());
#ifdef _OPENMP
  out.threads = o.threads > 0 ? o.threads : omp_get_max_threads();
#endif
#pragma omp parallel for schedule(dynamic, 1) num_threads(out.threads)
  for (std::int64_t j = 0; j < count; ++j) {
    if (stopped.load() || (o.stop && o.stop())) {
      stopped = true;
      continue;
    }
    const std::size_t i = todo[static_cast<std::size_t>(j)];
    PointResult r;
    try {
      r = evaluate_point(s, i);
    } catch (const std::exception& e) {  // never a number for a point that failed
      std::string what = std::string("error: ") + e.what();
      for (char& c : what) {
        if (c == ',' || c == '\t' || c == '\n' || c == '\r') c = ' ';  // one CSV cell, one line
      }
      r = {what, {}};
    }
    const std::lock_guard<std::mutex> guard(lock);
    if (checkpoint.is_open()) {
      checkpoint << checkpoint_line(i, r);
      checkpoint.flush();
    }
    done[i] = std::move(r);
    ++finished;
    if (o.progress) o.progress(finished, n);
  }
  out.complete = !stopped.load();
  out.results.reserve(n);
  for (auto& d : done) out.results.push_back(d ? std::move(*d) : PointResult{"not_run", {}});
  return out;
}

}  // namespace newtop::sweep
