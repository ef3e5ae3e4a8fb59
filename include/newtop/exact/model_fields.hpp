#pragma once
/// \file
/// The exact and multipole fields plugged into Model (newtop/model/model.hpp), which only declares
/// them: including this header completes them, so that visit_model(model, f) can hand f the
/// concrete BasicModel<ExactField> or BasicModel<MultipoleField>. The fields of a model built from
/// a mass model (Model::exact, Model::multipole) are reached without naming the model's variant:
/// `exact_field(model)`, `exact_model(model)`.

#include "newtop/exact/exact_field.hpp"
#include "newtop/exact/mass_models.hpp"
#include "newtop/exact/multipole.hpp"
#include "newtop/model/model.hpp"

namespace newtop {

/// The exact field of a model of kind exact; nullptr for a quadratic or multipole model.
const ExactField* exact_field(const Model& model);
/// The multipole field of a model of kind multipole; nullptr otherwise.
const MultipoleField* multipole_field(const Model& model);

/// The model as the concrete BasicModel<ExactField> the steppers run on; throws InputError naming
/// the model's field kind unless it is exact. The reference lives as long as a copy of the model.
const BasicModel<ExactField>& exact_model(const Model& model);
/// The model as the concrete BasicModel<MultipoleField>; throws InputError naming the model's field
/// kind unless it is multipole.
const BasicModel<MultipoleField>& multipole_model(const Model& model);

}  // namespace newtop
