#pragma once
// Hostile mesh, TetGen and point-mass files, each with its exact bytes and the one line newtop
// must answer (the message after the file's path). Used by the library tests
// (tests/io/test_mesh_errors.cpp) and the command-line tests (tests/cli/test_mesh_cli.cpp); each
// is also a regression input of its fuzz corpus (tests/fuzz/corpus/READER/NAME).

#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace newtop::test {

using namespace std::string_literals;  // bytes with NULs

struct BadFile {
  const char* name;    // also the file name in tests/fuzz/corpus/<corpus>/
  const char* corpus;  // mesh_off, mesh_ply, mesh_stl, mesh_obj, tetgen (node|face), point_csv
  std::string bytes;
  std::string message;  // after the path
};

/// The cube of data/polyhedra as OFF, with `last` as the last line.
inline std::string off_cube(const std::string& last) {
  return "OFF\n8 12 0\n-1 -1 -1\n1 -1 -1\n1 1 -1\n-1 1 -1\n-1 -1 1\n1 -1 1\n1 1 1\n-1 1 1\n"
         "3 1 3 2\n3 0 3 1\n3 0 1 5\n3 0 5 4\n3 0 7 3\n3 0 4 7\n3 1 2 6\n3 1 6 5\n3 2 3 6\n"
         "3 3 7 6\n3 4 5 6\n" +
         last + "\n";
}

/// The cube's TetGen .node file.
inline const std::string kCubeNode =
    "8 3 0 0\n0 -1 -1 -1\n1 1 -1 -1\n2 1 1 -1\n3 -1 1 -1\n4 -1 -1 1\n5 1 -1 1\n6 1 1 1\n"
    "7 -1 1 1\n";

/// The cube's .node and .face files in the tetgen corpus's form (`NODE|FACE`), with `last` as the
/// last face line.
inline std::string tetgen_cube(const std::string& last) {
  return kCubeNode +
         "|12 0\n0 1 3 2\n1 0 3 1\n2 0 1 5\n3 0 5 4\n4 0 7 3\n5 0 4 7\n6 1 2 6\n7 1 6 5\n"
         "8 2 3 6\n9 3 7 6\n10 4 5 6\n" +
         last + "\n";
}

inline const std::string kPlyHead =
    "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float "
    "y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";

