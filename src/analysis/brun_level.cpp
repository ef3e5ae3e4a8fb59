#include "newtop/analysis/brun_level.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace newtop {
namespace {

using Complex = std::complex<double>;

// Newton steps to polish a companion-matrix root of D (quadratic convergence from ~1e-12).
constexpr int kPolishSteps = 4;

/// P′(e_i) = Π_{j≠i}(e_i − e_j).
double dP(const BrunCurve& k, int i) {
  return (k.e[i] - k.e[(i + 1) % 3]) * (k.e[i] - k.e[(i + 2) % 3]);
}

Complex horner(const std::array<double, 5>& c, Complex u) {
  Complex r = c[4];
  for (int i = 3; i >= 0; --i) r = r * u + c[i];
  return r;
}

Complex horner_derivative(const std::array<double, 5>& c, Complex u) {
  Complex r = 4 * c[4];
  for (int i = 3; i >= 1; --i) r = r * u + static_cast<double>(i) * c[i];
  return r;
}

}  // namespace

double brun_P(const BrunCurve& k, double u) { return (u - k.e[0]) * (u - k.e[1]) * (u - k.e[2]); }

double brun_M(const BrunCurve& k, double u) { return brun_N(k, u) - k.f * k.f * u; }

State brun_state_from_point(const BrunCurve& k, const BrunPoint& p,
                            const std::array<double, 3>& S) {
  State x;
  for (int i = 0; i < 3; ++i) {
    x.gamma[i] = S[i] * std::sqrt((p.u[0] - k.e[i]) * (p.u[1] - k.e[i]) / dP(k, i));
  }
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, l = (i + 2) % 3;
    double sum = 0.0;
    for (int s = 0; s < 2; ++s) {
      sum += p.w[s] * (p.u[s] - k.e[i]) / ((p.u[1 - s] - p.u[s]) * brun_P(k, p.u[s]));
    }
    x.m[i] = (k.e[l] - k.e[j]) * x.gamma[j] * x.gamma[l] * sum + k.f * x.gamma[i];
  }
  return from_working_frame(k, x);
}

double brun_coupling(const BrunCurve& k, const State& s) {
  const State x = to_working_frame(k, s);
  const auto u = brun_u(k, x.gamma);
  const double f = k.f;
  double mixed = 0.0;
  for (int i = 0; i < 3; ++i) mixed += k.e[i] * (x.m[i] - f * x.gamma[i]) * x.gamma[i];
  return f * f * (u[0] + u[1] - k.e[0] - k.e[1] - k.e[2]) - 2 * f * mixed;
}

double brun_momentum_bracket(const BrunCurve& k, const State& s) {
  const State x = to_working_frame(k, s);
  const auto u = brun_u(k, x.gamma);
  const double V = (k.e[1] - k.e[0]) * (k.e[2] - k.e[1]) * (k.e[2] - k.e[0]);
  return k.f * (u[1] - u[0]) / (4 * V * x.gamma.prod());
}

double brun_coupling_at(const BrunCurve& k, const BrunPoint& p, const std::array<double, 3>& S) {
  const double P1 = brun_P(k, p.u[0]), P2 = brun_P(k, p.u[1]);
  // V γ1γ2γ3 = S1S2S3 V Π_i √((u1 − e_i)(u2 − e_i)/P′(e_i)) = S1S2S3 √(−P(u1) P(u2)), since
  // Π_i P′(e_i) = −V².
  const double Vg = S[0] * S[1] * S[2] * std::sqrt(-P1 * P2);
  const double f = k.f;
  return f * f * (p.u[0] + p.u[1] - k.e[0] - k.e[1] - k.e[2]) +
         2 * f * Vg * (p.w[0] / P1 - p.w[1] / P2) / (p.u[1] - p.u[0]);
}

