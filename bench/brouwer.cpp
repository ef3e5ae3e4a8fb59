// Round-off over long runs (Brouwer's law): the errors of γ·γ, m·γ and the energy of splitting2
// must grow like t^½ (a random walk of unbiased roundings), not like t.
//
// γ·γ and m·γ are exact invariants of every sub-flow, so their error is round-off alone. The energy
// also carries the method's bounded truncation error; its round-off part is isolated by running
// the same method in long double beside the double run (a "shadow": the same sub-flows, same
// coefficients; its own round-off is 2000× smaller) and taking E_double − E_shadow. The motion is
// regular (Brun's case, the libration of docs/performance.md regime (c)), so the two runs part
// only slowly. RMS over an ensemble of runs at checkpoints N/4^k, and the least-squares exponent.
//
// Run: build/bench/brouwer [runs] [steps] [h] [shadow 0|1] [data.csv]
//   defaults: 8 runs, 2^24 steps, h = 0.01, shadow on.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "newtop/analysis/field_scan.hpp"
#include "wp_support.hpp"

namespace {

using namespace newtop;
using LD = long double;

QuadraticModel brouwer_model() {
  return QuadraticModel{Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3::Zero()),
                        QuadraticField::coulomb(0.0, 1.0)};
}

State start(const QuadraticModel& m, int run) {
  const double d = 0.003 * run;
  return state_from_omega(m.body, Vec3(0.05 + d, -0.1, 0.12 - d),
                          Vec3(1.0, 0.15 + d, -0.1).normalized());
}

// The long-double shadow of a SplittingStepper: the same coefficients, frame and sub-flows
// (sub_flows.hpp, instantiated for long double), the kick of the quadratic field in long double.
class Shadow {
 public:
  Shadow(const QuadraticModel& m, const CompositionTable& t, const SplitOrdering& o,
         const State& x0)
      : o_(o), c_(splitting_coefficients(t, o)), f_(split_frame(m.body, o)) {
    for (int w = 0; w < 3; ++w) {
      const int i = f_.axis[w];
      const LD I = m.body.inertia()[i], Ir = m.body.inertia()[f_.axis[2]];
      rate_[w] =
          o.free_body == FreeBodySplit::spin ? (w == 2 ? 0.0L : 1.0L / I - 1.0L / Ir) : 1.0L / I;
      li_[w] = LD(m.field.lambda_) * I;
      b_[w] = LD(f_.sign[w]) * LD(m.body.mass()) * LD(m.field.g) * LD(m.body.center_of_mass()[i]);
      z_.set(w, LD(f_.sign[w]) * LD(x0.m[i]), LD(f_.sign[w]) * LD(x0.gamma[i]));
    }
    inv_ref_ = 1.0L / LD(m.body.inertia()[f_.axis[2]]);
  }
  void step(LD h) {
    for (std::size_t i = 0; i < c_.a.size(); ++i) {
      if (c_.b[i] != 0.0) kick(c_.b[i] * h);
      flow(c_.a[i] * h);
    }
    if (c_.b.back() != 0.0) kick(c_.b.back() * h);
  }
  // Energy ½ Σ m_i²/I_i + ½ λ γ·Iγ (k = 0, r0 = 0) in long double.
  LD energy() const {
    LD e = 0;
    for (int w = 0; w < 3; ++w) {
      const LD inv_i = o_.free_body == FreeBodySplit::spin ? rate_[w] + inv_ref_ : rate_[w];
      e += 0.5L * z_.m(w) * z_.m(w) * inv_i + 0.5L * li_[w] * z_.g(w) * z_.g(w);
    }
    return e;
  }

 private:
  void kick(LD t) {
    LD G[3], g[3];
    for (int w = 0; w < 3; ++w) g[w] = z_.g(w), G[w] = b_[w] + li_[w] * g[w];
    const LD L[3] = {g[1] * G[2] - g[2] * G[1], g[2] * G[0] - g[0] * G[2],
                     g[0] * G[1] - g[1] * G[0]};
    for (int w = 0; w < 3; ++w) z_.set(w, z_.m(w) + t * L[w], z_.g(w));
  }
  void flow(LD t) {
    const LD t2 = t / 2;
    if (o_.free_body == FreeBodySplit::spin) {
      spin_flow(z_, t * inv_ref_);
      axis_flow<0>(z_, t2 * rate_[0], LD(0));
      axis_flow<1>(z_, t * rate_[1], LD(0));
      axis_flow<0>(z_, t2 * rate_[0], LD(0));
    } else {
      axis_flow<0>(z_, t2 * rate_[0], LD(0));
      axis_flow<1>(z_, t2 * rate_[1], LD(0));
      axis_flow<2>(z_, t * rate_[2], LD(0));
      axis_flow<1>(z_, t2 * rate_[1], LD(0));
      axis_flow<0>(z_, t2 * rate_[0], LD(0));
    }
  }

