// PLY reader (Greg Turk's polygon file format): the header declares elements and their properties;
// the data follow in ASCII (one element instance a line) or in binary (either byte order). Every
// element is read in the header's order; vertex x, y, z and the face list vertex_indices (or
// vertex_index) are kept, everything else is checked and skipped. Counts, list lengths and byte
// sizes are checked against the data before anything is allocated.

#include "mesh_ply.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "mesh_formats.hpp"
#include "mesh_input.hpp"

namespace newtop::io::detail {
namespace {

using ply::Element;
using ply::Format;
using ply::Header;
using ply::is_integer;
using ply::Property;
using ply::range_of;
using ply::size_of;
using ply::Type;

struct At {
  const Element& element;
  std::int64_t k;
  const Property& property;
  std::string str() const { return element.name + " " + std::to_string(k) + ": " + property.name; }
};

std::string integer_range(Type t) {
  const auto [lo, hi] = range_of(t);
  return "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
}

/// Values of the ASCII data: one element instance a line.
class AsciiValues {
 public:
  AsciiValues(const std::string& path, std::string_view data, int header_lines)
      : path_(path), lines_(data, '\0'), offset_(header_lines) {}

  void begin(const Element& e, std::int64_t k) {
    const auto l = lines_.next();
    if (!l) {
      line_ = offset_ + lines_.line();
      fail("element " + e.name + ": the header announces " + std::to_string(e.count) +
           ", the file ends after " + std::to_string(k));
    }
    line_ = offset_ + l->number;
    split(l->text, tok_);
    next_ = 0;
  }
  std::int64_t integer(Type t, const At& at) {
    const std::string_view s = token(at);
    const auto v = parse_integer(s);
    const auto [lo, hi] = range_of(t);
    if (!v || *v < lo || *v > hi) {
      fail(at.str() + ": expected an integer in " + integer_range(t) + ", found " +
           (v ? std::to_string(*v) : quote(s)));
    }
    return *v;
  }
  double number(Type t, const At& at) {
    if (is_integer(t)) return static_cast<double>(integer(t, at));
    const std::string_view s = token(at);
    const auto x = parse_double(s);
    if (!x || !std::isfinite(*x)) fail(at.str() + ": expected a finite number, found " + quote(s));
    return *x;
  }
  void skip(Type t, const At& at) {
    if (is_integer(t)) {
      (void)integer(t, at);
    } else if (const std::string_view s = token(at); !parse_double(s)) {
      fail(at.str() + ": expected a number, found " + quote(s));
    }
  }
  /// A list length: at most the values left on the line.
  std::int64_t count(Type t, const At& at, Type) {
    const std::int64_t n = integer(t, at);
    const auto left = static_cast<std::int64_t>(tok_.size() - next_);
    if (n < 0 || n > left) {
      fail(at.str() + ": the list length is " + std::to_string(n) + ", the line holds " +
           std::to_string(left) + " more values");
    }
    return n;
  }
  void end(const Element& e, std::int64_t k) {
    if (next_ != tok_.size()) {
      fail(e.name + " " + std::to_string(k) + ": expected " + std::to_string(next_) +
           " values on the line, found " + std::to_string(tok_.size()));
    }
  }
  void finish() {
    if (const auto l = lines_.next()) {
      line_ = offset_ + l->number;
      fail("data after the last element the header announces");
    }
  }
  Where where() const { return {path_, line_}; }
  [[noreturn]] void fail(const std::string& what) const { detail::fail(where(), what); }

 private:
  std::string_view token(const At& at) {
    if (next_ >= tok_.size()) fail(at.str() + ": the line ends early");
    return tok_[next_++];
  }
  const std::string& path_;
  Lines lines_;
  int offset_;
  int line_ = 0;
  std::vector<std::string_view> tok_;
  std::size_t next_ = 0;
};

/// Values of the binary data, in the file's byte order.
class BinaryValues {
 public:
  BinaryValues(const std::string& path, std::string_view bytes, std::size_t start, bool big)
      : path_(path), data_(bytes), pos_(start), big_(big) {}

  void begin(const Element&, std::int64_t) {}
  std::int64_t integer(Type t, const At& at) {
    const std::uint64_t raw = take(t, at);
    switch (t) {
      case Type::i8:
        return static_cast<std::int8_t>(raw);
      case Type::i16:
        return static_cast<std::int16_t>(raw);
      case Type::i32:
        return static_cast<std::int32_t>(raw);
      default:
        return static_cast<std::int64_t>(raw);
    }
  }
  double number(Type t, const At& at) {
    if (is_integer(t)) return static_cast<double>(integer(t, at));
    const std::uint64_t raw = take(t, at);
    const double x = t == Type::f32 ? std::bit_cast<float>(static_cast<std::uint32_t>(raw))
                                    : std::bit_cast<double>(raw);
    if (!std::isfinite(x)) fail(at.str() + ": expected a finite number, found " + format_number(x));
    return x;
  }
  void skip(Type t, const At& at) { (void)take(t, at); }
  /// A list length: at most the items of that type left in the file.
  std::int64_t count(Type t, const At& at, Type item) {
    const std::int64_t n = integer(t, at);
    const auto left = static_cast<std::int64_t>((data_.size() - pos_) / size_of(item));
    if (n < 0 || n > left) {
      fail(at.str() + ": the list length is " + std::to_string(n) + ", the file holds " +
           std::to_string(left) + " more items");
    }
    return n;
  }
  void end(const Element&, std::int64_t) {}
  void finish() {
    if (pos_ != data_.size()) {
      last_ = pos_;
      fail(std::to_string(data_.size() - pos_) +
           " bytes after the last element the header announces");
    }
  }
  Where where() const { return {path_, 0}; }
  [[noreturn]] void fail(const std::string& what) const {
    detail::fail({path_}, "byte " + std::to_string(last_) + ": " + what);
  }

