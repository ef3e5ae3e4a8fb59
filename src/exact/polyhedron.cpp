#include "newtop/exact/polyhedron.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>

#include "detail.hpp"
#include "newtop/exact/mass_models.hpp"

namespace newtop {
namespace {

// A triangle is degenerate when twice its area is below this fraction of the squared size of the
// mesh: a few hundred ulps, far below any triangle a shape model intends, far above round-off of
// the cross product of two edges (~4 eps of |a||b|).
constexpr double kDegenerateArea = 256 * std::numeric_limits<double>::epsilon();

std::string edge_name(int i, int j) {
  return "(" + std::to_string(i) + ", " + std::to_string(j) + ")";
}

std::uint64_t key(int i, int j) {
  const auto a = static_cast<std::uint64_t>(std::min(i, j));
  const auto b = static_cast<std::uint64_t>(std::max(i, j));
  return (a << 32) | b;
}

/// Faces sharing each undirected edge (in order of appearance).
using EdgeFaces = std::unordered_map<std::uint64_t, std::vector<int>>;

EdgeFaces edge_faces(const std::vector<Triangle>& faces) {
  EdgeFaces map;
  map.reserve(faces.size() * 2);
  for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
    for (int c = 0; c < 3; ++c) map[key(faces[f][c], faces[f][(c + 1) % 3])].push_back(f);
  }
  return map;
}

/// +1 if face f traverses i → j, −1 if j → i.
int direction(const Triangle& t, int i, int j) {
  for (int c = 0; c < 3; ++c) {
    if (t[c] == i && t[(c + 1) % 3] == j) return 1;
  }
  return -1;
}

void check_faces(const std::vector<Vec3>& v, const std::vector<Triangle>& faces) {
  if (faces.size() < 4) {
    throw InputError("mesh: expected a closed surface of at least 4 triangles, found " +
                     std::to_string(faces.size()));
  }
  Eigen::AlignedBox3d box;
  for (const Triangle& t : faces) {
    for (int c : t) {
      if (c < 0 || c >= static_cast<int>(v.size())) {
        throw InputError("mesh: face vertex index " + std::to_string(c) + " out of range [0, " +
                         std::to_string(v.size()) + ")");
      }
      box.extend(v[c]);
    }
  }
  const double scale2 = box.diagonal().squaredNorm();
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Triangle& t = faces[f];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      throw InputError("mesh: degenerate triangle: face " + std::to_string(f) +
                       " repeats a vertex (" + std::to_string(t[0]) + ", " + std::to_string(t[1]) +
                       ", " + std::to_string(t[2]) + ")");
    }
    const double area2 = (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).norm();
    if (!(area2 > kDegenerateArea * scale2)) {
      throw InputError("mesh: degenerate triangle: face " + std::to_string(f) +
                       " has zero area (collinear vertices " + std::to_string(t[0]) + ", " +
                       std::to_string(t[1]) + ", " + std::to_string(t[2]) + ")");
    }
  }
}

void check_closed(const EdgeFaces& map) {
  for (const auto& [k, fs] : map) {
    if (fs.size() != 2) {
      const int i = static_cast<int>(k >> 32), j = static_cast<int>(k & 0xffffffffu);
      throw InputError("mesh: not a closed manifold surface: edge " + edge_name(i, j) +
                       " belongs to " + std::to_string(fs.size()) + " face(s) (face " +
                       std::to_string(fs[0]) + (fs.size() > 1 ? ", …" : "") +
                       "), expected exactly 2");
    }
  }
}

/// Flips faces so that every shared edge is traversed once each way (breadth-first over each
/// connected component, keeping the component's first face). Returns the number of flips.
int make_consistent(std::vector<Triangle>& faces, const EdgeFaces& map) {
  std::vector<int> state(faces.size(), 0);  // 0 unvisited, 1 visited
  int flips = 0;
  for (std::size_t seed = 0; seed < faces.size(); ++seed) {
    if (state[seed]) continue;
    std::vector<int> queue{static_cast<int>(seed)};
    state[seed] = 1;
    while (!queue.empty()) {
      const int f = queue.back();
      queue.pop_back();
      for (int c = 0; c < 3; ++c) {
        const int i = faces[f][c], j = faces[f][(c + 1) % 3];
        for (int g : map.at(key(i, j))) {
          if (g == f || state[g]) continue;
          if (direction(faces[g], i, j) == 1) {
            std::swap(faces[g][1], faces[g][2]);
            ++flips;
          }
          state[g] = 1;
          queue.push_back(g);
        }
      }
    }
  }
  return flips;
}

