// Fuzz harness: the surface grammar of `newtop section --surface` (phase::parse_surface). An
// accepted surface has finite coefficients, at least one nonzero, parses again from its own text
// to the same surface, and gives a finite section function for a body (or is refused for one).
// The same bytes go to the section's other word, `--direction` (phase::parse_direction): an
// accepted direction is its own name.

#include <cmath>
#include <cstdlib>

#include "harness.hpp"
#include "newtop/phase/section.hpp"
#include "newtop/phase/surface.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace newtop;
  static const Body body = Body::from_principal({1.0, 1.5, 2.2}, 1.0, Vec3::Zero(), {0.1, 0, 0});
  static const State x{{0.3, -0.2, 1.1}, Vec3(0.48, -0.6, 0.64)};
  const std::string text = fuzz::bytes(data, size);
  fuzz::expect_result_or_input_error([&] {
    if (phase::to_string(phase::parse_direction(text)) != text) std::abort();
  });
  fuzz::expect_result_or_input_error([&] {
    const phase::Surface s = phase::parse_surface(text);
    const bool finite = s.a_omega.allFinite() && s.a_m.allFinite() && s.a_gamma.allFinite() &&
                        s.a_normal.allFinite() && std::isfinite(s.c);
    const bool nonzero = !(s.a_omega.isZero(0.0) && s.a_m.isZero(0.0) && s.a_gamma.isZero(0.0) &&
                           s.a_normal.isZero(0.0));
    if (!finite || !nonzero || s.text != text) std::abort();
    const phase::Surface again = phase::parse_surface(s.text);
    if (again.a_omega != s.a_omega || again.a_m != s.a_m || again.a_gamma != s.a_gamma ||
        again.a_normal != s.a_normal || again.c != s.c) {
      std::abort();
    }
    const phase::SurfaceFunction g(s, body, s.has_normal());
    if (!std::isfinite(g(x)) || !std::isfinite(g.scale(x))) std::abort();
  });
  return 0;
}
