// The tangent map of the splitting sub-flows (tangent.hpp).

#include "newtop/phase/tangent.hpp"

#include <array>
#include <cmath>
#include <string>

#include "newtop/integrate/taylor.hpp"

namespace newtop::phase {

namespace {

/// x turned about body axis a by θ (sin θ = s, cos θ − 1 = cm1) for x = m and γ, and V by the
/// derivative, with dθ/dm_a = rate.
void turn_about_axis(int a, double s, double cm1, double rate, State& x, Tangent& V) {
  const int J = (a + 1) % 3, K = (a + 2) % 3;
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

/// 1/(2n + 3)! for n = 0 … 8: the Taylor coefficients of (φ − sin φ)/φ³ in −φ².
constexpr std::array<double, 9> kF3Series = [] {
  std::array<double, 9> c{};
  double f = 6.0;  // 3!
  for (int n = 0; n < 9; ++n) {
    c[n] = 1.0 / f;
    f *= (2.0 * n + 4.0) * (2.0 * n + 5.0);
  }
  return c;
}();

/// (φ − sin φ)/φ³ as a function of φ²: its Taylor series Σ (−φ²)^n / (2n + 3)! to n = 8 for
/// φ² ≤ 1 (the first term left out is below 1/21! ≈ 2e-20, against the sum's 1/6), the closed
/// form above.
double spin_f3(double phi2) {
  if (phi2 <= 1.0) {
    double sum = 0.0;
    for (int n = 8; n >= 0; --n) sum = kF3Series[n] - phi2 * sum;
    return sum;
  }
  const double phi = std::sqrt(phi2);
  return (phi - std::sin(phi)) / (phi2 * phi);
}

}  // namespace

void axis_flow_tangent(const Body& body, int a, double t, State& x, Tangent& V) {
  const double rate = t / body.inertia()[a];
  double s, cm1;
  sin_cosm1(rate * (x.m[a] - body.gyrostat()[a]), s, cm1);
  turn_about_axis(a, s, cm1, rate, x, V);
}

void axis_flow_tangent(int a, double ta, double tb, State& x, Tangent& V) {
  double s, cm1;
  sin_cosm1(x.m[a] * ta + tb, s, cm1);
  turn_about_axis(a, s, cm1, ta, x, V);
}

void spin_flow_tangent(double tau, State& x, Tangent& V) {
  const Vec3 u = -tau * x.m;
  const double phi2 = u.squaredNorm();
  double f1, f2;
  spin_factors(phi2, f1, f2);
  const double f3 = spin_f3(phi2);
  auto rotate = [&](const Vec3& y) -> Vec3 {
    const Vec3 c = u.cross(y);
    return y + (f1 * c + f2 * u.cross(c));
  };
  x.gamma = rotate(x.gamma);
  for (Eigen::Index c = 0; c < V.cols(); ++c) {
    const Vec3 dm = V.col(c).head<3>();
    const Vec3 um = u.cross(dm);
    const Vec3 j_dm = dm + (f2 * um + f3 * u.cross(um));  // J(u) δm
    V.col(c).tail<3>() = rotate(V.col(c).tail<3>()) + tau * x.gamma.cross(j_dm);
  }
}

void check_tangent_split(FreeBodySplit split) {
  if (split == FreeBodySplit::exact) {
    throw InputError(
        "split: expected the axes or the spin split of the free body for the tangent map, found " +
        std::string(to_string(split)));
  }
}

void check_ensemble_tangent_split(FreeBodySplit split) {
  if (split != FreeBodySplit::axes) {
    throw InputError(
        "split: expected the axes split of the free body for the ensemble tangent map, found " +
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
  const std::array<int, 3>& axis = frame_.axis;
  if (ordering_.free_body == FreeBodySplit::axes) {
    axis_flow_tangent(body, axis[0], t2, x, V);
    axis_flow_tangent(body, axis[1], t2, x, V);
    axis_flow_tangent(body, axis[2], t, x, V);
    axis_flow_tangent(body, axis[1], t2, x, V);
    axis_flow_tangent(body, axis[0], t2, x, V);
    return;
  }
  // The spin split, in SpinFlow's order; the rates α_w = 1/I_w − 1/I_k and the gyrostat terms
  // −k_w/I_w in the body frame (the working frame's signs cancel in θ).
  const Vec3& I = body.inertia();
  const Vec3& k = body.gyrostat();
  auto rotation = [&](int w, double tw) {
    axis_flow_tangent(axis[w], tw * frame_.rate[w], -tw * k[axis[w]] / I[axis[w]], x, V);
  };
  spin_flow_tangent(t * frame_.inv_ref, x, V);
  rotation(0, t2);
  if (frame_.gyrostat_ref) {
    rotation(1, t2);
    rotation(2, t);
    rotation(1, t2);
  } else {
    rotation(1, t);
  }
  rotation(0, t2);
}

}  // namespace newtop::phase
