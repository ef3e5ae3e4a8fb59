#pragma once
// Internal: dense (d+1)³ tables of multi-indexed coefficients (mass moments, Taylor coefficients).

#include <cstddef>
#include <vector>

namespace newtop::detail {

/// Dense (d+1)³ table indexed (i·(d+1) + j)·(d+1) + k, zero where i + j + k > d.
struct Table {
  int d;
  std::vector<double> v;
  explicit Table(int degree)
      : d(degree), v(static_cast<std::size_t>((degree + 1) * (degree + 1) * (degree + 1)), 0.0) {}
  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(i) * (d + 1) + j) * (d + 1) + k;
  }
  double& operator()(int i, int j, int k) { return v[index(i, j, k)]; }
  double operator()(int i, int j, int k) const { return v[index(i, j, k)]; }
  /// Zero for a negative index.
  double at(int i, int j, int k) const {
    if (i < 0 || j < 0 || k < 0) return 0.0;
    return v[index(i, j, k)];
  }
};

}  // namespace newtop::detail
