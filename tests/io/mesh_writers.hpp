#pragma once
// Writers of the mesh formats newtop reads, for the tests: the same mesh in every format and
// encoding, written independently of the readers (numbers with 17 significant digits, binary
// values assembled byte by byte in the stated order).

#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "newtop/io/mesh.hpp"

namespace newtop::test {

inline std::string num(double x) { return format_number(x); }

inline std::string off_text(const io::Mesh& m) {
  std::string s =
      "OFF\n" + std::to_string(m.vertices.size()) + " " + std::to_string(m.faces.size()) + " 0\n";
  for (const Vec3& v : m.vertices) s += num(v[0]) + " " + num(v[1]) + " " + num(v[2]) + "\n";
  for (const Triangle& t : m.faces) {
    s += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) +
         "\n";
  }
  return s;
}

inline std::string obj_text(const io::Mesh& m) {
  std::string s = "# written by the tests\no mesh\n";
  for (const Vec3& v : m.vertices) s += "v " + num(v[0]) + " " + num(v[1]) + " " + num(v[2]) + "\n";
  for (const Triangle& t : m.faces) {
    s += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " +
         std::to_string(t[2] + 1) + "\n";
  }
  return s;
}

inline std::string ply_header(const io::Mesh& m, const char* format, const char* coord) {
  return std::string("ply\nformat ") + format +
         " 1.0\ncomment written by the tests\nelement vertex " + std::to_string(m.vertices.size()) +
         "\nproperty " + coord + " x\nproperty " + coord + " y\nproperty " + coord +
         " z\nelement face " + std::to_string(m.faces.size()) +
         "\nproperty list uchar int vertex_indices\nend_header\n";
}

inline std::string ply_ascii(const io::Mesh& m) {
  std::string s = ply_header(m, "ascii", "double");
  for (const Vec3& v : m.vertices) s += num(v[0]) + " " + num(v[1]) + " " + num(v[2]) + "\n";
  for (const Triangle& t : m.faces) {
    s += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) +
         "\n";
  }
  return s;
}

/// `n` bytes of `bits`, least significant first unless big_endian.
inline void put(std::string& s, std::uint64_t bits, int n, bool big_endian) {
  for (int i = 0; i < n; ++i) {
    const int shift = 8 * (big_endian ? n - 1 - i : i);
    s += static_cast<char>((bits >> shift) & 0xff);
  }
}

/// Binary PLY with double (or float, rounding the coordinates) vertices and int32 indices.
inline std::string ply_binary(const io::Mesh& m, bool big_endian, bool doubles = true) {
  std::string s = ply_header(m, big_endian ? "binary_big_endian" : "binary_little_endian",
                             doubles ? "double" : "float");
  for (const Vec3& v : m.vertices) {
    for (int c = 0; c < 3; ++c) {
      if (doubles) {
        put(s, std::bit_cast<std::uint64_t>(v[c]), 8, big_endian);
      } else {
        put(s, std::bit_cast<std::uint32_t>(static_cast<float>(v[c])), 4, big_endian);
      }
    }
  }
  for (const Triangle& t : m.faces) {
    put(s, 3, 1, big_endian);
    for (int c = 0; c < 3; ++c) put(s, static_cast<std::uint32_t>(t[c]), 4, big_endian);
  }
  return s;
}

inline std::string stl_ascii(const io::Mesh& m) {
  std::string s = "solid written by the tests\n";
  for (const Triangle& t : m.faces) {
    s += "  facet normal 0 0 0\n    outer loop\n";
    for (int c = 0; c < 3; ++c) {
      const Vec3& v = m.vertices[t[c]];
      s += "      vertex " + num(v[0]) + " " + num(v[1]) + " " + num(v[2]) + "\n";
    }
    s += "    endloop\n  endfacet\n";
  }
  return s + "endsolid written by the tests\n";
}

/// Binary STL (float32 corners, so coordinates are rounded to float); `header` fills the first of
/// the 80 header bytes.
inline std::string stl_binary(const io::Mesh& m, std::string_view header = "binary STL") {
  std::string s(header.substr(0, 80));
  s.resize(80, ' ');
  put(s, m.faces.size(), 4, false);
  for (const Triangle& t : m.faces) {
    s.append(12, '\0');  // normal (0, 0, 0)
    for (int c = 0; c < 3; ++c) {
      for (int k = 0; k < 3; ++k) {
        put(s, std::bit_cast<std::uint32_t>(static_cast<float>(m.vertices[t[c]][k])), 4, false);
      }
    }
    put(s, 0, 2, false);
  }
  return s;
}

inline std::filesystem::path write_file(const std::filesystem::path& p, std::string_view bytes) {
  std::filesystem::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return p;
}

}  // namespace newtop::test
