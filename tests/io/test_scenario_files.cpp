// Files that are not what a reader can take: the scenario file itself and the files a scenario
// names (meshes, point CSVs) must be regular files of bounded size, refused with one line before
// anything reads them (a directory failed late, /dev/zero read forever, a FIFO blocked).

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "newtop/io/scenario.hpp"
#include "reject.hpp"
#include "support/cli.hpp"

namespace newtop::io {
namespace test_scenario_files {
namespace {

using newtop::test::run_newtop;
using newtop::test::Stderr;

const std::string kInitial = "[initial]\nomega = [0.5, 1.1, -0.4]\ngamma = [0.48, -0.6, 0.64]\n";

// The scenario file as named on the command line: exit 2, exactly `message` on stderr.
void expect_scenario_refused(const std::string& path, const std::string& message) {
  try {
    load_scenario(path);
    ADD_FAILURE() << path << ": accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
  const auto r = run_newtop("integrals " + path, Stderr::separate);
  EXPECT_EQ(r.code, 2) << path;
  EXPECT_EQ(r.err, "newtop: error: " + message + "\n");
  EXPECT_EQ(r.out, "");
}

std::string fifo(const std::string& name) {
  const std::string path = testing::TempDir() + "newtop_io_" + name;
  std::filesystem::remove(path);
  EXPECT_EQ(::mkfifo(path.c_str(), 0600), 0);
  return path;
}

std::string sparse_file(const std::string& name, std::uintmax_t bytes) {
  const std::string path = test::write_file(name, "");
  std::filesystem::resize_file(path, bytes);
  return path;
}

TEST(ScenarioFiles, ScenarioFileMustBeARegularFileOfBoundedSize) {
  const std::string dir = testing::TempDir() + "newtop_io_dir.toml";
  std::filesystem::create_directories(dir);
  expect_scenario_refused(dir, dir + ": scenario file: expected a regular file, found a directory");
  expect_scenario_refused("/dev/zero",
                          "/dev/zero: scenario file: expected a regular file, found a character "
                          "device");
  const std::string f = fifo("scenario.fifo");
  expect_scenario_refused(f, f + ": scenario file: expected a regular file, found a FIFO (named "
                                 "pipe)");
  // 4 MiB + 1 byte (a sparse file: nothing is written).
  const std::string big = sparse_file("big.toml", (std::uintmax_t{4} << 20) + 1);
  expect_scenario_refused(big,
                          big + ": scenario file: expected at most 4194304 bytes, found 4194305");
  const std::string none = testing::TempDir() + "newtop_io_none.toml";
  expect_scenario_refused(none, none + ": scenario file: cannot read it: no such file");
  // The bound also holds for text handed to the parser directly.
  try {
    parse_scenario(std::string((std::size_t{4} << 20) + 1, '#'), "s.toml");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "s.toml: malformed TOML: 4194305 bytes, more than the 4194304 bytes newtop reads "
              "from a TOML file");
  }
}

std::string mesh_scenario(const std::string& file) {
  return "[mass_model]\nkind = \"polyhedron\"\nfile = \"" + file +
         "\"\nmass = 1.0\n[field]\nkind = \"exact\"\nmu = 1.0\nR = 100.0\n" + kInitial;
}

TEST(ScenarioFiles, MassModelFileMustBeARegularFileOfBoundedSize) {
  const std::string head = ":3:8: [mass_model] file: ";
  test::expect_rejected("mesh_dev_zero", mesh_scenario("/dev/zero"),
                        head + "/dev/zero: expected a regular file, found a character device");
  const std::string dir = testing::TempDir() + "newtop_io_mesh_dir.off";
  std::filesystem::create_directories(dir);
  test::expect_rejected("mesh_dir", mesh_scenario(dir),
                        head + dir + ": expected a regular file, found a directory");
  const std::string f = fifo("mesh.off");
  test::expect_rejected("mesh_fifo", mesh_scenario(f),
                        head + f + ": expected a regular file, found a FIFO (named pipe)");
  // 256 MiB + 1 byte, sparse.
  const std::string big = sparse_file("big.off", (std::uintmax_t{256} << 20) + 1);
  test::expect_rejected("mesh_big", mesh_scenario(big),
                        head + big + ": expected at most 268435456 bytes, found 268435457");
  std::filesystem::remove(big);
  test::expect_rejected("mesh_empty_name", mesh_scenario(""),
                        head + "expected a file name, found an empty string");
  // A TetGen pair needs both files: the .face named, its .node missing.
  const std::string face = test::write_file("lonely.face", "1 0\n0 0 1 2\n");
  const std::string node = face.substr(0, face.size() - 5) + ".node";
  std::filesystem::remove(node);
  test::expect_rejected("tetgen_partner", mesh_scenario(face),
                        head + node + ": cannot read it: no such file");
  // Point masses from a file: the same checks.
  test::expect_rejected("csv_dev_zero",
                        "[mass_model]\nkind = \"points\"\nfile = \"/dev/zero\"\n[field]\nmu = 1\n"
                        "R = 10\n" +
                            kInitial,
                        head + "/dev/zero: expected a regular file, found a character device");
}

TEST(ScenarioFiles, RelativeNamesAreTakenFromTheScenarioFolder) {
  // The scenario in the scratch folder names "masses.csv" there; from another working directory
  // the program finds it.
  test::write_file("masses.csv",
                   "m, x, y, z\n1, 1, 0, 0\n1, -1, 0, 0\n2, 0, 1, 0\n2, 0, -1, 0\n"
                   "3, 0, 0, 1\n3, 0, 0, -1\n");
  const std::string path =
      test::write_file("relative.toml",
                       "[mass_model]\nfile = \"newtop_io_masses.csv\"\nkind = \"points\"\n"
                       "[field]\nmu = 1\nR = 10\n" +
                           kInitial);
  const auto r = run_newtop("integrals " + path + " --json", Stderr::separate);
  EXPECT_EQ(r.code, 0) << r.err;
}

}  // namespace
}  // namespace test_scenario_files
}  // namespace newtop::io
