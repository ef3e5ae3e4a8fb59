#pragma once
/// \file
/// Families continued by pseudo-arclength (docs/continuation.md): the symmetric periodic solutions
/// of Beletsky's equation of one spin–orbit resonance along a path of (e, k), and the relative
/// equilibria of the orbit model along a path in the principal moments.

#include <functional>

#include "newtop/analysis/continuation.hpp"
#include "newtop/orbit/orbit_model.hpp"
#include "newtop/orbit/spin_orbit.hpp"

namespace newtop {

/// The problem (e, k) at the parameter value p: a path through the plane of Beletsky's equation.
using PitchPath = std::function<PitchProblem(double p)>;

/// p is the eccentricity, k fixed.
PitchPath eccentricity_path(double k);

/// p is the principal moment `index` (0, 1, 2) of `inertia` (A, B, C), the others fixed, e fixed:
/// k = (B − A)/C.
PitchPath inertia_path(const Vec3& inertia, int index, double eccentricity);

/// The symmetric periodic solutions of resonance r that start on the reversibility line θ(0) =
/// line (0 or π/2) along the path, from p0 to p1 (docs/continuation.md §2). The unknown is θ′(0);
/// the residual θ(πN) − line − Mπ/2 (docs/orbit.md §9). With Φ(πN, 0) = [[a, b], [c, d]] and D
/// its determinant, the reversibility gives the monodromy's trace T = 2(ad + bc)/D, whence
/// T − 2 = 4bc/D and T + 2 = 4ad/D: the family folds where b = ∂θ(πN)/∂θ′(0) = 0 (dp/ds = 0),
/// the symmetric solution has a pitchfork (a branch point: a pair of asymmetric solutions) where
/// c = 0, and a flip where T + 2 = 0. Test functions: T + 2 (flip) and c (branch_point).
/// The start is the symmetric solution on `line` at p0 whose θ′(0) is nearest to `guess`
/// (periodic_solutions' scan); InputError when there is none, when line is neither 0 nor π/2, or
/// the path throws at p0 or p1.
/// FamilyPoint: values (θ(0), θ′(0)), period 2πN, the two multipliers, stability as
/// to_string(FloquetStability), tests (T + 2, c).
Family resonance_family(const PitchPath& path, double p0, double p1, const SpinOrbitResonance& r,
                        double line, double guess, const ContinuationSettings& settings = {});

/// (e, k) as a function of two parameters (p, q): each is the eccentricity (code
/// kEccentricityKey) or the principal moment 0, 1, 2 of `inertia` (k = (B − A)/C), the other
/// values fixed at `inertia` and `eccentricity`. InputError for an unknown code or p, q the same.
inline constexpr int kEccentricityKey = -1;
using PitchPlanePath = std::function<PitchProblem(double p, double q)>;
PitchPlanePath pitch_plane_path(const Vec3& inertia, double eccentricity, int p_key, int q_key);

/// The locus of an event of the resonance family (fold, flip or branch_point, located at
/// p = event.value for q = q0) continued in the second parameter q from q0 to q1 (docs/
/// continuation.md §2): unknowns (θ′(0), p), residuals θ(πN) − line − Mπ/2 and the event's
/// defining function: b = Φ₀₁(πN, 0) (fold), T + 2 (flip, T over the period in one piece),
/// c = Φ₁₀(πN, 0) (branch_point). FamilyPoint: parameter q, values (θ(0), θ′(0), p), period,
/// multipliers and stability of the periodic solution there. InputError for a Krein event.
/// By default at most 400 points a curve: a curve that runs into the edge of the domain (e → 0 at
/// the tip of a resonance tongue, where the two flip curves meet) ends there in small steps.
inline const ContinuationSettings kBoundarySettings{.max_points = 400};
Family resonance_boundary(const PitchPlanePath& path, const BifurcationEvent& event, double q0,
                          double q1, const SpinOrbitResonance& r, double line,
                          const ContinuationSettings& settings = kBoundarySettings);

/// Branch switching at a flip or a branch point of the resonance family (docs/continuation.md
/// §2): the new family by 2-D shooting, unknowns (θ(0), θ′(0)), residual x(2πN′) − x(0) −
/// (M′π, 0) with the Jacobian [Φ(2πN′, 0) − I, F_p] (F_p by a central difference). At a flip the
/// period-doubled family: N′ = 2N, M′ = 2M (the parent solves it too and crosses it at the flip);
/// at a branch point the asymmetric pair: N′ = N, M′ = M. It leaves the event along (v, 0), v the
/// eigenvector of the parent's monodromy for −1 (flip) or +1 (branch point), and is continued by
/// continue_branch within [p_min, p_max] (which must contain the event). FamilyPoint: values
/// (θ(0), θ′(0)), period 2πN′, the two multipliers of Φ(2πN′, 0), stability, tests (T + 2, the
/// branch-point determinant). InputError for a fold or a Krein event.
Family resonance_branch(const PitchPath& path, const BifurcationEvent& event, double p_min,
                        double p_max, const SpinOrbitResonance& r, double line,
                        const ContinuationSettings& settings = {});

/// The relative equilibrium at rest in the orbital frame (circular orbit, rate 1) with the radius
/// along body axis `radial` and the orbit normal along body axis `normal` (principal axes), as the
/// principal moment `index` of `inertia` moves from p0 to p1 (docs/continuation.md §4); the
/// moments at both ends must form a body (InputError otherwise). FamilyPoint: values (the three
/// moments), the six leaf eigenvalues (in units of ω0), stability as to_string(OrbitStability),
/// tests: the constant term a0 of the characteristic cubic in σ = s² (a branch point where it
/// changes sign: an eigenvalue pair through 0, as at k_R = k_Y) and its discriminant (a Krein
/// collision where it changes sign at a double σ < 0, as on 1 + 3k_R + k_R k_Y = 4√(k_R k_Y)).
Family equilibrium_family(const Vec3& inertia, int radial, int normal, int index, double p0,
                          double p1, const ContinuationSettings& settings = {});

}  // namespace newtop