  SplitOrdering o_;
  SplittingCoefficients c_;
  SplitFrame f_;
  LD rate_[3], li_[3], b_[3], inv_ref_;
  PhaseT<LD> z_;
};

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::atoi(argv[1]) : 8;
  const std::int64_t steps = argc > 2 ? std::atoll(argv[2]) : (1 << 24);
  const double h = argc > 3 ? std::atof(argv[3]) : 0.01;
  const bool shadow = argc > 4 ? std::atoi(argv[4]) != 0 : true;
  FILE* data = argc > 5 ? std::fopen(argv[5], "w") : nullptr;
  const QuadraticModel m = brouwer_model();
  const CompositionTable& table = composition_table("splitting2");
  const SplitOrdering order = default_ordering(table);
  std::vector<std::int64_t> checks;
  for (std::int64_t n = steps; n >= 1024; n /= 4) checks.insert(checks.begin(), n);
  const std::size_t K = checks.size();
  std::vector<double> sg(K), sa(K), se(K), te(K);
  const double t0 = wp::cpu_seconds();
  for (int run = 0; run < runs; ++run) {
    State x = start(m, run);
    const double g0 = geometric(x), a0 = area(x), scale = x.m.norm();
    SplittingStepper s(table, order);
    Shadow sh(m, table, order, x);
    const LD e0 = sh.energy();
    std::size_t k = 0;
    for (std::int64_t i = 1; i <= steps; ++i) {
      s.step(m, x, h);
      if (shadow) sh.step(h);
      if (i == checks[k]) {
        sg[k] += std::pow(geometric(x) - g0, 2);
        sa[k] += std::pow((area(x) - a0) / scale, 2);
        if (shadow) {
          const double e = energy(m, x);
          se[k] += std::pow(double((LD(e) - sh.energy()) / e0), 2);
          te[k] += std::pow(double((LD(e) - e0) / e0), 2);
        }
        ++k;
      }
    }
  }
  std::printf("splitting2 (%s split, kick %s), h = %g, %d runs of %lld steps, %.0f s CPU\n",
              order.free_body == FreeBodySplit::spin ? "spin" : "axes",
              order.kick_outside ? "outside" : "inside", h, runs, (long long)steps,
              wp::cpu_seconds() - t0);
  std::printf(
      "| steps | rms gamma.gamma error | rms m.gamma error / |m| | rms rel. energy round-off | "
      "rms rel. energy error (total) |\n|---|---|---|---|---|\n");
  std::vector<double> n, g, a, e;
  if (data)
    std::fprintf(data, "steps,rms_geometric,rms_area,rms_energy_roundoff,rms_energy_total\n");
  for (std::size_t k = 0; k < K; ++k) {
    n.push_back(double(checks[k]));
    g.push_back(std::sqrt(sg[k] / runs));
    a.push_back(std::sqrt(sa[k] / runs));
    e.push_back(std::sqrt(se[k] / runs));
    const double tot = std::sqrt(te[k] / runs);
    std::printf("| %lld | %.3e | %.3e | %.3e | %.3e |\n", (long long)checks[k], g.back(), a.back(),
                e.back(), tot);
    if (data)
      std::fprintf(data, "%lld,%.6e,%.6e,%.6e,%.6e\n", (long long)checks[k], g.back(), a.back(),
                   e.back(), tot);
  }
  std::printf("\nfitted exponents (error ∝ N^p): gamma.gamma %.3f, m.gamma %.3f",
              loglog_slope(n, g), loglog_slope(n, a));
  if (shadow) std::printf(", energy round-off %.3f", loglog_slope(n, e));
  std::printf("\n");
  if (data) std::fclose(data);
  return 0;
}
