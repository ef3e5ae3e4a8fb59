#include <array>
#include <string>
#include <utility>

#include "newtop/integrate/sub_flows.hpp"
#include "newtop/orbit/orbit_integrate.hpp"

namespace newtop {
namespace {

/// Body axes by increasing moment: least, middle, largest.
std::array<int, 3> axes_by_moment(const Body& body) {
  std::array<int, 3> a{0, 1, 2};
  const Vec3& I = body.inertia();
  if (I[a[0]] > I[a[1]]) std::swap(a[0], a[1]);
  if (I[a[1]] > I[a[2]]) std::swap(a[1], a[2]);
  if (I[a[0]] > I[a[1]]) std::swap(a[0], a[1]);
  return a;
}

/// The free body over the time τ, Strang-split over the axes: least-moment axis outermost,
/// largest in the centre.
void free_body(const Body& body, const std::array<int, 3>& a, OrbitState& x, double tau) {
  rotate_about_body_axis(body, x, a[0], 0.5 * tau);
  rotate_about_body_axis(body, x, a[1], 0.5 * tau);
  rotate_about_body_axis(body, x, a[2], tau);
  rotate_about_body_axis(body, x, a[1], 0.5 * tau);
  rotate_about_body_axis(body, x, a[0], 0.5 * tau);
}

std::vector<OrbitStage> make_program(const CompositionTable& table, bool kick_outside) {
  std::vector<OrbitStage> p;
  auto push = [&](bool kick, double fraction) {
    if (kick && !p.empty() && p.back().kick) {
      p.back().fraction += fraction;  // adjacent kicks at the same ν: exact merge
    } else {
      p.push_back({kick, fraction});
    }
  };
  for (double g : table.gamma) {
    push(kick_outside, 0.5 * g);
    push(!kick_outside, g);
    push(kick_outside, 0.5 * g);
  }
  return p;
}

}  // namespace

void rotate_about_body_axis(const Body& body, OrbitState& x, int axis, double tau) {
  constexpr int next[3] = {1, 2, 0};
  const int j = next[axis], k = next[j];
  double s, cm1;
  sin_cosm1(tau * (x.m[axis] - body.gyrostat()[axis]) / body.inertia()[axis], s, cm1);
  for (Vec3* v : {&x.m, &x.gamma, &x.normal}) {
    const double a = (*v)[j], b = (*v)[k];
    (*v)[j] = a + (cm1 * a + s * b);
    (*v)[k] = b + (cm1 * b - s * a);
  }
}

void gravity_gradient_kick(const Body& body, OrbitState& x, double impulse) {
  x.m += impulse * x.gamma.cross(body.inertia().cwiseProduct(x.gamma));
}

void orbital_rotation(OrbitState& x, double angle) {
  double s, cm1;
  sin_cosm1(angle, s, cm1);
  const Vec3 n = x.normal.normalized();
  const Vec3 u = n.cross(x.gamma);
  x.gamma += s * u - cm1 * n.cross(u);
}

OrbitSplittingStepper::OrbitSplittingStepper(const CompositionTable& table)
    : OrbitSplittingStepper(table, table.order > 2) {}

OrbitSplittingStepper::OrbitSplittingStepper(const CompositionTable& table, bool kick_outside)
    : order_(table.order), program_(make_program(table, kick_outside)) {}

void OrbitSplittingStepper::step(const CircularOrbitModel& model, OrbitState& x, double h) const {
  const Body& body = model.body();
  const auto axes = axes_by_moment(body);
  const double w0 = model.orbit().rate, lambda = model.orbit().lambda_;
  for (const OrbitStage& st : program_) {
    const double tau = st.fraction * h;
    if (st.kick) {
      gravity_gradient_kick(body, x, lambda * tau);
    } else {
      free_body(body, axes, x, tau);
      orbital_rotation(x, w0 * tau);
    }
  }
}

void OrbitSplittingStepper::step(const EllipticOrbitModel& model, OrbitState& x, double nu,
                                 double h) const {
  const Body& body = model.body();
  const EllipticOrbit& orbit = model.orbit();
  const auto axes = axes_by_moment(body);
  // ν at each stage from the cumulative fraction (not accumulated stage by stage).
  double done = 0.0;
  for (const OrbitStage& st : program_) {
    const double nu_here = nu + done * h;
    if (st.kick) {
      const double sigma_lambda = time_per_anomaly(orbit, nu_here) * lambda_at(orbit, nu_here);
      gravity_gradient_kick(body, x, sigma_lambda * st.fraction * h);
    } else {
      const double nu_next = nu + (done + st.fraction) * h;
      free_body(body, axes, x, elapsed_time(orbit, nu_here, nu_next));
      orbital_rotation(x, nu_next - nu_here);
      done += st.fraction;
    }
  }
}

namespace {

/// The engine's fixed-step driver at the nominal step `step`.
template <class M>
OrbitOutcome run_fixed(const OrbitSplittingStepper& stepper, const M& model, const OrbitState& x,
                       double a, double b, double step, const OrbitObserver& observer) {
  IntegrateOptions options;
  options.step = step;
  if (!observer) return integrate(stepper, model, x, a, b, options);
  return integrate(stepper, model, x, a, b, options, observer);
}

}  // namespace

OrbitOutcome integrate(const OrbitSplittingStepper& stepper, const CircularOrbitModel& model,
                       OrbitState x, double t0, double t1, double step,
                       const OrbitObserver& observer) {
  return run_fixed(stepper, model, x, t0, t1, step, observer);
}

OrbitOutcome integrate(const OrbitSplittingStepper& stepper, const EllipticOrbitModel& model,
                       OrbitState x, double nu0, double nu1, double step,
                       const OrbitObserver& observer) {
  return run_fixed(stepper, model, x, nu0, nu1, step, observer);
}

void check_state(const OrbitState& x) {
  const std::pair<const char*, const Vec3*> parts[] = {
      {"m", &x.m}, {"gamma", &x.gamma}, {"normal", &x.normal}};
  for (const auto& [name, v] : parts) {
    if (!v->allFinite()) {
      throw InputError(std::string(name) + ": expected finite numbers, found " + format_vector(*v));
    }
  }
}

}  // namespace newtop
