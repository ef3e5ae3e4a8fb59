// The Taylor ensemble against heyoka's batch mode (one integrator over `lanes` trajectories in
// SIMD lanes), in the regimes (a), (b3), (c) of work_precision: CPU time per trajectory to a final
// state error of 1e-9 and 1e-12 (|Δm| + |Δγ| at T against Fehlberg 7(8) in long double at 1e-19),
// interpolated in log–log on a ladder of tolerances; heyoka's JIT compilation is not counted.
// Every trajectory starts at the regime's start (the same work in every lane, for both).
//
// Built only when CMake finds heyoka (CMAKE_PREFIX_PATH); run:
//   build/bench/taylor_ensemble_heyoka [regimes] [rounds] [lanes]
//   regimes: letters among a, b, c (default abc); rounds: the best of (default 3); lanes: heyoka's
//   batch size (default 8, AVX-512's doubles), newtop's ensemble runs 2 × lanes trajectories;
//   0: newtop's scalar taylor against heyoka's scalar integrator (taylor_adaptive<double>).
//   build/bench/taylor_ensemble_heyoka [regimes] [rounds] [lanes] tangent
//   the same with one tangent vector δx carried along by each trajectory (newtop: the ensemble's
//   tangent runs, TaylorEnsemble::integrate_tangent; heyoka: its batch integrator on the system and
//   δẋ = J(x) δx, J by heyoka's symbolic derivatives), from δx = (1, 1, 1, 1, 1, 1)/√6 as newtop
//   chaos starts (phase::initial_tangent), not renormalised; the error is the state's, and both
//   take the step from the state's and the vector's coefficients together.

#include <cstdio>
#include <cstdlib>
#include <heyoka/heyoka.hpp>
#include <string>
#include <vector>

#include "taylor_ensemble_wp.hpp"

namespace {

namespace hy = heyoka;
using namespace wp;

// ṁ = m × ω + γ × (M g r0 + λ I γ), γ̇ = γ × ω, ω = I⁻¹ (m − k) (docs/model.md §4).
std::vector<std::pair<hy::expression, hy::expression>> euler_poisson(const QuadraticModel& q) {
  const auto [m0, m1, m2, g0, g1, g2] = hy::make_vars("m0", "m1", "m2", "g0", "g1", "g2");
  const hy::expression m[3] = {m0, m1, m2}, g[3] = {g0, g1, g2};
  hy::expression w[3], f[3];
  for (int i = 0; i < 3; ++i) {
    const double I = q.body.inertia()[i];
    w[i] = (m[i] - hy::expression(q.body.gyrostat()[i])) * hy::expression(1.0 / I);
    f[i] = hy::expression(q.body.mass() * q.field.g * q.body.center_of_mass()[i]) +
           hy::expression(q.field.lambda_ * I) * g[i];
  }
  std::vector<std::pair<hy::expression, hy::expression>> sys;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    sys.push_back(hy::prime(m[i]) = m[j] * w[k] - m[k] * w[j] + g[j] * f[k] - g[k] * f[j]);
  }
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    sys.push_back(hy::prime(g[i]) = g[j] * w[k] - g[k] * w[j]);
  }
  return sys;
}

// The system with one tangent vector (dm0 … dg2): δẋ_i = Σ_j ∂f_i/∂x_j δx_j.
std::vector<std::pair<hy::expression, hy::expression>> with_tangent(const QuadraticModel& q) {
  auto sys = euler_poisson(q);
  const char* names[6] = {"m0", "m1", "m2", "g0", "g1", "g2"};
  std::vector<std::pair<hy::expression, hy::expression>> out = sys;
  for (int i = 0; i < 6; ++i) {
    std::vector<hy::expression> terms;
    for (int j = 0; j < 6; ++j) {
      terms.push_back(hy::diff(sys[static_cast<std::size_t>(i)].second,
                               hy::expression(hy::variable(names[j]))) *
                      hy::expression(hy::variable(std::string("d") + names[j])));
    }
    out.emplace_back(hy::expression(hy::variable(std::string("d") + names[i])),
                     hy::sum(std::move(terms)));
  }
  return out;
}

// The start (and with `tangent` the start of the tangent vector, phase::initial_tangent's).
std::vector<double> start_of(const Regime& r, bool tangent) {
  std::vector<double> x{r.x0.m[0],     r.x0.m[1],     r.x0.m[2],
                        r.x0.gamma[0], r.x0.gamma[1], r.x0.gamma[2]};
  if (tangent) {
    const TangentVector v = phase::initial_tangent(1).col(0);
    for (int i = 0; i < 6; ++i) x.push_back(v[i]);
  }
  return x;
}

WpPoint heyoka_batch(const Regime& r, const LState& ref, double tol, std::uint32_t lanes,
                     int rounds, bool tangent) {
  const std::vector<double> x0 = start_of(r, tangent);
  const std::size_t dim = x0.size();
  std::vector<double> start(dim * lanes);
  for (std::uint32_t l = 0; l < lanes; ++l) {
    for (std::size_t i = 0; i < dim; ++i) start[i * lanes + l] = x0[i];
  }
  hy::taylor_adaptive_batch<double> ta(tangent ? with_tangent(r.model) : euler_poisson(r.model),
                                       start, lanes, hy::kw::tol = tol);
  const double cpu = best_cpu(rounds, [&] {
    std::copy(start.begin(), start.end(), ta.get_state_data());
    ta.set_time(std::vector<double>(lanes, 0.0));
    ta.propagate_until(r.T);
  });
  const State x{
      Vec3(ta.get_state()[0], ta.get_state()[lanes], ta.get_state()[2 * lanes]),
      Vec3(ta.get_state()[3 * lanes], ta.get_state()[4 * lanes], ta.get_state()[5 * lanes])};
  return {tol, state_error(x, ref), cpu / lanes};
}

