// Closed-form potential of a homogeneous polyhedron (Werner & Scheeres 1997).

#include <cmath>
#include <vector>

#include "newtop/exact/polyhedron.hpp"

namespace newtop {
namespace {

// Faces and edges are summed in blocks of this size; the blocks' partial sums are added in order,
// so the result does not depend on how many threads evaluate the blocks.
constexpr int kBlock = 512;

struct Partial {
  double edge_sum = 0.0, face_sum = 0.0;                    // Σ r·E r L, Σ (n·r)² ω
  Vec3 edge_grad = Vec3::Zero(), face_grad = Vec3::Zero();  // Σ E r L, Σ n (n·r) ω
};

void add_faces(const Polyhedron& p, const Vec3& x, int begin, int end, Partial& s) {
  const auto& V = p.vertices();
  const auto& F = p.faces();
  const auto& N = p.normals();
  for (int f = begin; f < end; ++f) {
    const Vec3 r1 = V[F[f][0]] - x, r2 = V[F[f][1]] - x, r3 = V[F[f][2]] - x;
    const double l1 = r1.norm(), l2 = r2.norm(), l3 = r3.norm();
    const double num = r1.dot(r2.cross(r3));
    const double den = l1 * l2 * l3 + l1 * r2.dot(r3) + l2 * r3.dot(r1) + l3 * r1.dot(r2);
    const double omega = 2.0 * std::atan2(num, den);
    const double nr = N[f].dot(r1);
    s.face_sum += nr * nr * omega;
    s.face_grad += (nr * omega) * N[f];
  }
}

void add_edges(const Polyhedron& p, const Vec3& x, int begin, int end, Partial& s) {
  const auto& V = p.vertices();
  const auto& Ed = p.edges();
  for (int k = begin; k < end; ++k) {
    const auto& e = Ed[k];
    const Vec3 r1 = V[e.i] - x, r2 = V[e.j] - x;
    const double a = r1.norm(), b = r2.norm(), len = (V[e.j] - V[e.i]).norm();
    // a + b − e = 2(ab + r1·r2)/(a + b + e): no cancellation away from the edge itself.
    const double sum = a + b + len;
    const double L = std::log(sum * sum / (2.0 * (a * b + r1.dot(r2))));
    const auto& E = e.E;
    const Vec3 Er{E[0] * r1.x() + E[3] * r1.y() + E[4] * r1.z(),
                  E[3] * r1.x() + E[1] * r1.y() + E[5] * r1.z(),
                  E[4] * r1.x() + E[5] * r1.y() + E[2] * r1.z()};
    s.edge_sum += r1.dot(Er) * L;
    s.edge_grad += L * Er;
  }
}

}  // namespace

Attraction attraction(const Polyhedron& p, const Vec3& x, int threads) {
  const int nf = static_cast<int>(p.faces().size());
  const int ne = static_cast<int>(p.edges().size());
  const int bf = (nf + kBlock - 1) / kBlock, be = (ne + kBlock - 1) / kBlock;
  const int blocks = bf + be;
  std::vector<Partial> part(static_cast<std::size_t>(blocks));
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
  for (int b = 0; b < blocks; ++b) {
    if (b < bf) {
      add_faces(p, x, b * kBlock, std::min(nf, (b + 1) * kBlock), part[b]);
    } else {
      const int c = b - bf;
      add_edges(p, x, c * kBlock, std::min(ne, (c + 1) * kBlock), part[b]);
    }
  }
  Partial t;
  for (const Partial& s : part) {
    t.edge_sum += s.edge_sum;
    t.face_sum += s.face_sum;
    t.edge_grad += s.edge_grad;
    t.face_grad += s.face_grad;
  }
  const double sigma = p.density();
  return {0.5 * sigma * (t.edge_sum - t.face_sum), sigma * (t.face_grad - t.edge_grad)};
}

}  // namespace newtop
