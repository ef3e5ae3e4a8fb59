// Valid meshes in every format and encoding give the same polyhedron: the cube and Eros of
// data/polyhedra (TetGen) written by the tests as OFF, OBJ, ASCII and binary PLY (both byte
// orders) and ASCII and binary STL, read back and compared bit for bit with the TetGen original.

#include <gtest/gtest.h>
#include <unistd.h>

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "mesh_writers.hpp"
#include "newtop/exact/mass_models.hpp"
#include "newtop/io/mesh.hpp"
#include "support/cli.hpp"

namespace newtop {
namespace test_mesh_formats {
namespace {

namespace fs = std::filesystem;

// Mass properties are sums of a few dozen products of exact coordinates: a few hundred ulps.
constexpr double kSumTol = 256 * std::numeric_limits<double>::epsilon();

const std::string kData = std::string(NEWTOP_DATA_DIR) + "/polyhedra/";

fs::path scratch(const std::string& name) {
  return newtop::test::scratch_path("newtop_mesh", name);
}

/// Same vertices (bit for bit) and same faces, in the same order.
void expect_same(const Polyhedron& a, const Polyhedron& b, const std::string& what) {
  ASSERT_EQ(a.faces().size(), b.faces().size()) << what;
  ASSERT_EQ(a.vertices().size(), b.vertices().size()) << what;
  EXPECT_TRUE(a.faces() == b.faces()) << what;
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.vertices().size(); ++i)
    differ += a.vertices()[i] != b.vertices()[i];
  EXPECT_EQ(differ, 0u) << what;
}

struct Writer {
  const char* name;
  const char* extension;
  std::function<std::string(const io::Mesh&)> write;
  bool exact;  // false when the format rounds coordinates to float
};

const std::vector<Writer>& writers() {
  static const std::vector<Writer> w = {
      {"off", ".off", test::off_text, true},
      {"obj", ".obj", test::obj_text, true},
      {"ply_ascii", ".ply", test::ply_ascii, true},
      {"ply_binary_le", ".ply", [](const io::Mesh& m) { return test::ply_binary(m, false); }, true},
      {"ply_binary_be", ".ply", [](const io::Mesh& m) { return test::ply_binary(m, true); }, true},
      {"ply_binary_float", ".ply",
       [](const io::Mesh& m) { return test::ply_binary(m, false, false); }, false},
      {"stl_ascii", ".stl", test::stl_ascii, true},
      {"stl_binary", ".stl", [](const io::Mesh& m) { return test::stl_binary(m); }, false},
  };
  return w;
}

/// The mesh with its coordinates rounded to float, as float formats store it.
io::Mesh rounded_to_float(io::Mesh m) {
  for (Vec3& v : m.vertices) v = v.cast<float>().cast<double>();
  return m;
}

void expect_every_format_gives(const std::string& tetgen_file, const std::string& name) {
  const io::Mesh original = io::read_mesh(kData + tetgen_file);
  const Polyhedron reference = io::load_polyhedron(kData + tetgen_file, 1.0);
  const io::Mesh rounded = rounded_to_float(original);
  const Polyhedron rounded_reference = Polyhedron::make(rounded.vertices, rounded.faces, 1.0);
  for (const Writer& w : writers()) {
    const fs::path p = scratch(name + "_" + w.name + w.extension);
    test::write_file(p, w.write(original));
    expect_same(io::load_polyhedron(p.string(), 1.0), w.exact ? reference : rounded_reference,
                name + " as " + w.name);
  }
}

TEST(MeshFormats, CubeInEveryFormatIsTheTetgenCube) {
  expect_every_format_gives("cube.node", "cube");
}

TEST(MeshFormats, ErosInEveryFormatIsTheTetgenEros) {
  // 24,235 nodes of which 7,374 on the surface: the interior ones go into every file and are
  // dropped by the polyhedron; STL keeps only the corners of its facets.
  expect_every_format_gives("eros.face", "eros");
}

TEST(MeshFormats, TsoulisPrismReadsItsOwnCoordinates) {
  const io::Mesh m = io::read_mesh(kData + "tsoulis.off");
  ASSERT_EQ(m.vertices.size(), 8u);
  ASSERT_EQ(m.faces.size(), 12u);
  EXPECT_EQ(m.vertices[0], Vec3(-20.0, 0.0, 25.0));
  EXPECT_EQ(m.vertices[6], Vec3(0.0, 10.0, 15.0));
  EXPECT_EQ(m.faces[0], (Triangle{0, 1, 3}));
  EXPECT_EQ(m.faces[11], (Triangle{4, 7, 6}));
  // 20 × 10 × 10 box: exact in binary, so the signed-tetrahedra sum is exact.
  EXPECT_EQ(io::load_polyhedron(kData + "tsoulis.off", 1.0).volume(), 2000.0);
}

// The cube [-1, 1]^3 as 6 quadrilaterals, each with its own 4 corners (24 vertices): the readers
// must split the quads and join the repeated corners into a closed surface.
constexpr const char* kQuadCubeOff = R"(OFF
# a cube of quads, every face with its own corners
24 6 0
-1 -1 -1
-1 1 -1
1 1 -1
1 -1 -1
-1 -1 1
1 -1 1
1 1 1
-1 1 1
-1 -1 -1
1 -1 -1
1 -1 1
-1 -1 1
1 -1 -1
1 1 -1
1 1 1
1 -1 1
1 1 -1
-1 1 -1
-1 1 1
1 1 1
-1 1 -1
-1 -1 -1
-1 -1 1
-1 1 1
4 0 1 2 3
4 4 5 6 7
4 8 9 10 11
4 12 13 14 15
4 16 17 18 19
4 20 21 22 23
)";

TEST(MeshFormats, QuadsAreSplitAndRepeatedCornersJoined) {
  const fs::path p = test::write_file(scratch("quad_cube.OFF"), kQuadCubeOff);
  const Polyhedron q = io::load_polyhedron(p.string(), 1.0);
  EXPECT_EQ(q.faces().size(), 12u);
  EXPECT_EQ(q.vertices().size(), 8u);
  // Side 2, density 1: J = M (2² + 2²) / 12 on the diagonal; sums of a few dozen products of
  // exact coordinates (kSumTol).
  EXPECT_NEAR(q.volume(), 8.0, kSumTol * 8.0);
  const MassProperties mp = mass_properties(q);
  EXPECT_LE(mp.center_of_mass.norm(), kSumTol);
  EXPECT_LE((mp.inertia_tensor - Mat3::Identity() * 8.0 * 8.0 / 12.0).norm(), kSumTol * 8.0);
}

TEST(MeshFormats, ObjCornerFormsAndRelativeIndices) {
  // The cube of cube.node: corners as v, v/vt, v//vn, v/vt/vn and negative (relative) indices.
  const fs::path p = test::write_file(scratch("forms.obj"), R"(mtllib cube.mtl
o cube
v -1 -1 -1
v 1 -1 -1
v 1 1 -1
v -1 1 -1
v -1 -1 1
v 1 -1 1
v 1 1 1 0.5 0.5 0.5
v -1 1 1 1.0
vt 0 0
vn 0 0 1
g bottom
usemtl grey
s off
f 2 4 3
f 1/1 4/1 2/1
f 1//1 2//1 6//1
f 1/1/1 6/1/1 5/1/1
f -8 -1 -5
f 1 5 8
f 2 3 7
f 2 7 6
f 3 4 7
f 4 8 7
f 5 6 7
f 5 7 8
l 1 2
)");
  expect_same(io::load_polyhedron(p.string(), 1.0), io::load_polyhedron(kData + "cube.node", 1.0),
              "obj corner forms");
}

TEST(MeshFormats, PlySkipsOtherElementsAndProperties) {
  // A tetrahedron with normals, colours, a texture list and an edge element around the geometry.
  const fs::path p = test::write_file(scratch("tet.ply"), R"(ply
format ascii 1.0
comment extra data that is read and skipped
obj_info made by hand
element vertex 4
property float nx
property double x
property double y
property uchar red
property double z
element edge 1
property int vertex1
property int vertex2
element face 4
property list uchar float texcoord
property list uchar uint vertex_index
property uchar green
end_header
0.5 0 0 255 0
0 1 0 0 0
0 0 1 7 0
0 0 0 1 1
0 1
2 0.5 0.5 3 0 2 1 8
0 3 0 1 3 0
0 3 0 3 2 0
0 3 1 2 3 0
)");
  const Polyhedron t = io::load_polyhedron(p.string(), 6.0);
  EXPECT_EQ(t.faces().size(), 4u);
  EXPECT_NEAR(mass_properties(t).mass, 1.0, kSumTol);
}

TEST(MeshFormats, BinaryStlWhoseHeaderSaysSolid) {
  // Many exporters begin the 80-byte header of a binary file with "solid": the size decides.
  const io::Mesh cube = io::read_mesh(kData + "cube.node");
  const fs::path p =
      test::write_file(scratch("solid_header.stl"), test::stl_binary(cube, "solid cube"));
  expect_same(io::load_polyhedron(p.string(), 1.0), io::load_polyhedron(kData + "cube.node", 1.0),
              "binary STL with a solid header");
}

TEST(MeshFormats, TetgenOneBasedWithAttributesMarkersAndNeighbours) {
  const fs::path node = test::write_file(scratch("one.node"), R"(4 3 1 1
1 1 0 0 0.25 7
2 0 1 0 0.25 7
3 0 0 1 0.25 7
4 0 0 0 0.25 7
)");
  test::write_file(scratch("one.face"),
                   R"(# faces, with boundary markers and the adjacent tetrahedra of tetgen -nn
4 1
1 1 2 3 1 1 -1
2 4 3 2 1 1 -1
3 4 1 3 1 1 -1
4 4 2 1 1 1 -1
)");
  const Polyhedron t = io::load_polyhedron(node.string(), 1.0);
  EXPECT_EQ(t.faces().size(), 4u);
  EXPECT_NEAR(t.volume(), 1.0 / 6.0, kSumTol);
}

}  // namespace
}  // namespace test_mesh_formats
}  // namespace newtop
