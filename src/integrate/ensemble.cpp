#include "newtop/integrate/ensemble.hpp"

#include <algorithm>
#include <string>

#include "ensemble_program.hpp"
#include "newtop/integrate/splitting.hpp"

namespace newtop {

EnsembleState::EnsembleState(std::span<const State> states) {
  for (const State& x : states) push_back(x);
}

State EnsembleState::operator[](std::size_t i) const {
  State x;
  for (int w = 0; w < 3; ++w) {
    x.m[w] = m[w][i];
    x.gamma[w] = gamma[w][i];
  }
  return x;
}

void EnsembleState::set(std::size_t i, const State& x) {
  for (int w = 0; w < 3; ++w) {
    m[w][i] = x.m[w];
    gamma[w][i] = x.gamma[w];
  }
}

void EnsembleState::push_back(const State& x) {
  for (int w = 0; w < 3; ++w) {
    m[w].push_back(x.m[w]);
    gamma[w].push_back(x.gamma[w]);
  }
}

namespace detail {

void ensemble_sin_cosm1(double theta, double& s, double& cm1) { sin_cosm1(theta, s, cm1); }

void ensemble_spin_factors(double phi2, double& f1, double& f2) { spin_factors(phi2, f1, f2); }

void ensemble_exact_flow(const Body& body, double m[3], double g[3], double t) {
  const State x = free_body_flow(body, State{Vec3(m[0], m[1], m[2]), Vec3(g[0], g[1], g[2])}, t);
  for (int w = 0; w < 3; ++w) {
    m[w] = x.m[w];
    g[w] = x.gamma[w];
  }
}

}  // namespace detail

std::string_view simd_path_name(SimdPath path) {
  switch (path) {
    case SimdPath::avx2:
      return "avx2";
    case SimdPath::avx512:
      return "avx512";
    case SimdPath::portable:
      break;
  }
  return "portable";
}

bool simd_path_available(SimdPath path) {
  switch (path) {
    case SimdPath::portable:
      return true;
#ifdef NEWTOP_ENSEMBLE_X86
    case SimdPath::avx2:
      return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    case SimdPath::avx512:
      return __builtin_cpu_supports("avx512f");
#endif
    default:
      return false;
  }
}

SimdPath best_simd_path() {
  for (SimdPath p : {SimdPath::avx512, SimdPath::avx2}) {
    if (simd_path_available(p)) return p;
  }
  return SimdPath::portable;
}

std::size_t simd_block(SimdPath path) {
  switch (path) {
#ifdef NEWTOP_ENSEMBLE_X86
    case SimdPath::avx2:
      return detail::ensemble_block_avx2();
    case SimdPath::avx512:
      return detail::ensemble_block_avx512();
#endif
    default:
      return detail::ensemble_block_portable();
  }
}

EnsembleStepper::EnsembleStepper(const CompositionTable& table, SimdPath path)
    : EnsembleStepper(table, default_ordering(table), path) {}

EnsembleStepper::EnsembleStepper(const CompositionTable& table, SplitOrdering ordering,
                                 SimdPath path)
    : order_(table.order), ordering_(ordering), path_(path) {
  if (!simd_path_available(path)) {
    throw InputError("simd: expected a path this build and CPU support (best: " +
                     std::string(simd_path_name(best_simd_path())) + "), found " +
                     std::string(simd_path_name(path)));
  }
  SplittingCoefficients c = splitting_coefficients(table, ordering);
  a_ = std::move(c.a);
  b_ = std::move(c.b);
}

namespace detail {

std::vector<EnsembleStage> ensemble_step_program(const std::vector<double>& a,
                                                 const std::vector<double>& b, FreeBodySplit split,
                                                 const SplitFrame& f, double h, bool per_lane) {
  std::vector<EnsembleStage> p;
  // θ = m_w (ta rate_w) + tb k_over_i_w; `fixed`: θ = m_w ta + tb k_over_i_w.
  auto rotate = [&](int w, double ta, double tb, bool fixed = false) {
    const auto op = static_cast<EnsembleOp>(static_cast<int>(EnsembleOp::rotate0) + w);
    if (per_lane) {
      p.push_back({op, ta, tb, fixed});
    } else {
      p.push_back({op, fixed ? ta : ta * f.rate[w], tb * f.k_over_i[w]});
    }
  };
  auto flow = [&](double t) {
    const double t2 = 0.5 * t;
    switch (split) {
      case FreeBodySplit::axes:  // AxesFlow
        rotate(0, t2, -t2);
        rotate(1, t2, -t2);
        rotate(2, t, -t);
        rotate(1, t2, -t2);
        rotate(0, t2, -t2);
        break;
      case FreeBodySplit::spin:  // SpinFlow<gyrostat_ref>
        p.push_back({EnsembleOp::spin, per_lane ? t : t * f.inv_ref, 0.0});
        rotate(0, t2, -t2);
        if (f.gyrostat_ref) {
          rotate(1, t2, -t2);
          rotate(2, 0.0, -t, true);
          rotate(1, t2, -t2);
        } else {
          rotate(1, t, -t);
        }
        rotate(0, t2, -t2);
        break;
      case FreeBodySplit::exact:  // ExactFlow
        p.push_back({EnsembleOp::exact, t, 0.0});
        break;
    }
  };
  const std::size_t s = a.size();
  for (std::size_t i = 0; i < s; ++i) {
    if (b[i] != 0.0) p.push_back({EnsembleOp::kick, b[i] * h, 0.0});
    flow(a[i] * h);
  }
  if (b[s] != 0.0) p.push_back({EnsembleOp::kick, b[s] * h, 0.0});
  return p;
}

void ensemble_run(SimdPath path, const EnsembleTask& task) {
  switch (path) {
#ifdef NEWTOP_ENSEMBLE_X86
    case SimdPath::avx2:
      ensemble_run_avx2(task);
      break;
    case SimdPath::avx512:
      ensemble_run_avx512(task);
      break;
#endif
    default:
      ensemble_run_portable(task);
      break;
  }
}

}  // namespace detail

void EnsembleStepper::advance(const QuadraticModel& model, EnsembleState& x, double h,
                              std::int64_t steps) {
  const std::size_t n = x.size();
  if (n == 0 || steps <= 0) return;
  SplitFrame f = split_frame(model.body, ordering_);
  if (ordering_.free_body == FreeBodySplit::exact) {  // run_step<Axes<0, 1, 2>, ExactFlow>
    f.axis = {0, 1, 2};
    f.sign = {1.0, 1.0, 1.0};
  }
  const std::vector<detail::EnsembleStage> program =
      detail::ensemble_step_program(a_, b_, ordering_.free_body, f, h, false);

  const std::size_t block = simd_block(path_);
  const std::size_t padded = (n + block - 1) / block * block;
  workspace_.assign(6 * padded, 0.0);
  detail::EnsembleTask task{};
  task.stages = program.data();
  task.stage_count = program.size();
  const Body& body = model.body;
  const double mg = body.mass() * model.field.g;
  for (int w = 0; w < 3; ++w) {
    const int i = f.axis[w];
    task.grad0[w] = mg * (f.sign[w] * body.center_of_mass()[i]);
    task.inertia[w] = body.inertia()[i];
    task.m[w] = workspace_.data() + std::size_t(w) * padded;
    task.g[w] = workspace_.data() + std::size_t(3 + w) * padded;
    // Working frame (the signs are exact); the padding repeats the last point.
    for (std::size_t j = 0; j < padded; ++j) {
      const std::size_t from = std::min(j, n - 1);
      task.m[w][j] = f.sign[w] * x.m[i][from];
      task.g[w][j] = f.sign[w] * x.gamma[i][from];
    }
  }
  task.lambda = model.field.lambda_;
  task.body = &body;
  task.n = padded;
  task.steps = steps;

  detail::ensemble_run(path_, task);

  for (int w = 0; w < 3; ++w) {
    const int i = f.axis[w];
    for (std::size_t j = 0; j < n; ++j) {
      x.m[i][j] = f.sign[w] * task.m[w][j];
      x.gamma[i][j] = f.sign[w] * task.g[w][j];
    }
  }
}

}  // namespace newtop