void check_consistent(const std::vector<Triangle>& faces, const EdgeFaces& map) {
  for (const auto& [k, fs] : map) {
    const int i = static_cast<int>(k >> 32), j = static_cast<int>(k & 0xffffffffu);
    if (direction(faces[fs[0]], i, j) == direction(faces[fs[1]], i, j)) {
      throw InputError("mesh: inconsistent orientation: faces " + std::to_string(fs[0]) + " and " +
                       std::to_string(fs[1]) + " traverse edge " + edge_name(i, j) +
                       " in the same direction (use reorient = true to fix)");
    }
  }
}

double signed_volume(const std::vector<Vec3>& v, const std::vector<Triangle>& faces) {
  double vol = 0.0;
  for (const Triangle& t : faces) vol += v[t[0]].dot(v[t[1]].cross(v[t[2]]));
  return vol / 6.0;
}

/// σ/24 Σ_f det(a, b, c) (a + b + c) in double-double: every product and sum of the exact vertex
/// coordinates carried error-free, the result rounded once.
Vec3 accurate_first_moment(const std::vector<Vec3>& v, const std::vector<Triangle>& faces,
                           double sigma) {
  using detail::DoubleDouble;
  using detail::two_prod;
  using detail::two_sum;
  DoubleDouble sum[3];
  for (const Triangle& t : faces) {
    const Vec3 &a = v[t[0]], &b = v[t[1]], &c = v[t[2]];
    DoubleDouble det;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const DoubleDouble bxc = two_prod(b[j], c[k]) + -two_prod(b[k], c[j]);
      det = det + DoubleDouble{a[i], 0.0} * bxc;
    }
    for (int i = 0; i < 3; ++i)
      sum[i] = sum[i] + det * (two_sum(a[i], b[i]) + DoubleDouble{c[i], 0.0});
  }
  return sigma / 24.0 * Vec3(sum[0].value(), sum[1].value(), sum[2].value());
}

/// The structure-of-arrays streams of the closed form (Polyhedron::Streams).
Polyhedron::Streams make_streams(const std::vector<Vec3>& v, const std::vector<Triangle>& faces,
                                 const std::vector<Vec3>& normals,
                                 const std::vector<Polyhedron::Edge>& edges) {
  Polyhedron::Streams s;
  for (const Vec3& p : v) {
    s.vx.push_back(p.x());
    s.vy.push_back(p.y());
    s.vz.push_back(p.z());
  }
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Vec3 &a = v[faces[f][0]], &b = v[faces[f][1]], &c = v[faces[f][2]];
    const Vec3& n = normals[f];
    s.fa.push_back(faces[f][0]);
    s.fb.push_back(faces[f][1]);
    s.fc.push_back(faces[f][2]);
    s.nx.push_back(n.x());
    s.ny.push_back(n.y());
    s.nz.push_back(n.z());
    s.h.push_back(n.dot(a));
    s.area2.push_back((b - a).cross(c - a).norm());
    s.bc2.push_back((c - b).squaredNorm());
    s.ca2.push_back((a - c).squaredNorm());
    s.ab2.push_back((b - a).squaredNorm());
  }
  for (const Polyhedron::Edge& e : edges) {
    const auto& E = e.E;
    const Vec3& a = v[e.i];
    const Vec3 c{E[0] * a.x() + E[3] * a.y() + E[4] * a.z(),
                 E[3] * a.x() + E[1] * a.y() + E[5] * a.z(),
                 E[4] * a.x() + E[5] * a.y() + E[2] * a.z()};
    s.ei.push_back(e.i);
    s.ej.push_back(e.j);
    s.length.push_back(e.length);
    for (int m = 0; m < 6; ++m) s.E[m].push_back(E[m]);
    s.cx.push_back(c.x());
    s.cy.push_back(c.y());
    s.cz.push_back(c.z());
    s.k.push_back(a.dot(c));
  }
  return s;
}

}  // namespace

