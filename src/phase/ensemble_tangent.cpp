#include "newtop/phase/ensemble_tangent.hpp"

#include <string>

#include "../integrate/ensemble_tangent_kernel.hpp"

namespace newtop::phase {

EnsembleTangentStepper::EnsembleTangentStepper(const CompositionTable& table,
                                               const SplitOrdering& ordering, SimdPath path)
    : order_(table.order), ordering_(ordering), path_(path) {
  if (ordering.free_body != FreeBodySplit::axes) {
    throw InputError("ordering: expected the axes split of the free body for the tangent map");
  }
  if (!simd_path_available(path)) {
    throw InputError("simd: expected a path this build and CPU support, found " +
                     std::string(simd_path_name(path)));
  }
  SplittingCoefficients c = splitting_coefficients(table, ordering);
  a_ = std::move(c.a);
  b_ = std::move(c.b);
}

void EnsembleTangentStepper::advance(const QuadraticModel& model, EnsembleState& x,
                                     std::vector<Tangent>& V, double h, std::int64_t steps) {
  const std::size_t n = x.size();
  if (V.size() != n) {
    throw InputError("tangent: expected one set of tangent vectors per point (" +
                     std::to_string(n) + "), found " + std::to_string(V.size()));
  }
  if (n == 0 || steps <= 0) return;
  const auto columns = V[0].cols();
  for (const Tangent& t : V) {
    if (t.cols() != columns || columns < 1) {
      throw InputError("tangent: expected the same number (1 to 6) of tangent vectors per point");
    }
  }
  // The stages of TangentSplittingStepper::step and free_body, with its constants.
  const Body& body = model.body;
  const std::array<int, 3> axes = split_frame(body, ordering_).axis;
  std::vector<detail::EnsembleStage> program;
  auto rotate = [&](int axis, double t) {
    program.push_back(
        {static_cast<detail::EnsembleOp>(static_cast<int>(detail::EnsembleOp::rotate0) + axis),
         t / body.inertia()[axis], body.gyrostat()[axis]});
  };
  const std::size_t s = a_.size();
  for (std::size_t i = 0; i <= s; ++i) {
    if (b_[i] != 0.0) program.push_back({detail::EnsembleOp::kick, b_[i] * h, 0.0});
    if (i == s) break;
    const double t = a_[i] * h, t2 = 0.5 * t;
    rotate(axes[0], t2);
    rotate(axes[1], t2);
    rotate(axes[2], t);
    rotate(axes[1], t2);
    rotate(axes[0], t2);
  }

  constexpr std::size_t kWidest = 8;  // a multiple of every kernel's lanes
  const std::size_t padded = (n + kWidest - 1) / kWidest * kWidest;
  const auto cols = static_cast<std::size_t>(columns);
  workspace_.assign((6 + 6 * cols) * padded, 0.0);
  detail::EnsembleTangentTask task{};
  task.stages = program.data();
  task.stage_count = program.size();
  const double mg = body.mass() * model.field.g;
  for (int w = 0; w < 3; ++w) {
    task.grad0[w] = mg * body.center_of_mass()[w];
    task.inertia[w] = body.inertia()[w];
  }
  task.lambda = model.field.lambda_;
  task.columns = static_cast<int>(columns);
  task.n = padded;
  task.steps = steps;
  double* next = workspace_.data();
  auto take = [&] {
    double* p = next;
    next += padded;
    return p;
  };
  for (int w = 0; w < 3; ++w) task.m[w] = take();
  for (int w = 0; w < 3; ++w) task.g[w] = take();
  for (int r = 0; r < 6; ++r) {
    for (std::size_t c = 0; c < cols; ++c) task.v[r][c] = take();
  }
  for (std::size_t j = 0; j < padded; ++j) {  // the padding repeats the last point
    const std::size_t from = std::min(j, n - 1);
    for (int w = 0; w < 3; ++w) {
      task.m[w][j] = x.m[w][from];
      task.g[w][j] = x.gamma[w][from];
    }
    for (int r = 0; r < 6; ++r) {
      for (std::size_t c = 0; c < cols; ++c) {
        task.v[r][c][j] = V[from](r, static_cast<Eigen::Index>(c));
      }
    }
  }

  switch (path_) {
#ifdef NEWTOP_ENSEMBLE_X86
    case SimdPath::avx2:
      detail::ensemble_tangent_run_avx2(task);
      break;
    case SimdPath::avx512:
      detail::ensemble_tangent_run_avx512(task);
      break;
#endif
    default:
      detail::ensemble_tangent_run_portable(task);
      break;
  }

  for (std::size_t j = 0; j < n; ++j) {
    for (int w = 0; w < 3; ++w) {
      x.m[w][j] = task.m[w][j];
      x.gamma[w][j] = task.g[w][j];
    }
    for (int r = 0; r < 6; ++r) {
      for (std::size_t c = 0; c < cols; ++c) {
        V[j](r, static_cast<Eigen::Index>(c)) = task.v[r][c][j];
      }
    }
  }
}

}  // namespace newtop::phase
