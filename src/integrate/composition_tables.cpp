#include "newtop/integrate/composition_tables.hpp"

#include <cmath>
#include <iterator>
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

// Near-integrable splittings from a quadrature rule on [0, 1] (Laskar & Robutel, Celest. Mech. Dyn.
// Astr. 80 (2001) 39): the kicks sit at the nodes with the weights, the free-body flows fill the
// gaps, so the O(ε) error is the quadrature's (order 2n for n Gauss or n + 1 Lobatto nodes).
CompositionTable quadrature_table(std::string_view name, std::string_view reference,
                                  std::vector<double> nodes, std::vector<double> weights) {
  CompositionTable t{name, 2, {}, reference};
  const bool lobatto = nodes.front() == 0.0;
  double last = 0.0;
  if (!lobatto) t.b.push_back(0.0);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i] > last) t.a.push_back(nodes[i] - last);
    t.b.push_back(weights[i]);
    last = nodes[i];
  }
  if (last < 1.0) {
    t.a.push_back(1.0 - last);
    t.b.push_back(0.0);
  }
  return t;
}

// A symmetric ABA method from the first half of its flows a_1 … and kicks b_1 …, the middle
// coefficient last: with `flow_in_middle` the middle is a flow (odd number of flows).
CompositionTable aba_table(std::string_view name, int order, std::string_view reference,
                           std::initializer_list<double> flows, std::initializer_list<double> kicks,
                           bool flow_in_middle) {
  CompositionTable t{name, order, {}, reference};
  t.a = flow_in_middle ? symmetric(flows) : std::vector<double>(flows);
  if (!flow_in_middle) t.a.insert(t.a.end(), std::rbegin(flows), std::rend(flows));
  t.b = {0.0};
  std::vector<double> k = flow_in_middle ? std::vector<double>(kicks) : symmetric(kicks);
  if (flow_in_middle) k.insert(k.end(), std::rbegin(kicks), std::rend(kicks));
  t.b.insert(t.b.end(), k.begin(), k.end());
  t.b.push_back(0.0);
  return t;
}

const std::vector<CompositionTable>& near_tables() {
  constexpr std::string_view kLR = "Laskar & Robutel, Celest. Mech. Dyn. Astr. 80 (2001) 39";
  constexpr std::string_view kBCFLMM =
      "Blanes, Casas, Farrés, Laskar, Makazaga & Murua, Appl. Numer. Math. 68 (2013) 58 (as "
      "listed in Farrés et al., Celest. Mech. Dyn. Astr. 116 (2013) 141)";
  const double r3 = std::sqrt(3.0) / 6, r15 = std::sqrt(15.0) / 10, r5 = std::sqrt(5.0) / 10,
               r21 = std::sqrt(21.0) / 14;
  const double g4a = std::sqrt(3.0 / 7 - 2.0 / 7 * std::sqrt(6.0 / 5)) / 2,
               g4b = std::sqrt(3.0 / 7 + 2.0 / 7 * std::sqrt(6.0 / 5)) / 2;
  const double w4a = (18 + std::sqrt(30.0)) / 72, w4b = (18 - std::sqrt(30.0)) / 72;
  static const std::vector<CompositionTable> t{
      quadrature_table("saba2", kLR, {0.5 - r3, 0.5 + r3}, {0.5, 0.5}),
      quadrature_table("saba3", kLR, {0.5 - r15, 0.5, 0.5 + r15}, {5.0 / 18, 8.0 / 18, 5.0 / 18}),
      quadrature_table("saba4", kLR, {0.5 - g4b, 0.5 - g4a, 0.5 + g4a, 0.5 + g4b},
                       {w4b, w4a, w4a, w4b}),
      quadrature_table("sbab2", kLR, {0.0, 0.5, 1.0}, {1.0 / 6, 2.0 / 3, 1.0 / 6}),
      quadrature_table("sbab3", kLR, {0.0, 0.5 - r5, 0.5 + r5, 1.0},
                       {1.0 / 12, 5.0 / 12, 5.0 / 12, 1.0 / 12}),
      quadrature_table("sbab4", kLR, {0.0, 0.5 - r21, 0.5, 0.5 + r21, 1.0},
                       {1.0 / 20, 49.0 / 180, 16.0 / 45, 49.0 / 180, 1.0 / 20}),
      aba_table(
          "aba864", 4, kBCFLMM,
          {0.0711334264982231177779387300061549964174, 0.241153427956640098736487795326289649618,
           0.521411761772814789212136078067994229991, -0.333698616227678005726562603400438876027},
          {0.183083687472197221961703757166430291072, 0.310782859898574869507522291054262796375,
           -0.0265646185119588006972121379164987592663, 0.0653961422823734184559721793911134363710},
          false),
      aba_table(
          "aba1064", 4, kBCFLMM,
          {0.03809449742241219545697532230863756534060, 0.1452987161169137492940200726606637497442,
           0.2076276957255412507162056113249882065158, 0.4359097036515261592231548624010651844006,
           -0.6538612258327867093807117373907094120024},
          {0.09585888083707521061077150377145884776921, 0.2044461531429987806805077839164344779763,
           0.2170703479789911017143385924306336714532,
           -0.01737538195906509300561788011852699719871},
          true),
  };
  return t;
}

}  // namespace

std::span<const CompositionTable> composition_tables() { return tables(); }

std::span<const CompositionTable> near_integrable_tables() { return near_tables(); }

const CompositionTable& composition_table(std::string_view name) {
  for (const auto& t : tables()) {
    if (t.name == name) return t;
  }
  for (const auto& t : near_tables()) {
    if (t.name == name) return t;
  }
  std::string known;
  for (const auto& t : tables()) known += (known.empty() ? "" : ", ") + std::string(t.name);
  for (const auto& t : near_tables()) known += ", " + std::string(t.name);
  throw InputError("method: expected one of " + known + ", found '" + std::string(name) + "'");
}

}  // namespace newtop
