// Hostile mesh, TetGen and point-mass files through the newtop program: a scenario whose
// [mass_model] names the file ends with exit code 2 and exactly one line on standard error,
// `newtop: error: …` ending with the reader's message (tests/io/mesh_cases.hpp) — never a signal,
// a hang, an internal error or output on standard output.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/mesh_cases.hpp"
#include "support/cli.hpp"

namespace test_mesh_cli {
namespace {

namespace fs = std::filesystem;

fs::path scratch_dir() { return newtop::test::scratch_dir("newtop_mesh_cli"); }

/// A scenario whose [mass_model] reads `file` (point masses when `points`), in the exact field.
fs::path scenario_for(const std::string& file, bool points, const std::string& name) {
  const fs::path p = scratch_dir() / (name + ".toml");
  std::ofstream(p) << "[mass_model]\nkind = \"" << (points ? "points" : "polyhedron")
                   << "\"\nfile = \"" << file << "\"\n"
                   << (points ? "" : "density = 1.0\n")
                   << "\n[field]\nkind = \"exact\"\nmu = 1.0\nR = 100.0\n\n[initial]\nomega = [0, "
                      "0, 1]\ngamma = [0, 0, 1]\n";
  return p;
}

/// Runs `newtop ARGS` and checks the contract for bad input: exit 2, nothing on standard output,
/// one line on standard error that begins `newtop: error: ` and ends with `message`.
void expect_one_line_exit_2(const std::string& args, const std::string& message,
                            const std::string& what) {
  const auto r = newtop::test::run_newtop(args, newtop::test::Stderr::separate);
  EXPECT_EQ(r.code, 2) << what << "\n" << r.err;
  EXPECT_EQ(r.out, "") << what;
  ASSERT_FALSE(r.err.empty()) << what;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << what << "\n" << r.err;
  const std::string line = r.err.substr(0, r.err.size() - 1);
  EXPECT_EQ(line.rfind("newtop: error: ", 0), 0u) << what << "\n" << line;
  EXPECT_TRUE(line.size() >= message.size() &&
              line.compare(line.size() - message.size(), message.size(), message) == 0)
      << what << "\n  line: " << line << "\n  want: …" << message;
}

TEST(MeshCli, EveryHostileFileExitsTwoWithItsLine) {
  for (const newtop::test::BadFile& c : newtop::test::bad_files()) {
    const std::string stem = (scratch_dir() / c.name).string();
    const std::string file = newtop::test::write_case(c, stem);
    const bool points = std::string_view(c.corpus) == "point_csv";
    const fs::path scenario = scenario_for(file, points, c.name);
    expect_one_line_exit_2("field " + scenario.string() + " --gamma 0,0,1",
                           newtop::test::expected_message(c, stem),
                           std::string(c.corpus) + "/" + c.name);
  }
}

TEST(MeshCli, SimulateRefusesTheIssueOffFileBeforeRunning) {
  const newtop::test::BadFile& c = newtop::test::bad_files().front();  // header promises a face
  const std::string stem = (scratch_dir() / "simulate_case").string();
  const std::string file = newtop::test::write_case(c, stem);
  std::ofstream(scenario_for(file, false, "simulate_case"), std::ios::app)
      << "\n[integrate]\nt_end = 1.0\nstep = 0.1\n";
  expect_one_line_exit_2("simulate " + (scratch_dir() / "simulate_case.toml").string(),
                         newtop::test::expected_message(c, stem), "simulate");
}

TEST(MeshCli, NonRegularFilesAreRefused) {
  const fs::path dir = scratch_dir() / "directory.stl";
  fs::create_directories(dir);
  expect_one_line_exit_2(
      "field " + scenario_for(dir.string(), false, "dir").string() + " --gamma 0,0,1",
      dir.string() + ": expected a regular file, found a directory", "dir");
  expect_one_line_exit_2(
      "field " + scenario_for("/dev/zero", true, "zero").string() + " --gamma 0,0,1",
      "/dev/zero: expected a regular file, found a character device", "/dev/zero");
  const fs::path fifo = scratch_dir() / "fifo.obj";
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expect_one_line_exit_2(
      "field " + scenario_for(fifo.string(), false, "fifo").string() + " --gamma 0,0,1",
      fifo.string() + ": expected a regular file, found a FIFO (named pipe)", "fifo");
}

}  // namespace
}  // namespace test_mesh_cli
