// Closed-form potential of a homogeneous polyhedron (Werner & Scheeres 1997).

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "detail.hpp"
#include "newtop/exact/polyhedron.hpp"

// Vector variants of atan2 and log in glibc's libmvec (x86-64, glibc ≥ 2.35): declared here so that
// the `omp simd` loops below call them (glibc's own headers declare them only under -ffast-math).
#if defined(__x86_64__) && defined(__GLIBC__) && !defined(__clang__)
#include <immintrin.h>
#define NEWTOP_X86_KERNELS 1
#define NEWTOP_KERNEL __attribute__((target_clones("avx512f", "avx2", "default")))
extern "C" {
#pragma omp declare simd notinbranch
double atan2(double, double) noexcept;
#pragma omp declare simd notinbranch
double log(double) noexcept;
}
#else
#define NEWTOP_X86_KERNELS 0
#define NEWTOP_KERNEL
#endif

namespace newtop {
namespace {

// Faces and edges are summed in blocks of this size; the blocks' partial sums are added in order,
// so the result does not depend on how many threads evaluate the blocks.
constexpr int kBlock = 512;

/// The sums of the closed form over a block (symmetric 3 × 3 as xx, yy, zz, xy, xz, yz).
struct Partial {
  double face_sum = 0.0;     // Σ_f (n·r)² ω
  double face_grad[3] = {};  // Σ_f n (n·r) ω
  double face_hess[6] = {};  // Σ_f ω n nᵀ (when asked)
  double edge_k = 0.0;       // Σ_e L k
  double edge_c[3] = {};     // Σ_e L c
  double edge_E[6] = {};     // Σ_e L E
};

// Each block is two `omp simd` loops over contiguous streams (Polyhedron::Streams): the first
// computes the solid angles or edge factors, gathering only the distances |r| of the vertices
// (computed once per evaluation); GCC maps its atan2 or log to glibc's vector math (libmvec,
// ≤ 4 ulp), four or eight at a time in the AVX2 and AVX-512 clones. The second accumulates the
// sums, each lane its own partial sums added in a fixed order, in registers that no call clobbers
// (docs/performance.md).

/// ω_f = 2 atan2(r_a·(r_b × r_c), |r_a||r_b||r_c| + |r_a| r_b·r_c + |r_b| r_c·r_a + |r_c| r_a·r_b).
NEWTOP_KERNEL void add_faces(const Polyhedron::Streams& S, const double* len, const Vec3& x,
                             int begin, int end, bool hessian, Partial& s) {
  const double x0 = x.x(), x1 = x.y(), x2 = x.z();
  const int *fa = S.fa.data() + begin, *fb = S.fb.data() + begin, *fc = S.fc.data() + begin;
  const double *nx = S.nx.data() + begin, *ny = S.ny.data() + begin, *nz = S.nz.data() + begin;
  const double *h = S.h.data() + begin, *area2 = S.area2.data() + begin;
  const double *bc2 = S.bc2.data() + begin, *ca2 = S.ca2.data() + begin,
               *ab2 = S.ab2.data() + begin;
  const int n = end - begin;
  double nr[kBlock], omega[kBlock];
#pragma omp simd
  for (int q = 0; q < n; ++q) {
    const double la = len[fa[q]], lb = len[fb[q]], lc = len[fc[q]];
    nr[q] = h[q] - (nx[q] * x0 + ny[q] * x1 + nz[q] * x2);  // n·r
    const double bc = 0.5 * (lb * lb + lc * lc - bc2[q]);   // r_b·r_c
    const double ca = 0.5 * (lc * lc + la * la - ca2[q]);
    const double ab = 0.5 * (la * la + lb * lb - ab2[q]);
    const double den = la * lb * lc + la * bc + lb * ca + lc * ab;
    omega[q] = 2.0 * atan2(area2[q] * nr[q], den);
  }
  double sum = 0, g0 = 0, g1 = 0, g2 = 0;
#pragma omp simd reduction(+ : sum, g0, g1, g2)
  for (int q = 0; q < n; ++q) {
    const double w = nr[q] * omega[q];
    sum += nr[q] * w;
    g0 += w * nx[q];
    g1 += w * ny[q];
    g2 += w * nz[q];
  }
  s.face_sum = sum;
  s.face_grad[0] = g0, s.face_grad[1] = g1, s.face_grad[2] = g2;
  if (!hessian) return;
  double t0 = 0, t1 = 0, t2 = 0, t3 = 0, t4 = 0, t5 = 0;
#pragma omp simd reduction(+ : t0, t1, t2, t3, t4, t5)
  for (int q = 0; q < n; ++q) {
    t0 += omega[q] * nx[q] * nx[q];
    t1 += omega[q] * ny[q] * ny[q];
    t2 += omega[q] * nz[q] * nz[q];
    t3 += omega[q] * nx[q] * ny[q];
    t4 += omega[q] * nx[q] * nz[q];
    t5 += omega[q] * ny[q] * nz[q];
  }
  s.face_hess[0] = t0, s.face_hess[1] = t1, s.face_hess[2] = t2;
  s.face_hess[3] = t3, s.face_hess[4] = t4, s.face_hess[5] = t5;
}

/// L_e = ln((a + b + e)/(a + b − e)), a = |r_i|, b = |r_j|, e the edge's length.
NEWTOP_KERNEL void add_edges(const Polyhedron::Streams& S, const double* len, int begin, int end,
                             Partial& s) {
  const int *ei = S.ei.data() + begin, *ej = S.ej.data() + begin;
  const double *length = S.length.data() + begin, *k = S.k.data() + begin;
  const double *cx = S.cx.data() + begin, *cy = S.cy.data() + begin, *cz = S.cz.data() + begin;
  const double *E0 = S.E[0].data() + begin, *E1 = S.E[1].data() + begin,
               *E2 = S.E[2].data() + begin, *E3 = S.E[3].data() + begin,
               *E4 = S.E[4].data() + begin, *E5 = S.E[5].data() + begin;
  const int n = end - begin;
  double L[kBlock];
#pragma omp simd
  for (int q = 0; q < n; ++q) {
    const double a = len[ei[q]], b = len[ej[q]];
    L[q] = log((a + b + length[q]) / (a + b - length[q]));
  }
  double sk = 0, c0 = 0, c1 = 0, c2 = 0, t0 = 0, t1 = 0, t2 = 0, t3 = 0, t4 = 0, t5 = 0;
#pragma omp simd reduction(+ : sk, c0, c1, c2, t0, t1, t2, t3, t4, t5)
  for (int q = 0; q < n; ++q) {
    sk += L[q] * k[q];
    c0 += L[q] * cx[q];
    c1 += L[q] * cy[q];
    c2 += L[q] * cz[q];
    t0 += L[q] * E0[q];
    t1 += L[q] * E1[q];
    t2 += L[q] * E2[q];
    t3 += L[q] * E3[q];
    t4 += L[q] * E4[q];
    t5 += L[q] * E5[q];
  }
  s.edge_k = sk;
  s.edge_c[0] = c0, s.edge_c[1] = c1, s.edge_c[2] = c2;
  s.edge_E[0] = t0, s.edge_E[1] = t1, s.edge_E[2] = t2;
  s.edge_E[3] = t3, s.edge_E[4] = t4, s.edge_E[5] = t5;
}

/// |v − x| for the vertices [begin, end).
void distances_scalar(const Polyhedron::Streams& S, const Vec3& x, int begin, int end,
                      double* len) {
  for (int v = begin; v < end; ++v) {
    const double r0 = S.vx[v] - x.x(), r1 = S.vy[v] - x.y(), r2 = S.vz[v] - x.z();
    len[v] = std::sqrt(r0 * r0 + r1 * r1 + r2 * r2);
  }
}

#if NEWTOP_X86_KERNELS
// GCC does not vectorise std::sqrt unless errno is off (-fno-math-errno), and a sum of squares
// never sets it: these take the square roots four or eight at a time with the instruction itself.
[[gnu::target("avx512f")]] void distances_avx512(const Polyhedron::Streams& S, const Vec3& x,
                                                 int begin, int end, double* len) {
  const __m512d x0 = _mm512_set1_pd(x.x()), x1 = _mm512_set1_pd(x.y()), x2 = _mm512_set1_pd(x.z());
  int v = begin;
  for (; v + 8 <= end; v += 8) {
    const __m512d r0 = _mm512_sub_pd(_mm512_loadu_pd(&S.vx[v]), x0);
    const __m512d r1 = _mm512_sub_pd(_mm512_loadu_pd(&S.vy[v]), x1);
    const __m512d r2 = _mm512_sub_pd(_mm512_loadu_pd(&S.vz[v]), x2);
    const __m512d q = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(r0, r0), _mm512_mul_pd(r1, r1)),
                                    _mm512_mul_pd(r2, r2));
    _mm512_storeu_pd(&len[v], _mm512_sqrt_pd(q));
  }
  distances_scalar(S, x, v, end, len);
}

