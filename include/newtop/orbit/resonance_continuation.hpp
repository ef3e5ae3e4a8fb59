#pragma once
/// \file
/// One call for the whole continuation of a spin–orbit resonance (docs/continuation.md §2): the
/// family along a path, each located event's locus in a second parameter, and the branches from
/// its flips and branch points — what `newtop continue --family resonance` and Python's
/// `resonance_family` compute.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "newtop/orbit/orbit_families.hpp"

namespace newtop {

/// The second parameter q of the plane (p, q): each event's locus is continued in it from q0 (the
/// family's own value) to both ends c and d.
struct ResonanceSecondAxis {
  PitchPlanePath path;
  double c = 0, d = 0, q0 = 0;
};

struct ResonanceRequest {
  PitchPath path;  ///< (e, k) along the first parameter
  double p0 = 0, p1 = 0;
  SpinOrbitResonance resonance = newtop::resonance(1, 1);
  double line = 0;  ///< θ(0): 0 or π/2
  std::optional<ResonanceSecondAxis> second;
  bool switch_branches = false;  ///< continue the branch from each flip and branch point
};

/// A located event's locus in the second parameter, its points in order from c to d; `end` joins
/// the ends of the two halves (q0 → c, q0 → d) by a comma.
struct FamilyBoundary {
  BifurcationType type = BifurcationType::fold;
  std::vector<FamilyPoint> points;
  std::string end;
};

/// The family that leaves a located flip (period-doubled) or branch point (asymmetric).
struct FamilyBranch {
  std::size_t event = 0;  ///< its index in the parent's events
  Family family;
};

struct ResonanceContinuation {
  Family family;
  std::vector<FamilyBoundary> boundaries;  ///< one per event, with a second axis
  std::vector<FamilyBranch> branches;      ///< with switch_branches
};

/// The family starts at the symmetric solution on `line` whose θ′(0) is nearest to the resonance's
/// mean rate M/(2N). InputError where resonance_family, resonance_boundary or resonance_branch
/// throw it, and for a second axis together with switch_branches.
ResonanceContinuation continue_resonance(const ResonanceRequest& request);

}  // namespace newtop