// heyoka's scalar integrator (taylor_adaptive<double>) on the regime's start.
WpPoint heyoka_scalar(const Regime& r, const LState& ref, double tol, int rounds) {
  const std::vector<double> start{r.x0.m[0],     r.x0.m[1],     r.x0.m[2],
                                  r.x0.gamma[0], r.x0.gamma[1], r.x0.gamma[2]};
  hy::taylor_adaptive<double> ta(euler_poisson(r.model), start, hy::kw::tol = tol);
  const double cpu = best_cpu(rounds, [&] {
    std::copy(start.begin(), start.end(), ta.get_state_data());
    ta.set_time(0.0);
    ta.propagate_until(r.T);
  });
  const auto& x = ta.get_state();
  return {tol, state_error(State{Vec3(x[0], x[1], x[2]), Vec3(x[3], x[4], x[5])}, ref), cpu};
}

// newtop's ensemble with one tangent vector per trajectory (no observer: not renormalised) on n
// copies of the start: the error of the first and the CPU time per trajectory.
WpPoint ensemble_tangent(const Regime& r, const LState& ref, double tol, std::size_t n,
                         int rounds) {
  TaylorEnsemble e(tol, tol);
  const std::vector<State> x(n, r.x0);
  const std::vector<QuadraticModel> models{r.model};
  const std::vector<TangentVector> v0{phase::initial_tangent(1).col(0)};
  std::vector<Outcome> out;
  const double cpu = best_cpu(
      rounds, [&] { out = e.integrate_tangent(models, x, v0, 0.0, r.T, IntegrateOptions{}, {}); });
  return {tol, state_error(out[0].state, ref), cpu / static_cast<double>(n)};
}

// lanes = 0: newtop's scalar taylor against heyoka's scalar integrator.
void run_regime(const Regime& r, int rounds, std::uint32_t lanes, bool tangent) {
  const LState ref = reference(r, 1e-19L);
  std::vector<WpPoint> ours, theirs;
  bool same = true;
  std::printf("\n## %s\n%-8s %12s %14s %12s %14s\n", r.description.c_str(), "tol", "newtop error",
              lanes == 0 ? "scalar ms" : "ensemble ms", "heyoka error",
              lanes == 0 ? "scalar ms" : "batch ms");
  for (double tol : tolerance_ladder()) {
    TaylorStepper s(tol, tol);
    const State xs = integrate(s, r.model, r.x0, 0.0, r.T, IntegrateOptions{}).state;
    if (tangent) {
      ours.push_back(ensemble_tangent(r, ref, tol, 2 * lanes, rounds));
      theirs.push_back(heyoka_batch(r, ref, tol, lanes, rounds, true));
    } else if (lanes == 0) {
      ours.push_back(scalar_taylor(r, ref, tol, rounds));
      theirs.push_back(heyoka_scalar(r, ref, tol, rounds));
    } else {
      ours.push_back(ensemble_taylor(r, ref, tol, 2 * lanes, rounds, xs, same));
      theirs.push_back(heyoka_batch(r, ref, tol, lanes, rounds, false));
    }
    std::printf("%-8.1e %12.3e %14.5f %12.3e %14.5f\n", tol, ours.back().error,
                1e3 * ours.back().cpu, theirs.back().error, 1e3 * theirs.back().cpu);
  }
  if (!tangent) {
    std::printf("every lane of the ensemble the scalar run's bits: %s\n", same ? "yes" : "NO");
  }
  for (double target : {1e-9, 1e-12}) {
    const auto a = time_at(ours, target), b = time_at(theirs, target);
    if (a && b) {
      std::printf("error %.0e: %s %.5f ms, heyoka %s %.5f ms per trajectory (%.2fx)\n", target,
                  lanes == 0 ? "scalar" : "ensemble", 1e3 * *a, lanes == 0 ? "scalar" : "batch",
                  1e3 * *b, *a / *b);
    } else {
      std::printf("error %.0e: not bracketed by the ladder\n", target);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string which = argc > 1 ? argv[1] : "abc";
  const int rounds = argc > 2 ? std::atoi(argv[2]) : 3;
  const auto lanes = static_cast<std::uint32_t>(argc > 3 ? std::atoi(argv[3]) : 8);
  const bool tangent = argc > 4 && std::string(argv[4]) == "tangent";
  if (tangent && lanes == 0) {
    std::fprintf(stderr, "tangent: with heyoka's batch mode only (lanes > 0)\n");
    return 2;
  }
  if (tangent) {
    std::printf("with one tangent vector per trajectory: ");
  }
  if (lanes == 0) {
    std::printf("newtop's scalar taylor against heyoka's scalar integrator\n");
  } else {
    std::printf("newtop Taylor ensemble (%s) against heyoka's batch mode (%u lanes)\n",
                std::string(newtop::simd_path_name(newtop::best_simd_path())).c_str(), lanes);
  }
  if (which.find('a') != std::string::npos) run_regime(generic(), rounds, lanes, tangent);
  if (which.find('b') != std::string::npos)
    run_regime(fast_spin(1e-3, "b3"), rounds, lanes, tangent);
  if (which.find('c') != std::string::npos) run_regime(libration(), rounds, lanes, tangent);
}
