// The ensemble stepper with a model per point (ensemble.hpp, EnsembleModels): each lane holds its
// model's constants, computed by split_frame and as the scalar kick computes them, and the points
// are grouped by working frame so that every lane of a kernel runs the same program of stages.

#include <algorithm>
#include <numeric>
#include <string>

#include "ensemble_program.hpp"
#include "newtop/integrate/ensemble.hpp"

namespace newtop {
namespace {

// The frame of the split of a model, as SplittingStepper::step uses it.
SplitFrame model_frame(const Body& body, const SplitOrdering& ordering) {
  SplitFrame f = split_frame(body, ordering);
  if (ordering.free_body == FreeBodySplit::exact) {  // run_step<Axes<0, 1, 2>, ExactFlow>
    f.axis = {0, 1, 2};
    f.sign = {1.0, 1.0, 1.0};
  }
  return f;
}

// Points in one group run one program: the same working axes (and so signs) and, for the spin
// split, the same form of its flow.
bool same_program(const SplitFrame& a, const SplitFrame& b, FreeBodySplit split) {
  return a.axis == b.axis && (split != FreeBodySplit::spin || a.gyrostat_ref == b.gyrostat_ref);
}

bool same_ordering(const SplitOrdering& p, const SplitOrdering& q) {
  return p.axes == q.axes && p.kick_outside == q.kick_outside && p.by_moment == q.by_moment &&
         p.free_body == q.free_body;
}

// A multiple of every available kernel's block.
std::size_t common_block() {
  std::size_t unit = 1;
  for (SimdPath p : {SimdPath::portable, SimdPath::avx2, SimdPath::avx512}) {
    if (simd_path_available(p)) unit = std::lcm(unit, simd_block(p));
  }
  return unit;
}

}  // namespace

EnsembleModels::EnsembleModels(std::span<const QuadraticModel> models,
                               const SplitOrdering& ordering)
    : ordering_(ordering), models_(models.begin(), models.end()) {
  std::vector<SplitFrame> frames;
  frames.reserve(models_.size());
  for (std::size_t j = 0; j < models_.size(); ++j) {
    frames.push_back(model_frame(models_[j].body, ordering));
    auto g = std::find_if(groups_.begin(), groups_.end(), [&](const Group& x) {
      return same_program(x.frame, frames.back(), ordering.free_body);
    });
    if (g == groups_.end()) g = groups_.insert(groups_.end(), Group{frames.back(), {}, 0, {}});
    g->points.push_back(j);
  }
  const std::size_t unit = common_block();
  for (Group& g : groups_) {
    const std::size_t n = g.points.size();
    g.padded = (n + unit - 1) / unit * unit;
    g.constants.assign(detail::kLaneConstants * g.padded, 0.0);
    for (std::size_t j = 0; j < g.padded; ++j) {  // the padding repeats the last point
      const std::size_t point = g.points[std::min(j, n - 1)];
      const SplitFrame& f = frames[point];
      const QuadraticModel& model = models_[point];
      const Body& body = model.body;
      const double mg = body.mass() * model.field.g;
      auto set = [&](int c, double v) { g.constants[std::size_t(c) * g.padded + j] = v; };
      for (int w = 0; w < 3; ++w) {
        const int i = f.axis[w];
        set(detail::kLaneRate + w, f.rate[w]);
        set(detail::kLaneKOverI + w, f.k_over_i[w]);
        set(detail::kLaneGrad0 + w, mg * (f.sign[w] * body.center_of_mass()[i]));
        set(detail::kLaneInertia + w, body.inertia()[i]);
      }
      set(detail::kLaneInvRef, f.inv_ref);
      set(detail::kLaneLambda, model.field.lambda_);
    }
  }
}

void EnsembleStepper::advance(const EnsembleModels& models, EnsembleState& x, double h,
                              std::int64_t steps) {
  if (models.size() != x.size()) {
    throw InputError("ensemble: expected one model per point (" + std::to_string(x.size()) +
                     "), found " + std::to_string(models.size()));
  }
  if (!same_ordering(models.ordering(), ordering_)) {
    throw InputError("ensemble: expected models prepared for the stepper's ordering");
  }
  if (x.size() == 0 || steps <= 0) return;
  const std::size_t block = simd_block(path_);
  std::vector<const Body*> bodies;
  for (const EnsembleModels::Group& g : models.groups_) {
    const SplitFrame& f = g.frame;
    const std::vector<detail::EnsembleStage> program =
        detail::ensemble_step_program(a_, b_, ordering_.free_body, f, h, true);
    const std::size_t n = g.points.size();
    const std::size_t padded = (n + block - 1) / block * block;  // ≤ g.padded
    workspace_.assign(6 * padded, 0.0);
    detail::EnsembleTask task{};
    task.stages = program.data();
    task.stage_count = program.size();
    for (int c = 0; c < detail::kLaneConstants; ++c) {
      task.lane[c] = g.constants.data() + std::size_t(c) * g.padded;
    }
    bodies.clear();
    for (std::size_t j = 0; j < padded; ++j) {
      bodies.push_back(&models.models_[g.points[std::min(j, n - 1)]].body);
    }
    task.bodies = bodies.data();
    for (int w = 0; w < 3; ++w) {
      const int i = f.axis[w];
      task.m[w] = workspace_.data() + std::size_t(w) * padded;
      task.g[w] = workspace_.data() + std::size_t(3 + w) * padded;
      // Working frame (the signs are exact); the padding repeats the last point.
      for (std::size_t j = 0; j < padded; ++j) {
        const std::size_t from = g.points[std::min(j, n - 1)];
        task.m[w][j] = f.sign[w] * x.m[i][from];
        task.g[w][j] = f.sign[w] * x.gamma[i][from];
      }
    }
    task.n = padded;
    task.steps = steps;

    detail::ensemble_run(path_, task);

    for (int w = 0; w < 3; ++w) {
      const int i = f.axis[w];
      for (std::size_t j = 0; j < n; ++j) {
        x.m[i][g.points[j]] = f.sign[w] * task.m[w][j];
        x.gamma[i][g.points[j]] = f.sign[w] * task.g[w][j];
      }
    }
  }
}

}  // namespace newtop
