// The strict grammar of a section surface (surface.hpp).

#include "newtop/phase/surface.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace newtop::phase {
namespace {

/// The largest coefficient of the surface function (SurfaceFunction): its scale() squares the
/// coefficients (Eigen's norm()), which must stay below the largest double (1.8e308) with room for
/// three of them: 1e150.
constexpr double kMaxCoefficient = 1e150;

constexpr std::string_view kComponents = "a component (omega1..3, m1..3, gamma1..3, normal1..3)";

class Parser {
 public:
  Parser(std::string_view text, std::string_view field) : s_(text), field_(field) {}

  Surface parse() {
    Surface out;
    out.text = std::string(s_);
    std::array<bool, 12> seen{};
    bool first = true;
    for (;;) {
      skip_space();
      double sign = 1.0;
      if (peek() == '+' || peek() == '-') {
        sign = peek() == '-' ? -1.0 : 1.0;
        ++pos_;
        skip_space();
      } else if (!first) {
        fail("'+', '-' or '='");
      }
      first = false;
      double coef = 1.0;
      if (starts_number()) {
        coef = number();
        skip_space();
        if (peek() != '*') fail("'*' after the coefficient");
        ++pos_;
        skip_space();
      }
      const int k = component();
      if (seen[k]) fail("each component once", std::string(word_));
      seen[k] = true;
      Vec3& a = k < 3 ? out.a_omega : k < 6 ? out.a_m : k < 9 ? out.a_gamma : out.a_normal;
      a[k % 3] = sign * coef;
      skip_space();
      if (peek() == '=') break;
    }
    ++pos_;  // '='
    skip_space();
    if (!starts_number() && peek() != '-' && peek() != '+') fail("a number after '='");
    out.c = number();
    skip_space();
    if (pos_ != s_.size()) fail("the end of the expression after the number");
    if (out.a_omega.isZero(0.0) && out.a_m.isZero(0.0) && out.a_gamma.isZero(0.0) &&
        out.a_normal.isZero(0.0)) {
      throw InputError(std::string(field_) +
                       ": expected at least one nonzero coefficient, found '" + out.text + "'");
    }
    return out;
  }

 private:
  char peek() const { return pos_ < s_.size() ? s_[pos_] : '\0'; }
  void skip_space() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  bool starts_number() const {
    const char c = peek();
    return std::isdigit(static_cast<unsigned char>(c)) || c == '.';
  }
  [[noreturn]] void fail(std::string_view expected, std::string found = {}) const {
    if (found.empty()) {
      found = pos_ < s_.size() ? "'" + std::string(s_.substr(pos_, 12)) + "'" : "the end";
    } else {
      found = "'" + found + "' again";
    }
    throw InputError(std::string(field_) + ": expected " + std::string(expected) + " at column " +
                     std::to_string(pos_ + 1) + " of '" + std::string(s_) + "', found " + found);
  }
  double number() {
    double v = 0;
    const char* b = s_.data() + pos_;
    const char* e = s_.data() + s_.size();
    // std::from_chars takes no leading '+'.
    const bool plus = *b == '+';
    const auto r = std::from_chars(b + (plus ? 1 : 0), e, v);
    if (r.ec != std::errc() || (plus && b[1] == '-') || !std::isfinite(v)) fail("a finite number");
    pos_ = static_cast<std::size_t>(r.ptr - s_.data());
    return v;
  }
  int component() {
    const std::size_t start = pos_;
    while (pos_ < s_.size() && std::isalnum(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    word_ = s_.substr(start, pos_ - start);
    static constexpr std::array<std::string_view, 4> kNames{"omega", "m", "gamma", "normal"};
    for (int g = 0; g < 4; ++g) {
      for (int i = 0; i < 3; ++i) {
        if (word_ == std::string(kNames[g]) + std::to_string(i + 1)) return 3 * g + i;
      }
    }
    pos_ = start;
    fail(kComponents);
  }

  std::string_view s_, field_, word_;
  std::size_t pos_ = 0;
};

}  // namespace

Surface parse_surface(std::string_view text, std::string_view field) {
  return Parser(text, field).parse();
}

void require_body_surface(const Surface& s, std::string_view field) {
  if (!s.has_normal()) return;
  throw InputError(std::string(field) +
                   ": expected components omega1..3, m1..3, gamma1..3 on a body scenario, found '" +
                   s.text + "' (normal1..3, the orbit normal, only on an orbit scenario)");
}

SurfaceFunction::SurfaceFunction(const Surface& s, const Body& body, bool with_normal) {
  if (!with_normal) require_body_surface(s);
  b_normal = s.a_normal;
  const Vec3 w = s.a_omega.cwiseQuotient(body.inertia());  // a_ω·I⁻¹(m − k)
  b_m = s.a_m + w;
  b_gamma = s.a_gamma;
  d = s.c + w.dot(body.gyrostat());
  // Coefficients near the largest double (1e308*omega1 + 1e308*m1) would make g inf or NaN at
  // ordinary states, and beyond 1e154 its scale() (1e243*omega1 = 0); at most kMaxCoefficient,
  // g and its scale stay finite for |m|, |γ| up to 1e150.
  const double largest = std::max({b_m.lpNorm<Eigen::Infinity>(), b_gamma.lpNorm<Eigen::Infinity>(),
                                   b_normal.lpNorm<Eigen::Infinity>(), std::abs(d)});
  const bool finite =
      b_m.allFinite() && b_gamma.allFinite() && b_normal.allFinite() && std::isfinite(d);
  if (!finite || !(largest <= kMaxCoefficient)) {
    throw InputError("--surface: expected coefficients of at most " +
                     format_number(kMaxCoefficient) +
                     " in the Lie-Poisson variables (a_m + a_omega/I, a_gamma, c + a_omega.k/I), "
                     "found " +
                     format_number(largest) + " for '" + s.text + "' on this body");
  }
}

}  // namespace newtop::phase
