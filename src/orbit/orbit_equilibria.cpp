#include "newtop/orbit/orbit_equilibria.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include "equilibria_detail.hpp"
#include "newtop/analysis/equilibria.hpp"

namespace newtop {
namespace {

using orbit_detail::EquilibriumProblem;
using orbit_detail::Orientation;

constexpr double kEps = std::numeric_limits<double>::epsilon();
// Companion roots of the small secular polynomials: see analysis/equilibria.cpp.
constexpr double kImagTolerance = 1e-6;
// |secular function| at an accepted root (dimensionless, O(1) terms).
constexpr double kSecularResidual = 1e-10;
// Two orientations closer than this (max norm of γ and n) are one.
constexpr double kSameOrientation = 1e-8;
// τ = ξ_w² of a branch with Δ_w = 0 must be positive; below this it is the point where the branch
// meets the free branch (counted there).
constexpr double kPositiveAmplitude = 1e-12;

/// Polynomial product, coefficients constant term first.
Eigen::VectorXd multiply(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(a.size() + b.size() - 1);
  for (Eigen::Index i = 0; i < a.size(); ++i) r.segment(i, b.size()) += a[i] * b;
  return r;
}

Eigen::VectorXd linear(double c0, double c1) {
  Eigen::VectorXd v(2);
  v << c0, c1;
  return v;
}

/// Newton's method on a scalar function f (returning f and f′); false unless |f| ends small.
template <class F>
bool newton(const F& f, double& x) {
  for (int it = 0; it < 100; ++it) {
    const auto [v, d] = f(x);
    if (!std::isfinite(v) || d == 0.0) return false;
    const double dx = v / d;
    x -= dx;
    if (std::abs(dx) <= 4 * kEps * (1 + std::abs(x))) break;
  }
  const double v = f(x).first;
  return std::isfinite(v) && std::abs(v) <= kSecularResidual;
}

/// γ = ±e_j (c = 0), possible when h_j = 0: n in the plane ⊥ e_j with In + h ∥ n there,
/// (I_i + b) n_i = −h_i for the two other axes, a secular equation in b (docs/model.md §7 in a
/// plane).
void add_principal_gamma(const EquilibriumProblem& pb, int j, std::vector<Orientation>& out) {
  const int i = (j + 1) % 3, l = (j + 2) % 3;
  std::vector<Vec3> normals;
  const double hi = pb.h[i], hl = pb.h[l], Ii = pb.I[i], Il = pb.I[l];
  if (hi != 0.0 && hl != 0.0) {
    // h_i² (I_l + b)² + h_l² (I_i + b)² − (I_i + b)² (I_l + b)² = 0.
    const Eigen::VectorXd si = multiply(linear(Ii, 1), linear(Ii, 1));
    const Eigen::VectorXd sl = multiply(linear(Il, 1), linear(Il, 1));
    Eigen::VectorXd poly = -multiply(si, sl);
    poly.head(3) += hi * hi * sl + hl * hl * si;
    for (double b : real_polynomial_roots(poly, kImagTolerance)) {
      auto f = [&](double x) {
        const double ui = Ii + x, ul = Il + x;
        return std::pair{hi * hi / (ui * ui) + hl * hl / (ul * ul) - 1.0,
                         -2.0 * (hi * hi / (ui * ui * ui) + hl * hl / (ul * ul * ul))};
      };
      if (!newton(f, b)) continue;
      Vec3 n = Vec3::Zero();
      n[i] = -hi / (Ii + b);
      n[l] = -hl / (Il + b);
      normals.push_back(n.normalized());
    }
  } else if (hi == 0.0 && hl == 0.0) {
    for (double s : {1.0, -1.0}) {
      normals.push_back(s * Vec3::Unit(i));
      normals.push_back(s * Vec3::Unit(l));
    }
  } else {
    // One of them, say z, has h_z = 0: n = ±(the other axis), or b = −I_z with n_z free.
    const int z = hi == 0.0 ? i : l, o = hi == 0.0 ? l : i;
    normals.push_back(Vec3::Unit(o));
    normals.push_back(-Vec3::Unit(o));
    const double no = -pb.h[o] / (pb.I[o] - pb.I[z]);
    if (std::abs(no) < 1.0) {
      for (double s : {1.0, -1.0}) {
        Vec3 n = Vec3::Zero();
        n[o] = no;
        n[z] = s * std::sqrt((1.0 - no) * (1.0 + no));
        normals.push_back(n);
      }
    }
  }
  for (const Vec3& n : normals) {
    out.push_back({Vec3::Unit(j), n});
    out.push_back({-Vec3::Unit(j), n});
  }
}

/// Δ_w = 0 for an axis w with h_w = 0 (c ≠ 0, ξ_w free): on the line q = −ε I_w² − p I_w,
/// Δ_i = (I_i − I_w)(ε (I_i + I_w) + p); Σ_{active} h_i²/Δ_i = κ fixes p, and the quartic,
/// linear in τ = ξ_w², fixes τ > 0 (four orientations: ±ξ_w, ±c).
void add_line_branch(const EquilibriumProblem& pb, const std::vector<int>& active, int w,
                     std::vector<Orientation>& out) {
  auto D = [&](int i, double p) {
    return (pb.I[i] - pb.I[w]) * (pb.eps * (pb.I[i] + pb.I[w]) + p);
  };
  // κ Π Δ_i − Σ_i h_i² Π_{k≠i} Δ_k, a polynomial in p of degree |active|.
  Eigen::VectorXd all = Eigen::VectorXd::Ones(1);
  for (int i : active) all = multiply(all, linear(D(i, 0.0), pb.I[i] - pb.I[w]));
  Eigen::VectorXd poly = pb.kappa * all;
  for (int i : active) {
    Eigen::VectorXd term = Eigen::VectorXd::Constant(1, pb.h[i] * pb.h[i]);
    for (int k : active) {
      if (k != i) term = multiply(term, linear(D(k, 0.0), pb.I[k] - pb.I[w]));
    }
    poly.head(term.size()) -= term;
  }
  for (double p : real_polynomial_roots(poly, kImagTolerance)) {
    auto f = [&](double x) {
      double v = -pb.kappa, d = 0;
      for (int i : active) {
        const double Di = D(i, x);
        v += pb.h[i] * pb.h[i] / Di;
        d -= pb.h[i] * pb.h[i] * (pb.I[i] - pb.I[w]) / (Di * Di);
      }
      return std::pair{v, d};
    };
    if (!newton(f, p)) continue;
    Vec3 xi = Vec3::Zero();
    double S0 = 0, S1 = 0, S2 = 0, E = 0;
    for (int i : active) {
      xi[i] = pb.h[i] / D(i, p);
      const double x2 = xi[i] * xi[i];
      S0 += x2;
      S1 += x2 * pb.I[i];
      S2 += x2 * pb.I[i] * pb.I[i];
      E += x2 * (pb.I[i] - pb.I[w]) * (pb.I[i] - pb.I[w]);
    }
    const double eps2 = pb.eps * pb.eps;
    const double tau = (S0 - eps2 * (S0 * S2 - S1 * S1)) / (eps2 * E - 1.0);
    if (!(tau > kPositiveAmplitude)) continue;
    for (double s : {1.0, -1.0}) {
      xi[w] = s * std::sqrt(tau);
      orbit_detail::add_from_amplitudes(pb, xi, out);
    }
  }
}

Mat3 cross_matrix(const Vec3& a) {
  Mat3 m;
  m << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return m;
}

/// A few Newton steps on SO(3) for the torque balance T = ω0 (ω0 In + k) × n + λ γ × Iγ = 0,
/// turning (γ, n) together by a body-frame rotation φ (δγ = φ × γ, δn = φ × n):
/// ∂T/∂φ = −(ω0² ([In]× − [n]× I) + ω0 [k]×) [n]× − λ ([γ]× I − [Iγ]×) [γ]×.
/// The polynomial route leaves ~1e-12 near tangencies; this restores round-off. Kept only while
/// the residual decreases.
Orientation polish_orientation(const CircularOrbitModel& model, Orientation o) {
  const Vec3& I = model.body().inertia();
  const Vec3& k = model.body().gyrostat();
  const double w0 = model.orbit().rate, lambda = model.orbit().lambda_;
  const Mat3 Im = I.asDiagonal();
  auto torque = [&](const Orientation& x) {
    return Vec3(w0 * (w0 * I.cwiseProduct(x.normal) + k).cross(x.normal) +
                lambda * x.gamma.cross(I.cwiseProduct(x.gamma)));
  };
  Vec3 T = torque(o);
  for (int it = 0; it < 4; ++it) {
    const Vec3& g = o.gamma;
    const Vec3& n = o.normal;
    const Mat3 J =
        -(w0 * w0 * (cross_matrix(I.cwiseProduct(n)) - cross_matrix(n) * Im) +
          w0 * cross_matrix(k)) *
            cross_matrix(n) -
        lambda * (cross_matrix(g) * Im - cross_matrix(I.cwiseProduct(g))) * cross_matrix(g);
    const Vec3 phi = -J.fullPivLu().solve(T);
    if (!phi.allFinite() || phi.norm() == 0.0) break;
    const Mat3 R = Eigen::AngleAxisd(phi.norm(), phi.normalized()).toRotationMatrix();
    const Orientation next{(R * g).normalized(), (R * n).normalized()};
    const Vec3 T_next = torque(next);
    if (!(T_next.norm() < T.norm())) break;
    o = next;
    T = T_next;
  }
  return o;
}

EquilibriumProblem make_problem(const CircularOrbitModel& model) {
  const double w0 = model.orbit().rate, lambda = model.orbit().lambda_;
  if (!(w0 > 0) || !(lambda > 0)) {
    throw InputError("orbit: relative equilibria need rate > 0 and lambda > 0, found rate = " +
                     format_number(w0) + ", lambda = " + format_number(lambda));
  }
  const Vec3& I = model.body().inertia();
  const double Imax = I.maxCoeff();
  for (int i = 0; i < 3; ++i) {
    if (std::abs(I[i] - I[(i + 1) % 3]) <= kOrbitEquilibriumDegeneracy * Imax) {
      throw InputError(
          "inertia: relative equilibria are listed for distinct principal moments (equal moments "
          "give continuous families), found " +
          format_vector(I));
    }
  }
  EquilibriumProblem pb{I / Imax, model.body().gyrostat() / (w0 * Imax), lambda / (w0 * w0), 0.0};
  pb.kappa = 1.0 + 1.0 / pb.eps;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(pb.h[i]) <= kOrbitEquilibriumDegeneracy) pb.h[i] = 0.0;
  }
  return pb;
}

}  // namespace

