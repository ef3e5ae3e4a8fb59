// The compiled entry points (run.hpp) against the templates they are made of (methods.hpp): every
// method, every field and both state types give the same Outcome and the same observed steps,
// bit for bit — one dispatch, no change of arithmetic.

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "newtop/exact/mass_models.hpp"
#include "newtop/integrate/methods.hpp"
#include "newtop/integrate/run.hpp"
#include "newtop/model/model.hpp"
#include "support/problems.hpp"

namespace newtop {
namespace test_run {
namespace {

std::vector<Model> models() {
  const auto points = std::make_shared<const MassModel>(PointMasses(
      {1.0, 2.0, 1.5, 0.5},
      {Vec3(1.0, 0.2, 0.0), Vec3(-0.4, 0.8, 0.3), Vec3(0.1, -0.6, 0.9), Vec3(-0.5, -0.3, -0.7)}));
  return {Model(test::generic_model(Vec3(0.1, -0.2, 0.3))), Model::exact(points, 1.0, 3.0),
          Model::multipole(points, 4, 1.0, 3.0)};
}

std::vector<MethodSettings> methods_to_try() {
  return {{"splitting2", 0.01, 0, 0, std::nullopt},   {"splitting6", 0.02, 0, 0, std::nullopt},
          {"rk4", 0.01, 0, 0, std::nullopt},          {"dopri5", 0.0, 1e-9, 1e-9, std::nullopt},
          {"rkf78", 0.0, 1e-11, 1e-11, std::nullopt}, {"dop853", 0.0, 1e-11, 1e-11, std::nullopt}};
}

void expect_same(const Outcome& a, const Outcome& b, const std::string& what) {
  EXPECT_EQ(a.status, b.status) << what;
  EXPECT_EQ(a.t, b.t) << what;
  EXPECT_EQ(a.steps, b.steps) << what;
  EXPECT_EQ(a.rejected, b.rejected) << what;
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(a.state.m[i], b.state.m[i]) << what;
    EXPECT_EQ(a.state.gamma[i], b.state.gamma[i]) << what;
  }
  ASSERT_EQ(a.attitude.has_value(), b.attitude.has_value()) << what;
  if (a.attitude) {
    EXPECT_EQ(a.attitude->coeffs(), b.attitude->coeffs()) << what;
  }
}

template <class X>
void compare_runs(const Model& model, const X& x0, const MethodSettings& method,
                  const std::string& what) {
  std::vector<double> seen_compiled, seen_template;
  const Outcome compiled = run_method(method, model, x0, 0.0, 2.0, {}, [&](double t, const X& x) {
    seen_compiled.push_back(t);
    seen_compiled.push_back(x.gamma[2]);
  });
  const Outcome direct = visit_model(model, [&](const auto& m) {
    return run_method(method, m, x0, 0.0, 2.0, IntegrateOptions{}, [&](double t, const X& x) {
      seen_template.push_back(t);
      seen_template.push_back(x.gamma[2]);
    });
  });
  expect_same(compiled, direct, what);
  EXPECT_EQ(seen_compiled, seen_template) << what;
  // The observer saw t0 and every accepted step.
  EXPECT_EQ(seen_compiled.size(), 2u * static_cast<std::size_t>(compiled.steps + 1)) << what;

  // Sampled at requested times, with and without a step observer.
  const OutputTimes times = OutputTimes::every(0.25, 0.0, 2.0);
  std::vector<double> s_compiled, s_template;
  const Outcome sc = run_method_sampled(method, model, x0, 0.0, 2.0, times, {},
                                        [&](std::int64_t k, double t, const X& x) {
                                          s_compiled.push_back(static_cast<double>(k) + t);
                                          s_compiled.push_back(x.m[0]);
                                        });
  const Outcome st = visit_model(model, [&](const auto& m) {
    return run_method_sampled(method, m, x0, 0.0, 2.0, times, IntegrateOptions{},
                              [&](std::int64_t k, double t, const X& x) {
                                s_template.push_back(static_cast<double>(k) + t);
                                s_template.push_back(x.m[0]);
                              });
  });
  expect_same(sc, st, what + " (sampled)");
  EXPECT_EQ(s_compiled, s_template) << what;
  EXPECT_EQ(s_compiled.size(), 2u * static_cast<std::size_t>(times.size())) << what;
}

TEST(CompiledRun, EqualsTheTemplateForEveryMethodFieldAndStateType) {
  for (const Model& model : models()) {
    const State x0{Vec3(0.4, -0.3, 0.9), Vec3(0.6, 0.0, 0.8)};
    const OrientedState o0 =
        with_attitude(x0, Quaternion(Eigen::AngleAxisd(0.7, Vec3(0.3, 0.4, 0.5).normalized())));
    for (const MethodSettings& method : methods_to_try()) {
      const std::string what = std::string(to_string(model.kind())) + " " + method.name;
      compare_runs(model, x0, method, what);
      compare_runs(model, o0, method, what + " with attitude");
    }
  }
}

TEST(CompiledRun, ChecksItsInputLikeTheTemplate) {
  const Model model(test::generic_model());
  const State x0{Vec3(0.4, -0.3, 0.9), Vec3(0.6, 0.0, 0.8)};
  EXPECT_THROW(run_method({"splitting2", -1.0, 0, 0, std::nullopt}, model, x0, 0.0, 1.0),
               InputError);
  EXPECT_THROW(run_method({"nonsense", 0.1, 0, 0, std::nullopt}, model, x0, 0.0, 1.0), InputError);
  const State bad{Vec3(std::nan(""), 0, 0), Vec3(0, 0, 1)};
  EXPECT_THROW(run_method({"rk4", 0.1, 0, 0, std::nullopt}, model, bad, 0.0, 1.0), InputError);
}

}  // namespace
}  // namespace test_run
}  // namespace newtop
