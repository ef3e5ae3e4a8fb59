#pragma once
// The model of an ensemble kernel's lanes (ensemble_kernel.hpp): one model for all, its constants
// splatted, or a model per lane, its constants loaded per block. The kernel asks a model for the
// operands of each stage; both give the scalar stepper's numbers for each lane. Private to
// src/integrate, in an unnamed namespace as the kernel (compiled once per instruction set).

#include <cstddef>

#include "ensemble_kernel.hpp"

namespace newtop::detail::ensemble_simd {
namespace {

#define NEWTOP_MODEL_AI inline __attribute__((always_inline))

// The constants of one model shared by every lane: the stage's numbers, splatted.
template <class Isa>
struct SharedModel {
  using V = typename Isa::V;
  const EnsembleTask& k;
  std::size_t first;  // unused: one model for every block
  NEWTOP_MODEL_AI V ta(const EnsembleStage& st, int, int) const { return Isa::splat(st.a); }
  NEWTOP_MODEL_AI V tb(const EnsembleStage& st, int, int) const { return Isa::splat(st.b); }
  NEWTOP_MODEL_AI V tau(const EnsembleStage& st, int) const { return Isa::splat(st.a); }
  NEWTOP_MODEL_AI V grad0(int w, int) const { return Isa::splat(k.grad0[w]); }
  NEWTOP_MODEL_AI V lambda(int) const { return Isa::splat(k.lambda); }
  NEWTOP_MODEL_AI V inertia(int w, int) const { return Isa::splat(k.inertia[w]); }
  const Body& body(int, int) const { return *k.body; }
};

// A model per lane: the block's constants loaded from the task's arrays (`first`: the block's first
// point), the stage's times multiplied by them as the scalar flows multiply (t2 * f.rate[w]).
template <class Isa>
struct LaneModels {
  using V = typename Isa::V;
  static constexpr int W = int(sizeof(V) / sizeof(double));
  const EnsembleTask& k;
  std::size_t first;
  NEWTOP_MODEL_AI V load(int c, int b) const {
    V v;
    __builtin_memcpy(&v, k.lane[c] + first + std::size_t(b * W), sizeof(V));
    return v;
  }
  NEWTOP_MODEL_AI V ta(const EnsembleStage& st, int I, int b) const {
    return st.fixed ? Isa::splat(st.a) : Isa::splat(st.a) * load(kLaneRate + I, b);
  }
  NEWTOP_MODEL_AI V tb(const EnsembleStage& st, int I, int b) const {
    return Isa::splat(st.b) * load(kLaneKOverI + I, b);
  }
  NEWTOP_MODEL_AI V tau(const EnsembleStage& st, int b) const {
    return Isa::splat(st.a) * load(kLaneInvRef, b);
  }
  NEWTOP_MODEL_AI V grad0(int w, int b) const { return load(kLaneGrad0 + w, b); }
  NEWTOP_MODEL_AI V lambda(int b) const { return load(kLaneLambda, b); }
  NEWTOP_MODEL_AI V inertia(int w, int b) const { return load(kLaneInertia + w, b); }
  const Body& body(int b, int l) const { return *k.bodies[first + std::size_t(b * W + l)]; }
};

#undef NEWTOP_MODEL_AI

}  // namespace
}  // namespace newtop::detail::ensemble_simd
