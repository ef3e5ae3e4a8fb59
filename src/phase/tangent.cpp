// The tangent map of the splitting sub-flows (tangent.hpp).

#include "newtop/phase/tangent.hpp"

namespace newtop::phase {

void axis_flow_tangent(const Body& body, int a, double t, State& x, Tangent& V) {
  const int J = (a + 1) % 3, K = (a + 2) % 3;
  const double rate = t / body.inertia()[a];
  double s, cm1;
  sin_cosm1(rate * (x.m[a] - body.gyrostat()[a]), s, cm1);
  auto turn = [&](double& xj, double& xk) {
    const double u = xj, v = xk;
    xj = u + (cm1 * u + s * v);
    xk = v + (cm1 * v - s * u);
  };
  turn(x.m[J], x.m[K]);
  turn(x.gamma[J], x.gamma[K]);
  // δx' = R δx + (x' × e_a) rate δm_a, for x = m (rows 0..2) and γ (rows 3..5).
  const Eigen::Matrix<double, 1, Eigen::Dynamic, Eigen::RowMajor, 1, 6> dphi = rate * V.row(a);
  for (int base : {0, 3}) {
    for (Eigen::Index c = 0; c < V.cols(); ++c) turn(V(base + J, c), V(base + K, c));
    const Vec3& y = base == 0 ? x.m : x.gamma;
    // (y × e_a)_J = y_K, (y × e_a)_K = −y_J.
    V.row(base + J) += y[K] * dphi;
    V.row(base + K) -= y[J] * dphi;
  }
}

void check_tangent_split(FreeBodySplit split) {
  if (split != FreeBodySplit::axes) {
    throw InputError("split: expected the axes split of the free body for the tangent map, found " +
                     std::string(to_string(split)));
  }
}

void check_tangent_method(const MethodSettings& settings) {
  validate(settings);
  if (method_info(settings.name).kind == MethodKind::splitting) {
    check_tangent_split(free_body_split(settings));
  }
}

TangentSplittingStepper::TangentSplittingStepper(const CompositionTable& table,
                                                 const SplitOrdering& ordering)
    : order_(table.order), ordering_(ordering), c_(splitting_coefficients(table, ordering)) {
  check_tangent_split(ordering.free_body);
}

TangentSplittingStepper::TangentSplittingStepper(const SplittingStepper& stepper)
    : order_(stepper.order()), ordering_(stepper.ordering()), c_(stepper.coefficients()) {
  check_tangent_split(ordering_.free_body);
}

void TangentSplittingStepper::free_body(const Body& body, double t, State& x, Tangent& V) const {
  const double t2 = 0.5 * t;
  axis_flow_tangent(body, axes_[0], t2, x, V);
  axis_flow_tangent(body, axes_[1], t2, x, V);
  axis_flow_tangent(body, axes_[2], t, x, V);
  axis_flow_tangent(body, axes_[1], t2, x, V);
  axis_flow_tangent(body, axes_[0], t2, x, V);
}

}  // namespace newtop::phase
