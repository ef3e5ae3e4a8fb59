#include "mesh_section.hpp"

#include <filesystem>
#include <numbers>

#include "newtop/io/mesh.hpp"

namespace newtop::io {
namespace {

// [body] and [mass_model] agree when the inertia tensors, masses and centres of mass differ by less
// than this fraction of their size: values typed to 8 significant digits pass, a different body
// does not.
constexpr double kAgreement = 1e-7;

std::string resolve(const std::string& base, const std::string& file) {
  const std::filesystem::path p(file);
  return p.is_absolute() || base.empty() ? file : (std::filesystem::path(base) / p).string();
}

/// density, or mass / volume when `mass` is given instead.
double density_of(TableReader& r, double volume) {
  const bool d = r.has("density"), m = r.has("mass");
  if (d == m) r.fail("density", "expected exactly one of density or mass");
  const double v = r.number(d ? "density" : "mass");
  if (!(v > 0)) r.fail(d ? "density" : "mass", "expected a number > 0, found " + format_number(v));
  return d ? v : v / volume;
}

template <class F>
auto wrap(TableReader& r, const std::string& fallback_key, F&& make) {
  try {
    return make();
  } catch (const InputError& e) {
    const std::string msg = e.what();
    const auto colon = msg.find(':');
    const std::string key = msg.substr(0, colon);
    for (const char* k :
         {"points", "density", "semi_axes", "dimensions", "center", "scale", "mesh"}) {
      if (key == k) r.fail(key == "mesh" ? fallback_key : key, msg.substr(colon + 2));
    }
    r.fail(fallback_key, msg);
  }
}

}  // namespace

std::shared_ptr<const MassModel> read_mass_model(TableReader& r, const std::string& base) {
  const std::string kind = r.string("kind");
  std::shared_ptr<const MassModel> out;
  if (kind == "points") {
    if (r.has("file") == r.has("points"))
      r.fail("points", "expected exactly one of points or file");
    if (r.has("file")) {
      const std::string f = resolve(base, r.string("file"));
      out =
          wrap(r, "file", [&] { return std::make_shared<const MassModel>(read_point_masses(f)); });
    } else {
      std::vector<double> m;
      std::vector<Vec3> x;
      for (const auto& row : r.rows("points", 4)) {
        m.push_back(row[0]);
        x.emplace_back(row[1], row[2], row[3]);
      }
      out = wrap(r, "points", [&] { return std::make_shared<const MassModel>(PointMasses(m, x)); });
    }
  } else if (kind == "polyhedron") {
    const std::string f = resolve(base, r.string("file"));
    const double scale = r.optional_number("scale").value_or(1.0);
    const Orientation o = r.boolean("reorient", false) ? Orientation::reorient : Orientation::check;
    // The volume does not depend on the density: read the mesh once with density 1.
    const Polyhedron unit = wrap(r, "file", [&] { return load_polyhedron(f, 1.0, scale, o); });
    const double sigma = density_of(r, unit.volume());
    out = std::make_shared<const MassModel>(
        Polyhedron::make(unit.vertices(), unit.faces(), sigma, Orientation::check));
  } else if (kind == "ellipsoid") {
    const Vec3 a = r.vec3("semi_axes");
    const Vec3 c = r.optional_vec3("center").value_or(Vec3::Zero());
    const double sigma = density_of(r, 4.0 / 3.0 * std::numbers::pi * a.prod());
    out = wrap(r, "semi_axes",
               [&] { return std::make_shared<const MassModel>(Ellipsoid::make(a, sigma, c)); });
  } else if (kind == "box") {
    const Vec3 d = r.vec3("dimensions");
    const Vec3 c = r.optional_vec3("center").value_or(Vec3::Zero());
    const double sigma = density_of(r, d.prod());
    out = wrap(r, "dimensions",
               [&] { return std::make_shared<const MassModel>(make_box(d, sigma, c)); });
  } else {
    r.fail("kind",
           "expected \"points\", \"polyhedron\", \"ellipsoid\" or \"box\", found \"" + kind + "\"");
  }
  r.finish();
  return out;
}

void check_agreement(TableReader& section, const Body& a, const Body& b) {
  const Mat3 Ja = a.principal_axes() * a.inertia_matrix() * a.principal_axes().transpose();
  const Mat3 Jb = b.principal_axes() * b.inertia_matrix() * b.principal_axes().transpose();
  const Vec3 ra = a.principal_axes() * a.center_of_mass(),
             rb = b.principal_axes() * b.center_of_mass();
  std::string diff;
  if ((Ja - Jb).norm() > kAgreement * Jb.norm()) {
    diff += " inertia tensor: [body] principal moments " + format_vector(a.inertia()) +
            ", [mass_model] " + format_vector(b.inertia()) + ";";
  }
  if (std::abs(a.mass() - b.mass()) > kAgreement * b.mass()) {
    diff += " mass: [body] " + format_number(a.mass()) + ", [mass_model] " +
            format_number(b.mass()) + ";";
  }
  if ((ra - rb).norm() > kAgreement * std::max(rb.norm(), std::sqrt(Jb.norm() / b.mass()))) {
    diff += " center_of_mass: [body] " + format_vector(ra) + ", [mass_model] " + format_vector(rb) +
            ";";
  }
  if (!diff.empty()) {
    diff.pop_back();
    section.fail("inertia", "[body] and [mass_model] disagree (relative tolerance 1e-7):" + diff);
  }
}

}  // namespace newtop::io