[[gnu::target("avx2")]] void distances_avx2(const Polyhedron::Streams& S, const Vec3& x, int begin,
                                            int end, double* len) {
  const __m256d x0 = _mm256_set1_pd(x.x()), x1 = _mm256_set1_pd(x.y()), x2 = _mm256_set1_pd(x.z());
  int v = begin;
  for (; v + 4 <= end; v += 4) {
    const __m256d r0 = _mm256_sub_pd(_mm256_loadu_pd(&S.vx[v]), x0);
    const __m256d r1 = _mm256_sub_pd(_mm256_loadu_pd(&S.vy[v]), x1);
    const __m256d r2 = _mm256_sub_pd(_mm256_loadu_pd(&S.vz[v]), x2);
    const __m256d q = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(r0, r0), _mm256_mul_pd(r1, r1)),
                                    _mm256_mul_pd(r2, r2));
    _mm256_storeu_pd(&len[v], _mm256_sqrt_pd(q));
  }
  distances_scalar(S, x, v, end, len);
}
#endif

void distances(const Polyhedron::Streams& S, const Vec3& x, int begin, int end, double* len) {
#if NEWTOP_X86_KERNELS
  static const bool avx512 = __builtin_cpu_supports("avx512f");
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (avx512) return distances_avx512(S, x, begin, end, len);
  if (avx2) return distances_avx2(S, x, begin, end, len);
#endif
  distances_scalar(S, x, begin, end, len);
}

