// [orbit] scenarios: [body], [orbit], [initial] (inertial or relative to the orbital frame),
// [integrate] and [output]; docs/scenario.md, "Orbit scenarios".

#include "newtop/io/orbit_scenario.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "file_check.hpp"
#include "newtop/orbit/lvlh.hpp"
#include "newtop/orbit/orbit_integrate.hpp"
#include "scenario_sections.hpp"
#include "toml_parse.hpp"
#include "toml_reader.hpp"

namespace newtop::io {
namespace {

// γ, n and a quaternion must be unit (and γ ⊥ n) to this accuracy: a file that writes 15
// significant digits passes, a hand-typed approximation does not (as for the fixed-centre γ).
constexpr double kUnitTolerance = 1e-12;

const std::vector<std::string> kOrbitSections{"body", "orbit", "initial", "integrate", "output"};
const std::vector<std::string> kOrbitBodyKeys{"inertia", "inertia_tensor", "mass", "center_of_mass",
                                              "gyrostat"};
const std::vector<std::string> kOrbitKeys{
    "kind", "mu", "radius", "rate", "semi_major_axis", "eccentricity", "true_anomaly"};
const std::vector<std::string> kOrbitInitialKeys{
    "omega",          "gamma",           "normal",         "quaternion", "euler_321",
    "roll_pitch_yaw", "lvlh_quaternion", "omega_relative", "normalize"};
const std::vector<std::string> kOrbitIntegrateKeys{"method", "step", "tol",
                                                   "t_end",  "t0",   "max_steps"};
const std::vector<std::string> kOrbitOutputKeys{"file", "every"};

/// [field] and [mass_model] are named as such; then unknown sections and keys, in every section.
void check_orbit_vocabulary(const toml::table& doc, const std::string& source) {
  TableReader top(doc, source, "");
  if (doc.contains("field")) {
    top.fail("field", "an orbit scenario has no [field] (the field is the orbit's): remove it");
  }
  if (doc.contains("mass_model")) {
    top.fail("mass_model", "not supported with [orbit] (the orbit model uses the quadratic field)");
  }
  top.check_keys(kOrbitSections);
  const std::pair<const char*, const std::vector<std::string>*> sections[] = {
      {"body", &kOrbitBodyKeys},
      {"orbit", &kOrbitKeys},
      {"initial", &kOrbitInitialKeys},
      {"integrate", &kOrbitIntegrateKeys},
      {"output", &kOrbitOutputKeys}};
  for (const auto& [name, keys] : sections) {
    if (const toml::table* t = doc[name].as_table())
      TableReader(*t, source, name).check_keys(*keys);
  }
}

Body read_orbit_body(TableReader& r) {
  if (r.has("inertia") == r.has("inertia_tensor")) {
    r.fail("inertia",
           "expected exactly one of inertia = [A, B, C] or inertia_tensor = 3x3, found " +
               std::string(r.has("inertia") ? "both" : "neither"));
  }
  const double mass = r.optional_number("mass").value_or(1.0);
  const Vec3 r0 = r.optional_vec3("center_of_mass").value_or(Vec3::Zero());
  const Vec3 k = r.optional_vec3("gyrostat").value_or(Vec3::Zero());
  return r.checked([&] {
    Body b = r.has("inertia") ? Body::from_principal(r.vec3("inertia"), mass, r0, k)
                              : Body::from_tensor(r.mat3("inertia_tensor"), mass, r0, k);
    r.finish();
    check_orbit_body(b);
    return b;
  });
}

std::variant<CircularOrbit, EllipticOrbit> read_orbit(TableReader& r) {
  const std::string kind = r.string("kind");
  if (kind == "circular") {
    r.only({"kind", "mu", "radius", "rate"}, kOrbitKeys, "kind = \"circular\"");
    const bool rate = r.has("rate"), mu = r.has("mu"), radius = r.has("radius");
    if (rate && !mu && !radius) {
      const double w0 = r.number("rate");
      return r.checked([&] { return CircularOrbit::from_rate(w0); });
    }
    if (mu && radius && !rate) {
      const double m = r.number("mu"), R = r.number("radius");
      return r.checked([&] { return CircularOrbit::from_mu_radius(m, R); });
    }
    r.fail(rate ? "rate" : (mu ? "mu" : "radius"),
           "expected either mu and radius, or rate, found " + std::string(rate ? "rate " : "") +
               (mu ? "mu " : "") + (radius ? "radius" : (rate || mu ? "" : "none of them")));
  }
  if (kind == "elliptic") {
    r.only({"kind", "mu", "semi_major_axis", "eccentricity", "true_anomaly"}, kOrbitKeys,
           "kind = \"elliptic\"");
    const double mu = r.number("mu"), a = r.number("semi_major_axis");
    const double e = r.number("eccentricity");
    const double nu0 = r.optional_number("true_anomaly").value_or(0.0);
    r.finish();
    return r.checked([&] { return EllipticOrbit::from_mu_axis(mu, a, e, nu0); });
  }
  r.fail("kind", "expected \"circular\" or \"elliptic\", found \"" + kind + "\"");
}

/// 3-2-1 (yaw ψ about e_n, pitch θ about the new e_t, roll φ about the new e_r) rotation: the
/// body axes in orbital components, R = R_n(ψ) R_t(θ) R_r(φ).
Mat3 rotation_from_euler_321(const Vec3& a) {
  return (Eigen::AngleAxisd(a[0], Vec3::UnitZ()) * Eigen::AngleAxisd(a[1], Vec3::UnitY()) *
          Eigen::AngleAxisd(a[2], Vec3::UnitX()))
      .toRotationMatrix();
}

/// quaternion = [w, x, y, z] (scalar first), unit to kUnitTolerance unless normalize = true.
Eigen::Quaterniond read_quaternion(const toml::table& t, TableReader& r, bool normalize,
                                   const std::string& key = "quaternion") {
  const toml::node& node = *t.get(key);
  const toml::array* a = node.as_array();
  if (!a || a->size() != 4) {
    r.fail(key, "expected an array of 4 numbers [w, x, y, z], found " + describe(node));
  }
  Eigen::Vector4d v;
  for (int i = 0; i < 4; ++i) {
    const toml::node& x = *a->get(static_cast<std::size_t>(i));
    if (!x.is_number() || !std::isfinite(x.value<double>().value())) {
      r.fail(key, "expected 4 finite numbers [w, x, y, z], found " + describe(node));
    }
    v[i] = x.value<double>().value();
  }
  const double norm = v.norm();
  if (norm == 0.0 || (!normalize && std::abs(norm - 1.0) > kUnitTolerance)) {
    r.fail(key, "expected a unit quaternion (|q| = 1 to 1e-12), found |q| = " +
                    format_number(norm) + "; add normalize = true to [initial] to rescale it");
  }
  v /= norm;
  return Eigen::Quaterniond(v[0], v[1], v[2], v[3]);
}

/// C(body←LVLH) from roll_pitch_yaw or lvlh_quaternion (docs/orbit.md §11), as the orbital
/// frame (columns e_r = γ, e_t = n × γ, e_n = n) in the user's body components.
Mat3 lvlh_frame(const toml::table& t, TableReader& r, bool normalize) {
  const Mat3 C =
      r.has("roll_pitch_yaw")
          ? body_from_roll_pitch_yaw(r.vec3("roll_pitch_yaw"))
          : Mat3(
                read_quaternion(t, r, normalize, "lvlh_quaternion").toRotationMatrix().transpose());
  Mat3 F;
  F.col(0) = -C.col(2);
  F.col(1) = C.col(0);
  F.col(2) = -C.col(1);
  return F;
}

OrbitState read_initial(const toml::table& t, TableReader& r, const Body& body, double rate) {
  const Mat3& P = body.principal_axes();  // user frame → principal axes: Pᵀ
  const int q = r.has("quaternion"), e = r.has("euler_321");
  const int l = r.has("roll_pitch_yaw") + r.has("lvlh_quaternion");
  const int direct = r.has("gamma") || r.has("normal") || r.has("omega");
  if (q + e + l + direct != 1) {
    r.fail(q ? "quaternion" : (e ? "euler_321" : (l ? "roll_pitch_yaw" : "gamma")),
           "expected exactly one of (omega, gamma, normal), quaternion, euler_321, "
           "roll_pitch_yaw or lvlh_quaternion, found " +
               std::string(q + e + l + direct == 0 ? "none" : "more than one"));
  }
  if (direct) {
    const Vec3 w = P.transpose() * r.vec3("omega");
    const OrbitState s{body.inertia().cwiseProduct(w) + body.gyrostat(),
                       P.transpose() * r.vec3("gamma"), P.transpose() * r.vec3("normal")};
    r.finish();
    r.checked([&] {
      check_orbit_state(s, kUnitTolerance);
      return 0;
    });
    return s;
  }
  const Vec3 w_rel = r.optional_vec3("omega_relative").value_or(Vec3::Zero());
  const bool normalize = r.boolean("normalize", false);
  if (l) {
    const Mat3 F = lvlh_frame(t, r, normalize);
    r.finish();
    return state_from_relative(body, P.transpose() * F, P.transpose() * w_rel, rate);
  }
  // Body axes in orbital components (the user's body frame).
  const Mat3 R = q ? read_quaternion(t, r, normalize).toRotationMatrix()
                   : rotation_from_euler_321(r.vec3("euler_321"));
  r.finish();
  // The orbital axes in the user's body components are the columns of Rᵀ; in principal axes Pᵀ Rᵀ.
  return state_from_relative(body, P.transpose() * R.transpose(), P.transpose() * w_rel, rate);
}

IntegrateSection read_orbit_integrate(TableReader& r) {
  IntegrateSection s;
  s.method = r.optional_string("method");
  if (r.has("step") && r.has("tol")) {
    r.fail("tol", "conflicts with step: give step (splitting methods) or tol (rkf78)");
  }
  s.step = r.optional_number("step");
  if (s.step && !(*s.step > 0))
    r.fail("step", "expected a number > 0, found " + format_number(*s.step));
  s.tol = r.optional_number("tol");
  if (s.tol && !(*s.tol > 0))
    r.fail("tol", "expected a number > 0, found " + format_number(*s.tol));
  s.t_end = r.optional_number("t_end");
  s.t0 = r.optional_number("t0").value_or(0.0);
  if (r.has("max_steps")) {
    s.max_steps = r.integer("max_steps", 1, std::numeric_limits<std::int64_t>::max());
  }
  r.finish();
  return s;
}

OutputSection read_orbit_output(TableReader& r) {
  OutputSection s;
  s.file = r.optional_string("file");
  if (s.file && s.file->empty()) r.fail("file", "expected a file name, found an empty string");
  if (r.has("every")) s.every = r.integer("every", 1, std::numeric_limits<std::int64_t>::max());
  r.finish();
  return s;
}

/// The orbit at its strongest (λ and the anomaly's rate at periapsis) and the right-hand side at
/// the start stay finite and at most kMaxMagnitude, as in a fixed-centre scenario
/// (scenario_checks.cpp): a rate of 1e200 gives λ = 3e400 = inf, and the run would stop at once.
void check_orbit_magnitudes(const OrbitScenario& s, const TableReader& orbit,
                            const TableReader& initial) {
  double lambda = 0.0, rate = 0.0;
  OrbitState d;
  if (const auto* c = std::get_if<CircularOrbit>(&s.orbit)) {
    lambda = c->lambda_;
    rate = c->rate;
  } else {
    const auto& e = std::get<EllipticOrbit>(s.orbit);
    lambda = lambda_at(e, 0.0);
    rate = anomaly_rate(e, 0.0);
  }
  if (!(lambda <= kMaxMagnitude) || !(rate <= kMaxMagnitude)) {
    orbit.fail(orbit.has("rate") ? "rate" : (orbit.has("radius") ? "radius" : "semi_major_axis"),
               "the orbit's lambda = " + format_number(lambda) +
                   " and rate = " + format_number(rate) + " (at periapsis) exceed " +
                   format_number(kMaxMagnitude) + ", the bound on every derived quantity");
  }
  if (const auto* c = std::get_if<CircularOrbit>(&s.orbit)) {
    d = rhs(CircularOrbitModel(s.body, *c), s.initial);
  } else {
    const auto& e = std::get<EllipticOrbit>(s.orbit);
    d = rhs(EllipticOrbitModel(s.body, e), s.initial, e.true_anomaly0);
  }
  const double size = std::max({d.m.lpNorm<Eigen::Infinity>(), d.gamma.lpNorm<Eigen::Infinity>(),
                                d.normal.lpNorm<Eigen::Infinity>()});
  // allFinite: a NaN component (inf − inf in m × ω) escapes the maximum.
  const bool finite = d.m.allFinite() && d.gamma.allFinite() && d.normal.allFinite();
  if (!finite || !(size <= kMaxMagnitude)) {
    const char* keys[] = {"omega", "omega_relative", "quaternion", "euler_321"};
    std::string key = "omega";
    for (const char* k : keys) {
      if (initial.has(k)) {
        key = k;
        break;
      }
    }
    initial.fail(key, "the rates at the start (largest |d/dt| = " + format_number(size) +
                          ") exceed " + format_number(kMaxMagnitude) +
                          ", the bound on every derived quantity (omega, the body's inertia and "
                          "the orbit's lambda = " +
                          format_number(lambda) + ")");
  }
}

}  // namespace

double OrbitScenario::rate_at_start() const {
  if (const auto* c = std::get_if<CircularOrbit>(&orbit)) return c->rate;
  const auto& e = std::get<EllipticOrbit>(orbit);
  return anomaly_rate(e, e.true_anomaly0);
}

bool is_orbit_scenario_text(const std::string& text) {
  // Bounded parsing (toml_parse.hpp): text toml++ must not see is reported by the ordinary reader.
  try {
    return parse_toml(text, "").contains("orbit");
  } catch (const InputError&) {
    return false;
  }
}

bool is_orbit_scenario(const std::string& path) {
  return is_orbit_scenario_text(read_regular_file(path, kMaxTomlBytes, "scenario file"));
}

OrbitScenario parse_orbit_scenario(const std::string& text, const std::string& source) {
  const toml::table doc = parse_toml(text, source);
  check_orbit_vocabulary(doc, source);
  TableReader top(doc, source, "");
  auto section = [&](const std::string& name, bool required) -> const toml::table* {
    const toml::table* t = top.table(name);
    if (!t && required) top.fail(name, "missing section [" + name + "]");
    return t;
  };
  TableReader body_reader(*section("body", true), source, "body");
  const Body body = read_orbit_body(body_reader);
  TableReader orbit_reader(*section("orbit", true), source, "orbit");
  OrbitScenario s{source, body, read_orbit(orbit_reader), {}, {}, {}, {}, {}};
  if (const toml::table* o = doc["orbit"].as_table()) {
    s.mu = (*o)["mu"].value<double>();
    s.radius = (*o)["radius"].value<double>();
    if (!s.radius) s.radius = (*o)["semi_major_axis"].value<double>();
  }
  const toml::table* init = section("initial", true);
  TableReader initial(*init, source, "initial");
  s.initial = read_initial(*init, initial, body, s.rate_at_start());
  check_orbit_magnitudes(s, orbit_reader, initial);
  if (const toml::table* t = section("integrate", false)) {
    TableReader r(*t, source, "integrate");
    s.integrate = read_orbit_integrate(r);
  }
  if (const toml::table* t = section("output", false)) {
    TableReader r(*t, source, "output");
    s.output = read_orbit_output(r);
  }
  top.finish();
  return s;
}

OrbitScenario load_orbit_scenario(const std::string& path) {
  return parse_orbit_scenario(read_regular_file(path, kMaxTomlBytes, "scenario file"), path);
}

}  // namespace newtop::io
