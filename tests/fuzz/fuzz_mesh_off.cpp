// Fuzz harness: the OFF mesh reader (bytes -> FILE.off -> read_mesh -> Polyhedron::make).

#include "mesh_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return newtop::fuzz::fuzz_mesh_file(data, size, ".off");
}
