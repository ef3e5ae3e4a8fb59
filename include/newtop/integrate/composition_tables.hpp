#pragma once
/// \file
/// Symmetric composition methods as data: Ψ_h = Φ_{γ_s h} ∘ … ∘ Φ_{γ_1 h} of a symmetric
/// second-order base method Φ raises the order to 4, 6 or 8 (Hairer, Lubich & Wanner, Geometric
/// Numerical Integration, 2nd ed., §V.3). Each table cites its source.

#include <span>
#include <string_view>
#include <vector>

namespace newtop {

struct CompositionTable {
  std::string_view name;       ///< method name as used by the command line
  int order;                   ///< order of the composition of a symmetric order-2 base
  std::vector<double> gamma;   ///< all s stage coefficients γ_1 … γ_s (Σγ_i = 1)
  std::string_view reference;  ///< where the coefficients were published
};

/// Every table newtop ships, lowest order first.
std::span<const CompositionTable> composition_tables();

/// The table with this name; throws InputError listing the known names if there is none.
const CompositionTable& composition_table(std::string_view name);

}  // namespace newtop
