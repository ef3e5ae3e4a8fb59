#include "newtop/analysis/euler_poinsot.hpp"

namespace newtop {

bool euler_poinsot_holds(const QuadraticModel& model) {
  const Body& b = model.body;
  const bool no_linear = model.field.g == 0.0 || b.mass() == 0.0 || b.center_of_mass().isZero(0.0);
  return model.field.lambda_ == 0.0 && no_linear && b.gyrostat().isZero(0.0);
}

}  // namespace newtop
