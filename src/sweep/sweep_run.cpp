// Running a sweep: points over OpenMP threads (dynamic schedule), results by index, and a
// checkpoint of the finished points that survives SIGKILL (docs/sweep.md).

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>

#include "newtop/integrate/ensemble.hpp"
#include "newtop/sweep/sweep.hpp"
#include "newtop/sweep/sweep_ensemble.hpp"

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

/// One line of the checkpoint back: nullopt for a line that is not whole.
std::optional<std::pair<std::size_t, PointResult>> parse_line(const std::string& line,
                                                              std::size_t width) {
  std::istringstream f(line);
  std::string index_text, status, values;
  if (!std::getline(f, index_text, '\t') || !std::getline(f, status, '\t')) return std::nullopt;
  std::getline(f, values);
  if (index_text.empty() || index_text.size() > 18 ||
      index_text.find_first_not_of("0123456789") != std::string::npos) {
    return std::nullopt;
  }
  PointResult r{status, {}};
  std::istringstream v(values);
  std::string cell;
  while (std::getline(v, cell, ',')) r.values.push_back(std::strtod(cell.c_str(), nullptr));
  if (status == "ok" ? r.values.size() != width : !r.values.empty()) return std::nullopt;
  return std::make_pair(static_cast<std::size_t>(std::stoull(index_text)), std::move(r));
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
    auto r = parse_line(line, width);
    if (!r || r->first >= done.size()) break;
    if (!done[r->first]) ++count;
    done[r->first] = std::move(r->second);
  }
  return count;
}

}  // namespace

SweepLedger::SweepLedger(const SweepFile& s, const RunOptions& o)
    : options_(o), done_(point_count(s)) {
  const std::size_t n = done_.size();
  if (!o.checkpoint.empty()) {
    const bool exists = std::filesystem::exists(o.checkpoint);
    if (exists && !o.resume) {
      throw InputError(
          "--out: " + o.checkpoint +
          " exists (an interrupted sweep): give --resume to complete it, or delete it");
    }
    if (exists) resumed_ = read_checkpoint(s, o.checkpoint, done_);
    // Rewritten whole (header and the points read) under a temporary name and renamed, then
    // appended to: a kill at any moment leaves a checkpoint that reads back.
    const std::string tmp = o.checkpoint + ".new";
    {
      std::ofstream fresh(tmp, std::ios::trunc);
      fresh << kMagic << ' ' << fingerprint(s) << '\n';
      for (std::size_t i = 0; i < n; ++i) {
        if (done_[i]) fresh << checkpoint_line(i, *done_[i]);
      }
      if (!fresh.flush()) throw InputError("--out: cannot write " + tmp);
    }
    std::filesystem::rename(tmp, o.checkpoint);
    checkpoint_.open(o.checkpoint, std::ios::app);
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!done_[i]) todo_.push_back(i);
  }
  finished_ = n - todo_.size();
}

void SweepLedger::record(std::size_t index, PointResult r) {
  const std::lock_guard<std::mutex> guard(lock_);
  if (checkpoint_.is_open()) {
    checkpoint_ << checkpoint_line(index, r);
    checkpoint_.flush();
  }
  done_[index] = std::move(r);
  ++finished_;
  if (options_.progress) options_.progress(finished_, done_.size());
}

SweepRun SweepLedger::finish(bool complete, int workers) {
  SweepRun out;
  out.resumed = resumed_;
  out.complete = complete;
  out.threads = workers;
  out.results.reserve(done_.size());
  for (auto& d : done_) out.results.push_back(d ? std::move(*d) : PointResult{"not_run", {}});
  return out;
}

PointResult evaluate_point_safely(const SweepFile& s, std::size_t index) {
  try {
    return evaluate_point(s, index);
  } catch (const std::exception& e) {  // never a number for a point that failed
    std::string what = std::string("error: ") + e.what();
    for (char& c : what) {
      if (c == ',' || c == '\t' || c == '\n' || c == '\r') c = ' ';  // one CSV cell, one line
    }
    return {what, {}};
  }
}

std::string encode_result(std::size_t index, const PointResult& r) {
  return checkpoint_line(index, r);
}

std::optional<std::pair<std::size_t, PointResult>> decode_result(const std::string& line,
                                                                 std::size_t width) {
  return parse_line(line, width);
}

std::size_t batch_size(const SweepFile& s, std::size_t count, int workers) {
  if (!ensemble_sweep(s)) return 1;
  const std::size_t shares = 4 * static_cast<std::size_t>(std::max(workers, 1));
  const std::size_t block = simd_block(best_simd_path());
  const std::size_t share = std::clamp<std::size_t>((count + shares - 1) / shares, 1, 256);
  return (share + block - 1) / block * block;
}

std::vector<PointResult> evaluate_batch(const SweepFile& s, std::span<const std::size_t> indices) {
  if (ensemble_sweep(s)) return evaluate_points(s, indices);
  std::vector<PointResult> r;
  r.reserve(indices.size());
  for (const std::size_t i : indices) r.push_back(evaluate_point_safely(s, i));
  return r;
}

SweepRun run_sweep(const SweepFile& s, const RunOptions& o) {
  SweepLedger ledger(s, o);
  const std::vector<std::size_t>& todo = ledger.todo();
  std::atomic<bool> stopped{false};
  const auto count = static_cast<std::int64_t>(todo.size());
  int threads = 1;
#ifdef _OPENMP
  threads = o.threads > 0 ? o.threads : omp_get_max_threads();
#endif
  // Batches of points (one point each unless the sweep goes through the ensemble stepper,
  // sweep_ensemble.hpp), each point's result the same bits as evaluate_point's.
  const auto batch = static_cast<std::int64_t>(batch_size(s, todo.size(), threads));
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::int64_t first = 0; first < count; first += batch) {
    if (stopped.load() || (o.stop && o.stop())) {
      stopped = true;
      continue;
    }
    const auto part = std::span<const std::size_t>(todo).subspan(
        static_cast<std::size_t>(first), static_cast<std::size_t>(std::min(batch, count - first)));
    std::vector<PointResult> r = evaluate_batch(s, part);
    for (std::size_t k = 0; k < part.size(); ++k) ledger.record(part[k], std::move(r[k]));
  }
  return ledger.finish(!stopped.load(), threads);
}

}  // namespace newtop::sweep