RelativeEquilibriumSet find_relative_equilibria(const CircularOrbitModel& model) {
  const EquilibriumProblem pb = make_problem(model);
  std::vector<Orientation> candidates;
  std::vector<int> active, zero;
  for (int i = 0; i < 3; ++i) (pb.h[i] != 0.0 ? active : zero).push_back(i);
  RelativeEquilibriumSet set;
  if (active.size() >= 2) {
    set.resultant_tail = orbit_detail::solve_free_branch(pb, active, candidates);
  }
  for (int w : zero) {
    if (!active.empty()) add_line_branch(pb, active, w, candidates);
    add_principal_gamma(pb, w, candidates);
  }
  for (const Orientation& raw : candidates) {
    const Orientation o = polish_orientation(model, raw);
    const bool seen = std::any_of(set.equilibria.begin(), set.equilibria.end(), [&](const auto& e) {
      return (e.gamma - o.gamma).cwiseAbs().maxCoeff() <= kSameOrientation &&
             (e.normal - o.normal).cwiseAbs().maxCoeff() <= kSameOrientation;
    });
    if (seen) continue;
    const OrbitState s = relative_rest_state(model, o.gamma, o.normal);
    const double r = fixed_point_residual(model, s);
    if (!(r <= kRelativeEquilibriumTolerance)) {
      ++set.unverified;
      continue;
    }
    set.polish_distance =
        std::max({set.polish_distance, (o.gamma - raw.gamma).cwiseAbs().maxCoeff(),
                  (o.normal - raw.normal).cwiseAbs().maxCoeff()});
    set.equilibria.push_back({o.gamma, o.normal, jacobi_integral(model, s), r,
                              relative_equilibrium_stability(model, s)});
  }
  std::sort(set.equilibria.begin(), set.equilibria.end(), [](const auto& a, const auto& b) {
    if (a.jacobi != b.jacobi) return a.jacobi < b.jacobi;
    return std::lexicographical_compare(a.gamma.data(), a.gamma.data() + 3, b.gamma.data(),
                                        b.gamma.data() + 3);
  });
  for (const auto& e : set.equilibria) {
    set.lyapunov += e.stability.verdict == OrbitStability::lyapunov;
    set.gyroscopic += e.stability.verdict == OrbitStability::gyroscopic;
    set.unstable += e.stability.verdict == OrbitStability::unstable;
  }
  return set;
}

}  // namespace newtop
