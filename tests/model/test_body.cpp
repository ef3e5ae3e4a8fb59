// Body construction (docs/model.md §1): validation of moments, tensors and the principal-axes
// rotation.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "newtop/model/body.hpp"
#include "support/problems.hpp"

namespace newtop {
namespace test_body {
namespace {

using test::kEps;

TEST(Body, RejectsNonPositiveMoment) {
  try {
    Body::from_principal(Vec3(1, -2, 2), 1, Vec3::Zero());
    FAIL() << "accepted B < 0";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("inertia"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("B = -2"), std::string::npos);
  }
}

TEST(Body, RejectsTriangleInequality) {
  try {
    Body::from_principal(Vec3(1, 2, 4.5), 1, Vec3::Zero());
    FAIL() << "accepted A + B < C";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("A + B >= C fails: 1 + 2 < 4.5"), std::string::npos)
        << e.what();
  }
}

TEST(Body, AcceptsFlatPlateWhereTriangleInequalityIsAnEquality) {
  // A flat plate in the xy plane has A + B = C exactly (the limiting case of the triangle
  // inequality, docs/model.md §1): accepted, also with the round-off of a diagonalisation (the
  // check's slack is 8 ε tr I = 16 ε C here); a C beyond that slack is no body.
  const Body b = Body::from_principal(Vec3(1, 2, 3), 1, Vec3::Zero());
  EXPECT_EQ(b.C(), 3.0);
  EXPECT_NO_THROW(Body::from_principal(Vec3(1, 2, 3 * (1 + 4 * kEps)), 1, Vec3::Zero()));
  EXPECT_THROW(Body::from_principal(Vec3(1, 2, 3 * (1 + 64 * kEps)), 1, Vec3::Zero()), InputError);
}

TEST(Body, RejectsNonFinite) {
  EXPECT_THROW(Body::from_principal(Vec3(1, NAN, 2), 1, Vec3::Zero()), InputError);
  EXPECT_THROW(Body::from_principal(Vec3(1, 1, 1), INFINITY, Vec3::Zero()), InputError);
  EXPECT_THROW(Body::from_principal(Vec3(1, 1, 1), 1, Vec3(0, NAN, 0)), InputError);
  EXPECT_THROW(Body::from_principal(Vec3(1, 1, 1), -1, Vec3::Zero()), InputError);
}

TEST(Body, TensorIsDiagonalisedAndVectorsRotated) {
  // Build J = P diag(1, 2, 2.5) Pᵀ for a known rotation P; the factory must recover the moments,
  // and r0 given in the user frame must map to Pᵀ r0.
  const Mat3 P = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3 moments(1.0, 2.0, 2.5);
  const Mat3 J = P * moments.asDiagonal() * P.transpose();
  const Vec3 r0_user = P * Vec3(0.1, -0.2, 0.3);
  const Body b = Body::from_tensor(J, 2.0, r0_user);
  // Eigen-decomposition of a 3×3 symmetric matrix is backward stable: errors ~ a few ε |J|.
  const double tol = 64 * kEps * moments.maxCoeff();
  EXPECT_NEAR(b.A(), 1.0, tol);
  EXPECT_NEAR(b.B(), 2.0, tol);
  EXPECT_NEAR(b.C(), 2.5, tol);
  EXPECT_NEAR(b.principal_axes().determinant(), 1.0, tol);
  // Each principal axis is ± the corresponding column of P; r0 components match up to that sign.
  for (int i = 0; i < 3; ++i) {
    const double s = b.principal_axes().col(i).dot(P.col(i)) > 0 ? 1.0 : -1.0;
    EXPECT_NEAR((b.principal_axes().col(i) - s * P.col(i)).norm(), 0.0, 1e3 * kEps);
    EXPECT_NEAR(b.center_of_mass()[i], s * Vec3(0.1, -0.2, 0.3)[i], 1e3 * kEps);
  }
}

TEST(Body, DiagonalTensorKeepsUserAxes) {
  const Body b = Body::from_tensor(Vec3(3, 2, 2).asDiagonal(), 1, Vec3(1, 0, 0));
  EXPECT_EQ(b.inertia(), Vec3(3, 2, 2));
  EXPECT_TRUE(b.principal_axes().isIdentity(0.0));
}

TEST(Body, RejectsAsymmetricTensor) {
  Mat3 J = Vec3(1, 1, 1).asDiagonal();
  J(0, 1) = 0.1;
  EXPECT_THROW(Body::from_tensor(J, 1, Vec3::Zero()), InputError);
}

}  // namespace
}  // namespace test_body
}  // namespace newtop
