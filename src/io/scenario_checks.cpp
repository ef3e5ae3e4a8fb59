// Magnitude checks of a scenario: every derived quantity, at the initial state and bounded over
// the whole motion, stays below kMaxMagnitude, or the key that drives it past is named.

#include <cmath>

#include "newtop/model/integrals.hpp"
#include "scenario_sections.hpp"

namespace newtop::io {
namespace {

// Product of magnitudes, 0 when any is 0 (never 0 × inf = NaN).
double product(std::initializer_list<double> xs) {
  double p = 1.0;
  for (double x : xs) {
    if (x == 0.0) return 0.0;
    p *= std::abs(x);
  }
  return p;
}

// The factor farthest from 1 on a log scale: the input that drives a product out of range.
Factor dominant(const std::vector<Factor>& fs) {
  Factor best = fs.front();
  double worst = -1.0;
  for (const Factor& f : fs) {
    const double size = f.value == 0.0 ? 0.0 : std::abs(f.power * std::log(std::abs(f.value)));
    if (size > worst) {
      worst = size;
      best = f;
    }
  }
  return best;
}

std::vector<Factor> join(std::vector<Factor> a, const std::vector<Factor>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

class Checker {
 public:
  Checker(const toml::table& doc, const std::string& source) : doc_(doc), source_(source) {}

  // Throws, naming the dominant input, when `value` (a magnitude) exceeds kMaxMagnitude.
  void bound(double value, const std::string& quantity, const std::vector<Factor>& inputs,
             const std::string& details) const {
    if (value <= kMaxMagnitude) return;  // NaN cannot arise: products avoid 0 × inf
    const Factor f = dominant(inputs);
    const toml::table* t = doc_[f.section].as_table();
    static const toml::table kEmpty;
    TableReader(t ? *t : kEmpty, source_, f.section)
        .fail(f.key, quantity + " = " + format_number(value) + " exceeds " +
                         format_number(kMaxMagnitude) + ", the bound on every derived quantity (" +
                         details + ")");
  }

 private:
  const toml::table& doc_;
  const std::string& source_;
};

}  // namespace

void check_magnitudes(const QuadraticModel& model, const State& x0, const FieldSection& field,
                      const BodySource& body, const toml::table& doc, const std::string& source) {
  const Checker check(doc, source);
  const Body& b = model.body;
  const Vec3& I = b.inertia();
  const double I_max = I.maxCoeff(), I_min = I.minCoeff();
  const double g = std::abs(model.field.g), lambda = std::abs(model.field.lambda_);
  const double r0 = b.center_of_mass().stableNorm(), k = b.gyrostat().stableNorm();
  const Vec3 w = omega(b, x0);
  const double w_norm = w.stableNorm();
  Factor inertia = body.inertia, mass = body.mass, com = body.center_of_mass, rotor = body.gyrostat;
  inertia.value = I_max;
  mass.value = b.mass();
  com.value = r0;
  rotor.value = k;
  const Factor omega_key{"initial", "omega", w_norm, 2};
  const std::string M_g_r0 = "M = " + format_number(b.mass()) + ", g = " + format_number(g) +
                             ", |r0| = " + format_number(r0);
  const std::string lam_I =
      "lambda = " + format_number(lambda) + ", max I = " + format_number(I_max);

  // The potential's coefficients: V = M g r0·γ + ½ λ γ·Iγ.
  const double P1 = product({b.mass(), g, r0});
  check.bound(P1, "M g |r0| (the potential's linear term)", join({mass, com}, field.g), M_g_r0);
  const double P2 = product({lambda, I_max});
  check.bound(P2, "lambda max(I) (the potential's quadratic term)", join({inertia}, field.lambda),
              lam_I);
  check.bound(k, "|k| (the gyrostatic moment)", {rotor}, "k = " + format_vector(b.gyrostat()));

  // The initial state: ½ ω·Iω, m = Iω + k.
  const double T0 = 0.5 * (I[0] * w[0] * w[0] + I[1] * w[1] * w[1] + I[2] * w[2] * w[2]);
  check.bound(T0, "the kinetic energy ½ ω·Iω", {omega_key, inertia},
              "|omega| = " + format_number(w_norm) + ", max I = " + format_number(I_max));

  // Over the motion, by the conservation of energy: T ≤ T0 + 2 max|V| with max|V| ≤ P1 + ½P2, so
  // |Iω| ≤ sqrt(2 T max I), |ω| ≤ sqrt(2T / min I), |m| ≤ |Iω| + |k|, and the rates
  // |ṁ| ≤ |m||ω| + |L| with |L| ≤ P1 + P2.
  const double T = T0 + 2.0 * P1 + P2;
  const double Iw = std::sqrt(2.0 * T * I_max), w_max = std::sqrt(2.0 * T / I_min);
  const double rate = (Iw + k) * w_max + P1 + P2;
  std::vector<Factor> drivers{omega_key, inertia};
  if (2.0 * P1 > T0) drivers = join({mass, com}, field.g);
  if (P2 > std::max(T0, 2.0 * P1)) drivers = join({inertia}, field.lambda);
  if (k > Iw) drivers = {rotor};
  if (I_max / I_min > T) drivers = {inertia};
  check.bound(rate, "the bound |m||omega| + |L| over the motion", drivers,
              "kinetic energy <= " + format_number(T) + ", |omega| <= " + format_number(w_max) +
                  ", |m| <= " + format_number(Iw + k));

  // The integrals as computed: Brun's I4 = |Iω|² − λ ABC γ·I⁻¹γ (ABC formed first).
  if (brun_holds(model)) {
    const double ABC = product({I[0], I[1], I[2]});
    check.bound(product({Iw, Iw}) + product({lambda, ABC}) / I_min,
                "Brun's integral |Iw|^2 + |lambda| ABC/min(I)", join({inertia}, field.lambda),
                lam_I + ", |Iw| <= " + format_number(Iw));
  }
  const IntegralValues v = integrals(model, x0);
  const double largest =
      std::max({std::abs(v.energy), std::abs(v.area), std::abs(v.geometric),
                std::abs(v.brun.value_or(0.0)), std::abs(v.lagrange.value_or(0.0))});
  check.bound(std::isfinite(largest) ? largest : HUGE_VAL, "an integral at the initial state",
              {omega_key, inertia}, "energy = " + format_number(v.energy));
}

}  // namespace newtop::io
