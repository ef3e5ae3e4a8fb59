#pragma once
/// \file
/// The lockstep kernel of the ensemble stepper (include/newtop/integrate/ensemble.hpp), private to
/// src/integrate. One step is a program of stages (kick, rotation about a working axis, spin,
/// exact free-body flow) with its constants computed once, exactly as the scalar stepper computes
/// them; the kernel runs it on blocks of points held in vector registers, one lane per point.
///
/// Every lane performs the operations of the scalar sub-flows (sub_flows.hpp, splitting.hpp) in
/// the same order on the same operands, without fused multiply-adds (these files are compiled with
/// -ffp-contract=off), so a point's result is the scalar stepper's bit for bit whatever its lane.
/// The rare lane outside the short Taylor series of sin θ, cos θ − 1 (θ² > 1e-4) is recomputed by
/// the scalar functions themselves (ensemble_sin_cosm1, ensemble_spin_factors), as is the exact
/// free-body flow.
///
/// The kernel is compiled once per instruction set (ensemble_portable.cpp, ensemble_avx2.cpp,
/// ensemble_avx512.cpp). Everything below that generates code lives in an unnamed namespace, so
/// that no function compiled for AVX2 or AVX-512 can be merged into, and run on behalf of, another
/// translation unit; the kernels call no inline function of another header.

#include <cstddef>
#include <cstdint>

namespace newtop {
class Body;
}

namespace newtop::detail {

enum class EnsembleOp : std::uint8_t { kick, rotate0, rotate1, rotate2, spin, exact };

/// One stage of a step: kick (m += t γ × ∂V/∂γ; a = t), rotation about working axis I (θ = m_I a +
/// b), spin (a = τ), exact free-body flow (a = t). With a model per lane the constants of the
/// model are the lane's and a stage holds the times they multiply, as the scalar flows multiply
/// them: rotation θ = m_I (a rate_I) + b k_over_i_I (θ = m_I a + b k_over_i_I when `fixed`), spin
/// τ = a inv_ref.
struct EnsembleStage {
  EnsembleOp op;
  double a;
  double b;
  bool fixed = false;
};

/// The per-lane constants of a model (SplitFrame's and the kick's), in the working frame.
enum LaneConstant : int {
  kLaneRate = 0,      // + w: rate[w]
  kLaneKOverI = 3,    // + w: k_over_i[w]
  kLaneInvRef = 6,    // inv_ref
  kLaneGrad0 = 7,     // + w: grad0[w]
  kLaneLambda = 10,   // λ
  kLaneInertia = 11,  // + w: inertia[w]
  kLaneConstants = 14
};

/// What a kernel works on: points in the working frame of the split as six arrays of n numbers
/// (n a multiple of the kernel's block), advanced by `steps` steps of the program.
struct EnsembleTask {
  const EnsembleStage* stages;
  std::size_t stage_count;
  /// The kick's field in the working frame: ∂V/∂γ_w = grad0[w] + lambda (inertia[w] γ_w).
  double grad0[3];
  double lambda;
  double inertia[3];
  const Body* body;  ///< for the exact free-body flow (working frame = body frame)
  /// A model per lane: its constants by LaneConstant (n numbers each; grad0, lambda, inertia and
  /// body above are then unused) and its body; all null: the one model above.
  const double* lane[kLaneConstants];
  const Body* const* bodies;
  double* m[3];
  double* g[3];
  std::size_t n;
  std::int64_t steps;
};

/// The scalar functions of sub_flows.hpp and splitting.hpp, compiled without target options
/// (ensemble.cpp), for the lanes the vector code leaves to them.
void ensemble_sin_cosm1(double theta, double& s, double& cm1);
void ensemble_spin_factors(double phi2, double& f1, double& f2);
void ensemble_exact_flow(const Body& body, double m[3], double g[3], double t);

/// The kernels, and the points each handles at once (n must be a multiple).
void ensemble_run_portable(const EnsembleTask& task);
std::size_t ensemble_block_portable();
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define NEWTOP_ENSEMBLE_X86 1
void ensemble_run_avx2(const EnsembleTask& task);
std::size_t ensemble_block_avx2();
void ensemble_run_avx512(const EnsembleTask& task);
std::size_t ensemble_block_avx512();
#endif

}  // namespace newtop::detail

#include "ensemble_kernel_models.hpp"

