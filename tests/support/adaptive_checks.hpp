#pragma once
// Checks shared by the tests of newtop's own adaptive methods (dop853, taylor): the error control
// against a reference near round-off, a run with an attitude against Fehlberg 7(8), and the
// command line that names the method.

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/cli.hpp"
#include "support/problems.hpp"

namespace newtop::test {

/// Over T = 10 of the generic model (gyrostat (0.1, −0.2, 0.05)), the error at T against
/// Fehlberg 7(8) at 1e-15 for tolerances 1e-6, 1e-8, 1e-10: each within tol_factor tol, and
/// falling by at least 10× for each 100× of the tolerance. make(tol) gives the stepper; returns
/// the errors.
template <class Make>
std::vector<double> expect_error_follows_the_tolerance(Make make, double tol_factor) {
  const QuadraticModel m = generic_model(Vec3(0.1, -0.2, 0.05));
  const State x0 = generic_state(m);
  constexpr double T = 10.0;
  const State ref = reference_solution(m, x0, T, 1e-15);
  std::vector<double> errors;
  for (double tol : {1e-6, 1e-8, 1e-10}) {
    auto s = make(tol);
    const Outcome o = integrate(s, m, x0, 0.0, T, IntegrateOptions{});
    EXPECT_EQ(o.status, Status::finished) << tol;
    const double e = distance(o.state, ref);
    EXPECT_LT(e, tol_factor * tol) << tol;
    if (!errors.empty()) {
      EXPECT_GT(errors.back() / e, 10.0) << tol << ": " << errors.back() << " → " << e;
    }
    errors.push_back(e);
  }
  return errors;
}

/// A run with an attitude from the generic state and q of 0.7 rad about (0.2, −0.4, 0.9): the
/// state and q at T = 20 against Fehlberg 7(8) with an attitude at 1e-13 (within 1e-9), the
/// renormalisation of q below 1e-11, and the continuous extension of a first step (trials of 0.5
/// until one is accepted) at its middle against the same reference (within 1e-10). make() gives
/// the stepper, at tolerance 1e-12.
template <class Make>
void expect_carries_the_attitude(Make make) {
  const QuadraticModel m = generic_model();
  OrientedState x0;
  static_cast<State&>(x0) = generic_state(m);
  x0.q = Quaternion(Eigen::AngleAxisd(0.7, Vec3(0.2, -0.4, 0.9).normalized()));
  auto s = make();
  Fehlberg78Stepper r(1e-13, 1e-13);
  const Outcome a = integrate(s, m, x0, 0.0, 20.0, IntegrateOptions{});
  const Outcome b = integrate(r, m, x0, 0.0, 20.0, IntegrateOptions{});
  ASSERT_EQ(a.status, Status::finished);
  ASSERT_TRUE(a.attitude && b.attitude);
  EXPECT_LT(distance(a.state, b.state), 1e-9);
  EXPECT_LT(a.attitude->angularDistance(*b.attitude), 1e-9);
  EXPECT_LT(a.attitude_projection, 1e-11);
  EXPECT_GT(a.attitude_projection, 0.0);  // q was renormalised: the check above is not vacuous
  auto first = make();
  OrientedState x = x0;
  double t = 0.0, dt = 0.5;
  int trials = 0;
  while (!first.try_step(m, x, t, dt)) ASSERT_LT(++trials, 20);
  ASSERT_GT(t, 0.0);
  const OrientedState mid = first.dense_oriented_state(m, 0.5 * t);
  const Outcome half = integrate(r, m, x0, 0.0, 0.5 * t, IntegrateOptions{});
  EXPECT_LT(distance(mid, half.state), 1e-10);
  EXPECT_LT(mid.q.angularDistance(*half.attitude), 1e-10);
}

/// `newtop simulate examples/brun.toml --t-end 2 --tol 1e-11 --method <method> --json`: its final
/// state against Fehlberg 7(8) at 1e-13 from the same command (within 1e-9); returns its JSON.
inline nlohmann::json expect_command_line_runs(const std::string& method) {
  const std::string brun = "simulate " + example_path("brun.toml") + " --t-end 2 --json";
  const CliResult r = run_newtop(brun + " --tol 1e-11 --method " + method, Stderr::separate);
  EXPECT_EQ(r.code, 0) << r.err;
  const CliResult rk = run_newtop(brun + " --tol 1e-13 --method rkf78", Stderr::separate);
  EXPECT_EQ(rk.code, 0) << rk.err;
  if (r.code != 0 || rk.code != 0) return {};
  const nlohmann::json j = nlohmann::json::parse(r.out), k = nlohmann::json::parse(rk.out);
  EXPECT_EQ(j["method"], method);
  for (const char* v : {"m", "gamma"}) {
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(j["final"][v][i].get<double>(), k["final"][v][i].get<double>(), 1e-9) << v;
    }
  }
  return j;
}

}  // namespace newtop::test
