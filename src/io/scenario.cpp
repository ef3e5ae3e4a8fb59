#include "newtop/io/scenario.hpp"

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <string_view>

#include "file_check.hpp"
#include "mesh_section.hpp"
#include "newtop/exact/exact_field.hpp"
#include "newtop/integrate/taylor.hpp"
#include "newtop/model/state_checks.hpp"
#include "scenario_sections.hpp"
#include "toml_parse.hpp"

namespace newtop::io {
namespace {

const std::vector<std::string> kSections{"body",    "mass_model", "field",
                                         "initial", "integrate",  "output"};
const std::vector<std::string> kBodyKeys{"inertia", "inertia_tensor", "mass", "center_of_mass",
                                         "gyrostat"};
const std::vector<std::string> kInitialKeys{
    "omega", "gamma", "normalize", "quaternion", "rotation_matrix", "euler_321", "euler_313"};
const std::vector<std::string> kIntegrateKeys{"method", "step",      "tol",  "t_end",
                                              "t0",     "max_steps", "split"};
const std::vector<std::string> kOutputKeys{"file", "every", "dt"};

/// Unknown sections and keys first, in every section: a misspelt key is reported as itself, not
/// as the required key it displaced.
void check_vocabulary(const toml::table& doc, const std::string& source) {
  TableReader(doc, source, "").check_keys(kSections);
  const std::pair<const char*, const std::vector<std::string>*> sections[] = {
      {"body", &kBodyKeys},       {"mass_model", &mass_model_keys()}, {"field", &field_keys()},
      {"initial", &kInitialKeys}, {"integrate", &kIntegrateKeys},     {"output", &kOutputKeys}};
  for (const auto& [name, keys] : sections) {
    if (const toml::table* t = doc[name].as_table())
      TableReader(*t, source, name).check_keys(*keys);
  }
}

Body read_body(TableReader& r) {
  const bool has_principal = r.has("inertia");
  const bool has_tensor = r.has("inertia_tensor");
  if (has_principal && has_tensor) {
    r.fail("inertia_tensor", "conflicts with inertia: give one of them");
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

BodySource body_source(const toml::table* body, const MassModelSection* model) {
  const std::string inertia =
      body && body->contains("inertia_tensor") ? "inertia_tensor" : "inertia";
  if (model && model->model) {
    const Factor m{"mass_model", model->key};
    return {m, m, m, {"body", "gyrostat"}};
  }
  return {{"body", "mass"}, {"body", "center_of_mass"}, {"body", inertia}, {"body", "gyrostat"}};
}

State read_initial(TableReader& r, const Body& body, std::optional<Quaternion>& attitude) {
  const Vec3 P_omega = r.vec3("omega");
  Vec3 P_gamma = r.vec3("gamma");
  const bool normalize = r.boolean("normalize", false);
  // The library's check (check_unit_gamma), located at [initial] gamma.
  try {
    if (normalize) {
      P_gamma = normalized_gamma(P_gamma);
    } else {
      check_unit_gamma(P_gamma);
    }
  } catch (const InputError& e) {
    std::string what = std::string(e.what()).substr(std::string_view("gamma: ").size());
    if (!normalize && what.starts_with("expected a unit vector (")) {
      what += "; add normalize = true to [initial] to rescale it";
    }
    r.fail("gamma", what);
  }
  attitude = read_attitude(r, normalize);
  r.finish();
  // Vectors are given in the user's frame; the body works in its principal axes.
  const Mat3& P = body.principal_axes();
  if (attitude) attitude = (*attitude * Quaternion(P)).normalized();
  return state_from_omega(body, P.transpose() * P_omega, P.transpose() * P_gamma);
}

/// The body of a mass model; what makes it impossible (an overflowing inertia tensor) is reported
/// at the [mass_model] key that defines the model.
Body body_of_model(const MassModelSection& mm, const toml::table& section, const Vec3& k,
                   const std::string& source) {
  try {
    return body_of(*mm.model, k);
  } catch (const InputError& e) {
    TableReader(section, source, "mass_model").fail(mm.key, std::string("its body: ") + e.what());
  }
}

/// The model of the run. With a mass model, the factories derive the body from it again (the same
/// body_of as body_value, already checked): the rotor is the one thing [body] adds, `k` as given
/// in [body] (the user's frame, as body_of takes it; body_value's is in the principal axes).
Model run_model(const MassModelSection& mm, const Body& body_value, const FieldSection& field,
                const CentreSection& c, const Vec3& k) {
  if (!mm.model) return Model(body_value, field.field);
  switch (c.kind) {
    case FieldKind::exact:
      return Model::exact(mm.model, c.mu, c.R, k);
    case FieldKind::multipole:
      return Model::multipole(mm.model, c.order, c.mu, c.R, k);
    case FieldKind::quadratic:
      break;
  }
  return Model::quadratic(mm.model, field.field, k);
}

/// [body], [mass_model] or both (then they must agree; [body] may then hold only a gyrostat).
Body read_body_or_mass_model(const toml::table* t, const toml::table* mm_table,
                             const MassModelSection& mm, const std::string& source) {
  if (!mm.model) {
    TableReader r(*t, source, "body");
    return read_body(r);
  }
  if (!t) return body_of_model(mm, *mm_table, Vec3::Zero(), source);
  TableReader r(*t, source, "body");
  const Vec3 k = r.optional_vec3("gyrostat").value_or(Vec3::Zero());
  const Body derived = body_of_model(mm, *mm_table, k, source);
  const bool whole = r.has("inertia") || r.has("inertia_tensor");
  const bool mass = r.has("mass"), com = r.has("center_of_mass");
  if (whole) {
    TableReader again(*t, source, "body");
    check_agreement(again, read_body(again), derived);
  } else if (mass || com) {
    r.fail(mass ? "mass" : "center_of_mass",
           "with [mass_model], give the whole body (inertia, mass, center_of_mass) to cross-check "
           "it, or only gyrostat");
  }
  r.finish();
  return derived;
}

IntegrateSection read_integrate(TableReader& r) {
  IntegrateSection s;
  s.method = r.optional_string("method");
  // A step is for the fixed-step methods, a tolerance for the adaptive ones: never both.
  if (r.has("step") && r.has("tol")) {
    r.fail("tol", "conflicts with step: give step (fixed-step methods) or tol (adaptive methods)");
  }
  if (s.method) {
    const MethodInfo& info = r.checked([&] { return method_info(*s.method); });
    const bool adaptive = info.kind == MethodKind::adaptive;
    if (r.has(adaptive ? "step" : "tol")) {
      r.fail(adaptive ? "step" : "tol", "conflicts with method = \"" + *s.method +
                                            "\", which takes " +
                                            (adaptive ? "a tolerance (tol)" : "a step (step)"));
    }
  }
  s.step = r.optional_number("step");
  if (s.step && !(*s.step > 0)) {
    r.fail("step", "expected a number > 0, found " + format_number(*s.step));
  }
  s.tol = r.optional_number("tol");
  if (s.tol && !(*s.tol > 0))
    r.fail("tol", "expected a number > 0, found " + format_number(*s.tol));
  s.t_end = r.optional_number("t_end");
  s.t0 = r.optional_number("t0").value_or(0.0);
  if (r.has("max_steps")) {
    s.max_steps = r.integer("max_steps", 1, std::numeric_limits<std::int64_t>::max());
  }
  s.split = r.optional_string("split");
  if (s.split) {
    r.checked([&] { return free_body_split(*s.split, "split"); });
    if (s.method && method_info(*s.method).kind != MethodKind::splitting) {
      r.fail("split", "applies to the splitting methods, found method = \"" + *s.method + "\"");
    }
    if (!s.method && s.tol) {
      r.fail("split", "applies to the splitting methods (a step), found tol");
    }
  }
  r.finish();
  return s;
}

OutputSection read_output(TableReader& r) {
  OutputSection s;
  s.file = r.optional_string("file");
  if (s.file && s.file->empty()) r.fail("file", "expected a file name, found an empty string");
  if (r.has("every")) s.every = r.integer("every", 1, std::numeric_limits<std::int64_t>::max());
  s.dt = r.optional_number("dt");
  if (s.dt && !(*s.dt > 0)) r.fail("dt", "expected a number > 0, found " + format_number(*s.dt));
  if (s.dt && r.has("every")) r.fail("dt", "expected either every or dt, found both");
  r.finish();
  return s;
}

}  // namespace

Scenario parse_scenario(const std::string& text, const std::string& source) {
  const toml::table doc = parse_toml(text, source);
  check_vocabulary(doc, source);
  TableReader top(doc, source, "");
  auto section = [&](const std::string& name, bool required) -> const toml::table* {
    const toml::table* t = top.table(name);
    if (!t && required) top.fail(name, "missing section [" + name + "]");
    return t;
  };
  MassModelSection mm;
  std::vector<std::string> input_files{source};
  const toml::table* mm_table = section("mass_model", false);
  if (mm_table) {
    TableReader r(*mm_table, source, "mass_model");
    mm = read_mass_model(r, std::filesystem::path(source).parent_path().string());
    input_files.insert(input_files.end(), mm.files.begin(), mm.files.end());
  }
  const toml::table* body_table = section("body", !mm.model);
  const Body body_value = read_body_or_mass_model(body_table, mm_table, mm, source);
  TableReader field_reader(*section("field", true), source, "field");
  CentreSection centre;
  const FieldSection field =
      read_field(field_reader, mm.model, centre, body_value.center_of_mass().isZero(0.0));
  const QuadraticModel checked{body_value, field.field};
  TableReader initial(*section("initial", true), source, "initial");
  std::optional<Quaternion> attitude;
  const State x0 = read_initial(initial, checked.body, attitude);
  check_magnitudes(checked, x0, field, body_source(body_table, mm_table ? &mm : nullptr), doc,
                   source);
  // [body] gyrostat as written (the user's frame), for the factories of a mass model's field.
  const Vec3 k = mm.model && body_table ? TableReader(*body_table, source, "body")
                                              .optional_vec3("gyrostat")
                                              .value_or(Vec3::Zero())
                                        : Vec3::Zero();
  Scenario s{source,     run_model(mm, body_value, field, centre, k), x0, attitude, {}, {},
             input_files};
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
  return parse_scenario(read_regular_file(path, kMaxTomlBytes, "scenario file"), path);
}

MethodSettings resolve_method(const Scenario& s, const IntegrateOverrides& o) {
  MethodSettings m;
  const std::string adaptive_default(
      default_adaptive_method(s.model.kind() == FieldKind::quadratic));
  const std::optional<double> step = o.step ? o.step : (o.tol ? std::nullopt : s.integrate.step);
  const std::optional<double> tol = o.tol ? o.tol : (o.step ? std::nullopt : s.integrate.tol);
  const bool named = o.method || (!o.step && !o.tol && s.integrate.method);
  if (o.method) {
    m.name = *o.method;
  } else if (o.step || o.tol) {
    m.name = o.step ? std::string(kDefaultFixedMethod) : adaptive_default;
  } else if (s.integrate.method) {
    m.name = *s.integrate.method;
  } else {
    m.name = step ? std::string(kDefaultFixedMethod) : adaptive_default;
  }
  const MethodInfo& info = method_info(m.name);
  const bool adaptive = info.kind == MethodKind::adaptive;
  if (m.name == "taylor" && s.model.kind() != FieldKind::quadratic) {
    throw InputError(s.source + ": " + kTaylorFieldOnly + ", found the " +
                     to_string(s.model.kind()) + " field");
  }
  if (!named && !step && !tol) {
    throw InputError(s.source +
                     ": [integrate]: a step or a tolerance is needed: give --step (fixed step, " +
                     std::string(kDefaultFixedMethod) + ") or --tol (adaptive, " +
                     adaptive_default + "), or step or tol in [integrate]");
  }
  if (adaptive && !tol) {
    throw InputError(s.source + ": tol: method " + m.name + " is adaptive and needs a tolerance" +
                     (step ? ", not a step" : "") + ": give --tol or [integrate] tol");
  }
  if (!adaptive && !step) {
    throw InputError(s.source + ": step: method " + m.name + " takes a fixed step" +
                     (tol ? ", not a tolerance" : "") + ": give --step or [integrate] step");
  }
  if (adaptive) {
    m.abs_tol = m.rel_tol = *tol;
  } else {
    m.step = *step;
  }
  const bool splitting = info.kind == MethodKind::splitting;
  if (o.split && !splitting) {
    throw InputError(s.source + ": split: applies to the splitting methods, found method " +
                     m.name);
  }
  const std::optional<std::string> split = o.split ? o.split : s.integrate.split;
  if (split && splitting) {
    const FreeBodySplit free_body = free_body_split(*split, "split");
    if (free_body == FreeBodySplit::exact && !s.model.body().gyrostat().isZero(0.0)) {
      throw InputError(s.source +
                       ": split: the exact free-body flow needs a body without a gyrostat (k = 0), "
                       "found k = " +
                       format_vector(s.model.body().gyrostat()));
    }
    SplitOrdering ordering = default_ordering(composition_table(m.name));
    ordering.free_body = free_body;
    m.ordering = ordering;
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
