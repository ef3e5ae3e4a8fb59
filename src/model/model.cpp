// Model's functions that need no field but the quadratic one (model.hpp); those that see an exact
// or multipole field are defined beside them (src/exact/model_fields.cpp).

#include "newtop/model/model.hpp"

namespace newtop {

const char* to_string(FieldKind k) {
  switch (k) {
    case FieldKind::exact:
      return "exact";
    case FieldKind::multipole:
      return "multipole";
    case FieldKind::quadratic:
      break;
  }
  return "quadratic";
}

QuadraticModel quadratic_approximation(const Model& model) {
  if (model.kind() == FieldKind::quadratic) return model.quadratic();
  const CentreParameters c = centre_parameters(model);
  return {model.body(), QuadraticField::from_mu_R(c.mu, c.R)};
}

}  // namespace newtop
