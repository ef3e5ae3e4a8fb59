// The scenario text of a model built in code (scenario_text.hpp).

#include "newtop/io/scenario_text.hpp"

#include <sstream>
#include <variant>

#include "newtop/exact/mass_models.hpp"
#include "newtop/exact/model_fields.hpp"
#include "newtop/exact/multipole.hpp"

namespace newtop::io {
namespace {

std::string toml_vector(const Vec3& v) {
  return "[" + format_number(v.x()) + ", " + format_number(v.y()) + ", " + format_number(v.z()) +
         "]";
}

/// [mass_model] of point masses or an ellipsoid; InputError for a polyhedron.
void write_mass_model(std::ostream& os, const MassModel& mm) {
  if (const auto* p = std::get_if<PointMasses>(&mm)) {
    os << "[mass_model]\nkind = \"points\"\npoints = [";
    for (std::size_t i = 0; i < p->masses().size(); ++i) {
      const Vec3& x = p->positions()[i];
      os << (i ? ", " : "") << "[" << format_number(p->masses()[i]) << ", " << format_number(x.x())
         << ", " << format_number(x.y()) << ", " << format_number(x.z()) << "]";
    }
    os << "]\n";
  } else if (const auto* e = std::get_if<Ellipsoid>(&mm)) {
    os << "[mass_model]\nkind = \"ellipsoid\"\nsemi_axes = " << toml_vector(e->semi_axes)
       << "\ndensity = " << format_number(e->density) << "\ncenter = " << toml_vector(e->center)
       << "\n";
  } else {
    throw InputError(
        "base: expected a model with a scenario text, found the field of a polyhedron built in "
        "code (a mesh is read from its file): give the scenario file that names its mesh");
  }
}

}  // namespace

std::string scenario_text(const Model& model, const State& x0) {
  const Body& body = model.body();
  std::ostringstream os;
  if (model.kind() == FieldKind::quadratic) {
    const QuadraticField& f = model.quadratic().field;
    os << "[body]\ninertia = " << toml_vector(body.inertia())
       << "\nmass = " << format_number(body.mass())
       << "\ncenter_of_mass = " << toml_vector(body.center_of_mass())
       << "\ngyrostat = " << toml_vector(body.gyrostat()) << "\n[field]\ng = " << format_number(f.g)
       << "\nlambda = " << format_number(f.lambda_)
       << "\n[initial]\nomega = " << toml_vector(omega(body, x0))
       << "\ngamma = " << toml_vector(x0.gamma) << "\n";
    return os.str();
  }
  if (!model.mass_model()) {
    throw InputError("base: expected the " + std::string(to_string(model.kind())) +
                     " field of a mass model, found none");
  }
  write_mass_model(os, *model.mass_model());
  const Mat3& P = body.principal_axes();
  if (!body.gyrostat().isZero(0.0))
    os << "[body]\ngyrostat = " << toml_vector(P * body.gyrostat()) << "\n";
  if (const ExactField* e = exact_field(model)) {
    os << "[field]\nkind = \"exact\"\nmu = " << format_number(e->mu)
       << "\nR = " << format_number(e->R) << "\n";
  } else if (const MultipoleField* m = multipole_field(model)) {
    os << "[field]\nkind = \"multipole\"\norder = " << m->order << "\nmu = " << format_number(m->mu)
       << "\nR = " << format_number(m->R) << "\n";
  }
  os << "[initial]\nomega = " << toml_vector(P * omega(body, x0))
     << "\ngamma = " << toml_vector(P * x0.gamma) << "\n";
  return os.str();
}

}  // namespace newtop::io
