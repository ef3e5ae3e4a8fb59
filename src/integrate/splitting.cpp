#include "newtop/integrate/splitting.hpp"

namespace newtop {
namespace {

void push(std::vector<SubFlow>& p, int axis, double fraction) {
  if (!p.empty() && p.back().axis == axis) {
    p.back().fraction += fraction;
  } else {
    p.push_back({axis, fraction});
  }
}

void push_free_body(std::vector<SubFlow>& p, const SplitOrdering& o, double c) {
  push(p, o.axes[0], 0.5 * c);
  push(p, o.axes[1], 0.5 * c);
  push(p, o.axes[2], c);
  push(p, o.axes[1], 0.5 * c);
  push(p, o.axes[0], 0.5 * c);
}

}  // namespace

std::vector<SubFlow> composition_program(const CompositionTable& table, const SplitOrdering& o) {
  std::vector<SubFlow> p;
  for (double c : table.gamma) {
    if (o.kick_outside) {
      push(p, -1, 0.5 * c);
      push_free_body(p, o, c);
      push(p, -1, 0.5 * c);
    } else {
      push_free_body(p, o, 0.5 * c);
      push(p, -1, c);
      push_free_body(p, o, 0.5 * c);
    }
  }
  return p;
}

}  // namespace newtop
