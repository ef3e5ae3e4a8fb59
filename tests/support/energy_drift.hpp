#pragma once
// The energy-drift measure of the conformance suite (tests/integrate/test_conformance.cpp): the
// largest energy error over the first and over the last tenth of a long run.

#include <algorithm>
#include <cmath>
#include <limits>

#include "newtop/model/integrals.hpp"

namespace newtop::test {

/// max |E − E0| over the first tenth and over the last tenth of `steps` steps of size h.
struct EnergyErrorProfile {
  double first = 0.0;
  double last = 0.0;
};

template <class Stepper>
EnergyErrorProfile energy_error_profile(Stepper stepper, const QuadraticModel& model, State x,
                                        double h, int steps) {
  const double e0 = energy(model, x);
  EnergyErrorProfile p;
  for (int i = 0; i < steps; ++i) {
    stepper.step(model, x, h);
    const double de = std::abs(energy(model, x) - e0);
    if (i < steps / 10) p.first = std::max(p.first, de);
    if (i >= steps - steps / 10) p.last = std::max(p.last, de);
  }
  return p;
}

/// Bounded energy error without drift: the last tenth's maximum error is at most twice the first
/// tenth's (a linear drift makes it ~9× larger; the factor 2 lets the quasi-periodic oscillation
/// of the modified energy reach a new maximum), plus 64 ε for an error that is round-off only.
inline bool without_drift(const EnergyErrorProfile& p) {
  return p.last < 2.0 * p.first + 64 * std::numeric_limits<double>::epsilon();
}

}  // namespace newtop::test
