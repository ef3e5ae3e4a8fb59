#include "prym_lattice.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "newtop/core/types.hpp"

namespace newtop::prym_lattice {
namespace {

// Period coordinates in a basis of four periods are rational with denominators up to this.
constexpr int kMaxDenominator = 64;
constexpr double kRational = 1e-7;
// Integer combinations searched for the torus lattice: |k_i| ≤ this.
constexpr int kSearch = 24;

/// The denominator of the best rational approximation of x with denominator ≤ kMaxDenominator,
/// or 0 when none is within kRational.
long denominator(double x) {
  for (long q = 1; q <= kMaxDenominator; ++q) {
    const double xq = x * static_cast<double>(q);
    if (std::abs(xq - std::round(xq)) < kRational * static_cast<double>(q)) return q;
  }
  return 0;
}

}  // namespace

/// A basis (columns) of the lattice the periods generate: their coordinates in four independent
/// periods are rational; integer row reduction (Euclid, column by column) of the scaled rows.
Eigen::Matrix4d lattice_basis(std::vector<Eigen::Vector4d> p) {
  std::sort(p.begin(), p.end(),
            [](const Eigen::Vector4d& a, const Eigen::Vector4d& b) { return a.norm() < b.norm(); });
  Eigen::Matrix4d B;
  int rank = 0;
  for (const Eigen::Vector4d& v : p) {
    Eigen::MatrixXd trial(4, rank + 1);
    trial << B.leftCols(rank), v;
    if (Eigen::FullPivLU<Eigen::MatrixXd>(trial).setThreshold(1e-6).rank() > rank)
      B.col(rank++) = v;
    if (rank == 4) break;
  }
  if (rank < 4) throw InputError("Brun frequencies: the periods span less than C^2");
  const Eigen::PartialPivLU<Eigen::Matrix4d> lu(B);
  std::vector<Eigen::Vector4d> coords;
  long den = 1;
  for (const Eigen::Vector4d& v : p) {
    coords.push_back(lu.solve(v));
    for (int i = 0; i < 4; ++i) {
      const long q = denominator(coords.back()[i]);
      if (q == 0) throw InputError("Brun frequencies: period coordinates are not rational");
      den = std::lcm(den, q);
    }
  }
  std::vector<std::array<long, 4>> rows;
  for (const auto& c : coords) {
    std::array<long, 4> r{};
    for (int i = 0; i < 4; ++i) r[i] = std::lround(c[i] * static_cast<double>(den));
    rows.push_back(r);
  }
  std::vector<std::array<long, 4>> echelon;
  for (int col = 0; col < 4; ++col) {
    std::vector<std::array<long, 4>> pivots, others;
    for (const auto& r : rows) {
      if (std::all_of(r.begin(), r.end(), [](long x) { return x == 0; })) continue;
      (r[col] != 0 ? pivots : others).push_back(r);
    }
    while (pivots.size() > 1) {
      std::sort(pivots.begin(), pivots.end(),
                [&](const auto& a, const auto& b) { return std::abs(a[col]) < std::abs(b[col]); });
      const auto pivot = pivots[0];
      std::vector<std::array<long, 4>> rest;
      for (std::size_t j = 1; j < pivots.size(); ++j) {
        auto r = pivots[j];
        const long q = r[col] / pivot[col];
        for (int i = 0; i < 4; ++i) r[i] -= q * pivot[i];
        (r[col] != 0 ? rest : others).push_back(r);
      }
      pivots = {pivot};
      pivots.insert(pivots.end(), rest.begin(), rest.end());
    }
    if (!pivots.empty()) echelon.push_back(pivots[0]);
    rows = others;
  }
  if (echelon.size() != 4)
    throw InputError("Brun frequencies: the period lattice is not of rank 4");
  Eigen::Matrix4d L;
  for (int j = 0; j < 4; ++j) {
    Eigen::Vector4d n;
    for (int i = 0; i < 4; ++i)
      n[i] = static_cast<double>(echelon[j][i]) / static_cast<double>(den);
    L.col(j) = B * n;
  }
  return L;
}

/// Lagrange–Gauss reduction of a basis of a lattice of R².
void reduce(Eigen::Vector2d& a, Eigen::Vector2d& b) {
  for (int it = 0; it < 100; ++it) {
    if (b.norm() < a.norm()) std::swap(a, b);
    const double q = std::round(a.dot(b) / a.dot(a));
    if (q == 0) break;
    b -= q * a;
  }
}

/// The lattice {τ : τ_H W_H + τ_c W_c ∈ Λ} (columns of L a basis of Λ), reduced.
Eigen::Matrix2d torus_lattice(const Eigen::Matrix4d& L, const Eigen::Matrix<double, 4, 2>& W) {
  const Eigen::Matrix<double, 4, 2> C = L.partialPivLu().solve(W);  // τ ↦ coordinates in Λ
  // Two rows R with the best-conditioned 2×2 block: τ = R⁻¹ k; the other rows S must be integer.
  int r0 = 0, r1 = 1;
  double best = 0;
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) {
      const double det = std::abs(C(i, 0) * C(j, 1) - C(i, 1) * C(j, 0));
      if (det > best) best = det, r0 = i, r1 = j;
    }
  }
  Eigen::Matrix2d R;
  R << C.row(r0), C.row(r1);
  const Eigen::Matrix2d Rinv = R.inverse();
  std::vector<Eigen::Vector2d> found;
  for (int a = -kSearch; a <= kSearch; ++a) {
    for (int b = -kSearch; b <= kSearch; ++b) {
      if (a == 0 && b == 0) continue;
      const Eigen::Vector2d tau = Rinv * Eigen::Vector2d(a, b);
      const Eigen::Vector4d n = C * tau;
      if ((n.array() - n.array().round()).abs().maxCoeff() < 1e-6) found.push_back(tau);
    }
  }
  if (found.empty()) throw InputError("Brun frequencies: no period of the torus found");
  std::sort(found.begin(), found.end(),
            [](const auto& x, const auto& y) { return x.norm() < y.norm(); });
  Eigen::Vector2d u = found[0], w = u;
  for (const auto& x : found) {
    if (std::abs(u[0] * x[1] - u[1] * x[0]) > 1e-6 * u.norm() * x.norm()) {
      w = x;
      break;
    }
  }
  if (w == u) throw InputError("Brun frequencies: the torus periods are collinear");
  reduce(u, w);
  Eigen::Matrix2d T;
  T << u, w;
  for (const auto& x : found) {  // every period found is an integer combination of the basis
    const Eigen::Vector2d c = T.inverse() * x;
    if ((c.array() - c.array().round()).abs().maxCoeff() > 1e-6) {
      throw InputError("Brun frequencies: the torus lattice needs a finer basis");
    }
  }
  return T;
}

}  // namespace newtop::prym_lattice
