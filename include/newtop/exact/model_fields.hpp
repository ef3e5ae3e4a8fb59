#pragma once
/// \file
/// The field of a Model built from a mass model (Model::exact, Model::multipole), reached without
/// naming the model's variant: `exact_field(model)` rather than
/// `std::get<BasicModel<ExactField>>(model.variant()).field`.

#include "newtop/exact/multipole.hpp"
#include "newtop/model/model.hpp"

namespace newtop {

/// The exact field of a model of kind exact; nullptr for a quadratic or multipole model.
const ExactField* exact_field(const Model& model);
/// The multipole field of a model of kind multipole; nullptr otherwise.
const MultipoleField* multipole_field(const Model& model);

/// The model as the concrete BasicModel<ExactField> the steppers run on; throws InputError naming
/// the model's field kind unless it is exact.
const BasicModel<ExactField>& exact_model(const Model& model);

}  // namespace newtop