namespace newtop::detail {
namespace ensemble_simd {
namespace {

#define NEWTOP_AI inline __attribute__((always_inline))

// The Taylor coefficients and branch limits of sub_flows.hpp (the same literals, so the same
// doubles; test_ensemble checks the results bit for bit).
constexpr double kS1 = -1.0 / 6, kS2 = 1.0 / 120, kS3 = -1.0 / 5040;
constexpr double kC0 = 1.0 / 2, kC1 = -1.0 / 24, kC2 = 1.0 / 720, kC3 = -1.0 / 40320;
constexpr double kShort = 1e-4;

/// A block of B vectors of the ISA's width W: the state of W·B points. Isa provides V (the vector
/// type), B, splat(x) and all_le(a, b) (every lane a ≤ b, false for NaN).
template <class Isa>
struct Block {
  using V = typename Isa::V;
  static constexpr int B = Isa::B;
  static constexpr int W = int(sizeof(V) / sizeof(double));
  V m[3][B];
  V g[3][B];
};

// Kick over t: ∂V/∂γ = grad0 + λ Iγ, L = γ × ∂V/∂γ, m += t L (kick in splitting.hpp, in the
// working frame: the signs of a proper signed permutation are exact, and the cross product keeps
// its form). γ += 0 as in the scalar kick (it turns −0 into +0).
template <class Isa, class M>
NEWTOP_AI void kick(Block<Isa>& z, const M& c, double t) {
  using V = typename Isa::V;
  const V T = Isa::splat(t), zero = Isa::splat(0.0);
  for (int b = 0; b < Isa::B; ++b) {
    const V g0 = z.g[0][b], g1 = z.g[1][b], g2 = z.g[2][b];
    const V lam = c.lambda(b);
    const V d0 = c.grad0(0, b) + lam * (c.inertia(0, b) * g0),
            d1 = c.grad0(1, b) + lam * (c.inertia(1, b) * g1),
            d2 = c.grad0(2, b) + lam * (c.inertia(2, b) * g2);
    z.m[0][b] = z.m[0][b] + T * (g1 * d2 - g2 * d1);
    z.m[1][b] = z.m[1][b] + T * (g2 * d0 - g0 * d2);
    z.m[2][b] = z.m[2][b] + T * (g0 * d1 - g1 * d0);
    z.g[0][b] = g0 + zero;
    z.g[1][b] = g1 + zero;
    z.g[2][b] = g2 + zero;
  }
}

// The flow of a function of m_I (axis_flow and rotate in sub_flows.hpp): θ = m_I ta + tb, then m
// and γ turn about e_I by x_J += cm1 x_J + s x_K, x_K += cm1 x_K − s x_J.
template <int I, class Isa, class M>
NEWTOP_AI void rotation(Block<Isa>& z, const M& c, const EnsembleStage& st) {
  using V = typename Isa::V;
  constexpr int J = (I + 1) % 3, K = (I + 2) % 3, B = Isa::B;
  const V lim = Isa::splat(kShort);
  V theta[B], t2[B], s[B], cm1[B];
  bool short_series = true;
  for (int b = 0; b < B; ++b) {
    theta[b] = z.m[I][b] * c.ta(st, I, b) + c.tb(st, I, b);
    t2[b] = theta[b] * theta[b];
    short_series &= Isa::all_le(t2[b], lim);
  }
  for (int b = 0; b < B; ++b) {
    const V t4 = t2[b] * t2[b];
    s[b] = theta[b] + (theta[b] * t2[b]) *
                          ((Isa::splat(kS1) + t2[b] * Isa::splat(kS2)) + t4 * Isa::splat(kS3));
    cm1[b] = -t2[b] * ((Isa::splat(kC0) + t2[b] * Isa::splat(kC1)) +
                       t4 * (Isa::splat(kC2) + t2[b] * Isa::splat(kC3)));
  }
  if (!short_series) [[unlikely]] {
    for (int b = 0; b < B; ++b) {
      for (int l = 0; l < Block<Isa>::W; ++l) {
        if (!(t2[b][l] <= kShort)) {
          double sl, cl;
          ensemble_sin_cosm1(theta[b][l], sl, cl);
          s[b][l] = sl;
          cm1[b][l] = cl;
        }
      }
    }
  }
  for (int b = 0; b < B; ++b) {
    const V mj = z.m[J][b], mk = z.m[K][b], gj = z.g[J][b], gk = z.g[K][b];
    z.m[J][b] = mj + (cm1[b] * mj + s[b] * mk);
    z.m[K][b] = mk + (cm1[b] * mk - s[b] * mj);
    z.g[J][b] = gj + (cm1[b] * gj + s[b] * gk);
    z.g[K][b] = gk + (cm1[b] * gk - s[b] * gj);
  }
}

// The flow of ½|m|²/I over t, τ = t/I (spin_flow in sub_flows.hpp): γ turns about m by Rodrigues'
// formula with u = −τ m.
template <class Isa, class M>
NEWTOP_AI void spin(Block<Isa>& z, const M& model, const EnsembleStage& st) {
  using V = typename Isa::V;
  const V lim = Isa::splat(kShort);
  for (int b = 0; b < Isa::B; ++b) {
    const V mtau = -model.tau(st, b);
    const V u0 = mtau * z.m[0][b], u1 = mtau * z.m[1][b], u2 = mtau * z.m[2][b];
    const V phi2 = u0 * u0 + u1 * u1 + u2 * u2;
    const V p4 = phi2 * phi2;
    V f1 = Isa::splat(1.0) +
           phi2 * ((Isa::splat(kS1) + phi2 * Isa::splat(kS2)) + p4 * Isa::splat(kS3));
    V f2 = (Isa::splat(kC0) + phi2 * Isa::splat(kC1)) +
           p4 * (Isa::splat(kC2) + phi2 * Isa::splat(kC3));
    if (!Isa::all_le(phi2, lim)) [[unlikely]] {
      for (int l = 0; l < Block<Isa>::W; ++l) {
        if (!(phi2[l] <= kShort)) {
          double a, c;
          ensemble_spin_factors(phi2[l], a, c);
          f1[l] = a;
          f2[l] = c;
        }
      }
    }
    const V g0 = z.g[0][b], g1 = z.g[1][b], g2 = z.g[2][b];
    const V c0 = u1 * g2 - u2 * g1, c1 = u2 * g0 - u0 * g2, c2 = u0 * g1 - u1 * g0;
    const V d0 = u1 * c2 - u2 * c1, d1 = u2 * c0 - u0 * c2, d2 = u0 * c1 - u1 * c0;
    z.g[0][b] = g0 + (f1 * c0 + f2 * d0);
    z.g[1][b] = g1 + (f1 * c1 + f2 * d1);
    z.g[2][b] = g2 + (f1 * c2 + f2 * d2);
  }
}

// The exact free-body flow, lane by lane through the scalar function.
template <class Isa, class M>
void exact(Block<Isa>& z, const M& c, double t) {
  for (int b = 0; b < Isa::B; ++b) {
    for (int l = 0; l < Block<Isa>::W; ++l) {
      double m[3] = {z.m[0][b][l], z.m[1][b][l], z.m[2][b][l]};
      double g[3] = {z.g[0][b][l], z.g[1][b][l], z.g[2][b][l]};
      ensemble_exact_flow(c.body(b, l), m, g, t);
      for (int w = 0; w < 3; ++w) {
        z.m[w][b][l] = m[w];
        z.g[w][b][l] = g[w];
      }
    }
  }
}

/// Advances every block of the task by task.steps steps, with the model M (SharedModel or
/// LaneModels).
template <class Isa, template <class> class M>
void run_model_blocks(const EnsembleTask& k) {
  using V = typename Isa::V;
  constexpr int B = Isa::B, W = Block<Isa>::W;
  constexpr std::size_t points = std::size_t(W) * B;
  for (std::size_t first = 0; first < k.n; first += points) {
    Block<Isa> z;
    const M<Isa> c{k, first};
    for (int w = 0; w < 3; ++w) {
      for (int b = 0; b < B; ++b) {
        __builtin_memcpy(&z.m[w][b], k.m[w] + first + std::size_t(b * W), sizeof(V));
        __builtin_memcpy(&z.g[w][b], k.g[w] + first + std::size_t(b * W), sizeof(V));
      }
    }
    for (std::int64_t step = 0; step < k.steps; ++step) {
      for (std::size_t i = 0; i < k.stage_count; ++i) {
        const EnsembleStage& st = k.stages[i];
        switch (st.op) {
          case EnsembleOp::kick:
            kick(z, c, st.a);
            break;
          case EnsembleOp::rotate0:
            rotation<0>(z, c, st);
            break;
          case EnsembleOp::rotate1:
            rotation<1>(z, c, st);
            break;
          case EnsembleOp::rotate2:
            rotation<2>(z, c, st);
            break;
          case EnsembleOp::spin:
            spin(z, c, st);
            break;
          case EnsembleOp::exact:
            exact(z, c, st.a);
            break;
        }
      }
    }
    for (int w = 0; w < 3; ++w) {
      for (int b = 0; b < B; ++b) {
        __builtin_memcpy(k.m[w] + first + std::size_t(b * W), &z.m[w][b], sizeof(V));
        __builtin_memcpy(k.g[w] + first + std::size_t(b * W), &z.g[w][b], sizeof(V));
      }
    }
  }
}

/// Advances every block of the task by task.steps steps (a model per lane where the task has one).
template <class Isa>
void run_blocks(const EnsembleTask& k) {
  if (k.lane[0] != nullptr) {
    run_model_blocks<Isa, LaneModels>(k);
  } else {
    run_model_blocks<Isa, SharedModel>(k);
  }
}

#undef NEWTOP_AI

}  // namespace
}  // namespace ensemble_simd
}  // namespace newtop::detail
