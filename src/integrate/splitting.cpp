#include "newtop/integrate/splitting.hpp"

#include <algorithm>
#include <string>

namespace newtop {

SplitOrdering default_ordering(const CompositionTable& table) {
  if (!table.a.empty()) return SplitOrdering{{0, 1, 2}, true, true, FreeBodySplit::exact};
  return SplitOrdering{{0, 1, 2}, table.order > 2, true, FreeBodySplit::axes};
}

namespace {

// Appends T(a h) to the step, merged with the flow before it when T is exact and no kick lies
// between them (the exact flows of one Hamiltonian add up: T(s) T(t) = T(s + t)).
void push_flow(SplittingCoefficients& c, double a, bool exact) {
  if (exact && !c.a.empty() && c.b.back() == 0.0) {
    c.a.back() += a;
  } else {
    c.a.push_back(a);
    c.b.push_back(0.0);
  }
}

}  // namespace

SplittingCoefficients splitting_coefficients(const CompositionTable& table,
                                             const SplitOrdering& o) {
  const bool exact = o.free_body == FreeBodySplit::exact;
  if (!table.a.empty()) {
    if (!exact) {
      throw InputError("ordering: method " + std::string(table.name) +
                       " is a near-integrable splitting and needs the exact free-body flow");
    }
    return SplittingCoefficients{table.a, table.b};
  }
  // Kicks are accumulated into b.back(), the kick after the last flow pushed; b[0] precedes
  // the first flow.
  SplittingCoefficients c{{}, {0.0}};
  for (double g : table.gamma) {
    if (o.kick_outside) {
      c.b.back() += 0.5 * g;
      push_flow(c, g, exact);
      c.b.back() += 0.5 * g;
    } else {
      push_flow(c, 0.5 * g, exact);
      c.b.back() += g;
      push_flow(c, 0.5 * g, exact);
    }
  }
  return c;
}

SplitFrame split_frame(const Body& body, const SplitOrdering& o) {
  const Vec3& I = body.inertia();
  const Vec3& k = body.gyrostat();
  std::array<int, 3> by_moment{0, 1, 2};  // body axes by increasing moment
  std::stable_sort(by_moment.begin(), by_moment.end(), [&](int i, int j) { return I[i] < I[j]; });
  SplitFrame f;
  for (int w = 0; w < 3; ++w) f.axis[w] = o.by_moment ? by_moment[o.axes[w]] : o.axes[w];
  // An odd permutation is made proper by reversing the last working axis.
  const int inversions =
      (f.axis[0] > f.axis[1]) + (f.axis[0] > f.axis[2]) + (f.axis[1] > f.axis[2]);
  if (inversions % 2 == 1) f.sign[2] = -1.0;
  const int r = f.axis[2];
  f.inv_ref = 1.0 / I[r];
  for (int w = 0; w < 3; ++w) {
    const int i = f.axis[w];
    f.k_over_i[w] = f.sign[w] * k[i] / I[i];
    f.rate[w] = o.free_body == FreeBodySplit::spin ? 1.0 / I[i] - 1.0 / I[r] : 1.0 / I[i];
  }
  if (o.free_body == FreeBodySplit::spin) f.rate[2] = 0.0;
  f.gyrostat_ref = k[r] != 0.0;
  return f;
}

std::size_t SplittingStepper::stages() const {
  const auto kicks = static_cast<std::size_t>(std::count_if(
      coefficients_.b.begin(), coefficients_.b.end(), [](double b) { return b != 0; }));
  const std::size_t per_flow = ordering_.free_body == FreeBodySplit::axes   ? 5
                               : ordering_.free_body == FreeBodySplit::spin ? 6
                                                                            : 1;
  return kicks + per_flow * coefficients_.a.size();
}

}  // namespace newtop
