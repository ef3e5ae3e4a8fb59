// The field of a model built from a mass model (model_fields.hpp).

#include "newtop/exact/model_fields.hpp"

#include <string>

namespace newtop {

const ExactField* exact_field(const Model& model) {
  const auto* m = std::get_if<BasicModel<ExactField>>(&model.variant());
  return m ? &m->field : nullptr;
}

const MultipoleField* multipole_field(const Model& model) {
  const auto* m = std::get_if<BasicModel<MultipoleField>>(&model.variant());
  return m ? &m->field : nullptr;
}

const BasicModel<ExactField>& exact_model(const Model& model) {
  const auto* m = std::get_if<BasicModel<ExactField>>(&model.variant());
  if (!m) {
    throw InputError(std::string("model: expected an exact field, found a ") +
                     to_string(model.kind()) + " one");
  }
  return *m;
}

}  // namespace newtop
