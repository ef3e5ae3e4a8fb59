#include "newtop/phase/ensemble_tangent.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "../integrate/ensemble_tangent_kernel.hpp"

namespace newtop::phase {

EnsembleTangentStepper::EnsembleTangentStepper(const CompositionTable& table,
                                               const SplitOrdering& ordering, SimdPath path)
    : order_(table.order), ordering_(ordering), path_(path) {
  check_ensemble_tangent_split(ordering.free_body);
  if (!simd_path_available(path)) {
    throw InputError("simd: expected a path this build and CPU support, found " +
                     std::string(simd_path_name(path)));
  }
  SplittingCoefficients c = splitting_coefficients(table, ordering);
  a_ = std::move(c.a);
  b_ = std::move(c.b);
}

namespace {

// The number of columns of every point's tangent vectors (InputError where they differ).
std::size_t tangent_columns(const EnsembleState& x, const std::vector<Tangent>& V) {
  if (V.size() != x.size()) {
    throw InputError("tangent: expected one set of tangent vectors per point (" +
                     std::to_string(x.size()) + "), found " + std::to_string(V.size()));
  }
  const auto columns = V.empty() ? 1 : V[0].cols();
  for (const Tangent& t : V) {
    if (t.cols() != columns || columns < 1) {
      throw InputError("tangent: expected the same number (1 to 6) of tangent vectors per point");
    }
  }
  return static_cast<std::size_t>(columns);
}

// The stages of TangentSplittingStepper::step and free_body: rotations about the body axes in the
// order `axes`, with a = t/I and b = k of the model, or with a model per lane a = t.
std::vector<newtop::detail::EnsembleStage> tangent_program(const std::vector<double>& a,
                                                           const std::vector<double>& b,
                                                           const std::array<int, 3>& axes, double h,
                                                           const Body* body) {
  std::vector<newtop::detail::EnsembleStage> program;
  auto rotate = [&](int axis, double t) {
    const auto op = static_cast<newtop::detail::EnsembleOp>(
        static_cast<int>(newtop::detail::EnsembleOp::rotate0) + axis);
    if (body) {
      program.push_back({op, t / body->inertia()[axis], body->gyrostat()[axis]});
    } else {
      program.push_back({op, t, 0.0});
    }
  };
  const std::size_t s = a.size();
  for (std::size_t i = 0; i <= s; ++i) {
    if (b[i] != 0.0) program.push_back({newtop::detail::EnsembleOp::kick, b[i] * h, 0.0});
    if (i == s) break;
    const double t = a[i] * h, t2 = 0.5 * t;
    rotate(axes[0], t2);
    rotate(axes[1], t2);
    rotate(axes[2], t);
    rotate(axes[1], t2);
    rotate(axes[0], t2);
  }
  return program;
}

// Runs the task on the points `points` of x and V (their tangent vectors' `cols` columns): copied
// into the workspace (padded with the last point), advanced, copied back.
void run_points(SimdPath path, newtop::detail::EnsembleTangentTask& task,
                const std::vector<std::size_t>& points, std::size_t cols, EnsembleState& x,
                std::vector<Tangent>& V, std::vector<double>& workspace) {
  const std::size_t n = points.size();
  constexpr std::size_t kWidest = 8;  // a multiple of every kernel's lanes
  const std::size_t padded = (n + kWidest - 1) / kWidest * kWidest;
  workspace.assign((6 + 6 * cols) * padded, 0.0);
  task.columns = static_cast<int>(cols);
  task.n = padded;
  double* next = workspace.data();
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
    const std::size_t from = points[std::min(j, n - 1)];
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

  switch (path) {
#ifdef NEWTOP_ENSEMBLE_X86
    case SimdPath::avx2:
      newtop::detail::ensemble_tangent_run_avx2(task);
      break;
    case SimdPath::avx512:
      newtop::detail::ensemble_tangent_run_avx512(task);
      break;
#endif
    default:
      newtop::detail::ensemble_tangent_run_portable(task);
      break;
  }

  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t to = points[j];
    for (int w = 0; w < 3; ++w) {
      x.m[w][to] = task.m[w][j];
      x.gamma[w][to] = task.g[w][j];
    }
    for (int r = 0; r < 6; ++r) {
      for (std::size_t c = 0; c < cols; ++c) {
        V[to](r, static_cast<Eigen::Index>(c)) = task.v[r][c][j];
      }
    }
  }
}

}  // namespace

void EnsembleTangentStepper::advance(const QuadraticModel& model, EnsembleState& x,
                                     std::vector<Tangent>& V, double h, std::int64_t steps) {
  const std::size_t cols = tangent_columns(x, V);
  const std::size_t n = x.size();
  if (n == 0 || steps <= 0) return;
  const Body& body = model.body;
  const std::vector<newtop::detail::EnsembleStage> program =
      tangent_program(a_, b_, split_frame(body, ordering_).axis, h, &body);
  newtop::detail::EnsembleTangentTask task{};
  task.stages = program.data();
  task.stage_count = program.size();
  const double mg = body.mass() * model.field.g;
  for (int w = 0; w < 3; ++w) {
    task.grad0[w] = mg * body.center_of_mass()[w];
    task.inertia[w] = body.inertia()[w];
  }
  task.lambda = model.field.lambda_;
  task.steps = steps;
  std::vector<std::size_t> all(n);
  for (std::size_t j = 0; j < n; ++j) all[j] = j;
  run_points(path_, task, all, cols, x, V, workspace_);
}

void EnsembleTangentStepper::advance(const EnsembleModels& models, EnsembleState& x,
                                     std::vector<Tangent>& V, double h, std::int64_t steps) {
  const std::size_t cols = tangent_columns(x, V);
  const SplitOrdering& o = models.ordering();
  if (models.size() != x.size() || o.axes != ordering_.axes || o.by_moment != ordering_.by_moment ||
      o.free_body != ordering_.free_body) {
    throw InputError("tangent: expected one model per point, prepared for the stepper's ordering");
  }
  if (x.size() == 0 || steps <= 0) return;
  for (const EnsembleModels::Group& g : models.groups_) {
    // The group's rotation order (split_frame's axes, the same for its models); the models'
    // constants per lane in the body frame, padded with the last point's.
    const std::vector<newtop::detail::EnsembleStage> program =
        tangent_program(a_, b_, g.frame.axis, h, nullptr);
    const std::size_t n = g.points.size();
    const std::size_t padded = (n + 7) / 8 * 8;
    constants_.assign(newtop::detail::kTangentConstants * padded, 0.0);
    for (std::size_t j = 0; j < padded; ++j) {
      const QuadraticModel& m = models.models_[g.points[std::min(j, n - 1)]];
      const Body& body = m.body;
      const double mg = body.mass() * m.field.g;
      auto set = [&](int c, double v) { constants_[std::size_t(c) * padded + j] = v; };
      for (int w = 0; w < 3; ++w) {
        set(newtop::detail::kTangentInertia + w, body.inertia()[w]);
        set(newtop::detail::kTangentGyrostat + w, body.gyrostat()[w]);
        set(newtop::detail::kTangentGrad0 + w, mg * body.center_of_mass()[w]);
      }
      set(newtop::detail::kTangentLambda, m.field.lambda_);
    }
    newtop::detail::EnsembleTangentTask task{};
    task.stages = program.data();
    task.stage_count = program.size();
    for (int c = 0; c < newtop::detail::kTangentConstants; ++c) {
      task.lane[c] = constants_.data() + std::size_t(c) * padded;
    }
    task.steps = steps;
    run_points(path_, task, g.points, cols, x, V, workspace_);
  }
}

}  // namespace newtop::phase