BrunIntegrals brun_integrals_at(const BrunCurve& k, const BrunPoint& p,
                                const std::array<double, 3>& S) {
  const double u1 = p.u[0], u2 = p.u[1];
  const double q1 = p.w[0] * p.w[0] / brun_P(k, u1), q2 = p.w[1] * p.w[1] / brun_P(k, u2);
  const double sum_e = k.e[0] + k.e[1] + k.e[2];
  const double K = brun_coupling_at(k, p, S);
  BrunIntegrals r;
  r.c = (q2 - q1) / (u1 - u2) - k.lambda_ * (u1 + u2) + k.lambda_ * sum_e + k.f * k.f;
  r.h = (K + k.lambda_ * u1 * u2 + (u2 * q1 - u1 * q2) / (u1 - u2)) / (2 * k.kappa);
  return r;
}

std::array<Complex, 3> brun_lax(const BrunCurve& k, const State& s, Complex u) {
  const State x = to_working_frame(k, s);
  const Complex sl = std::sqrt(Complex(k.lambda_));
  std::array<Complex, 3> w{};
  for (int i = 0; i < 3; ++i) w[i] = std::sqrt(u - k.e[i]);
  std::array<Complex, 3> X{};
  for (int i = 0; i < 3; ++i) {
    X[i] = w[i] * x.m[i] + sl * w[(i + 1) % 3] * w[(i + 2) % 3] * x.gamma[i];
  }
  return X;
}

Eigen::Matrix3cd brun_rational_lax(const BrunCurve& k, const State& s, Complex l) {
  const State x = to_working_frame(k, s);
  Eigen::Matrix3cd L;
  const Vec3& m = x.m;
  L << 0, -m[2], m[1], m[2], 0, -m[0], -m[1], m[0], 0;
  for (int i = 0; i < 3; ++i) {
    L(i, i) -= l * k.lambda_ * k.e[i];
    for (int j = 0; j < 3; ++j) L(i, j) += x.gamma[i] * x.gamma[j] / l;
  }
  return L;
}

BrunSpectralCurve brun_spectral_curve(const BrunCurve& k) {
  BrunSpectralCurve g;
  // D = N² − 4λf² P, N = n0 + n1 u + n2 u², P = u³ − S u² + S2 u − S3.
  const double S = k.e[0] + k.e[1] + k.e[2];
  const double S2 = k.e[0] * k.e[1] + k.e[1] * k.e[2] + k.e[2] * k.e[0];
  const double S3 = k.e[0] * k.e[1] * k.e[2];
  const std::array<double, 3> N{2 * k.kappa * k.h, k.c - k.lambda_ * S, k.lambda_};
  const std::array<double, 4> P{-S3, S2, -S, 1.0};
  g.discriminant.fill(0.0);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) g.discriminant[i + j] += N[i] * N[j];
  }
  const double q = 4 * k.lambda_ * k.f * k.f;
  for (int i = 0; i < 4; ++i) g.discriminant[i] -= q * P[i];
  if (k.f == 0.0) {  // D = N²: the roots of N, each double (exact)
    g.branch_point = {Complex(k.nu[0]), Complex(k.nu[0]), Complex(k.nu[1]), Complex(k.nu[1])};
    return g;
  }
  Eigen::Matrix4d companion = Eigen::Matrix4d::Zero();
  companion.diagonal(-1).setOnes();
  for (int i = 0; i < 4; ++i) companion(i, 3) = -g.discriminant[i] / g.discriminant[4];
  const Eigen::Vector4cd z = Eigen::EigenSolver<Eigen::Matrix4d>(companion, false).eigenvalues();
  for (int r = 0; r < 4; ++r) {
    Complex u = z[r];
    for (int it = 0; it < kPolishSteps; ++it) {
      const Complex d = horner_derivative(g.discriminant, u);
      if (d == Complex(0.0)) break;
      u -= horner(g.discriminant, u) / d;
    }
    g.branch_point[r] = u;
  }
  std::sort(g.branch_point.begin(), g.branch_point.end(), [](Complex a, Complex b) {
    const bool ra = a.imag() == 0.0, rb = b.imag() == 0.0;
    if (ra != rb) return ra;
    return a.real() != b.real() ? a.real() < b.real() : a.imag() < b.imag();
  });
  return g;
}

}  // namespace newtop
