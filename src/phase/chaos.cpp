// Chaos indicators: renormalisation and accumulation (chaos.hpp).

#include "newtop/phase/chaos.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>

namespace newtop::phase {

ChaosIndicators::ChaosIndicators(double t0, int vectors) : t0_(t0), t_prev_(t0), n_(vectors) {}

Tangent initial_tangent(int vectors) {
  if (vectors == 1) return Tangent::Constant(6, 1, 1.0 / std::sqrt(6.0));
  return Tangent::Identity(6, vectors);
}

std::array<double, 6> renormalise_tangent(Tangent& V) {
  std::array<double, 6> log_r{};
  if (V.cols() == 1) {
    const double norm = V.col(0).norm();
    log_r[0] = std::log(norm);
    V.col(0) /= norm;
    return log_r;
  }
  // Benettin: V = QR, the logs of |R_ii| accumulate, Q (signs fixed so that R_ii > 0) goes on.
  const Eigen::HouseholderQR<Eigen::Matrix<double, 6, 6>> qr(V.leftCols(6));
  const Eigen::Matrix<double, 6, 6> R = qr.matrixQR().triangularView<Eigen::Upper>();
  Eigen::Matrix<double, 6, 6> Q = qr.householderQ();
  for (int i = 0; i < 6; ++i) {
    const double r = R(i, i);
    log_r[i] = std::log(std::abs(r));
    if (r < 0) Q.col(i) = -Q.col(i);
  }
  V = Q;
  return log_r;
}

void ChaosIndicators::operator()(double t, Tangent& V) { accumulate(t, renormalise_tangent(V)); }

void ChaosIndicators::accumulate(double t, const std::array<double, 6>& log_growth) {
  const double delta = log_growth[0];  // ln(|δ_n|/|δ_{n−1}|) of the first vector
  if (n_ == 1) {
    log_r_[0] += delta;
  } else {
    for (int i = 0; i < 6; ++i) log_r_[i] += log_growth[i];
  }
  log_norm_ += delta;
  fli_ = std::max(fli_, log_norm_);
  // s is the time elapsed along the run, |t − t0|: a backward run gives the indicators of the
  // backward flow.
  const double s0 = std::abs(t_prev_ - t0_), s1 = std::abs(t - t0_);
  s_ += 0.5 * (s0 + s1) * delta;  // ∫ s d ln|δ| over the step, s at the step's middle
  const double y = s1 > 0 ? 2 * s_ / s1 : 0.0;
  mean_integral_ += 0.5 * (y_prev_ + y) * (s1 - s0);
  y_prev_ = y;
  t_prev_ = t;
}

ChaosSample ChaosIndicators::sample() const {
  ChaosSample c;
  c.t = t_prev_;
  const double s = std::abs(t_prev_ - t0_);
  if (!(s > 0)) return c;
  c.lyapunov_max = log_norm_ / s;
  c.megno_y = y_prev_;
  c.megno = mean_integral_ / s;
  c.fli = fli_;
  if (n_ == 6) {
    std::array<double, 6> sp;
    for (int i = 0; i < 6; ++i) sp[i] = log_r_[i] / s;
    c.spectrum = sp;
  }
  return c;
}

}  // namespace newtop::phase
