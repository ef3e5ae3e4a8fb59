// The orbit's Taylor ensemble against the scalar Taylor run of each trajectory (the same bits, so
// the same accuracy; checked here, the program aborts otherwise): CPU time per trajectory for N
// librating satellites (each its own start, about 0.1 rad off the rest orientation of the orbital
// frame) over ten orbits, on a circle (in t) and on an ellipse of eccentricity 0.1 (in ν), at
// tolerances 1e-9 and 1e-12, on every SIMD path of this CPU. The medians of interleaved rounds.
//
// Run: build/bench/orbit_taylor_ensemble [rounds] [N] (default 5, 64)

#include "newtop/orbit/orbit_taylor_ensemble.hpp"

#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "newtop/orbit/orbit_integrate.hpp"

namespace {

using namespace newtop;

double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// The i-th start: turned from the rest orientation (least moment radial, largest along the
/// normal) by about 0.1 rad, spinning a few per cent off the orbit's rate.
OrbitState librating(const Body& body, double rate, std::size_t i) {
  const double s = 0.01 * static_cast<double>(i % 17);
  const Mat3 S = Eigen::Quaterniond(1.0, 0.05 - 0.3 * s, -0.04 + 0.2 * s, 0.03)
                     .normalized()
                     .toRotationMatrix();
  const Vec3 n = S.col(2);
  const Vec3 w = rate * (n + Vec3(0.02 - s, -0.03, 0.025 + s));
  return {body.inertia().cwiseProduct(w) + body.gyrostat(), S.col(0), n};
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

template <class M>
void measure(const char* name, const M& model, const std::vector<OrbitState>& x, double a, double b,
             int rounds) {
  const std::vector<M> models{model};
  for (double tol : {1e-9, 1e-12}) {
    const MethodSettings taylor("taylor", 0.0, tol, tol);
    std::vector<OrbitOutcome> scalar(x.size());
    std::vector<double> t_scalar;
    std::vector<std::vector<double>> t_lanes(3);
    std::int64_t steps = 0;
    for (int r = 0; r < rounds; ++r) {
      double c0 = cpu_seconds();
      for (std::size_t i = 0; i < x.size(); ++i) {
        scalar[i] = run_orbit_method(taylor, model, x[i], a, b, 100'000'000);
      }
      t_scalar.push_back((cpu_seconds() - c0) / static_cast<double>(x.size()));
      for (SimdPath path : {SimdPath::portable, SimdPath::avx2, SimdPath::avx512}) {
        if (!simd_path_available(path)) continue;
        OrbitTaylorEnsemble e(tol, tol, path);
        IntegrateOptions opt;  // run_orbit_method's
        opt.max_steps = 100'000'000;
        opt.initial_step = std::abs(b - a) / 1000.0;
        c0 = cpu_seconds();
        const std::vector<OrbitOutcome> out = e.integrate(models, x, a, b, opt);
        t_lanes[static_cast<std::size_t>(path)].push_back((cpu_seconds() - c0) /
                                                          static_cast<double>(x.size()));
        for (std::size_t i = 0; i < x.size(); ++i) {
          if (!(out[i].state == scalar[i].state) || out[i].steps != scalar[i].steps) std::abort();
        }
      }
    }
    for (const OrbitOutcome& o : scalar) steps += o.steps;
    const double s = median(t_scalar);
    std::printf("%-22s %-6.0e %8.1f %12.4f", name, tol,
                static_cast<double>(steps) / static_cast<double>(x.size()), 1e3 * s);
    for (SimdPath path : {SimdPath::portable, SimdPath::avx2, SimdPath::avx512}) {
      const auto& t = t_lanes[static_cast<std::size_t>(path)];
      if (t.empty()) {
        std::printf(" %18s", "—");
      } else {
        std::printf("   %9.4f (%4.2f)", 1e3 * median(t), median(t) / s);
      }
    }
    std::printf("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  const std::size_t n = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 64;
  const Body body = Body::from_principal(Vec3(1.0, 1.6, 2.1), 1.0, Vec3::Zero());
  const double rate = 0.7, orbits = 10.0;
  std::vector<OrbitState> x;
  for (std::size_t i = 0; i < n; ++i) x.push_back(librating(body, rate, i));
  std::printf(
      "orbit Taylor ensemble: %zu librating satellites, ten orbits, %d rounds; CPU ms per "
      "trajectory (ratio to the scalar run), every lane checked to be the scalar run's "
      "bits\n",
      n, rounds);
  std::printf("%-22s %-6s %8s %12s %18s %18s %18s\n", "orbit", "tol", "steps", "scalar", "portable",
              "avx2", "avx512");
  measure("circular (t)", CircularOrbitModel(body, CircularOrbit::from_rate(rate)), x, 0.0,
          orbits * 2 * std::numbers::pi / rate, rounds);
  measure("elliptic e = 0.1 (nu)",
          EllipticOrbitModel(body, EllipticOrbit::from_mean_motion(rate, 0.1, 0.0)), x, 0.0,
          orbits * 2 * std::numbers::pi, rounds);
  return 0;
}