Mat3 symmetric(const double (&m)[6]) {
  Mat3 a;
  a << m[0], m[3], m[4], m[3], m[1], m[5], m[4], m[5], m[2];
  return a;
}

/// The sums of the closed form over all faces and edges, in fixed blocks added in order.
struct FaceEdgeSums {
  double edge_sum, face_sum;  // Σ_e r·E r L, Σ_f (n·r)² ω
  Vec3 edge_grad, face_grad;  // Σ_e E r L, Σ_f n (n·r) ω
  Mat3 edge_hess, face_hess;  // Σ_e E L, Σ_f n nᵀ ω (the latter when asked)
};

FaceEdgeSums sums(const Polyhedron& p, const Vec3& x, int threads, bool hessian) {
  const Polyhedron::Streams& S = p.streams();
  const int nf = static_cast<int>(S.fa.size());
  const int ne = static_cast<int>(S.ei.size());
  const int nv = static_cast<int>(S.vx.size());
  const int bv = (nv + kBlock - 1) / kBlock;
  const int bf = (nf + kBlock - 1) / kBlock, be = (ne + kBlock - 1) / kBlock;
  const int blocks = bf + be;
  std::vector<Partial> part(static_cast<std::size_t>(blocks));
  const auto len = std::make_unique_for_overwrite<double[]>(static_cast<std::size_t>(nv));
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
#pragma omp for schedule(static)
    for (int b = 0; b < bv; ++b)
      distances(S, x, b * kBlock, std::min(nv, (b + 1) * kBlock), len.get());
#pragma omp for schedule(static)
    for (int b = 0; b < blocks; ++b) {
      if (b < bf) {
        add_faces(S, len.get(), x, b * kBlock, std::min(nf, (b + 1) * kBlock), hessian, part[b]);
      } else {
        const int c = b - bf;
        add_edges(S, len.get(), c * kBlock, std::min(ne, (c + 1) * kBlock), part[b]);
      }
    }
  }
  Partial t;
  for (const Partial& s : part) {
    t.face_sum += s.face_sum;
    t.edge_k += s.edge_k;
    for (int i = 0; i < 3; ++i) t.face_grad[i] += s.face_grad[i], t.edge_c[i] += s.edge_c[i];
    for (int i = 0; i < 6; ++i) t.face_hess[i] += s.face_hess[i], t.edge_E[i] += s.edge_E[i];
  }
  const Vec3 c(t.edge_c[0], t.edge_c[1], t.edge_c[2]);
  const Mat3 E = symmetric(t.edge_E);
  const Vec3 Ex = E * x;
  // Σ L (c − E x) and Σ L (k − 2 c·x + x·E x).
  return {t.edge_k - 2.0 * c.dot(x) + x.dot(Ex),
          t.face_sum,
          c - Ex,
          Vec3(t.face_grad[0], t.face_grad[1], t.face_grad[2]),
          E,
          symmetric(t.face_hess)};
}

}  // namespace

Attraction attraction(const Polyhedron& p, const Vec3& x, int threads) {
  const FaceEdgeSums t = sums(p, x, threads, false);
  const double sigma = p.density();
  const Vec3 grad = sigma * (t.face_grad - t.edge_grad);
  return {0.5 * sigma * (t.edge_sum - t.face_sum), grad, grad.cross(x)};
}

GravityGradient gravity_gradient(const Polyhedron& p, const Vec3& x, int threads) {
  const FaceEdgeSums t = sums(p, x, threads, true);
  const double sigma = p.density();
  const Vec3 grad = sigma * (t.face_grad - t.edge_grad);
  GravityGradient g;
  g.tensor = sigma * (t.edge_hess - t.face_hess);
  g.moment_jacobian = detail::cross_matrix(grad) - detail::cross_matrix(x) * g.tensor;
  return g;
}

}  // namespace newtop
