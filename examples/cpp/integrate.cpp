// A body in a Newtonian field, integrated by a method of the library (docs/cpp.md, "Integrate").
// Prints the energy drift and exits 0 when the run finished and kept the energy.
#include <cmath>
#include <cstdio>
#include <newtop/newtop.hpp>

int main() {
  using namespace newtop;
  const Model model(Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3(0.0, 0.0, 0.1)),
                    QuadraticField::from_mu_R(1.0, 2.0));  // g = mu/R^2, lambda = 3 mu/R^3
  const State x0 = state_from_omega(model.body(), Vec3(0.1, 0.2, 0.3), Vec3(0.0, 0.6, 0.8));

  // Any method on any field, compiled in the library: a name and a step (or tolerances).
  const Outcome out = run_method({"splitting6", 0.01}, model, x0, 0.0, 100.0);
  // A stepper of one's own on the field's model (the template driver of integrate/driver.hpp).
  SplittingStepper stepper(composition_table("splitting6"));
  const Outcome same =
      integrate(stepper, model.quadratic(), x0, 0.0, 100.0, IntegrateOptions{.step = 0.01});

  const double drift = std::abs(energy(model, out.state) - energy(model, x0));
  std::printf("newtop %s: %s after %lld steps, |energy drift| = %.3g\n", NEWTOP_VERSION_STRING,
              to_string(out.status).data(), static_cast<long long>(out.steps), drift);
  // splitting6 at h = 0.01 keeps this energy (~0.5) to ~1e-12; 1e-9 leaves a wide margin.
  const bool ok = out.status == Status::finished && drift < 1e-9 && same.state == out.state;
  return ok ? 0 : 1;
}
