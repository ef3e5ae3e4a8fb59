#include "newtop/io/scenario.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "mesh_section.hpp"
#include "newtop/exact/exact_field.hpp"
#include "toml_reader.hpp"

namespace newtop::io {
namespace {

// γ must be a unit vector to this accuracy unless [initial] normalize = true: a file that writes
// 15 significant digits passes, a hand-typed approximation such as [0.6, 0.8, 0.01] does not.
constexpr double kUnitTolerance = 1e-12;

Body read_body(TableReader& r) {
  const bool has_principal = r.has("inertia");
  const bool has_tensor = r.has("inertia_tensor");
  if (has_principal && has_tensor) {
    r.fail("inertia_tensor", "expected either inertia or inertia_tensor, found both");
  }
  if (!has_principal && !has_tensor) {
    r.fail("inertia", "missing: give inertia = [A, B, C] or inertia_tensor = [[..],[..],[..]]");
  }
  const double mass = r.optional_number("mass").value_or(1.0);
  const Vec3 r0 = r.optional_vec3("center_of_mass").value_or(Vec3::Zero());
  const Vec3 k = r.optional_vec3("gyrostat").value_or(Vec3::Zero());
  return r.checked([&] {
    Body b = has_principal ? Body::from_principal(r.vec3("inertia"), mass, r0, k)
                           : Body::from_tensor(r.mat3("inertia_tensor"), mass, r0, k);
    r.finish();
    return b;
  });
}

QuadraticField read_field(TableReader& r, ExactSettings& exact) {
  const std::string kind = r.optional_string("kind").value_or("");
  // Unknown keys (typos) first: a misspelt "g" must be reported as such, not as a missing g.
  r.finish({"N", "plane_offset", "g", "lambda", "mu", "R", "order"});
  QuadraticField f;
  if (kind == "exact" || kind == "multipole") {
    exact.kind = kind == "exact" ? FieldKind::exact : FieldKind::multipole;
    exact.mu = r.number("mu");
    exact.R = r.number("R");
    if (exact.kind == FieldKind::multipole) {
      const std::int64_t order = r.integer("order");
      if (order < 1 || order > 30) {
        r.fail("order", "expected an integer in [1, 30], found " + std::to_string(order));
      }
      exact.order = static_cast<int>(order);
    }
    if (!exact.mass_model) r.fail("kind", "kind = \"" + kind + "\" needs a [mass_model] section");
    f = r.checked([&] { return QuadraticField::from_mu_R(exact.mu, exact.R); });
    r.checked([&] { return ExactField::make(exact.mass_model, exact.mu, exact.R); });
  } else if (kind == "brun") {
    const double N = r.number("N");
    const double d = r.optional_number("plane_offset").value_or(0.0);
    f = r.checked([&] { return QuadraticField::brun(N, d); });
  } else if (kind == "uniform") {
    const double g = r.number("g");
    f = r.checked([&] { return QuadraticField::uniform(g); });
  } else if (kind.empty() || kind == "newtonian" || kind == "coulomb") {
    const bool g = r.has("g"), lam = r.has("lambda"), R = r.has("R"), mu = r.has("mu");
    if (mu && R && !g && !lam) {
      const double vmu = r.number("mu"), vR = r.number("R");
      f = r.checked([&] { return QuadraticField::from_mu_R(vmu, vR); });
    } else if (g && R && !lam && !mu) {
      const double vg = r.number("g"), vR = r.number("R");
      f = r.checked([&] { return QuadraticField::from_g_R(vg, vR); });
    } else if (g && lam && !R && !mu) {
      const double vg = r.number("g"), vl = r.number("lambda");
      f = r.checked([&] { return QuadraticField::coulomb(vg, vl); });
    } else {
      r.fail(g ? "g" : (mu ? "mu" : "lambda"),
             "expected exactly one of (g, lambda), (g, R), (mu, R), or kind = \"brun\" with N, "
             "or kind = \"uniform\" with g; found " +
                 std::string(g ? "g " : "") + (lam ? "lambda " : "") + (mu ? "mu " : "") +
                 (R ? "R" : (g || lam || mu ? "" : "none of them")));
    }
  } else {
    r.fail("kind",
           "expected \"newtonian\", \"coulomb\", \"uniform\", \"brun\", \"exact\" or "
           "\"multipole\", found \"" +
               kind + "\"");
  }
  r.finish({"N", "plane_offset", "g", "lambda", "mu", "R", "order"});
  return f;
}

State read_initial(TableReader& r, const Body& body) {
  const Vec3 P_omega = r.vec3("omega");
  Vec3 P_gamma = r.vec3("gamma");
  const bool normalize = r.boolean("normalize", false);
  const double norm = P_gamma.norm();
  if (norm == 0.0) r.fail("gamma", "expected a unit vector, found [0, 0, 0]");
  if (normalize) {
    P_gamma /= norm;
  } else if (std::abs(norm - 1.0) > kUnitTolerance) {
    r.fail("gamma", "expected a unit vector (|gamma| = 1 to 1e-12), found |gamma| = " +
                        format_number(norm) + "; add normalize = true to [initial] to rescale it");
  }
  r.finish();
  // Vectors are given in the user's frame; the body works in its principal axes.
  const Mat3& P = body.principal_axes();
  return state_from_omega(body, P.transpose() * P_omega, P.transpose() * P_gamma);
}

/// [body], [mass_model] or both (then they must agree; [body] may then hold only a gyrostat).
Body read_body_or_mass_model(const toml::table* t, const ExactSettings& exact,
                             const std::string& source) {
  if (!exact.mass_model) {
    TableReader r(*t, source, "body");
    return read_body(r);
  }
  if (!t) return body_of(*exact.mass_model);
  TableReader r(*t, source, "body");
  const Vec3 k = r.optional_vec3("gyrostat").value_or(Vec3::Zero());
  const Body derived = body_of(*exact.mass_model, k);
  if (r.has("inertia") || r.has("inertia_tensor")) {
    TableReader again(*t, source, "body");
    check_agreement(again, read_body(again), derived);
  }
  r.finish({"mass", "center_of_mass"});
  if (!r.has("inertia") && !r.has("inertia_tensor") && (r.has("mass") || r.has("center_of_mass"))) {
    r.fail(r.has("mass") ? "mass" : "center_of_mass",
           "with [mass_model], give the whole body (inertia, mass, center_of_mass) to cross-check "
           "it, or only gyrostat");
  }
  return derived;
}

IntegrateSection read_integrate(TableReader& r) {
  IntegrateSection s;
  s.method = r.optional_string("method");
  if (s.method) r.checked([&] { return method_info(*s.method); });
  s.step = r.optional_number("step");
  if (s.step && !(*s.step > 0))
    r.fail("step", "expected a number > 0, found " + format_number(*s.step));
  s.tol = r.optional_number("tol");
  if (s.tol && !(*s.tol > 0))
    r.fail("tol", "expected a number > 0, found " + format_number(*s.tol));
  s.t_end = r.optional_number("t_end");
  s.t0 = r.optional_number("t0").value_or(0.0);
  s.max_steps = r.optional_integer("max_steps");
  if (s.max_steps && *s.max_steps < 1) r.fail("max_steps", "expected an integer >= 1");
  r.finish();
  return s;
}

OutputSection read_output(TableReader& r) {
  OutputSection s;
  s.file = r.optional_string("file");
  s.every = r.optional_integer("every").value_or(1);
  if (s.every < 1) r.fail("every", "expected an integer >= 1, found " + std::to_string(s.every));
  r.finish();
  return s;
}

}  // namespace

Scenario parse_scenario(const std::string& text, const std::string& source) {
  toml::table doc;
  try {
    doc = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << source << ":" << e.source().begin.line << ":" << e.source().begin.column
       << ": malformed TOML: " << e.description();
    throw InputError(os.str());
  }
  TableReader top(doc, source, "");
  auto section = [&](const std::string& name, bool required) -> const toml::table* {
    const toml::table* t = top.table(name);
    if (!t && required) top.fail(name, "missing section [" + name + "]");
    return t;
  };
  ExactSettings exact;
  if (const toml::table* t = section("mass_model", false)) {
    TableReader r(*t, source, "mass_model");
    exact.mass_model = read_mass_model(r, std::filesystem::path(source).parent_path().string());
  }
  const Body body_value =
      read_body_or_mass_model(section("body", !exact.mass_model), exact, source);
  TableReader field(*section("field", true), source, "field");
  Model model{body_value, read_field(field, exact)};
  TableReader initial(*section("initial", true), source, "initial");
  const State x0 = read_initial(initial, model.body);
  Scenario s{source, model, x0, {}, {}, exact};
  if (const toml::table* t = section("integrate", false)) {
    TableReader r(*t, source, "integrate");
    s.integrate = read_integrate(r);
  }
  if (const toml::table* t = section("output", false)) {
    TableReader r(*t, source, "output");
    s.output = read_output(r);
  }
  top.finish();
  return s;
}

Scenario load_scenario(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot read the scenario file (missing or unreadable)");
  std::ostringstream os;
  os << in.rdbuf();
  if (in.bad()) throw InputError(path + ": cannot read the scenario file");
  return parse_scenario(os.str(), path);
}

MethodSettings resolve_method(const Scenario& s, const IntegrateOverrides& o) {
  MethodSettings m;
  const std::optional<double> step = o.step ? o.step : (o.tol ? std::nullopt : s.integrate.step);
  const std::optional<double> tol = o.tol ? o.tol : (o.step ? std::nullopt : s.integrate.tol);
  if (o.method) {
    m.name = *o.method;
  } else if (o.step || o.tol) {
    m.name = std::string(o.step ? kDefaultFixedMethod : kDefaultAdaptiveMethod);
  } else if (s.integrate.method) {
    m.name = *s.integrate.method;
  } else {
    m.name = std::string(step ? kDefaultFixedMethod : kDefaultAdaptiveMethod);
  }
  const MethodInfo& info = method_info(m.name);
  if (info.kind == MethodKind::adaptive) {
    if (!tol) {
      throw InputError(s.source + ": tol: method " + m.name +
                       " needs a tolerance: give --tol or [integrate] tol");
    }
    m.abs_tol = m.rel_tol = *tol;
  } else {
    if (!step) {
      throw InputError(s.source + ": step: method " + m.name +
                       " needs a step: give --step or [integrate] step");
    }
    m.step = *step;
  }
  validate(m);
  return m;
}

double resolve_t_end(const Scenario& s, const IntegrateOverrides& o) {
  if (o.t_end) return *o.t_end;
  if (s.integrate.t_end) return *s.integrate.t_end;
  throw InputError(s.source + ": t_end: missing: give --t-end or [integrate] t_end");
}

}  // namespace newtop::io
