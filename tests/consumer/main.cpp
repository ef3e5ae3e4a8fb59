// Integrates a heavy top with an installed newtop and checks that energy is conserved.
#include <cmath>
#include <cstdio>
#include <newtop/newtop.hpp>

int main() {
  using namespace newtop;
  const Model model{Body::from_principal(Vec3(2, 2, 1), 1.0, Vec3(0, 0, 0.5)),
                    QuadraticField::uniform(9.81)};
  const State x0 = state_from_omega(model.body, Vec3(0.3, 0, 20), Vec3(0.6, 0, 0.8));
  SplittingStepper stepper(composition_table("splitting4"));
  const Outcome out = integrate(stepper, model, x0, 0.0, 10.0, IntegrateOptions{.step = 1e-3});
  const double drift = std::abs(energy(model, out.state) - energy(model, x0));
  std::printf("consumer: %s, energy drift %.3g\n", std::string(to_string(out.status)).c_str(),
              drift);
  // splitting4 at h = 1e-3 on this top conserves energy to ~1e-10 relative (energy ~ 200).
  return out.status == Status::finished && drift < 1e-6 ? 0 : 1;
}
