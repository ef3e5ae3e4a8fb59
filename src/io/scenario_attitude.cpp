// [initial]'s attitude: quaternion, rotation_matrix, euler_321 or euler_313 (docs/scenario.md).

#include <cmath>
#include <optional>

#include "newtop/model/attitude.hpp"
#include "scenario_sections.hpp"

namespace newtop::io {
namespace {

const std::vector<std::string> kAttitudeKeys{"quaternion", "rotation_matrix", "euler_321",
                                             "euler_313"};

/// "a, b, c or d" (last = " or "), or with last = " and " "a and b".
std::string listed(const std::vector<std::string>& keys, const std::string& last = " or ") {
  std::string s;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    s += (i == 0 ? "" : i + 1 == keys.size() ? last : ", ") + keys[i];
  }
  return s;
}

Quaternion read_quaternion(TableReader& r, bool normalize) {
  const std::vector<double> v = r.numbers("quaternion", 4);
  Quaternion q(v[0], v[1], v[2], v[3]);  // scalar first in the file and in Eigen's constructor
  // The norm without overflow or underflow: of the quaternion scaled by its largest component.
  const double largest = q.coeffs().cwiseAbs().maxCoeff();
  if (largest == 0.0) r.fail("quaternion", "expected a unit quaternion, found [0, 0, 0, 0]");
  q.coeffs() /= largest;
  const double norm = largest * q.norm();
  if (!normalize && std::abs(norm - 1.0) > kAttitudeTolerance) {
    r.fail("quaternion", "expected a unit quaternion (|q| = 1 to " +
                             format_number(kAttitudeTolerance) +
                             "), found |q| = " + format_number(norm) +
                             "; add normalize = true to [initial] to rescale it");
  }
  return q.normalized();
}

Quaternion read_rotation_matrix(TableReader& r) {
  const Mat3 R = r.mat3("rotation_matrix");
  const double defect = orthonormality_defect(R);
  if (!(defect <= kAttitudeTolerance)) {
    r.fail("rotation_matrix",
           "expected a rotation matrix (max |R^T R - I| <= " + format_number(kAttitudeTolerance) +
               "), found max |R^T R - I| = " + format_number(defect));
  }
  const double det = R.determinant();
  if (!(det > 0)) {
    r.fail("rotation_matrix", "expected a rotation matrix (det R = +1), found det R = " +
                                  format_number(det) + " (a reflection)");
  }
  return Quaternion(R).normalized();
}

}  // namespace

const std::vector<std::string>& attitude_keys() { return kAttitudeKeys; }

std::optional<Quaternion> read_attitude(TableReader& r, bool normalize) {
  std::vector<std::string> given;
  for (const auto& k : kAttitudeKeys) {
    if (r.has(k)) given.push_back(k);
  }
  if (given.empty()) return std::nullopt;
  if (given.size() > 1) {
    r.fail(given[1], "expected one attitude key (" + listed(kAttitudeKeys) + "), found " +
                         listed(given, " and "));
  }
  const std::string& key = given[0];
  if (key == "quaternion") return read_quaternion(r, normalize);
  if (key == "rotation_matrix") return read_rotation_matrix(r);
  const Vec3 angles = r.vec3(key);
  return key == "euler_321" ? from_euler_321(angles) : from_euler_313(angles);
}

}  // namespace newtop::io
