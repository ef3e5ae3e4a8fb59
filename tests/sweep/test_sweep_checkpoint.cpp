// The checkpoint of a sweep read back by --resume: the points restored equal the computed ones to
// the bit, a line cut by a kill is ignored, and a line edited after it was written (found by
// tests/fuzz/fuzz_checkpoint.cpp: format 1 restored `0 ok 7,garbage,-1e300` as linearly_stable = 7,
// lyapunov_stable = 0) refuses the checkpoint.

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <limits>
#include <string>

#include "newtop/sweep/sweep.hpp"
#include "support/cli.hpp"

namespace test_sweep_checkpoint {
namespace {

namespace fs = std::filesystem;
using namespace newtop;

fs::path scratch(const std::string& name) {
  return test::scratch_path("newtop_sweep_checkpoint", name);
}

sweep::SweepFile beletsky_sweep() {
  const std::string text = "scenario = \"" + test::example_path("stability_beletsky.toml") +
                           "\"\nquantities = [\"stability\"]\n[[axes]]\nkey = "
                           "\"stability.omega\"\nvalues = [0.5, 1.2, 2.0]\n[stability]\naxis = "
                           "\"z\"\n";
  return sweep::load_sweep(test::write_text(scratch("sweep.toml"), text).string());
}

/// The points a checkpoint restores ("not_run" where it has none).
sweep::SweepRun resume(const sweep::SweepFile& s, const fs::path& checkpoint) {
  sweep::RunOptions o;
  o.checkpoint = checkpoint.string();
  o.resume = true;
  sweep::SweepLedger ledger(s, o);
  return ledger.finish(true, 1);
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

TEST(SweepCheckpoint, RestoresThePointsToTheBitAndRefusesAnEditedLine) {
  const sweep::SweepFile s = beletsky_sweep();
  const fs::path checkpoint = scratch("out.csv.checkpoint");
  fs::remove(checkpoint);
  sweep::RunOptions o;
  o.checkpoint = checkpoint.string();
  o.threads = 1;
  const sweep::SweepRun run = sweep::run_sweep(s, o);
  const std::string text = test::read_text(checkpoint);

  const sweep::SweepRun back = resume(s, checkpoint);
  EXPECT_EQ(back.resumed, 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(back.results[i].status, run.results[i].status) << i;
    EXPECT_TRUE(same_bits(back.results[i].values, run.results[i].values)) << i;
  }

  // The last line cut short (no newline): ignored, its point computed again.
  test::write_text(checkpoint, text.substr(0, text.size() - 5));
  EXPECT_EQ(resume(s, checkpoint).resumed, 2u);

  // A value of the first point edited: the line's check refuses the checkpoint, naming the line.
  std::string edited = text;
  const std::size_t values = edited.find("\tok\t") + 4;
  edited[values] = edited[values] == '1' ? '7' : '1';
  test::write_text(checkpoint, edited);
  try {
    resume(s, checkpoint);
    ADD_FAILURE() << "an edited checkpoint was read back";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
  }
  fs::remove(checkpoint);
}

TEST(SweepCheckpoint, TheTransportLineReadsBackAndRefusesAnEditedOne) {
  const sweep::PointResult r{"ok", {1.0, std::numeric_limits<double>::quiet_NaN(), -0.125}};
  const std::string line = sweep::encode_result(7, r);
  const auto back = sweep::decode_result(line, 3);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->first, 7u);
  EXPECT_EQ(back->second.values[2], -0.125);
  std::string edited = line;
  edited[edited.find("-0.125")] = '+';
  EXPECT_FALSE(sweep::decode_result(edited, 3));
  EXPECT_FALSE(sweep::decode_result(line, 2));  // another width
}

}  // namespace
}  // namespace test_sweep_checkpoint
