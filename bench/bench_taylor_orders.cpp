// The work–precision of Taylor's method at each order: for a regime of work_precision and each
// order given, the state error at T and the CPU time per trajectory of the ensemble (the best SIMD
// path; N copies of the start) on the ladder of tolerances — the data behind the order rule
// (taylor_order, docs/methods.md "Taylor"). With "scalar" the scalar run instead.
//
// Run: build/bench/bench_taylor_orders [regime] [orders] [N] [scalar]
//   regime: a, b (b3) or c (default c); orders: comma-separated (default 10,12,14,17,20,24; 0 is
//   the order rule's); N: trajectories (default 16).

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "taylor_ensemble_wp.hpp"

int main(int argc, char** argv) {
  using namespace wp;
  const std::string which = argc > 1 ? argv[1] : "c";
  std::stringstream orders(argc > 2 ? argv[2] : "10,12,14,17,20,24");
  const std::size_t n = argc > 3 ? std::strtoul(argv[3], nullptr, 10) : 16;
  const bool scalar = argc > 4 && std::string(argv[4]) == "scalar";
  const Regime r = which == "a" ? generic() : which == "b" ? fast_spin(1e-3, "b3") : libration();
  const LState ref = reference(r, 1e-19L);
  std::printf("## %s\n%-6s %-8s %12s %12s\n", r.name.c_str(), "order", "tol", "error",
              scalar ? "scalar ms" : "ensemble ms");
  for (std::string item; std::getline(orders, item, ',');) {
    const int order = std::atoi(item.c_str());
    for (double tol : tolerance_ladder()) {
      TaylorEnsemble e(tol, tol, best_simd_path(), order);
      const std::vector<State> x(scalar ? 1 : n, r.x0);
      const std::vector<QuadraticModel> models{r.model};
      Outcome out;
      const double cpu = best_cpu(3, [&] {
        if (scalar) {
          TaylorStepper s(tol, tol, order);
          out = integrate(s, r.model, r.x0, 0.0, r.T, IntegrateOptions{});
        } else {
          out = e.integrate(models, x, 0.0, r.T)[0];
        }
      });
      std::printf("%-6d %-8.1e %12.3e %12.5f\n", e.order(), tol, state_error(out.state, ref),
                  1e3 * cpu / static_cast<double>(x.size()));
    }
  }
}
