// Running a sweep: points over OpenMP threads (dynamic schedule), results by index, and a
// checkpoint of the finished points that survives SIGKILL (docs/sweep.md).

#include "newtop/sweep/sweep.hpp"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <mutex>
#include <sstream>
#include <string_view>

#include "newtop/integrate/ensemble.hpp"
#include "newtop/sweep/sweep_ensemble.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace newtop::sweep {
namespace {

constexpr const char* kMagic = "newtop-sweep-checkpoint 2";

/// FNV-1a, 64 bits, of a sequence of texts (each closed by a 0xff byte, which UTF-8 never holds).
class Fnv {
 public:
  Fnv& add(std::string_view text) {
    for (const unsigned char c : text) {
      h_ ^= c;
      h_ *= 1099511628211ull;
    }
    h_ ^= 0xff;
    h_ *= 1099511628211ull;
    return *this;
  }
  std::uint64_t value() const { return h_; }
  std::string hex() const {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h_));
    return buf;
  }

 private:
  std::uint64_t h_ = 14695981039346656037ull;
};

/// The hash of the sweep file, the base scenario and the columns: a checkpoint of another sweep is
/// refused.
std::string fingerprint(const SweepFile& s) {
  Fnv h;
  h.add(s.text).add(s.base_text);
  for (const auto& c : quantity_columns(s)) h.add(c);
  return h.hex();
}

/// One finished point: `index<TAB>status<TAB>v1,v2,…<TAB>check` (shortest round-trip numbers),
/// `check` the hash of the key (the sweep's fingerprint in a checkpoint) and the rest of the line:
/// a line edited or damaged after it was written does not read back.
std::string checkpoint_line(std::size_t index, const PointResult& r, std::string_view key) {
  std::string line = std::to_string(index) + '\t' + r.status + '\t';
  for (std::size_t k = 0; k < r.values.size(); ++k) {
    line += (k ? "," : "") +
            (std::isnan(r.values[k]) ? std::string("nan") : format_number(r.values[k]));
  }
  return line + '\t' + Fnv().add(key).add(line).hex() + '\n';
}

/// A value as written by checkpoint_line: `nan` or a whole number (std::from_chars, round trip).
std::optional<double> parse_value(std::string_view cell) {
  if (cell == "nan") return std::numeric_limits<double>::quiet_NaN();
  double v = 0;
  const auto r = std::from_chars(cell.data(), cell.data() + cell.size(), v);
  if (cell.empty() || r.ec != std::errc() || r.ptr != cell.data() + cell.size()) {
    return std::nullopt;
  }
  return v;
}

/// One line of checkpoint_line back (without its newline): nullopt unless it is whole, its check
/// matches and it holds `width` values for the status ok (none for another status).
std::optional<std::pair<std::size_t, PointResult>> parse_line(std::string_view line,
                                                              std::size_t width,
                                                              std::string_view key) {
  // The check as a number (16 lowercase hex digits), compared as one.
  const std::size_t check = line.rfind('\t');
  if (check == std::string_view::npos) return std::nullopt;
  const std::string_view check_text = line.substr(check + 1);
  std::uint64_t written = 0;
  const auto parsed =
      std::from_chars(check_text.data(), check_text.data() + check_text.size(), written, 16);
  if (check_text.size() != 16 ||
      check_text.find_first_not_of("0123456789abcdef") != std::string_view::npos ||
      parsed.ptr != check_text.data() + check_text.size() ||
      written != Fnv().add(key).add(line.substr(0, check)).value()) {
    return std::nullopt;
  }
  const std::size_t tab1 = line.find('\t');
  const std::size_t tab2 = line.find('\t', tab1 + 1);
  if (tab2 >= check) return std::nullopt;
  const std::string_view index_text = line.substr(0, tab1);
  const std::string_view values = line.substr(tab2 + 1, check - tab2 - 1);
  if (index_text.empty() || index_text.size() > 18 ||
      index_text.find_first_not_of("0123456789") != std::string_view::npos) {
    return std::nullopt;
  }
  PointResult r{std::string(line.substr(tab1 + 1, tab2 - tab1 - 1)), {}};
  if (r.status.empty()) return std::nullopt;
  for (std::size_t begin = 0; !values.empty() && begin <= values.size();) {
    const std::size_t end = std::min(values.find(',', begin), values.size());
    const std::optional<double> v = parse_value(values.substr(begin, end - begin));
    if (!v) return std::nullopt;
    r.values.push_back(*v);
    begin = end + 1;
  }
  if (r.status == "ok" ? r.values.size() != width : !r.values.empty()) return std::nullopt;
  return std::make_pair(static_cast<std::size_t>(std::stoull(std::string(index_text))),
                        std::move(r));
}

/// Reads the finished points back; a last line cut short by a kill (no newline) is ignored, any
/// other line that does not read back as a point of this sweep refuses the checkpoint.
std::size_t read_checkpoint(const SweepFile& s, const std::string& path,
                            std::vector<std::optional<PointResult>>& done) {
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string key = fingerprint(s);
  std::istringstream lines(text);
  std::string line;
  if (!std::getline(lines, line) || line != std::string(kMagic) + ' ' + key) {
    throw InputError("--resume: " + path +
                     " is the checkpoint of another sweep (or not one); "
                     "delete it to start again");
  }
  const std::size_t width = quantity_columns(s).size();
  std::size_t count = 0, number = 1;
  std::size_t pos = line.size() + 1;
  while (std::getline(lines, line)) {
    pos += line.size() + 1;
    ++number;
    if (pos > text.size() + 1 || text[pos - 1] != '\n') break;  // no newline: cut by the kill
    auto r = parse_line(line, width, key);
    if (!r || r->first >= done.size()) {
      throw InputError("--resume: " + path + " line " + std::to_string(number) +
                       ": expected a finished point of this sweep, found a damaged or edited "
                       "line; delete the checkpoint to start again");
    }
    if (!done[r->first]) ++count;
    done[r->first] = std::move(r->second);
  }
  return count;
}

}  // namespace

SweepLedger::SweepLedger(const SweepFile& s, const RunOptions& o)
    : options_(o), key_(fingerprint(s)), done_(point_count(s)) {
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
      fresh << kMagic << ' ' << key_ << '\n';
      for (std::size_t i = 0; i < n; ++i) {
        if (done_[i]) fresh << checkpoint_line(i, *done_[i], key_);
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
    checkpoint_ << checkpoint_line(index, r, key_);
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
  return checkpoint_line(index, r, "");
}

std::optional<std::pair<std::size_t, PointResult>> decode_result(const std::string& line,
                                                                 std::size_t width) {
  std::string_view l(line);
  if (!l.empty() && l.back() == '\n') l.remove_suffix(1);
  return parse_line(l, width, "");
}

std::size_t batch_size(const SweepFile& s, std::size_t count, int workers) {
  if (s.model != BaseModel::fixed_point || !ensemble_sweep(s)) return 1;
  const std::size_t shares = 4 * static_cast<std::size_t>(std::max(workers, 1));
  const std::size_t block = simd_block(best_simd_path());
  const std::size_t share = std::clamp<std::size_t>((count + shares - 1) / shares, 1, 256);
  return (share + block - 1) / block * block;
}

std::vector<PointResult> evaluate_batch(const SweepFile& s, std::span<const std::size_t> indices) {
  // The ensemble stepper holds the fixed point's model: an orbit's points run one by one.
  if (s.model == BaseModel::fixed_point && ensemble_sweep(s)) return evaluate_points(s, indices);
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
