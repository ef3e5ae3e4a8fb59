#pragma once
/// \file
/// The lockstep kernel of the ensemble tangent stepper (include/newtop/phase/ensemble_tangent.hpp):
/// the state and up to six tangent vectors per point, through the sub-flows of
/// TangentSplittingStepper (phase/tangent.hpp, src/phase/tangent.cpp) in the body frame: the
/// rotation about body axis a by θ = (t/I_a)(m_a − k_a) with its derivative, and the kick with
/// δm += t (∂L/∂γ) δγ. The rotations and the state do the scalar operations in the scalar order
/// (bit-identical); the kick forms (∂L/∂γ) δγ = γ × (λ I δγ) − (∂V/∂γ) × δγ directly rather than
/// through the 3 × 3 matrix, so the tangent vectors agree with the scalar stepper's to round-off.
/// The same rules as ensemble_kernel.hpp: compiled per instruction set, code in an unnamed
/// namespace.

#include "ensemble_kernel.hpp"

namespace newtop::detail {

/// Points and their tangent vectors: v[r][c] is row r (δm then δγ) of tangent vector c, as n
/// numbers; stages: kick (a = t) or rotation about body axis I (rotateI: a = t/I_I, b = k_I).
/// With a model per lane: the lanes' constants by TangentLaneConstant (n numbers each; grad0,
/// lambda and inertia are then unused), and a rotation stage holds the time t (rate = t/I_I and
/// k_I taken per lane); all null: the one model.
enum TangentLaneConstant : int {
  kTangentInertia = 0,   // + w: I_w
  kTangentGyrostat = 3,  // + w: k_w
  kTangentGrad0 = 6,     // + w: M g r0_w
  kTangentLambda = 9,    // λ
  kTangentConstants = 10
};

struct EnsembleTangentTask {
  const EnsembleStage* stages;
  std::size_t stage_count;
  double grad0[3];  ///< M g r0 (body frame): ∂V/∂γ = grad0 + λ Iγ
  double lambda;
  double inertia[3];
  const double* lane[kTangentConstants];
  double* m[3];
  double* g[3];
  double* v[6][6];
  int columns;
  std::size_t n;
  std::int64_t steps;
};

void ensemble_tangent_run_portable(const EnsembleTangentTask& task);
#ifdef NEWTOP_ENSEMBLE_X86
void ensemble_tangent_run_avx2(const EnsembleTangentTask& task);
void ensemble_tangent_run_avx512(const EnsembleTangentTask& task);
#endif

namespace ensemble_simd {
namespace {

template <class Isa>
struct TangentBlock {
  using V = typename Isa::V;
  static constexpr int W = int(sizeof(V) / sizeof(double));
  V m[3], g[3], v[6][6];
};

// The model of the lanes: one for all (the task's constants, the stage's rate and k_I) or one per
// lane (loaded at the block's first point; rate = t/I_I per lane, as axis_flow_tangent divides).
template <class Isa>
struct TangentShared {
  using V = typename Isa::V;
  const EnsembleTangentTask& k;
  std::size_t first;  // unused
  V rate(const EnsembleStage& st, int) const { return Isa::splat(st.a); }
  V gyrostat(const EnsembleStage& st, int) const { return Isa::splat(st.b); }
  V grad0(int w) const { return Isa::splat(k.grad0[w]); }
  V lambda() const { return Isa::splat(k.lambda); }
  V inertia(int w) const { return Isa::splat(k.inertia[w]); }
};

template <class Isa>
struct TangentLanes {
  using V = typename Isa::V;
  const EnsembleTangentTask& k;
  std::size_t first;
  V load(int c) const {
    V v;
    __builtin_memcpy(&v, k.lane[c] + first, sizeof(V));
    return v;
  }
  V rate(const EnsembleStage& st, int I) const {
    return Isa::splat(st.a) / load(kTangentInertia + I);
  }
  V gyrostat(const EnsembleStage&, int I) const { return load(kTangentGyrostat + I); }
  V grad0(int w) const { return load(kTangentGrad0 + w); }
  V lambda() const { return load(kTangentLambda); }
  V inertia(int w) const { return load(kTangentInertia + w); }
};

// kick_tangent: δm += t (γ × (λ I δγ) − (∂V/∂γ) × δγ), then m += t γ × ∂V/∂γ.
template <class Isa, class M>
inline __attribute__((always_inline)) void tangent_kick(TangentBlock<Isa>& z,
                                                        const EnsembleTangentTask& k, const M& md,
                                                        double t) {
  using V = typename Isa::V;
  const V lam = md.lambda(), T = Isa::splat(t);
  const V i0 = md.inertia(0), i1 = md.inertia(1), i2 = md.inertia(2);
  const V g0 = z.g[0], g1 = z.g[1], g2 = z.g[2];
  const V d0 = md.grad0(0) + lam * (i0 * g0);
  const V d1 = md.grad0(1) + lam * (i1 * g1);
  const V d2 = md.grad0(2) + lam * (i2 * g2);
  for (int c = 0; c < k.columns; ++c) {
    const V e0 = z.v[3][c], e1 = z.v[4][c], e2 = z.v[5][c];
    const V w0 = lam * (i0 * e0), w1 = lam * (i1 * e1), w2 = lam * (i2 * e2);
    z.v[0][c] = z.v[0][c] + T * ((g1 * w2 - g2 * w1) - (d1 * e2 - d2 * e1));
    z.v[1][c] = z.v[1][c] + T * ((g2 * w0 - g0 * w2) - (d2 * e0 - d0 * e2));
    z.v[2][c] = z.v[2][c] + T * ((g0 * w1 - g1 * w0) - (d0 * e1 - d1 * e0));
  }
  z.m[0] = z.m[0] + T * (g1 * d2 - g2 * d1);
  z.m[1] = z.m[1] + T * (g2 * d0 - g0 * d2);
  z.m[2] = z.m[2] + T * (g0 * d1 - g1 * d0);
}

template <class Isa>
inline __attribute__((always_inline)) void turn(typename Isa::V& u, typename Isa::V& w,
                                                typename Isa::V s, typename Isa::V cm1) {
  const typename Isa::V a = u, b = w;
  u = a + (cm1 * a + s * b);
  w = b + (cm1 * b - s * a);
}

// axis_flow_tangent: θ = rate (m_I − k_I); m and γ turn about e_I; δx' = R δx + (x' × e_I) rate
// δm_I.
template <int I, class Isa>
inline __attribute__((always_inline)) void tangent_rotation(TangentBlock<Isa>& z, int columns,
                                                            typename Isa::V R,
                                                            typename Isa::V k_i) {
  using V = typename Isa::V;
  constexpr int J = (I + 1) % 3, K = (I + 2) % 3;
  const V theta = R * (z.m[I] - k_i);
  const V t2 = theta * theta, t4 = t2 * t2;
  V s = theta + (theta * t2) * ((Isa::splat(kS1) + t2 * Isa::splat(kS2)) + t4 * Isa::splat(kS3));
  V cm1 = -t2 * ((Isa::splat(kC0) + t2 * Isa::splat(kC1)) +
                 t4 * (Isa::splat(kC2) + t2 * Isa::splat(kC3)));
  if (!Isa::all_le(t2, Isa::splat(kShort))) [[unlikely]] {
    for (int l = 0; l < TangentBlock<Isa>::W; ++l) {
      if (!(t2[l] <= kShort)) {
        double sl, cl;
        ensemble_sin_cosm1(theta[l], sl, cl);
        s[l] = sl;
        cm1[l] = cl;
      }
    }
  }
  turn<Isa>(z.m[J], z.m[K], s, cm1);
  turn<Isa>(z.g[J], z.g[K], s, cm1);
  for (int c = 0; c < columns; ++c) {
    const V dphi = R * z.v[I][c];
    turn<Isa>(z.v[J][c], z.v[K][c], s, cm1);
    z.v[J][c] = z.v[J][c] + z.m[K] * dphi;
    z.v[K][c] = z.v[K][c] - z.m[J] * dphi;
    turn<Isa>(z.v[3 + J][c], z.v[3 + K][c], s, cm1);
    z.v[3 + J][c] = z.v[3 + J][c] + z.g[K] * dphi;
    z.v[3 + K][c] = z.v[3 + K][c] - z.g[J] * dphi;
  }
}

template <class Isa, template <class> class M>
void run_tangent_model_blocks(const EnsembleTangentTask& k) {
  using V = typename Isa::V;
  constexpr std::size_t W = TangentBlock<Isa>::W;
  for (std::size_t first = 0; first < k.n; first += W) {
    TangentBlock<Isa> z;
    const M<Isa> md{k, first};
    for (int w = 0; w < 3; ++w) {
      __builtin_memcpy(&z.m[w], k.m[w] + first, sizeof(V));
      __builtin_memcpy(&z.g[w], k.g[w] + first, sizeof(V));
    }
    for (int r = 0; r < 6; ++r) {
      for (int c = 0; c < k.columns; ++c)
        __builtin_memcpy(&z.v[r][c], k.v[r][c] + first, sizeof(V));
    }
    for (std::int64_t step = 0; step < k.steps; ++step) {
      for (std::size_t i = 0; i < k.stage_count; ++i) {
        const EnsembleStage& st = k.stages[i];
        switch (st.op) {
          case EnsembleOp::kick:
            tangent_kick(z, k, md, st.a);
            break;
          case EnsembleOp::rotate0:
            tangent_rotation<0>(z, k.columns, md.rate(st, 0), md.gyrostat(st, 0));
            break;
          case EnsembleOp::rotate1:
            tangent_rotation<1>(z, k.columns, md.rate(st, 1), md.gyrostat(st, 1));
            break;
          case EnsembleOp::rotate2:
            tangent_rotation<2>(z, k.columns, md.rate(st, 2), md.gyrostat(st, 2));
            break;
          default:  // spin and exact flows have no tangent kernel (refused by the stepper)
            break;
        }
      }
    }
    for (int w = 0; w < 3; ++w) {
      __builtin_memcpy(k.m[w] + first, &z.m[w], sizeof(V));
      __builtin_memcpy(k.g[w] + first, &z.g[w], sizeof(V));
    }
    for (int r = 0; r < 6; ++r) {
      for (int c = 0; c < k.columns; ++c)
        __builtin_memcpy(k.v[r][c] + first, &z.v[r][c], sizeof(V));
    }
  }
}

template <class Isa>
void run_tangent_blocks(const EnsembleTangentTask& k) {
  if (k.lane[0] != nullptr) {
    run_tangent_model_blocks<Isa, TangentLanes>(k);
  } else {
    run_tangent_model_blocks<Isa, TangentShared>(k);
  }
}

}  // namespace
}  // namespace ensemble_simd
}  // namespace newtop::detail