inline const std::vector<BadFile>& bad_files() {
  static const std::vector<BadFile> cases = {
      // --- OFF: the inputs and what Assimp 5.2.5 aborted or hung on ---
      {"issue_header_promises_a_face", "mesh_off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n",
       ":5: the header (line 2) announces 1 face, the file ends after 0"},
      {"issue_index_99_on_8_vertices", "mesh_off", off_cube("3 4 6 99"),
       ":22: face 11: vertex index 99 out of range [0, 8)"},
      {"assimp_abort_vertex_line_holds_a_face", "mesh_off",
       "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
       ":6: vertex 3: expected 3 numbers, found 4 values"},
      {"assimp_abort_counts_only", "mesh_off", "OFF\n1 1 0",
       ":2: the header (line 2) announces 1 vertex, the file ends after 0"},
      {"assimp_abort_binary_bytes", "mesh_off", "OFF\n1 1 0\n0 0 0\x01\0\0\0\0\0\0\0\n"s,
       ":3: vertex 0: expected a finite number, found "
       "\"0\\x01\\x00\\x00\\x00\\x00\\x00\\x00\\x00\""},
      {"assimp_hang_vertex_count", "mesh_off", "OFF\n99999999 1 0\n0 0 0\n",
       ":2: vertex count: expected an integer in [0, 16777216], found 99999999"},
      {"assimp_hang_face_count", "mesh_off", "OFF\n3 99999999 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
       ":2: face count: expected an integer in [0, 33554432], found 99999999"},
      {"negative_index", "mesh_off", off_cube("3 4 6 -1"),
       ":22: face 11: vertex index -1 out of range [0, 8)"},
      {"index_beyond_64_bits", "mesh_off", off_cube("3 4 6 99999999999999999999"),
       ":22: face 11: vertex index: expected an integer, found \"99999999999999999999\""},
      {"extra_face", "mesh_off", off_cube("3 4 6 7\n3 4 6 7"),
       ":23: expected the end of the file after the 12 faces the header (line 2) announces, found "
       "\"3\""},
      {"infinite_coordinate", "mesh_off", "OFF\n3 1 0\n0 0 0\n1e999 0 0\n0 1 0\n3 0 1 2\n",
       ":4: vertex 1: expected a finite number, found \"1e999\" (beyond the range of a double)"},
      {"empty", "mesh_off", "", ": expected the keyword OFF, found an empty file"},
      // --- PLY ---
      {"issue_format_ascii_without_end", "mesh_ply", "ply\nformat ascii",
       ":2: expected one line `format ascii|binary_little_endian|binary_big_endian 1.0`"},
      {"assimp_segv_truncated_binary_face", "mesh_ply",
       kPlyHead + std::string(36, '\0') + "\x03\0\0\0\0\x01"s,
       ": byte 205: face 0: vertex_indices: the list length is 3, the file holds 1 more items"},
      {"assimp_segv_list_length_255", "mesh_ply",
       kPlyHead + std::string(36, '\0') + "\xff\0\0\0\0\x01"s,
       ": byte 205: face 0: vertex_indices: the list length is 255, the file holds 1 more items"},
      {"truncated_ascii_face", "mesh_ply",
       "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty "
       "float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 "
       "0\n0 1 0\n3 0 1",
       ":13: face 0: vertex_indices: the list length is 3, the line holds 2 more values"},
      {"end_header_is_the_last_byte", "mesh_ply",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty "
       "float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header",
       ":9: element vertex: the header announces 1, the file ends after 0"},
      {"vertex_count_beyond_limit", "mesh_ply",
       "ply\nformat ascii 1.0\nelement vertex 4294967295\nproperty float x\nend_header\n",
       ":3: element vertex count: expected an integer in [0, 16777216], found 4294967295"},
      {"no_face_element", "mesh_ply",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty "
       "float z\nend_header\n0 0 0\n",
       ": expected an element face with a list property vertex_indices"},
      // --- STL ---
      {"too_short", "mesh_stl", "\x01\x02\x03"s,
       ": not an STL file: it does not begin with `solid` and is shorter than the 84 bytes of a "
       "binary STL"},
      {"binary_size_mismatch", "mesh_stl",
       std::string(80, ' ') + "\x02\0\0\0"s + std::string(50, '\0'),
       ": not an STL file: a binary STL of 2 facets has 184 bytes, the file 134, and it does not "
       "begin with `solid`"},
      {"ascii_nan_corner", "mesh_stl",
       "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex nan 0 0\nvertex 0 1 "
       "0\nendloop\nendfacet\nendsolid t\n",
       ":5: facet 0: expected a finite number, found \"nan\""},
      {"ascii_without_endloop", "mesh_stl",
       "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
       "endfacet\nendsolid t\n",
       ":7: expected `endloop`, found \"endfacet\""},
      // --- OBJ ---
      {"index_out_of_range", "mesh_obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n",
       ":4: face: vertex index 4 out of range [1, 3] (or [-3, -1] from the end)"},
      {"index_zero", "mesh_obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n",
       ":4: face: vertex index 0 out of range [1, 3] (or [-3, -1] from the end)"},
      {"free_form_surface", "mesh_obj", "v 0 0 0\ncstype bspline\nsurf 0 1 0 1 1\n",
       ":2: free-form geometry (\"cstype\") is not supported: newtop reads polygonal meshes (v "
       "and f)"},
      {"four_part_corner", "mesh_obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3\n",
       ":4: face corner \"1/1/1/1\": expected v, v/vt, v//vn or v/vt/vn"},
      // --- TetGen (.node before the '|', .face after) ---
      {"issue_node_count_minus_one", "tetgen", "-1 3 0 0\n0 0 0 0\n|",
       ".node:1: count: expected an integer in [0, 16777216], found -1"},
      {"issue_index_1e10", "tetgen", tetgen_cube("11 4 6 1e10"),
       ".face:13: face 11: node index: expected an integer, found \"1e10\""},
      {"issue_index_10000000000", "tetgen", tetgen_cube("11 4 6 10000000000"),
       ".face:13: face 11: node index 10000000000 out of range [0, 8)"},
      {"index_int_min", "tetgen", tetgen_cube("11 4 6 -2147483648"),
       ".face:13: face 11: node index -2147483648 out of range [0, 8)"},
      {"issue_face_file_is_a_vertical_tab", "tetgen", kCubeNode + "|\v",
       ".face: expected a header `count markers`, found nothing"},
      {"node_count_1e300", "tetgen", "1e300 3 0 0\n0 0 0 0\n|",
       ".node:1: count: expected an integer in [0, 16777216], found \"1e300\""},
      {"fractional_face_count", "tetgen", kCubeNode + "|12.5 0\n",
       ".face:1: count: expected an integer in [0, 33554432], found \"12.5\""},
      {"node_numbering_gap", "tetgen", "4 3 0 0\n0 0 0 0\n1 1 0 0\n3 0 1 0\n4 0 0 1\n|",
       ".node:4: node index: expected 2 (numbered consecutively from 0), found 3"},
      // --- point-mass CSV ---
      {"issue_inf_in_first_row", "point_csv", "inf, 0, 0, 0\n1, 1, 0, 0\n",
       ":1: column 1 (m): expected a finite number, found \"inf\""},
      {"nan_after_header", "point_csv", "m, x, y, z\n1, 0, 0, 0\n2, 1, nan, 0\n",
       ":3: column 3 (y): expected a finite number, found \"nan\""},
      {"three_columns", "point_csv", "# masses\n1, 0, 0\n",
       ":2: expected 4 fields `m, x, y, z`, found 3"},
      {"empty_field", "point_csv", "1,,0,0\n",
       ":1: column 2 (x): expected a finite number, found \"\""},
      {"negative_mass", "point_csv", "m x y z\n-1 0 0 0\n",
       ":2: column 1 (m): expected a mass > 0, found -1"},
  };
  return cases;
}

/// Writes a case's file(s) as `stem` + extension (TetGen: stem.node and stem.face) and returns
/// the path to name: the mesh file, the .face of a TetGen pair, or the CSV file.
inline std::string write_case(const BadFile& c, const std::string& stem) {
  const auto put = [](const std::string& p, std::string_view bytes) {
    std::ofstream(p, std::ios::binary)
        .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  };
  const std::string_view k = c.corpus;
  if (k == "tetgen") {
    const std::size_t bar = c.bytes.find('|');
    put(stem + ".node", std::string_view(c.bytes).substr(0, bar));
    put(stem + ".face", bar == std::string::npos ? "" : std::string_view(c.bytes).substr(bar + 1));
    return stem + ".face";
  }
  const std::string path = stem + (k == "point_csv" ? ".csv" : "." + std::string(k.substr(5)));
  put(path, c.bytes);
  return path;
}

/// The line newtop must answer for a case written with write_case(c, stem).
inline std::string expected_message(const BadFile& c, const std::string& stem) {
  const std::string_view k = c.corpus;
  if (k == "tetgen") return stem + c.message;
  return stem + (k == "point_csv" ? ".csv" : "." + std::string(k.substr(5))) + c.message;
}

}  // namespace newtop::test
