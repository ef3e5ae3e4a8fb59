// Fuzz harness: the potential file of find-integrals --potential (TOML text ->
// PolynomialPotential), and the search it feeds: a potential the reader accepts must give finite
// singular values and coefficients (the reader's bounds are there to guarantee it).

#include <cmath>
#include <cstdlib>

#include "harness.hpp"
#include "newtop/io/potential_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const newtop::Body body =
      newtop::Body::from_principal({1.0, 1.5, 2.2}, 1.0, newtop::Vec3::Zero());
  const std::string text = newtop::fuzz::bytes(data, size);
  newtop::fuzz::expect_result_or_input_error([&] {
    const newtop::PolynomialPotential v = newtop::io::parse_potential(text, "fuzz.toml", body);
    const newtop::IntegralSearch s = newtop::find_integrals(
        newtop::BasicModel<newtop::PolynomialPotential>{body, v}, {.degree = 2});
    for (double x : s.singular_values) {
      if (!std::isfinite(x)) std::abort();
    }
    for (const auto& i : s.integrals) {
      for (double c : i.coefficients) {
        if (!std::isfinite(c)) std::abort();
      }
    }
  });
  return 0;
}
