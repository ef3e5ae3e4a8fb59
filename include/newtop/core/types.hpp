#pragma once
/// \file
/// Basic vocabulary of newtop: Eigen aliases and the exception for bad input.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <stdexcept>
#include <string>

namespace newtop {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// Bad input at an API or file boundary. The message names the field, what was expected and what
/// was found, e.g. `inertia: triangle inequality A + B >= C fails: 1 + 2 < 4.5`.
class InputError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// A moment about O and its derivative along one direction (the kick of one tangent vector needs
/// both, and a mass model can form them in one pass).
struct MomentAndDerivative {
  Vec3 moment = Vec3::Zero();
  Vec3 derivative = Vec3::Zero();
};

/// Formats a number with enough digits to round-trip (17 significant digits, shortest form); −0 is
/// written as 0 (the sign of a zero carries no information in any of newtop's outputs).
std::string format_number(double x);

/// Formats a vector as `[x, y, z]` with format_number.
std::string format_vector(const Vec3& v);

}  // namespace newtop
