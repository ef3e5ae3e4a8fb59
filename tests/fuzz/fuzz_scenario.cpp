// Fuzz harness: the scenario reader (TOML text -> validated Scenario). A scenario the reader
// accepts must have finite integrals and a finite right-hand side at its initial state (the
// reader's magnitude checks are there to guarantee it).

#include <cstdlib>

#include "harness.hpp"
#include "newtop/io/scenario.hpp"
#include "newtop/model/integrals.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = newtop::fuzz::bytes(data, size);
  newtop::fuzz::expect_result_or_input_error([&] {
    const newtop::io::Scenario s = newtop::io::parse_scenario(text, "fuzz.toml");
    const newtop::IntegralValues v = newtop::integrals(s.model, s.initial);
    const newtop::State d = newtop::rhs(s.model, s.initial);
    const bool finite = std::isfinite(v.energy) && std::isfinite(v.area) &&
                        std::isfinite(v.brun.value_or(0.0)) && d.m.allFinite() &&
                        d.gamma.allFinite() && newtop::omega(s.model.body(), s.initial).allFinite();
    if (!finite) std::abort();
  });
  return 0;
}
