#include "mesh_section.hpp"

#include <cmath>
#include <filesystem>
#include <numbers>

#include "file_check.hpp"
#include "newtop/io/mesh.hpp"
#include "toml_parse.hpp"

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

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

/// The file named by `file`, resolved against the scenario's folder, checked before any reader
/// opens it: a regular file of bounded size (for a TetGen pair, both files). Every file read is
/// appended to `files`.
std::string checked_file(TableReader& r, const std::string& base, std::vector<std::string>& files) {
  const std::string name = r.string("file");
  if (name.empty()) r.fail("file", "expected a file name, found an empty string");
  const std::string path = resolve(base, name);
  std::vector<std::string> paths{path};
  if (ends_with(path, ".node") || ends_with(path, ".face")) {
    paths.push_back(path.substr(0, path.size() - 5) +
                    (ends_with(path, ".node") ? ".face" : ".node"));
  }
  for (const std::string& p : paths) {
    const std::string problem = regular_file_problem(p, kMaxModelFileBytes);
    if (!problem.empty()) r.fail("file", printable(p, 200) + ": " + problem);
  }
  files.insert(files.end(), paths.begin(), paths.end());
  return path;
}

/// density, or mass / volume when `mass` is given instead.
double density_of(TableReader& r, double volume, const std::string& size_key) {
  const bool d = r.has("density"), m = r.has("mass");
  if (d && m) r.fail("mass", "conflicts with density: give one of them");
  if (!d && !m) r.fail("density", "missing: give density or mass");
  const double v = r.number(d ? "density" : "mass");
  if (!(v > 0)) r.fail(d ? "density" : "mass", "expected a number > 0, found " + format_number(v));
  if (m && !(std::isfinite(volume) && volume > 0)) {
    r.fail(size_key, "expected a finite volume > 0 to divide the mass by, found the volume " +
                         format_number(volume));
  }
  const double sigma = d ? v : v / volume;
  if (!std::isnormal(sigma)) {
    r.fail("mass", "the density mass/volume = " + format_number(v) + "/" + format_number(volume) +
                       " = " + format_number(sigma) + " is out of range");
  }
  return sigma;
}

struct KindKeys {
  const char* kind;
  std::vector<std::string> keys;  // every key this model takes
  std::vector<std::string> own;   // keys no other model takes: they imply this kind
};

const std::vector<KindKeys>& kinds() {
  static const std::vector<KindKeys> k{
      {"points", {"kind", "points", "file"}, {"points"}},
      {"polyhedron",
       {"kind", "file", "density", "mass", "scale", "reorient"},
       {"scale", "reorient"}},
      {"ellipsoid", {"kind", "semi_axes", "density", "mass", "center"}, {"semi_axes"}},
      {"box", {"kind", "dimensions", "density", "mass", "center"}, {"dimensions"}},
  };
  return k;
}

/// The model's kind (given, or implied by a key of its own) and its keys; conflicting keys refused.
std::string kind_of(TableReader& r) {
  const std::optional<std::string> given = r.optional_string("kind");
  const KindKeys* found = nullptr;
  std::string reason;
  for (const KindKeys& k : kinds()) {
    if (given && *given == k.kind) {
      found = &k;
      reason = "kind = \"" + *given + "\"";
    }
  }
  if (given && !found) {
    r.fail("kind",
           "expected \"points\", \"polyhedron\", \"ellipsoid\" or \"box\", found the string \"" +
               printable(*given) + "\"");
  }
  for (const KindKeys& k : kinds()) {
    for (const std::string& key : k.own) {
      if (!found && r.has(key)) {
        found = &k;
        reason = key + " (kind = \"" + k.kind + "\")";
      }
    }
  }
  if (!found) {
    r.fail("kind",
           "missing: give kind = \"points\", \"polyhedron\", \"ellipsoid\" or \"box\" (a file "
           "alone may hold point masses or a mesh)");
  }
  r.only(found->keys, mass_model_keys(), reason);
  return found->kind;
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

const std::vector<std::string>& mass_model_keys() {
  static const std::vector<std::string> keys{"kind",       "points", "file",     "density",
                                             "mass",       "scale",  "reorient", "semi_axes",
                                             "dimensions", "center"};
  return keys;
}

MassModelSection read_mass_model(TableReader& r, const std::string& base) {
  const std::string kind = kind_of(r);
  MassModelSection out;
  if (kind == "points") {
    if (r.has("file") && r.has("points")) {
      r.fail("file", "conflicts with points: give the masses inline or in a file, not both");
    }
    if (!r.has("file") && !r.has("points")) {
      r.fail("points", "missing: give points = [[m, x, y, z], ...] or file = \"masses.csv\"");
    }
    out.key = r.has("file") ? "file" : "points";
    if (r.has("file")) {
      const std::string f = checked_file(r, base, out.files);
      out.model =
          wrap(r, "file", [&] { return std::make_shared<const MassModel>(read_point_masses(f)); });
    } else {
      std::vector<double> m;
      std::vector<Vec3> x;
      for (const auto& row : r.rows("points", 4)) {
        m.push_back(row[0]);
        x.emplace_back(row[1], row[2], row[3]);
      }
      out.model =
          wrap(r, "points", [&] { return std::make_shared<const MassModel>(PointMasses(m, x)); });
    }
  } else if (kind == "polyhedron") {
    out.key = "file";
    const std::string f = checked_file(r, base, out.files);
    const double scale = r.optional_number("scale").value_or(1.0);
    const Orientation o = r.boolean("reorient", false) ? Orientation::reorient : Orientation::check;
    // The volume does not depend on the density: read the mesh once with density 1.
    const Polyhedron unit = wrap(r, "file", [&] { return load_polyhedron(f, 1.0, scale, o); });
    const double sigma = density_of(r, unit.volume(), "file");
    out.model = wrap(r, "file", [&] {
      return std::make_shared<const MassModel>(
          Polyhedron::make(unit.vertices(), unit.faces(), sigma, Orientation::check));
    });
  } else if (kind == "ellipsoid") {
    out.key = "semi_axes";
    const Vec3 a = r.vec3("semi_axes");
    const Vec3 c = r.optional_vec3("center").value_or(Vec3::Zero());
    const double sigma = density_of(r, 4.0 / 3.0 * std::numbers::pi * a.prod(), "semi_axes");
    out.model = wrap(r, "semi_axes", [&] {
      return std::make_shared<const MassModel>(Ellipsoid::make(a, sigma, c));
    });
  } else {  // box
    out.key = "dimensions";
    const Vec3 d = r.vec3("dimensions");
    const Vec3 c = r.optional_vec3("center").value_or(Vec3::Zero());
    const double sigma = density_of(r, d.prod(), "dimensions");
    out.model = wrap(r, "dimensions",
                     [&] { return std::make_shared<const MassModel>(make_box(d, sigma, c)); });
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