void Polyhedron::check_mass_properties(const Polyhedron& p) {
  if (!std::isfinite(p.volume_)) {
    throw InputError("mesh: the volume overflows (" + format_number(p.volume_) +
                     "): vertex coordinates too large");
  }
  const MassProperties mp = mass_properties(p);
  if (!std::isfinite(mp.mass)) {
    throw InputError("density: the mass density * volume overflows (" + format_number(p.density_) +
                     " * " + format_number(p.volume_) + ")");
  }
  if (!mp.inertia_tensor.allFinite() || !mp.center_of_mass.allFinite()) {
    throw InputError("mesh: the inertia tensor overflows (mass " + format_number(mp.mass) +
                     "): vertex coordinates or density too large");
  }
}

Polyhedron Polyhedron::make(std::vector<Vec3> vertices, std::vector<Triangle> faces, double density,
                            Orientation orientation) {
  if (!std::isfinite(density) || !(density > 0)) {
    throw InputError("density: expected a finite number > 0, found " + format_number(density));
  }
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (!vertices[i].allFinite()) {
      throw InputError("mesh: vertex " + std::to_string(i) +
                       ": expected finite coordinates, found " + format_vector(vertices[i]));
    }
  }
  check_faces(vertices, faces);
  const EdgeFaces map = edge_faces(faces);
  check_closed(map);
  Polyhedron p;
  if (orientation == Orientation::reorient) p.flipped_ = make_consistent(faces, map);
  check_consistent(faces, map);
  double vol = signed_volume(vertices, faces);
  if (vol < 0 && orientation == Orientation::reorient) {
    for (Triangle& t : faces) std::swap(t[1], t[2]);
    p.flipped_ = static_cast<int>(faces.size()) - p.flipped_;
    vol = -vol;
  }
  if (!(vol > 0)) {
    throw InputError("mesh: inward orientation: the signed volume is " + format_number(vol) +
                     " (expected > 0 with outward normals; use reorient = true to fix)");
  }
  // Drop unused vertices and renumber.
  std::vector<int> index(vertices.size(), -1);
  for (Triangle& t : faces) {
    for (int& c : t) {
      if (index[c] < 0) {
        index[c] = static_cast<int>(p.vertices_.size());
        p.vertices_.push_back(vertices[c]);
      }
      c = index[c];
    }
  }
  p.faces_ = std::move(faces);
  p.density_ = density;
  p.volume_ = vol;
  for (const Triangle& t : p.faces_) {
    const Vec3& a = p.vertices_[t[0]];
    p.normals_.push_back((p.vertices_[t[1]] - a).cross(p.vertices_[t[2]] - a).normalized());
  }
  for (const auto& [k, fs] : edge_faces(p.faces_)) {
    int i = static_cast<int>(k >> 32), j = static_cast<int>(k & 0xffffffffu);
    int A = fs[0], B = fs[1];
    if (direction(p.faces_[A], i, j) != 1) std::swap(A, B);  // A traverses i → j, B j → i
    const Vec3 d = p.vertices_[j] - p.vertices_[i];
    const Vec3 nA = p.normals_[A], nB = p.normals_[B];
    const Mat3 E0 =
        nA * d.cross(nA).normalized().transpose() + nB * (-d).cross(nB).normalized().transpose();
    const Mat3 E = 0.5 * (E0 + E0.transpose());
    p.edges_.push_back({i, j, d.norm(), {E(0, 0), E(1, 1), E(2, 2), E(0, 1), E(0, 2), E(1, 2)}});
  }
  // A fixed edge order (the hash map's order is unspecified) keeps results reproducible.
  std::sort(p.edges_.begin(), p.edges_.end(),
            [](const Edge& a, const Edge& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
  p.streams_ = make_streams(p.vertices_, p.faces_, p.normals_, p.edges_);
  p.first_moment_ = accurate_first_moment(p.vertices_, p.faces_, density);
  check_mass_properties(p);
  return p;
}

}  // namespace newtop
