#include "newtop/io/potential_file.hpp"

#include <cmath>
#include <map>

#include "file_check.hpp"
#include "toml_parse.hpp"
#include "toml_reader.hpp"

namespace newtop::io {
namespace {

std::string exponents_text(const std::array<int, 3>& p) {
  return "(" + std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " + std::to_string(p[2]) +
         ")";
}

}  // namespace

PolynomialPotential parse_potential(const std::string& text, const std::string& source,
                                    const Body& body) {
  const toml::table doc = parse_toml(text, source);
  TableReader top(doc, source, "");
  top.check_keys({"potential"});
  const toml::table* section = top.table("potential");
  if (!section) top.fail("potential", "missing section [potential]");
  TableReader r(*section, source, "potential");
  r.check_keys({"terms"});
  const toml::node* terms_node = section->get("terms");
  if (!terms_node) r.fail("terms", "missing: give terms = [[coefficient, i, j, k], ...]");
  const toml::array* terms = terms_node->as_array();
  if (!terms)
    r.fail("terms", "expected an array of [coefficient, i, j, k], found " + describe(*terms_node));
  PolynomialPotential v;
  std::map<std::array<int, 3>, std::size_t> seen;  // exponents -> row
  for (std::size_t i = 0; i < terms->size(); ++i) {
    const toml::node& node = *terms->get(i);
    const std::string name = "terms[" + std::to_string(i) + "]";
    const toml::array* t = node.as_array();
    if (!t || t->size() != 4) {
      r.fail_at(node, name, "expected [coefficient, i, j, k], found " + describe(node));
    }
    PotentialTerm term;
    term.coefficient = r.element_number(name, *t->get(0), "coefficient");
    if (std::abs(term.coefficient) > kMaxPotentialCoefficient) {
      r.fail_at(node, name,
                "expected a coefficient of magnitude at most " +
                    format_number(kMaxPotentialCoefficient) + ", found " +
                    format_number(term.coefficient));
    }
    for (int k = 0; k < 3; ++k) {
      const toml::node& e = *t->get(static_cast<std::size_t>(k) + 1);
      const auto* n = e.as_integer();
      if (!n || n->get() < 0 || n->get() > kMaxPotentialExponent) {
        r.fail_at(node, name,
                  "expected the exponent of gamma" + std::to_string(k + 1) +
                      " to be an integer in [0, " + std::to_string(kMaxPotentialExponent) +
                      "], found " + describe(e));
      }
      term.power[static_cast<std::size_t>(k)] = static_cast<int>(n->get());
    }
    const auto [at, fresh] = seen.emplace(term.power, i);
    if (!fresh) {
      r.fail_at(node, name,
                "the exponents " + exponents_text(term.power) + " repeat terms[" +
                    std::to_string(at->second) + "]: give each monomial once");
    }
    v.terms.push_back(term);
  }
  double sum = 0.0;  // at most 729 terms of at most 1e100
  for (const auto& t : v.terms) sum += std::abs(t.coefficient);
  const double rate = sum * kMaxPotentialExponent / body.inertia().minCoeff();
  if (!(rate <= kMaxPotentialCoefficient)) {
    r.fail("terms", "expected sum |coefficient| * " + std::to_string(kMaxPotentialExponent) +
                        " / min(A, B, C) of at most " + format_number(kMaxPotentialCoefficient) +
                        ", found " + format_number(sum) + " * " +
                        std::to_string(kMaxPotentialExponent) + " / " +
                        format_number(body.inertia().minCoeff()) + " = " + format_number(rate));
  }
  return v;
}

PolynomialPotential load_potential(const std::string& path, const Body& body) {
  return parse_potential(read_regular_file(path, kMaxTomlBytes, "potential file"), path, body);
}

}  // namespace newtop::io
