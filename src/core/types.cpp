#include "newtop/core/types.hpp"

#include <charconv>

namespace newtop {

std::string format_number(double x) {
  if (x == 0.0) x = 0.0;  // −0 compares equal to 0: print it as 0
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof(buf), x);
  return std::string(buf, res.ptr);
}

std::string format_vector(const Vec3& v) {
  return "[" + format_number(v.x()) + ", " + format_number(v.y()) + ", " + format_number(v.z()) +
         "]";
}

}  // namespace newtop
