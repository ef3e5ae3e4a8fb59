// Mass properties of the mass models against closed forms; mesh validation messages.

#include <gtest/gtest.h>

#include <limits>
#include <numbers>

#include "newtop/exact/mass_models.hpp"
#include "newtop/io/mesh.hpp"

namespace newtop {
namespace test_mass_models {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// Mass properties are sums of a few dozen products of exact coordinates: a few hundred ulps.
constexpr double kSumTol = 256 * kEps;

const std::string kData = std::string(NEWTOP_DATA_DIR) + "/polyhedra/";

void expect_mat_near(const Mat3& a, const Mat3& b, double tol) {
  EXPECT_LE((a - b).cwiseAbs().maxCoeff(), tol * b.cwiseAbs().maxCoeff()) << a << "\n vs\n" << b;
}

TEST(MassProperties, CubeFromTetgenFileMatchesClosedForm) {
  const io::Mesh m = io::read_mesh(kData + "cube.node");
  const Polyhedron p = Polyhedron::make(m.vertices, m.faces, 2.5);
  const MassProperties mp = mass_properties(p);
  EXPECT_NEAR(mp.mass, 2.5 * 8.0, kSumTol * 20);
  EXPECT_LE(mp.center_of_mass.norm(), kSumTol);
  // Cube of side 2: J = M (2² + 2²)/12 on the diagonal.
  expect_mat_near(mp.inertia_tensor, Mat3::Identity() * 20.0 * 8.0 / 12.0, kSumTol);
}

TEST(MassProperties, OffsetBoxObeysParallelAxisTheorem) {
  const Vec3 d(1.0, 2.0, 3.0), c(0.5, -0.25, 2.0);
  const MassProperties mp = mass_properties(make_box(d, 3.0, c));
  const double M = 3.0 * 6.0;
  EXPECT_NEAR(mp.mass, M, kSumTol * M);
  EXPECT_LE((mp.center_of_mass - c).norm(), kSumTol * c.norm());
  const Vec3 d2 = d.cwiseAbs2();
  const Mat3 Jc = (M / 12.0 * Vec3(d2.y() + d2.z(), d2.x() + d2.z(), d2.x() + d2.y())).asDiagonal();
  expect_mat_near(mp.inertia_tensor,
                  Jc + M * (c.squaredNorm() * Mat3::Identity() - c * c.transpose()), kSumTol);
}

TEST(MassProperties, TetrahedronMatchesClosedForm) {
  // Vertices O, a e_x, b e_y, c e_z: V = abc/6, r0 = (a, b, c)/4, J_xx = M(b² + c²)/10,
  // J_xy = −M ab/20.
  const double a = 1.0, b = 2.0, c = 3.0, sigma = 1.5;
  const Polyhedron p = Polyhedron::make({Vec3::Zero(), Vec3(a, 0, 0), Vec3(0, b, 0), Vec3(0, 0, c)},
                                        {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}, sigma);
  const MassProperties mp = mass_properties(p);
  const double M = sigma * a * b * c / 6.0;
  EXPECT_NEAR(mp.mass, M, kSumTol * M);
  EXPECT_LE((mp.center_of_mass - Vec3(a, b, c) / 4.0).norm(), kSumTol);
  Mat3 J;
  J << b * b + c * c, -a * b / 2, -a * c / 2, -a * b / 2, a * a + c * c, -b * c / 2, -a * c / 2,
      -b * c / 2, a * a + b * b;
  expect_mat_near(mp.inertia_tensor, M / 10.0 * J, kSumTol);
}

TEST(MassProperties, EllipsoidAndPointMasses) {
  const Ellipsoid e = Ellipsoid::make(Vec3(1, 2, 3), 2.0, Vec3(0, 0, 1));
  const MassProperties me = mass_properties(e);
  const double M = 2.0 * 4.0 / 3.0 * std::numbers::pi * 6.0;
  EXPECT_NEAR(me.mass, M, kSumTol * M);
  // J_zz about O = M(a² + b²)/5 (the offset is along z); J_xx = M(b² + c²)/5 + M·1².
  EXPECT_NEAR(me.inertia_tensor(2, 2), M * 5.0 / 5.0, kSumTol * M);
  EXPECT_NEAR(me.inertia_tensor(0, 0), M * 13.0 / 5.0 + M, kSumTol * M);
  const PointMasses pm({1.0, 3.0}, {Vec3(1, 0, 0), Vec3(0, 2, 0)});
  const MassProperties mp = mass_properties(pm);
  EXPECT_EQ(mp.mass, 4.0);
  EXPECT_EQ(mp.center_of_mass, Vec3(0.25, 1.5, 0.0));
  EXPECT_EQ(mp.inertia_tensor(2, 2), 1.0 + 12.0);
}

std::vector<Vec3> cube_vertices() { return make_box(Vec3(2, 2, 2), 1.0).vertices(); }
std::vector<Triangle> cube_faces() { return make_box(Vec3(2, 2, 2), 1.0).faces(); }

std::string error_of(std::vector<Vec3> v, std::vector<Triangle> f,
                     Orientation o = Orientation::check) {
  try {
    Polyhedron::make(std::move(v), std::move(f), 1.0, o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(MeshValidation, SaysExactlyWhatIsWrong) {
  auto f = cube_faces();
  std::swap(f[3][1], f[3][2]);
  EXPECT_NE(error_of(cube_vertices(), f).find("inconsistent orientation: faces"),
            std::string::npos);
  auto open = cube_faces();
  open.pop_back();
  EXPECT_NE(error_of(cube_vertices(), open).find("not a closed manifold surface: edge"),
            std::string::npos);
  auto inward = cube_faces();
  for (auto& t : inward) std::swap(t[1], t[2]);
  EXPECT_NE(error_of(cube_vertices(), inward).find("inward orientation"), std::string::npos);
  auto degenerate = cube_faces();
  degenerate[0][1] = degenerate[0][0];
  EXPECT_NE(error_of(cube_vertices(), degenerate).find("degenerate triangle: face 0"),
            std::string::npos);
  auto v = cube_vertices();
  auto collinear = cube_faces();
  v.push_back(0.5 * (v[0] + v[1]));
  collinear.push_back({0, 1, 8});
  EXPECT_NE(error_of(v, collinear).find("zero area"), std::string::npos);
}

TEST(MeshValidation, ReorientFixesFlippedAndInwardFaces) {
  const MassProperties ref = mass_properties(make_box(Vec3(2, 2, 2), 1.0));
  auto f = cube_faces();
  std::swap(f[3][1], f[3][2]);
  std::swap(f[7][1], f[7][2]);
  const Polyhedron p = Polyhedron::make(cube_vertices(), f, 1.0, Orientation::reorient);
  EXPECT_EQ(p.flipped_faces(), 2);
  EXPECT_NEAR(mass_properties(p).mass, ref.mass, kSumTol * ref.mass);
  for (auto& t : f) std::swap(t[1], t[2]);
  const Polyhedron q = Polyhedron::make(cube_vertices(), f, 1.0, Orientation::reorient);
  EXPECT_EQ(q.flipped_faces(), 10);  // 10 of the 12 input faces pointed inwards
  expect_mat_near(mass_properties(q).inertia_tensor, ref.inertia_tensor, kSumTol);
}

TEST(MeshFiles, OffThroughAssimpAndErosThroughTetgen) {
  // Tsoulis' prism: 20 × 10 × 25 box-like prism of 8 vertices and 12 triangles.
  const Polyhedron prism = io::load_polyhedron(kData + "tsoulis.off", 1.0);
  EXPECT_EQ(prism.faces().size(), 12u);
  EXPECT_NEAR(prism.volume(), 20.0 * 10.0 * 10.0, kSumTol * 2000.0);
  const Polyhedron eros = io::load_polyhedron(kData + "eros.face", 1.0);
  EXPECT_EQ(eros.faces().size(), 14744u);
  EXPECT_EQ(eros.vertices().size(), 7374u);  // interior TetGen nodes dropped
  EXPECT_THROW(io::read_mesh(kData + "missing.obj"), InputError);
}

}  // namespace
}  // namespace test_mass_models
}  // namespace newtop
