// Grid points that are exact where the decimal grid is representable (newtop/core/grid.hpp).
#include "newtop/core/grid.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string_view>

namespace newtop {
namespace {

/// Integers exactly representable in a double (and in int64 with room for the sums below).
constexpr std::int64_t kExact = std::int64_t{1} << 53;

/// x = digits · 10^exponent, from the shortest decimal that reads back as x; nullopt when the
/// digits do not fit below 2⁵³ (never for a shortest form: at most 17 digits, but then
/// 10^17 > 2⁵³ and the caller's products would not fit anyway).
struct Decimal {
  std::int64_t digits = 0;
  int exponent = 0;
};

std::optional<Decimal> shortest_decimal(double x) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof(buf), x, std::chars_format::scientific);
  const std::string_view s(buf, static_cast<std::size_t>(res.ptr - buf));  // "-d.ddde±xx"
  const std::size_t e = s.find('e');
  Decimal d;
  int fraction_digits = 0;
  bool negative = false, after_point = false;
  for (const char c : s.substr(0, e)) {
    if (c == '-') {
      negative = true;
    } else if (c == '.') {
      after_point = true;
    } else {
      if (d.digits >= kExact / 10) return std::nullopt;
      d.digits = 10 * d.digits + (c - '0');
      fraction_digits += after_point ? 1 : 0;
    }
  }
  int exponent = 0;
  std::from_chars(s.data() + e + (s[e + 1] == '+' ? 2 : 1), s.data() + s.size(), exponent);
  d.exponent = exponent - fraction_digits;
  if (negative) d.digits = -d.digits;
  return d;
}

/// 10^p for 0 <= p <= 15 (exact in int64 and in a double).
std::int64_t power_of_ten(int p) {
  std::int64_t r = 1;
  for (int i = 0; i < p; ++i) r *= 10;
  return r;
}

/// |a · b| < 2⁵³ for non-negative b.
bool product_fits(std::int64_t a, std::int64_t b) { return b == 0 || std::llabs(a) < kExact / b; }

/// The exact point as numerator / denominator, both below 2⁵³, or nullopt.
std::optional<double> exact_point(double lo, double hi, std::int64_t n, std::int64_t k) {
  const auto a = shortest_decimal(lo), b = shortest_decimal(hi);
  if (!a || !b) return std::nullopt;
  // Bring both to the common exponent q = min: digits scaled by 10^(exponent − q).
  const int q = std::min(a->exponent, b->exponent);
  const int pa = a->exponent - q, pb = b->exponent - q;
  if (pa > 15 || pb > 15 || q < -15 || q > 15) return std::nullopt;
  if (!product_fits(a->digits, power_of_ten(pa)) || !product_fits(b->digits, power_of_ten(pb))) {
    return std::nullopt;
  }
  const std::int64_t A = a->digits * power_of_ten(pa), B = b->digits * power_of_ten(pb);
  // lo + k (hi − lo)/(n − 1) = (A (n − 1 − k) + B k) 10^q / (n − 1).
  if (!product_fits(A, n - 1 - k) || !product_fits(B, k)) return std::nullopt;
  const std::int64_t num = A * (n - 1 - k) + B * k;
  if (std::llabs(num) >= kExact) return std::nullopt;
  std::int64_t den = n - 1;
  std::int64_t scaled = num;
  if (q < 0) {
    if (!product_fits(den, power_of_ten(-q))) return std::nullopt;
    den *= power_of_ten(-q);
  } else {
    if (!product_fits(num, power_of_ten(q))) return std::nullopt;
    scaled = num * power_of_ten(q);
  }
  // Both operands exact, so the quotient is the correctly rounded value of the exact point.
  return static_cast<double>(scaled) / static_cast<double>(den);
}

}  // namespace

double grid_value(double lo, double hi, std::int64_t n, std::int64_t k) {
  if (n <= 1 || k <= 0) return lo;
  if (k >= n - 1) return hi;
  if (std::isfinite(lo) && std::isfinite(hi)) {
    if (const auto x = exact_point(lo, hi, n, k)) return *x;
  }
  const double m = static_cast<double>(n - 1);
  return (lo * (m - static_cast<double>(k)) + hi * static_cast<double>(k)) / m;
}

}  // namespace newtop
