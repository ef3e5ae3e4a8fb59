#pragma once
/// \file
/// The comma- and colon-separated lists of the command line (docs/cli.md): `--times 0.5,1,2`,
/// `--gamma g1,g2,g3`, `--scan-R R1:R2:N`, `--scan-omega LO:HI:N`, `--scan P1=LO:HI:N,P2=LO:HI:M`,
/// `--resonances p:q,…`, `--spin LO:HI:N` and `--diagram debra-delp --scan k_R=…,k_Y=…`. Each
/// returns the values or throws InputError naming the option, what was expected and what was
/// found (one line).

#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "newtop/analysis/stability_spin.hpp"
#include "newtop/core/types.hpp"
#include "newtop/orbit/spin_orbit.hpp"

namespace newtop::io {

/// The one reader of the colon-separated values of the command line ("LO:HI:N", "A:B", "P:Q"):
/// the values of types T... (double or int) separated by ':', blanks allowed around each, nothing
/// after; std::nullopt when the text is not of that form. Each option's parser below checks its
/// own bounds and names the option in its message. Compiled for (double, double, int),
/// (double, double) and (int, int).
template <class... T>
std::optional<std::tuple<T...>> read_colon_values(const std::string& text);

/// The finite times of a comma-separated list, in the order given; throws InputError naming the
/// option and the item that is not a number.
std::vector<double> parse_times(const std::string& option, const std::string& text);

/// `--gamma g1,g2,g3`: three numbers, a finite non-zero vector, returned normalized.
Vec3 parse_gamma(const std::string& text);

/// `--scan-R R1:R2:N`: 2 ≤ N ≤ kMaxScanPoints distances from R1 to R2, 0 < R1 < R2.
struct RadiusScan {
  double R1, R2;
  int n;
};
RadiusScan parse_radius_scan(const std::string& text);

/// N equally spaced values of a parameter from lo to hi (lo alone when N = 1).
struct Range {
  std::string name;
  double lo, hi;
  int n;
  double at(int k) const { return n == 1 ? lo : lo + (hi - lo) * k / (n - 1); }
  std::vector<double> values() const {
    std::vector<double> v;
    for (int k = 0; k < n; ++k) v.push_back(at(k));
    return v;
  }
};

/// "LO:HI:N" (or "NAME=LO:HI:N" when `named`, NAME in omega, lambda, A, B, C), N from 1 to
/// kMaxScanPoints; `flag` names the option in messages.
Range parse_range(const std::string& flag, const std::string& text, bool named);

/// Grid points of --scan at most: 1e6 eigenvalue problems take seconds and the CSV ~60 MB.
inline constexpr long long kMaxGridPoints = 1000000;

/// --scan "P1=LO:HI:N,P2=LO:HI:M" with N·M ≤ kMaxGridPoints.
std::pair<Range, Range> parse_grid(const std::string& spec);

/// `--resonances p:q,p:q,…`: each pair of integers checked by resonance(p, q).
std::vector<SpinOrbitResonance> parse_resonances(const std::string& text);

/// `--spin LO:HI:N`: LO ≤ HI finite, 1 ≤ N ≤ 10000.
struct SpinScan {
  double lo, hi;
  int n;
};
SpinScan parse_spin(const std::string& text);

/// One axis of the Debra–DelPup diagram (`--scan k_R=LO:HI:N,k_Y=LO:HI:M`); the defaults are the
/// diagram without --scan.
struct RatioAxis {
  double lo = -0.99, hi = 0.99;
  int n = 67;
};
/// "k_R=LO:HI:N,k_Y=LO:HI:M" with |k| < 1, counts ≥ 1 and N·M ≤ kMaxGridPoints.
std::pair<RatioAxis, RatioAxis> parse_ratio_scan(const std::string& text);

}  // namespace newtop::io
