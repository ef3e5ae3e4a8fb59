#pragma once
// Internal: the header of a PLY file (Greg Turk's polygon file format, version 1.0): its format,
// and the elements with their properties in the order the data follow.

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace newtop::io::detail::ply {

enum class Type { i8, u8, i16, u16, i32, u32, f32, f64 };

struct Property {
  std::string name;
  Type type{};  // of the value, or of the items of a list
  bool list = false;
  Type count_type{};
};

struct Element {
  std::string name;
  std::int64_t count = 0;
  std::vector<Property> properties;
};

enum class Format { ascii, binary_le, binary_be };

struct Header {
  Format format{};
  std::vector<Element> elements;
  std::size_t data_offset = 0;  // first byte after end_header
  int lines = 0;                // lines of the header
};

bool is_integer(Type t);
/// Bytes of a value of the type in binary data.
std::size_t size_of(Type t);
/// Range of an integer type.
std::pair<std::int64_t, std::int64_t> range_of(Type t);

/// Reads and checks the header: the `ply` line, one `format` line, `element NAME COUNT` (vertex up
/// to kMaxVertices, others up to kMaxFaces), `property TYPE NAME` or `property list COUNT_TYPE
/// ITEM_TYPE NAME` (no duplicates), `comment` and `obj_info` lines, `end_header`.
Header read_header(const std::string& path, std::string_view bytes);

}  // namespace newtop::io::detail::ply
