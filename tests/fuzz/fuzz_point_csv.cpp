// Fuzz harness: the point-mass CSV reader (bytes -> FILE.csv -> read_point_masses). A result must
// hold only finite positions and positive finite masses.

#include <cmath>

#include "mesh_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const newtop::fuzz::TempFile file(std::string_view(reinterpret_cast<const char*>(data), size),
                                    ".csv");
  newtop::fuzz::expect_result_or_input_error([&] {
    const newtop::PointMasses p = newtop::io::read_point_masses(file.path());
    for (std::size_t i = 0; i < p.masses().size(); ++i) {
      newtop::fuzz::require(std::isfinite(p.masses()[i]) && p.masses()[i] > 0, "masses > 0");
      newtop::fuzz::require(p.positions()[i].allFinite(), "finite positions");
    }
  });
  return 0;
}
