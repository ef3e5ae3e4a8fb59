#pragma once
/// \file
/// Splitting methods as data. Symmetric compositions Ψ_h = Φ_{γ_s h} ∘ … ∘ Φ_{γ_1 h} of a symmetric
/// second-order base method Φ raise the order to 4, 6 or 8 (Hairer, Lubich & Wanner, Geometric
/// Numerical Integration, 2nd ed., §V.3). Near-integrable splittings of H = H_free + V, whose error
/// is O(ε h^p + ε² h^q) when V = O(ε), give the step K(b₀h) F(a₁h) K(b₁h) … F(a_s h) K(b_s h)
/// directly, F the exact free-body flow and K the kick. Each table cites its source.

#include <array>
#include <span>
#include <string_view>
#include <vector>

namespace newtop {

struct CompositionTable {
  std::string_view name;      ///< method name as used by the command line
  int order;                  ///< order of the composition of a symmetric order-2 base
  std::vector<double> gamma;  ///< compositions: all s stage coefficients γ_1 … γ_s (Σγ_i = 1)
  std::string_view reference;  ///< where the coefficients were published
  /// Near-integrable splittings (empty for compositions): the free-body flows a_1 … a_s and the
  /// kicks b_0 … b_s (Σa_i = Σb_i = 1; b_0 = b_s = 0 for a method that starts with a flow).
  std::vector<double> a = {};
  std::vector<double> b = {};
};

/// Every table newtop ships, lowest order first.
std::span<const CompositionTable> composition_tables();

/// Near-integrable splittings of H = H_free + V for the exact free-body flow (SABA_n, SBAB_n of
/// Laskar & Robutel; ABA(8,6,4), ABA(10,6,4) of Blanes et al.), measured in docs/performance.md.
std::span<const CompositionTable> near_integrable_tables();

/// The table with this name (either list); throws InputError listing the known names if there is
/// none.
const CompositionTable& composition_table(std::string_view name);

/// How the free-body flow T is computed.
enum class FreeBodySplit {
  /// Strang splitting into rotations about the three body axes:
  /// T(t) = R_i(t/2) R_j(t/2) R_k(t) R_j(t/2) R_i(t/2), with (i, j, k) = axes.
  axes,
  /// ½ m·I⁻¹m = ½|m|²/I_r + ½ Σ α_i m_i² with α_i = 1/I_i − 1/I_r and r = axes[2]: the |m|² flow (γ
  /// turns about m, m fixed) commutes with the rest and is exact; the rest is split into rotations
  /// about the two other axes: T(t) = S(t) R'_i(t/2) R'_j(t) R'_i(t/2), (i, j) = (axes[0],
  /// axes[1]).
  /// A gyrostatic k_r ≠ 0 adds a rotation of constant angle about e_r in the middle.
  spin,
  /// The exact Euler–Poinsot flow (free_body_flow.hpp); needs k = 0.
  exact,
};

/// How the base method is built from the free-body flow T and the kick K.
/// kick_outside: K(h/2) T(h) K(h/2); otherwise T(h/2) K(h) T(h/2). With by_moment, axes name the
/// axes by increasing moment (0 = least, 2 = largest) rather than x, y, z. The orderings' errors
/// differ by up to a factor ~40 on a generic body (docs/performance.md, "Ordering of the split").
struct SplitOrdering {
  std::array<int, 3> axes{0, 1, 2};
  bool kick_outside = false;
  bool by_moment = true;
  FreeBodySplit free_body = FreeBodySplit::axes;
};

/// The measured best ordering for a table (docs/performance.md): see splitting.cpp.
SplitOrdering default_ordering(const CompositionTable& table);

}  // namespace newtop
