#include "newtop/integrate/outcome.hpp"

namespace newtop {

std::string_view to_string(Status s) {
  switch (s) {
    case Status::finished:
      return "finished";
    case Status::non_finite:
      return "non_finite";
    case Status::step_size_underflow:
      return "step_size_underflow";
    case Status::step_limit:
      return "step_limit";
  }
  return "unknown";
}

}  // namespace newtop