 private:
  std::uint64_t take(Type t, const At& at) {
    const std::size_t n = size_of(t);
    last_ = pos_;
    if (data_.size() - pos_ < n) fail(at.str() + ": the file ends in the middle of a value");
    std::uint64_t raw = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const auto byte = static_cast<unsigned char>(data_[pos_ + (big_ ? n - 1 - i : i)]);
      raw |= static_cast<std::uint64_t>(byte) << (8 * i);
    }
    pos_ += n;
    return raw;
  }
  const std::string& path_;
  std::string_view data_;
  std::size_t pos_;
  std::size_t last_ = 0;
  bool big_;
};

bool is_face_list(const Property& p) {
  return p.list && (p.name == "vertex_indices" || p.name == "vertex_index");
}

/// The element of that name, or nullptr.
const Element* element_named(const Header& h, std::string_view name) {
  for (const Element& e : h.elements) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

/// The face element's first list named vertex_indices or vertex_index, or nullptr.
const Property* face_list(const Header& h) {
  const Element* face = element_named(h, "face");
  if (face == nullptr) return nullptr;
  for (const Property& p : face->properties) {
    if (is_face_list(p)) return &p;
  }
  return nullptr;
}

bool has_scalar(const Element* e, std::string_view name) {
  if (e == nullptr) return false;
  return std::any_of(e->properties.begin(), e->properties.end(),
                     [&](const Property& p) { return p.name == name && !p.list; });
}

/// Checks that the header declares what a surface needs: vertex x, y, z and a face list.
void check_layout(const std::string& path, const Header& h) {
  for (const Element& e : h.elements) {
    if (e.count > 0 && e.properties.empty()) {
      fail({path}, "element " + quote(e.name) + " has " + std::to_string(e.count) +
                       " instances but no properties");
    }
  }
  const Element* vertex = element_named(h, "vertex");
  if (!has_scalar(vertex, "x") || !has_scalar(vertex, "y") || !has_scalar(vertex, "z")) {
    fail({path}, "expected an element vertex with properties x, y and z");
  }
  const Property* list = face_list(h);
  if (list == nullptr) fail({path}, "expected an element face with a list property vertex_indices");
  if (!is_integer(list->type)) {
    fail({path}, "face " + list->name + ": expected an integer item type");
  }
}

template <class Values>
void read_face_list(Values& in, const At& at, std::int64_t nv, Mesh& mesh,
                    std::vector<int>& polygon) {
  const std::int64_t n = in.count(at.property.count_type, at, at.property.type);
  if (n < 3) in.fail(at.str() + ": expected at least 3 vertex indices, found " + std::to_string(n));
  check_limit(in.where(), "number of triangles",
              static_cast<std::int64_t>(mesh.faces.size()) + n - 2, kMaxFaces);
  polygon.clear();
  for (std::int64_t j = 0; j < n; ++j) {
    const std::int64_t v = in.integer(at.property.type, at);
    if (v < 0 || v >= nv) {
      in.fail(at.str() + ": vertex index " + std::to_string(v) + " out of range [0, " +
              std::to_string(nv) + ")");
    }
    polygon.push_back(static_cast<int>(v));
  }
  add_polygon(in.where(), polygon, mesh.faces);
}

template <class Values>
Mesh read_data(Values& in, const Header& h) {
  const std::int64_t nv = element_named(h, "vertex")->count;
  const Property* faces = face_list(h);
  Mesh mesh;
  std::vector<int> polygon;
  for (const Element& e : h.elements) {
    const bool vertex = e.name == "vertex";
    for (std::int64_t k = 0; k < e.count; ++k) {
      in.begin(e, k);
      Vec3 x = Vec3::Zero();
      for (const Property& p : e.properties) {
        const At at{e, k, p};
        if (&p == faces) {
          read_face_list(in, at, nv, mesh, polygon);
        } else if (p.list) {
          for (std::int64_t j = in.count(p.count_type, at, p.type); j > 0; --j) in.skip(p.type, at);
        } else if (vertex && p.name.size() == 1 && p.name[0] >= 'x' && p.name[0] <= 'z') {
          x[p.name[0] - 'x'] = in.number(p.type, at);
        } else {
          in.skip(p.type, at);
        }
      }
      in.end(e, k);
      if (vertex) mesh.vertices.push_back(x);
    }
  }
  in.finish();
  return mesh;
}

}  // namespace

Mesh read_ply(const std::string& path, std::string_view bytes) {
  const Header h = ply::read_header(path, bytes);
  check_layout(path, h);
  Mesh mesh;
  if (h.format == Format::ascii) {
    AsciiValues in(path, bytes.substr(h.data_offset), h.lines);
    mesh = read_data(in, h);
  } else {
    BinaryValues in(path, bytes, h.data_offset, h.format == Format::binary_be);
    mesh = read_data(in, h);
  }
  join_identical_vertices(mesh);
  return mesh;
}

}  // namespace newtop::io::detail