// Hostile files through the library: every case of mesh_cases.hpp gives exactly its InputError
// (one line, naming the file, the line and what was expected and found); files that are not
// regular files and files beyond the size limit are refused before they are read.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "mesh_cases.hpp"
#include "newtop/io/mesh.hpp"
#include "support/cli.hpp"

namespace newtop {
namespace test_mesh_errors {
namespace {

namespace fs = std::filesystem;

fs::path scratch_dir() { return newtop::test::scratch_dir("newtop_mesh_errors"); }

/// The message of the InputError that f() throws ("" if none).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string read_case(const test::BadFile& c, const std::string& path) {
  if (std::string_view(c.corpus) == "point_csv") {
    return error_of([&] { (void)io::read_point_masses(path); });
  }
  return error_of([&] { (void)io::read_mesh(path); });
}

TEST(MeshErrors, EveryHostileFileGivesItsOneLine) {
  for (const test::BadFile& c : test::bad_files()) {
    const std::string stem = (scratch_dir() / c.name).string();
    const std::string path = test::write_case(c, stem);
    EXPECT_EQ(read_case(c, path), test::expected_message(c, stem)) << c.corpus << "/" << c.name;
  }
}

TEST(MeshErrors, RegressionCasesAreInTheFuzzCorpora) {
  // The replay of each corpus under ctest (fuzz.replay.READER) then runs them through the harness.
  for (const test::BadFile& c : test::bad_files()) {
    const fs::path p = fs::path(NEWTOP_SOURCE_DIR) / "tests/fuzz/corpus" / c.corpus / c.name;
    std::ifstream in(p, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_TRUE(in.good() || in.eof()) << p;
    EXPECT_EQ(bytes, c.bytes) << p;
  }
}

TEST(MeshErrors, VerticalTabLineIsBlank) {
  // A line holding only a vertical tab is a blank line (issue: it once gave an internal error).
  const std::string stem = (scratch_dir() / "vt_cube").string();
  const test::BadFile c{"", "tetgen", test::tetgen_cube("11 4 6 7"), ""};
  std::string bytes = c.bytes;
  bytes.insert(bytes.find('|') + 1, "\v\n");
  const std::string path = test::write_case({"", "tetgen", bytes, ""}, stem);
  EXPECT_EQ(io::read_mesh(path).faces.size(), 12u);
}

TEST(MeshErrors, NonRegularFilesAreRefused) {
  const fs::path dir = scratch_dir() / "a_directory.off";
  fs::create_directories(dir);
  EXPECT_EQ(error_of([&] { (void)io::read_mesh(dir.string()); }),
            dir.string() + ": expected a regular file, found a directory");
  EXPECT_EQ(error_of([&] { (void)io::read_mesh("/dev/zero"); }),
            "/dev/zero: expected a regular file, found a character device");
  EXPECT_EQ(error_of([&] { (void)io::read_point_masses("/dev/zero"); }),
            "/dev/zero: expected a regular file, found a character device");
  const fs::path fifo = scratch_dir() / "a_fifo.ply";
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Opening a FIFO without a writer would block: the reader must not wait.
  EXPECT_EQ(error_of([&] { (void)io::read_mesh(fifo.string()); }),
            fifo.string() + ": expected a regular file, found a FIFO (named pipe)");
  const fs::path missing = scratch_dir() / "missing.stl";
  EXPECT_EQ(error_of([&] { (void)io::read_mesh(missing.string()); }),
            missing.string() + ": cannot read the file: No such file or directory");
}

TEST(MeshErrors, FileBeyondTheSizeLimit) {
  // A sparse file one byte over 1 GiB: refused from its size, without reading it.
  const fs::path big = scratch_dir() / "big.obj";
  std::ofstream(big).put('v');
  fs::resize_file(big, static_cast<std::uintmax_t>(io::kMaxInputBytes) + 1);
  EXPECT_EQ(error_of([&] { (void)io::read_mesh(big.string()); }),
            big.string() +
                ": the file has 1073741825 bytes, beyond the limit of 1073741824 bytes "
                "(1 GiB)");
  fs::remove(big);
}

TEST(MeshErrors, UnsupportedFormatsNameTheSupportedOnes) {
  const fs::path glb = scratch_dir() / "shape.glb";
  std::ofstream(glb) << "glTF";
  EXPECT_EQ(
      error_of([&] { (void)io::read_mesh(glb.string()); }),
      glb.string() +
          ": unsupported mesh format \".glb\": newtop reads .obj, .off, .ply, .stl and TetGen "
          ".node/.face (convert other formats first, e.g. with `assimp export FILE out.ply`)");
}

TEST(MeshErrors, PolyhedronErrorsNameTheFile) {
  // A valid OFF file whose surface is open: the polyhedron's own check, prefixed with the file.
  const fs::path open_box = scratch_dir() / "open.off";
  std::ofstream(open_box) << "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n";
  const std::string msg = error_of([&] { (void)io::load_polyhedron(open_box.string(), 1.0); });
  EXPECT_EQ(msg.rfind(open_box.string() + ": mesh: ", 0), 0u) << msg;
}

}  // namespace
}  // namespace test_mesh_errors
}  // namespace newtop
