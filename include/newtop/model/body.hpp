#pragma once
/// \file
/// The rigid body (docs/model.md §1): principal moments A, B, C at the fixed point O, mass M,
/// centre of mass r0 and gyrostatic moment k, all in the principal axes Oxyz.

#include "newtop/core/types.hpp"

namespace newtop {

/// An immutable rigid body (or gyrostat) about a fixed point O. Built only through the checked
/// factories below; every vector is expressed in the principal axes of inertia at O.
class Body {
 public:
  /// Body from principal moments (A, B, C) > 0 satisfying the triangle inequalities
  /// A + B >= C (and cyclic), mass M >= 0, centre of mass r0 and gyrostatic moment k, both in the
  /// principal axes. Throws InputError naming the offending field.
  static Body from_principal(const Vec3& inertia, double mass, const Vec3& center_of_mass,
                             const Vec3& gyrostat = Vec3::Zero());

  /// Body from a full symmetric inertia tensor J at O given in a user frame. J is diagonalised;
  /// principal_axes() holds the rotation P (columns = principal axes in the user frame, det P = +1)
  /// and center_of_mass and gyrostat (given in the user frame) are converted by Pᵀ. A tensor that
  /// is already diagonal keeps the user's axes (P = identity); otherwise the axes are sorted by
  /// increasing moment.
  static Body from_tensor(const Mat3& inertia_tensor, double mass, const Vec3& center_of_mass,
                          const Vec3& gyrostat = Vec3::Zero());

  double A() const { return inertia_.x(); }
  double B() const { return inertia_.y(); }
  double C() const { return inertia_.z(); }
  /// (A, B, C), the diagonal of I.
  const Vec3& inertia() const { return inertia_; }
  /// I as a diagonal matrix.
  Mat3 inertia_matrix() const { return inertia_.asDiagonal(); }
  double mass() const { return mass_; }
  /// r0 = (x0, y0, z0), centre of mass relative to O.
  const Vec3& center_of_mass() const { return center_of_mass_; }
  /// k = (k1, k2, k3), constant gyrostatic moment.
  const Vec3& gyrostat() const { return gyrostat_; }
  /// Columns are the principal axes expressed in the user's frame (identity when built from
  /// principal moments). A user-frame vector v maps to the body frame as Pᵀv.
  const Mat3& principal_axes() const { return principal_axes_; }

 private:
  Body(Vec3 inertia, double mass, Vec3 center_of_mass, Vec3 gyrostat, Mat3 axes)
      : inertia_(inertia),
        mass_(mass),
        center_of_mass_(center_of_mass),
        gyrostat_(gyrostat),
        principal_axes_(axes) {}

  Vec3 inertia_;
  double mass_;
  Vec3 center_of_mass_;
  Vec3 gyrostat_;
  Mat3 principal_axes_;
};

}  // namespace newtop
