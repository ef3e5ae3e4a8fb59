// [field] of a scenario file: which field the keys describe, conflicting keys refused.

#include <algorithm>

#include "newtop/exact/exact_field.hpp"
#include "scenario_sections.hpp"
#include "toml_parse.hpp"

namespace newtop::io {
namespace {

constexpr std::int64_t kMaxOrder = 30;

Factor factor(const std::string& key, double value, int power = 1) {
  return {"field", key, value, power};
}

// The three (g, λ) forms of the quadratic field without a kind, and the pairs of keys that belong
// to no common form.
const char* const kForms = "give (g, lambda), (g, R) or (mu, R)";

// g_irrelevant: the body's centre of mass is at the fixed point (r0 = 0), so that g, which only
// multiplies r0 in the potential, cannot matter: lambda alone is the field, with g = 0.
FieldSection quadratic_form(TableReader& r, const std::string& kind, bool g_irrelevant) {
  const bool g = r.has("g"), lam = r.has("lambda"), mu = r.has("mu"), R = r.has("R");
  const std::pair<const char*, const char*> clashes[] = {
      {"lambda", "R"}, {"lambda", "mu"}, {"g", "mu"}};
  for (const auto& [a, b] : clashes) {
    if (r.has(a) && r.has(b)) r.fail(b, std::string("conflicts with ") + a + ": " + kForms);
  }
  FieldSection f;
  if (g && lam) {
    const double vg = r.number("g"), vl = r.number("lambda");
    f.field = r.checked([&] { return QuadraticField::coulomb(vg, vl); });
    f.g = {factor("g", vg)};
    f.lambda = {factor("lambda", vl)};
  } else if (g && R) {
    const double vg = r.number("g"), vR = r.number("R");
    f.field = r.checked([&] { return QuadraticField::from_g_R(vg, vR); });
    f.g = {factor("g", vg)};
    f.lambda = {factor("g", vg), factor("R", vR, -1)};
  } else if (mu && R) {
    const double vmu = r.number("mu"), vR = r.number("R");
    f.field = r.checked([&] { return QuadraticField::from_mu_R(vmu, vR); });
    f.g = {factor("mu", vmu), factor("R", vR, -2)};
    f.lambda = {factor("mu", vmu), factor("R", vR, -3)};
  } else if (lam && g_irrelevant) {
    const double vl = r.number("lambda");
    f.field = r.checked([&] { return QuadraticField::coulomb(0.0, vl); });
    f.lambda = {factor("lambda", vl)};
  } else if (g) {
    r.fail("lambda", "missing: g needs lambda or R (or kind = \"uniform\" for uniform gravity)");
  } else if (lam) {
    r.fail("g", "missing: lambda needs g (where the centre of mass r0 is not 0)");
  } else if (mu) {
    r.fail("R", "missing: mu needs R");
  } else if (R) {
    r.fail("g", "missing: R needs g or mu");
  } else {
    r.fail("g", std::string("missing: ") + kForms +
                    ", or a kind (\"uniform\", \"brun\", \"exact\", \"multipole\")");
  }
  if (kind == "newtonian") {
    // A Newtonian centre attracts: g = μ/R² >= 0 and λ = 3μ/R³ >= 0.
    if (f.field.g < 0) {
      r.fail(g ? "g" : "mu",
             "kind = \"newtonian\" needs g >= 0 (an attracting centre), found g = " +
                 format_number(f.field.g) + "; kind = \"coulomb\" allows either sign");
    }
    if (f.field.lambda_ < 0) {
      r.fail(lam ? "lambda" : "R", "kind = \"newtonian\" needs lambda >= 0, found lambda = " +
                                       format_number(f.field.lambda_) +
                                       "; kind = \"coulomb\" allows either sign");
    }
  }
  return f;
}

FieldSection exact_form(TableReader& r, const std::string& kind,
                        const std::shared_ptr<const MassModel>& mass_model, CentreSection& exact) {
  exact.kind = kind == "exact" ? FieldKind::exact : FieldKind::multipole;
  exact.mu = r.number("mu");
  exact.R = r.number("R");
  if (exact.kind == FieldKind::multipole) {
    exact.order = static_cast<int>(r.integer("order", 1, kMaxOrder));
  }
  if (!mass_model) r.fail("kind", "kind = \"" + kind + "\" needs a [mass_model] section");
  FieldSection f;
  f.field = r.checked([&] { return QuadraticField::from_mu_R(exact.mu, exact.R); });
  r.checked([&] { return ExactField::make(mass_model, exact.mu, exact.R); });
  f.g = {factor("mu", exact.mu), factor("R", exact.R, -2)};
  f.lambda = {factor("mu", exact.mu), factor("R", exact.R, -3)};
  return f;
}

}  // namespace

const std::vector<std::string>& field_keys() {
  static const std::vector<std::string> keys{"kind", "g", "lambda",       "mu",
                                             "R",    "N", "plane_offset", "order"};
  return keys;
}

FieldSection read_field(TableReader& r, const std::shared_ptr<const MassModel>& mass_model,
                        CentreSection& exact, bool g_irrelevant) {
  const std::optional<std::string> given = r.optional_string("kind");
  const std::vector<std::string> kinds{"newtonian", "coulomb", "uniform",
                                       "brun",      "exact",   "multipole"};
  if (given && std::find(kinds.begin(), kinds.end(), *given) == kinds.end()) {
    r.fail("kind",
           "expected \"newtonian\", \"coulomb\", \"uniform\", \"brun\", \"exact\" or "
           "\"multipole\", found the string \"" +
               printable(*given) + "\"");
  }
  // Without a kind, keys that belong to one field only say which it is.
  std::string kind = given.value_or("");
  std::string reason = "kind = \"" + kind + "\"";
  if (!given && (r.has("N") || r.has("plane_offset"))) {
    kind = "brun";
    reason = std::string(r.has("N") ? "N" : "plane_offset") + " (Brun's field, kind = \"brun\")";
  } else if (!given && r.has("order")) {
    kind = "multipole";
    reason = "order (the multipole field, kind = \"multipole\")";
  }
  const std::vector<std::string> quadratic{"kind", "g", "lambda", "mu", "R"};
  FieldSection f;
  if (kind == "exact" || kind == "multipole") {
    r.only(kind == "exact" ? std::vector<std::string>{"kind", "mu", "R"}
                           : std::vector<std::string>{"kind", "mu", "R", "order"},
           field_keys(), reason);
    f = exact_form(r, kind, mass_model, exact);
  } else if (kind == "brun") {
    r.only({"kind", "N", "plane_offset"}, field_keys(), reason);
    const double N = r.number("N");
    const double d = r.optional_number("plane_offset").value_or(0.0);
    f.field = r.checked([&] { return QuadraticField::brun(N, d); });
    f.g = {factor("N", N), factor("plane_offset", d)};
    f.lambda = {factor("N", N)};
  } else if (kind == "uniform") {
    r.only({"kind", "g"}, field_keys(), reason);
    const double g = r.number("g");
    f.field = r.checked([&] { return QuadraticField::uniform(g); });
    f.g = {factor("g", g)};
  } else {  // newtonian, coulomb or no kind: the forms (g, lambda), (g, R), (mu, R)
    r.only(quadratic, field_keys(), given ? reason : "the quadratic field's keys");
    f = quadratic_form(r, kind, g_irrelevant);
  }
  r.finish();
  return f;
}

}  // namespace newtop::io
