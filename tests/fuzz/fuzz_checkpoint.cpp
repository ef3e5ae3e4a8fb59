// Fuzz harness: the checkpoint that `newtop sweep --resume` reads back (sweep::SweepLedger). The
// bytes are the checkpoint of a small fixed sweep (kSweep over base.toml, sweep_bases.hpp), whose
// points are computed once, fresh. The promise: a checkpoint is refused (InputError), or every
// point it restores equals the fresh point to the bit (status and values), and the checkpoint the
// ledger writes back restores the same points again.

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>

#include "harness.hpp"
#include "newtop/sweep/sweep.hpp"
#include "sweep_bases.hpp"

namespace {

using namespace newtop;

// 4 points of Beletsky's problem: two spin rates (one below, one above the threshold 0.99…) and
// two moments C, 7 columns each (stable and unstable verdicts, eigenvalues, equilibrium counts).
constexpr const char* kSweep = R"(scenario = "base.toml"
quantities = ["stability", "equilibria"]

[[axes]]
key = "stability.omega"
values = [0.5, 1.2]

[[axes]]
key = "body.inertia[2]"
values = [1.9, 2.3]

[stability]
axis = "z"
)";

void require(bool ok) {
  if (!ok) std::abort();
}

/// The same double to the bit, or both NaN (a NaN is written `nan` whatever its sign and payload:
/// the CSV leaves its cell empty, the JSON writes null).
bool same_bits(double a, double b) {
  return (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, sizeof a) == 0;
}

bool same(const sweep::PointResult& a, const sweep::PointResult& b) {
  if (a.status != b.status || a.values.size() != b.values.size()) return false;
  for (std::size_t k = 0; k < a.values.size(); ++k) {
    if (!same_bits(a.values[k], b.values[k])) return false;
  }
  return true;
}

struct Fixture {
  std::filesystem::path dir;
  sweep::SweepFile sweep;
  std::vector<sweep::PointResult> fresh;
};

void write_seeds(const Fixture& f, const std::filesystem::path& dir);

const Fixture& fixture() {
  static const Fixture f = [] {
    Fixture x;
    x.dir = std::filesystem::temp_directory_path() /
            ("newtop_fuzz_checkpoint_" + std::to_string(::getpid()));
    fuzz::write_sweep_bases(x.dir);
    fuzz::write_file(x.dir / "sweep.toml", kSweep);
    x.sweep = sweep::load_sweep((x.dir / "sweep.toml").string());
    for (std::size_t i = 0; i < sweep::point_count(x.sweep); ++i) {
      x.fresh.push_back(sweep::evaluate_point_safely(x.sweep, i));
    }
    if (const char* seeds = std::getenv("NEWTOP_FUZZ_CHECKPOINT_SEEDS")) write_seeds(x, seeds);
    return x;
  }();
  static const fuzz::FolderRemovedAtExit removed{f.dir};
  return f;
}

/// The points a checkpoint restores ("not_run" for the others), checked against the fresh ones.
std::vector<sweep::PointResult> restore(const Fixture& f, const std::string& path) {
  sweep::RunOptions o;
  o.checkpoint = path;
  o.resume = true;
  sweep::SweepLedger ledger(f.sweep, o);
  std::vector<sweep::PointResult> r = ledger.finish(true, 1).results;
  std::size_t restored = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (r[i].status == "not_run" && r[i].values.empty()) continue;
    ++restored;
    require(same(r[i], f.fresh[i]));
  }
  require(restored + ledger.todo().size() == r.size());
  return r;
}

/// With NEWTOP_FUZZ_CHECKPOINT_SEEDS=DIR, writes the seeds of tests/fuzz/corpus/checkpoint there:
/// the checkpoint of the whole sweep as run_sweep writes it, and its variants.
void write_seeds(const Fixture& f, const std::filesystem::path& dir) {
  const std::filesystem::path whole = dir / "seed_complete";
  std::filesystem::remove(whole);
  sweep::RunOptions o;
  o.checkpoint = whole.string();
  o.threads = 1;
  sweep::run_sweep(f.sweep, o);
  std::ifstream in(whole, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::size_t> ends;  // the end of each line, its newline included
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') ends.push_back(i + 1);
  }
  fuzz::write_file(dir / "seed_header_only", text.substr(0, ends[0]));
  fuzz::write_file(dir / "seed_two_points", text.substr(0, ends[2]));
  fuzz::write_file(dir / "seed_cut_by_a_kill", text.substr(0, ends[3] - 7));
  std::string edited = text;  // a digit of the first value changed: the check refuses the line
  const std::size_t digit = edited.find_first_of("123456789", edited.find('\t', ends[0]) + 4);
  edited[digit] = edited[digit] == '9' ? '8' : '9';
  fuzz::write_file(dir / "regress_edited_value", edited);
  std::string other = text;  // the header of another sweep
  other[ends[0] - 2] = other[ends[0] - 2] == '0' ? '1' : '0';
  fuzz::write_file(dir / "seed_another_sweep", other);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Fixture& f = fixture();
  const std::string path = (f.dir / "out.csv.checkpoint").string();
  fuzz::write_file(path, fuzz::bytes(data, size));
  fuzz::expect_result_or_input_error([&] {
    const std::vector<sweep::PointResult> first = restore(f, path);
    // The ledger rewrote the checkpoint (header and the points restored): it reads back the same.
    std::vector<sweep::PointResult> again;
    try {
      again = restore(f, path);
    } catch (const InputError&) {
      std::abort();
    }
    for (std::size_t i = 0; i < first.size(); ++i) require(same(first[i], again[i]));
  });
  return 0;
}
