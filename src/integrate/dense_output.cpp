#include "newtop/integrate/dense_output.hpp"

#include <cassert>

namespace newtop {

HermiteInterpolant::HermiteInterpolant(std::span<const double> theta, std::span<const Point> y,
                                       std::span<const Point> h_f) {
  const auto nodes = static_cast<int>(theta.size());
  assert(nodes >= 1 && nodes <= kMaxNodes && y.size() == theta.size() && h_f.size() == y.size());
  n_ = 2 * nodes;
  // Divided differences on z = (θ0, θ0, θ1, θ1, …): first differences at a doubled node are the
  // derivative; column j is overwritten in place from the bottom, leaving c_j = f[z_0, …, z_j].
  std::array<Point, 2 * kMaxNodes> q{};
  for (int i = 0; i < n_; ++i) {
    z_[i] = theta[i / 2];
    q[i] = y[i / 2];
  }
  for (int j = 1; j < n_; ++j) {
    for (int i = n_ - 1; i >= j; --i) {
      for (int k = 0; k < 6; ++k) {
        if (j == 1 && i % 2 == 1) {
          q[i][k] = h_f[i / 2][k];
        } else {
          q[i][k] = (q[i][k] - q[i - 1][k]) / (z_[i] - z_[i - j]);
        }
      }
    }
  }
  c_ = q;
}

HermiteInterpolant::Point HermiteInterpolant::operator()(double theta) const {
  Point u = c_[n_ - 1];
  for (int j = n_ - 2; j >= 0; --j) {
    for (int k = 0; k < 6; ++k) u[k] = c_[j][k] + (theta - z_[j]) * u[k];
  }
  return u;
}

}  // namespace newtop
