// Closed-form potential of a homogeneous polyhedron (Werner & Scheeres 1997).

#include <cmath>
#include <vector>

#include "detail.hpp"
#include "newtop/exact/polyhedron.hpp"

// Vector variants of atan2 and log in glibc's libmvec (x86-64, glibc ≥ 2.35): declared here so that
// the `omp simd` loops below call them (glibc's own headers declare them only under -ffast-math).
#if defined(__x86_64__) && defined(__GLIBC__) && !defined(__clang__)
#define NEWTOP_KERNEL __attribute__((target_clones("avx512f", "avx2", "default")))
extern "C" {
#pragma omp declare simd notinbranch
double atan2(double, double) noexcept;
#pragma omp declare simd notinbranch
double log(double) noexcept;
}
#else
#define NEWTOP_KERNEL
#endif

namespace newtop {
namespace {

// Faces and edges are summed in blocks of this size; the blocks' partial sums are added in order,
// so the result does not depend on how many threads evaluate the blocks.
constexpr int kBlock = 512;

struct Partial {
  double edge_sum = 0.0, face_sum = 0.0;                    // Σ r·E r L, Σ (n·r)² ω
  Vec3 edge_grad = Vec3::Zero(), face_grad = Vec3::Zero();  // Σ E r L, Σ n (n·r) ω
  Mat3 edge_hess = Mat3::Zero(), face_hess = Mat3::Zero();  // Σ E L, Σ n nᵀ ω (when asked)
};

/// Vertex positions relative to the field point, r = v − x, and their lengths, computed once per
/// evaluation (each vertex is shared by about six faces and six edges).
struct Relative {
  std::vector<Vec3> r;
  std::vector<double> len;
};

// The solid angles and edge factors are computed in three passes per block: geometry into small
// arrays, then atan2 / log over the arrays in `omp simd` loops, which GCC maps to glibc's vector
// math (libmvec, ≤ 4 ulp), then the sums. The transcendental functions dominate the cost; the
// AVX2 clone runs them four at a time where the processor has it (docs/performance.md).
NEWTOP_KERNEL void add_faces(const Polyhedron& p, const Relative& rel, int begin, int end,
                             bool hessian, Partial& s) {
  const auto& F = p.faces();
  const auto& N = p.normals();
  double num[kBlock], den[kBlock], nr[kBlock], omega[kBlock];
  const int n = end - begin;
  for (int q = 0; q < n; ++q) {
    const int f = begin + q;
    const auto [i1, i2, i3] = F[f];
    const Vec3 &r1 = rel.r[i1], &r2 = rel.r[i2], &r3 = rel.r[i3];
    const double l1 = rel.len[i1], l2 = rel.len[i2], l3 = rel.len[i3];
    num[q] = r1.dot(r2.cross(r3));
    den[q] = l1 * l2 * l3 + l1 * r2.dot(r3) + l2 * r3.dot(r1) + l3 * r1.dot(r2);
    nr[q] = N[f].dot(r1);
  }
#pragma omp simd
  for (int q = 0; q < n; ++q) omega[q] = 2.0 * atan2(num[q], den[q]);
  for (int q = 0; q < n; ++q) {
    s.face_sum += nr[q] * nr[q] * omega[q];
    s.face_grad += (nr[q] * omega[q]) * N[begin + q];
  }
  if (!hessian) return;
  for (int q = 0; q < n; ++q) s.face_hess += omega[q] * (N[begin + q] * N[begin + q].transpose());
}

NEWTOP_KERNEL void add_edges(const Polyhedron& p, const Relative& rel, int begin, int end,
                             bool hessian, Partial& s) {
  const auto& Ed = p.edges();
  double arg[kBlock], L[kBlock];
  const int n = end - begin;
  for (int q = 0; q < n; ++q) {
    const auto& e = Ed[begin + q];
    const Vec3 &r1 = rel.r[e.i], &r2 = rel.r[e.j];
    const double a = rel.len[e.i], b = rel.len[e.j];
    // a + b − e = 2(ab + r1·r2)/(a + b + e): no cancellation away from the edge itself.
    const double sum = a + b + e.length;
    arg[q] = sum * sum / (2.0 * (a * b + r1.dot(r2)));
  }
#pragma omp simd
  for (int q = 0; q < n; ++q) L[q] = log(arg[q]);
  for (int q = 0; q < n; ++q) {
    const auto& e = Ed[begin + q];
    const Vec3& r1 = rel.r[e.i];
    const auto& E = e.E;
    const Vec3 Er{E[0] * r1.x() + E[3] * r1.y() + E[4] * r1.z(),
                  E[3] * r1.x() + E[1] * r1.y() + E[5] * r1.z(),
                  E[4] * r1.x() + E[5] * r1.y() + E[2] * r1.z()};
    s.edge_sum += r1.dot(Er) * L[q];
    s.edge_grad += L[q] * Er;
  }
  if (!hessian) return;
  for (int q = 0; q < n; ++q) {
    const auto& E = Ed[begin + q].E;
    Mat3 m;
    m << E[0], E[3], E[4], E[3], E[1], E[5], E[4], E[5], E[2];
    s.edge_hess += L[q] * m;
  }
}

/// The sums of the closed form over all faces and edges, in fixed blocks added in order.
Partial sums(const Polyhedron& p, const Vec3& x, int threads, bool hessian) {
  const int nf = static_cast<int>(p.faces().size());
  const int ne = static_cast<int>(p.edges().size());
  const int bf = (nf + kBlock - 1) / kBlock, be = (ne + kBlock - 1) / kBlock;
  const int blocks = bf + be;
  std::vector<Partial> part(static_cast<std::size_t>(blocks));
  const int nv = static_cast<int>(p.vertices().size());
  Relative rel{std::vector<Vec3>(nv), std::vector<double>(nv)};
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
#pragma omp for schedule(static)
    for (int v = 0; v < nv; ++v) {
      rel.r[v] = p.vertices()[v] - x;
      rel.len[v] = rel.r[v].norm();
    }
#pragma omp for schedule(static)
    for (int b = 0; b < blocks; ++b) {
      if (b < bf) {
        add_faces(p, rel, b * kBlock, std::min(nf, (b + 1) * kBlock), hessian, part[b]);
      } else {
        const int c = b - bf;
        add_edges(p, rel, c * kBlock, std::min(ne, (c + 1) * kBlock), hessian, part[b]);
      }
    }
  }
  Partial t;
  for (const Partial& s : part) {
    t.edge_sum += s.edge_sum;
    t.face_sum += s.face_sum;
    t.edge_grad += s.edge_grad;
    t.face_grad += s.face_grad;
    t.edge_hess += s.edge_hess;
    t.face_hess += s.face_hess;
  }
  return t;
}

}  // namespace

Attraction attraction(const Polyhedron& p, const Vec3& x, int threads) {
  const Partial t = sums(p, x, threads, false);
  const double sigma = p.density();
  const Vec3 grad = sigma * (t.face_grad - t.edge_grad);
  return {0.5 * sigma * (t.edge_sum - t.face_sum), grad, grad.cross(x)};
}

GravityGradient gravity_gradient(const Polyhedron& p, const Vec3& x, int threads) {
  const Partial t = sums(p, x, threads, true);
  const double sigma = p.density();
  const Vec3 grad = sigma * (t.face_grad - t.edge_grad);
  GravityGradient g;
  g.tensor = sigma * (t.edge_hess - t.face_hess);
  g.moment_jacobian = detail::cross_matrix(grad) - detail::cross_matrix(x) * g.tensor;
  return g;
}

}  // namespace newtop
