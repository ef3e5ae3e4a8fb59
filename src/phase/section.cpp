// Poincaré sections: directions, coordinates on the section, the integrals' drift and the seeded
// orbits of a phase portrait (section.hpp).

#include "newtop/phase/section.hpp"

#include <cmath>
#include <numbers>
#include <optional>

#include "newtop/model/model.hpp"

namespace newtop::phase {

const char* to_string(Direction d) {
  switch (d) {
    case Direction::up:
      return "up";
    case Direction::down:
      return "down";
    default:
      return "both";
  }
}

Direction parse_direction(std::string_view s, std::string_view field) {
  if (s == "up") return Direction::up;
  if (s == "down") return Direction::down;
  if (s == "both") return Direction::both;
  throw InputError(std::string(field) + ": expected up, down or both, found '" + std::string(s) +
                   "'");
}

namespace {

/// The angle from a to b about the axis k (k ⟂ a, b); 0 when a or b vanishes.
double angle_about(const Vec3& a, const Vec3& b, const Vec3& k) {
  if (a.squaredNorm() == 0.0 || b.squaredNorm() == 0.0) return 0.0;
  return std::atan2(k.dot(a.cross(b)), a.dot(b));
}

}  // namespace

AndoyerDeprit andoyer_deprit(const State& x) {
  AndoyerDeprit v;
  v.G = x.m.norm();
  v.L = x.m[2];
  v.H = x.m.dot(x.gamma);
  v.l = (x.m[0] == 0.0 && x.m[1] == 0.0) ? 0.0 : std::atan2(x.m[0], x.m[1]);
  if (v.G > 0) {
    const Vec3 k = x.m / v.G;
    v.g = angle_about(x.gamma.cross(k), Vec3::UnitZ().cross(k), k);
  }
  return v;
}

int gamma_plane_axis(const Surface& s) {
  if (!s.of_gamma_only()) return -1;
  int axis = -1;
  for (int i = 0; i < 3; ++i) {
    if (s.a_gamma[i] == 0.0) continue;
    if (axis >= 0) return -1;
    axis = i;
  }
  return axis;
}

namespace {

/// The root a of α a² + 2β a + (κ − h) = 0 that makes g cross in the kept direction (ġ(a) of that
/// sign; the larger root first), or none.
template <class Rate>
std::optional<double> crossing_root(double alpha, double beta, double kappa_minus_h,
                                    Direction direction, Rate&& rate) {
  const double disc = beta * beta - alpha * kappa_minus_h;
  if (!(disc >= 0.0) || !(alpha > 0.0)) return std::nullopt;
  const double root = std::sqrt(disc);
  for (const double a : {(-beta + root) / alpha, (-beta - root) / alpha}) {
    const double r = rate(a);
    if (direction == Direction::both || (direction == Direction::up ? r > 0.0 : r < 0.0)) return a;
  }
  return std::nullopt;
}

/// Seeds on a surface with a momentum term (b_m ≠ 0; docs/section.md): γ over a Fibonacci
/// lattice of the sphere; for each, m on the line {b_m·m + b_γ·γ = d, m·γ = f}, m = m0 + a t with
/// t ∥ b_m × γ, and a a root of the energy equation crossing in the kept direction; K of the
/// seeds found, evenly spread over the lattice's order.
std::vector<State> seed_momentum_surface(const Model& model, const SurfaceFunction& g,
                                         const Levels& levels, int K, Direction direction) {
  const Body& body = model.body();
  const Vec3 inv_i = body.inertia().cwiseInverse();
  const int lattice = 64 * K;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  std::vector<State> found;
  for (int j = 0; j < lattice; ++j) {
    const double z = 1.0 - (2.0 * j + 1.0) / lattice;
    const double r = std::sqrt((1.0 - z) * (1.0 + z));
    const Vec3 gamma(r * std::cos(golden * j), r * std::sin(golden * j), z);
    const Vec3 normal = g.b_m.cross(gamma);
    if (!(normal.norm() > 1e-8 * g.b_m.norm())) continue;  // b_m ∥ γ: no line
    const Vec3 t = normal.normalized();
    // m0 = x b_m + y γ with b_m·m0 = d − b_γ·γ and γ·m0 = f (γ·γ = 1).
    const double bb = g.b_m.squaredNorm(), bg = g.b_m.dot(gamma);
    const double rhs1 = g.d - g.b_gamma.dot(gamma), rhs2 = levels.area;
    const double det = bb - bg * bg;
    const Vec3 m0 = ((rhs1 - bg * rhs2) / det) * g.b_m + ((bb * rhs2 - bg * rhs1) / det) * gamma;
    const Vec3 u = m0 - body.gyrostat();
    const double alpha = 0.5 * t.dot(inv_i.cwiseProduct(t));
    const double beta = 0.5 * t.dot(inv_i.cwiseProduct(u));
    const double kappa = 0.5 * u.dot(inv_i.cwiseProduct(u)) + potential(model, gamma);
    auto rate = [&](double a) {
      const State d = rhs(model, State{m0 + a * t, gamma});
      return g.b_m.dot(d.m) + g.b_gamma.dot(d.gamma);
    };
    if (const auto a = crossing_root(alpha, beta, kappa - levels.energy, direction, rate)) {
      found.push_back({m0 + *a * t, gamma});
    }
  }
  if (static_cast<int>(found.size()) <= K) return found;
  std::vector<State> seeds;
  for (int j = 0; j < K; ++j) {
    seeds.push_back(
        found[static_cast<std::size_t>((j + 0.5) * static_cast<double>(found.size()) / K)]);
  }
  return seeds;
}

}  // namespace

std::vector<State> seed_orbits(const Model& model, const Surface& surface, const Levels& levels,
                               int K, Direction direction) {
  if (K < 1) throw InputError("--orbits: expected an integer >= 1, found " + std::to_string(K));
  const SurfaceFunction g(surface, model.body());
  if (!g.b_m.isZero(0.0)) return seed_momentum_surface(model, g, levels, K, direction);
  const Body& body = model.body();
  const double norm = surface.a_gamma.norm();
  const Vec3 n = surface.a_gamma / norm;
  const double dist = surface.c / norm;  // the plane n·γ = dist
  std::vector<State> seeds;
  if (!(std::abs(dist) < 1.0)) return seeds;  // the plane misses the sphere: an empty level
  const double rho = std::sqrt((1.0 - dist) * (1.0 + dist));
  // An orthonormal basis (e1, e2) of the plane normal to n.
  const Vec3 e1 = n.unitOrthogonal(), e2 = n.cross(e1);
  const Vec3 inv_i = body.inertia().cwiseInverse();
  for (int j = 0; j < K; ++j) {
    const double phi = 2.0 * std::numbers::pi * (j + 0.5) / K;
    Vec3 gamma = dist * n + rho * (std::cos(phi) * e1 + std::sin(phi) * e2);
    gamma.normalize();
    const Vec3 t = n.cross(gamma).normalized();  // along the circle; ⟂ γ
    // ½(u + a t)·I⁻¹(u + a t) + V(γ) = h with u = f γ − k: α a² + 2β a + (κ − h) = 0.
    const Vec3 u = levels.area * gamma - body.gyrostat();
    const double alpha = 0.5 * t.dot(inv_i.cwiseProduct(t));
    const double beta = 0.5 * t.dot(inv_i.cwiseProduct(u));
    const double kappa = 0.5 * u.dot(inv_i.cwiseProduct(u)) + potential(model, gamma);
    const double disc = beta * beta - alpha * (kappa - levels.energy);
    if (!(disc >= 0.0)) continue;
    // dg/dt = ω·(a_γ × γ) = |a_γ| ρ' (2β + 2α a) has the sign of ±√disc at the roots.
    const double root = std::sqrt(disc);
    const double a = (direction == Direction::down ? -beta - root : -beta + root) / alpha;
    seeds.push_back({u + body.gyrostat() + a * t, gamma});
  }
  return seeds;
}

}  // namespace newtop::phase
