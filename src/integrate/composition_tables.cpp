#include "newtop/integrate/composition_tables.hpp"

#include <cmath>
#include <string>

#include "newtop/core/types.hpp"

namespace newtop {
namespace {

// Mirrors the first half of a symmetric method: {γ1 … γm, γ_{m+1}} -> {γ1 … γm, γ_{m+1}, γm … γ1}.
std::vector<double> symmetric(std::initializer_list<double> half_with_centre) {
  std::vector<double> g(half_with_centre);
  for (int i = static_cast<int>(g.size()) - 2; i >= 0; --i) g.push_back(g[static_cast<size_t>(i)]);
  return g;
}

std::vector<double> triple_jump() {
  const double c = std::cbrt(2.0);
  const double g1 = 1.0 / (2.0 - c);
  return {g1, -c * g1, g1};
}

std::vector<double> suzuki5() {
  const double c = std::cbrt(4.0);
  const double g1 = 1.0 / (4.0 - c);
  return {g1, g1, -c * g1, g1, g1};
}

const std::vector<CompositionTable>& tables() {
  static const std::vector<CompositionTable> t{
      {"splitting2", 2, {1.0}, "Strang (1968) / Störmer–Verlet: the symmetric base method itself"},
      {"splitting4-yoshida", 4, triple_jump(),
       "Yoshida, Phys. Lett. A 150 (1990) 262; Creutz & Gocksch (1989); the 'triple jump' "
       "γ1 = γ3 = 1/(2 − 2^(1/3))"},
      {"splitting4", 4, suzuki5(),
       "Suzuki, Phys. Lett. A 146 (1990) 319: s = 5, γ1 = γ2 = γ4 = γ5 = 1/(4 − 4^(1/3))"},
      {"splitting6", 6,
       symmetric({0.39216144400731413927925056, 0.33259913678935943859974864,
                  -0.70624617255763935980996482, 0.08221359629355080023149045,
                  0.79854399093482996339895035}),
       "Kahan & Li, Math. Comp. 66 (1997) 1089, method s9odr6a (as in Hairer, Lubich & Wanner, "
       "GNI §V.3.2, eq. (3.11))"},
      {"splitting8", 8,
       symmetric({0.13020248308889008087881763, 0.56116298177510838456196441,
                  -0.38947496264484728640807860, 0.15884190655515560089621075,
                  -0.39590389413323757733623154, 0.18453964097831570709183254,
                  0.25837438768632204729397911, 0.29501172360931029887096624,
                  -0.60550853383003451169892108}),
       "Kahan & Li, Math. Comp. 66 (1997) 1089, method s17odr8a (as in Hairer, Lubich & Wanner, "
       "GNI §V.3.2, eq. (3.12))"},
      {"splitting8-mclachlan", 8,
       symmetric({0.74167036435061295344822780, -0.40910082580003159399730010,
                  0.19075471029623837995387626, -0.57386247111608226665638773,
                  0.29906418130365592384446354, 0.33462491824529818378495798,
                  0.31529309239676659663205666, -0.79688793935291635401978884}),
       "McLachlan, SIAM J. Sci. Comput. 16 (1995) 151, s = 15 order 8 (as in Hairer, Lubich & "
       "Wanner, GNI §V.3.2)"},
  };
  return t;
}

}  // namespace

std::span<const CompositionTable> composition_tables() { return tables(); }

const CompositionTable& composition_table(std::string_view name) {
  for (const auto& t : tables()) {
    if (t.name == name) return t;
  }
  std::string known;
  for (const auto& t : tables()) known += (known.empty() ? "" : ", ") + std::string(t.name);
  throw InputError("method: expected one of " + known + ", found '" + std::string(name) + "'");
}

}  // namespace newtop
