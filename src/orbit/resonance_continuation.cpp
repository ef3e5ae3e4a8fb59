#include "newtop/orbit/resonance_continuation.hpp"

#include <algorithm>

namespace newtop {
namespace {

FamilyBoundary boundary(const ResonanceSecondAxis& s, const BifurcationEvent& ev,
                        const ResonanceRequest& rq) {
  FamilyBoundary b{ev.type, {}, ""};
  for (const double end : {s.c, s.d}) {
    if (end == s.q0) continue;
    const Family curve = resonance_boundary(s.path, ev, s.q0, end, rq.resonance, rq.line);
    if (end == s.c) {
      b.points.assign(curve.points.rbegin(), curve.points.rend());
    } else {
      b.points.insert(b.points.end(), curve.points.begin() + (s.q0 == s.c ? 0 : 1),
                      curve.points.end());
    }
    b.end += (b.end.empty() ? "" : ",") + curve.end;
  }
  return b;
}

}  // namespace

ResonanceContinuation continue_resonance(const ResonanceRequest& rq) {
  if (rq.second && rq.switch_branches) {
    throw InputError("switch: expected either a second parameter or branch switching, found both");
  }
  const SpinOrbitResonance& r = rq.resonance;
  const double centre = r.half_turns / (2.0 * r.periods);
  ResonanceContinuation out;
  out.family = resonance_family(rq.path, rq.p0, rq.p1, r, rq.line, centre);
  if (rq.second) {
    for (const BifurcationEvent& ev : out.family.events) {
      out.boundaries.push_back(boundary(*rq.second, ev, rq));
    }
  }
  if (rq.switch_branches) {
    const double lo = std::min(rq.p0, rq.p1), hi = std::max(rq.p0, rq.p1);
    for (std::size_t i = 0; i < out.family.events.size(); ++i) {
      const BifurcationEvent& ev = out.family.events[i];
      if (ev.type != BifurcationType::flip && ev.type != BifurcationType::branch_point) continue;
      out.branches.push_back({i, resonance_branch(rq.path, ev, lo, hi, r, rq.line)});
    }
  }
  return out;
}

}  // namespace newtop
