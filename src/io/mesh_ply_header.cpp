// PLY header reader (docs/exact_field.md, "Mesh files").

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "mesh_input.hpp"
#include "mesh_ply.hpp"

namespace newtop::io::detail::ply {
namespace {

std::optional<Type> type_named(std::string_view s) {
  static const std::pair<const char*, Type> kNames[] = {
      {"char", Type::i8},   {"int8", Type::i8},     {"uchar", Type::u8},   {"uint8", Type::u8},
      {"short", Type::i16}, {"int16", Type::i16},   {"ushort", Type::u16}, {"uint16", Type::u16},
      {"int", Type::i32},   {"int32", Type::i32},   {"uint", Type::u32},   {"uint32", Type::u32},
      {"float", Type::f32}, {"float32", Type::f32}, {"double", Type::f64}, {"float64", Type::f64}};
  for (const auto& [name, t] : kNames) {
    if (s == name) return t;
  }
  return std::nullopt;
}

}  // namespace

bool is_integer(Type t) { return t != Type::f32 && t != Type::f64; }

std::size_t size_of(Type t) {
  switch (t) {
    case Type::i8:
    case Type::u8:
      return 1;
    case Type::i16:
    case Type::u16:
      return 2;
    case Type::i32:
    case Type::u32:
    case Type::f32:
      return 4;
    case Type::f64:
      return 8;
  }
  return 8;
}

std::pair<std::int64_t, std::int64_t> range_of(Type t) {
  switch (t) {
    case Type::i8:
      return {-128, 127};
    case Type::u8:
      return {0, 255};
    case Type::i16:
      return {-32768, 32767};
    case Type::u16:
      return {0, 65535};
    case Type::i32:
      return {std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()};
    default:
      return {0, std::numeric_limits<std::uint32_t>::max()};
  }
}

namespace {

Property property(const Where& at, const std::vector<std::string_view>& tok) {
  Property p;
  p.list = tok.size() >= 2 && tok[1] == "list";
  if (tok.size() != (p.list ? 5u : 3u)) {
    fail(at, "expected `property TYPE NAME` or `property list COUNT_TYPE ITEM_TYPE NAME`");
  }
  const auto value = type_named(tok[p.list ? 3 : 1]);
  if (!value) fail(at, "unknown property type " + quote(tok[p.list ? 3 : 1]));
  p.type = *value;
  if (p.list) {
    const auto count = type_named(tok[2]);
    if (!count || !is_integer(*count)) {
      fail(at, "list count type: expected an integer type, found " + quote(tok[2]));
    }
    p.count_type = *count;
  }
  p.name = std::string(tok.back());
  return p;
}

void add_element(const Where& at, const std::vector<std::string_view>& tok, Header& h) {
  if (tok.size() != 3) fail(at, "expected `element NAME COUNT`");
  for (const Element& e : h.elements) {
    if (e.name == tok[1]) fail(at, "element " + quote(tok[1]) + " declared twice");
  }
  const std::int64_t limit = tok[1] == "vertex" ? kMaxVertices : kMaxFaces;
  const std::int64_t count =
      integer_in(at, "element " + std::string(tok[1]) + " count", tok[2], 0, limit);
  h.elements.push_back({std::string(tok[1]), count, {}});
}

}  // namespace

Header read_header(const std::string& path, std::string_view bytes) {
  Lines lines(bytes, '\0');
  const auto magic = lines.next_raw();
  if (!magic || magic->text != "ply") fail({path}, "expected the first line `ply`");
  Header h;
  bool format_seen = false;
  std::vector<std::string_view> tok;
  while (true) {
    const auto l = lines.next();
    if (!l) fail({path, lines.line()}, "the header ends without `end_header`");
    const Where at{path, l->number};
    split(l->text, tok);
    if (tok[0] == "end_header" && tok.size() == 1) {
      if (!format_seen) fail(at, "the header has no `format` line");
      h.data_offset = bytes.size() - lines.rest().size();
      h.lines = l->number;
      return h;
    }
    if (tok[0] == "comment" || tok[0] == "obj_info") continue;
    if (tok[0] == "format") {
      if (format_seen || tok.size() != 3 || tok[2] != "1.0") {
        fail(at, "expected one line `format ascii|binary_little_endian|binary_big_endian 1.0`");
      }
      if (tok[1] == "ascii") {
        h.format = Format::ascii;
      } else if (tok[1] == "binary_little_endian") {
        h.format = Format::binary_le;
      } else if (tok[1] == "binary_big_endian") {
        h.format = Format::binary_be;
      } else {
        fail(at, "unknown format " + quote(tok[1]));
      }
      format_seen = true;
    } else if (tok[0] == "element") {
      add_element(at, tok, h);
    } else if (tok[0] == "property") {
      if (h.elements.empty()) fail(at, "a property before any element");
      Property p = property(at, tok);
      for (const Property& q : h.elements.back().properties) {
        if (q.name == p.name) fail(at, "property " + quote(p.name) + " declared twice");
      }
      h.elements.back().properties.push_back(std::move(p));
    } else {
      fail(at, "unknown header line " + quote(tok[0]));
    }
  }
}

/// Names an element instance's property in messages, built only when one is needed.
}  // namespace newtop::io::detail::ply
