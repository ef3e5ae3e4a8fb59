// Fuzz harness: the TetGen reader. The input is split at its first '|' (a byte no TetGen file
// holds) into FILE.node (before) and FILE.face (after; empty when there is no '|'); read_mesh then
// reads the pair and Polyhedron::make builds the polyhedron.

#include <string_view>

#include "mesh_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const std::size_t bar = input.find('|');
  const std::string_view node = input.substr(0, bar);
  const std::string_view face = bar == std::string_view::npos ? "" : input.substr(bar + 1);
  const newtop::fuzz::TempFile node_file(node, ".node", "mesh");
  const newtop::fuzz::TempFile face_file(face, ".face", "mesh");
  newtop::fuzz::expect_result_or_input_error(
      [&] { newtop::fuzz::check_mesh(newtop::io::read_mesh(face_file.path())); });
  return 0;
}
