#include "mesh_input.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <numeric>

#include "file_check.hpp"

namespace newtop::io::detail {
namespace {

/// Closes a file descriptor when leaving scope.
struct Fd {
  int fd = -1;
  explicit Fd(int d) : fd(d) {}
  Fd(Fd&& o) noexcept : fd(o.fd) { o.fd = -1; }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  Fd& operator=(Fd&&) = delete;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

/// Opens the file without blocking (O_NONBLOCK: a FIFO must not wait for a writer) and checks
/// what fstat says of it.
Fd open_checked(const std::string& path, struct stat& st) {
  Fd f{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (f.fd < 0 || ::fstat(f.fd, &st) != 0) {
    throw InputError(path + ": cannot read the file: " + std::strerror(errno));
  }
  if (!S_ISREG(st.st_mode)) {
    throw InputError(path + ": expected a regular file, found " + file_kind(st.st_mode));
  }
  if (st.st_size > kMaxInputBytes) {
    throw InputError(path + ": the file has " + std::to_string(st.st_size) +
                     " bytes, beyond the limit of " + std::to_string(kMaxInputBytes) +
                     " bytes (1 GiB)");
  }
  return f;
}

}  // namespace

void check_input_file(const std::string& path) {
  struct stat st {};
  (void)open_checked(path, st);
}

std::string read_input_file(const std::string& path) {
  struct stat st {};
  const Fd f = open_checked(path, st);
  std::string bytes(static_cast<std::size_t>(st.st_size), '\0');
  std::size_t got = 0;
  while (got < bytes.size()) {
    const ssize_t n = ::read(f.fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError(path + ": cannot read the file: " + std::strerror(errno));
    if (n == 0) break;  // the file shrank while being read: keep what is there
    got += static_cast<std::size_t>(n);
  }
  bytes.resize(got);
  return bytes;
}

std::string quote(std::string_view token) {
  constexpr std::size_t kShown = 40;
  std::string out = "\"";
  for (std::size_t i = 0; i < std::min(token.size(), kShown); ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f && c != '"' && c != '\\') {
      out += static_cast<char>(c);
    } else if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else {
      static constexpr char kHex[] = "0123456789abcdef";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  out += token.size() > kShown ? "\"…" : "\"";
  return out;
}

std::string Where::str() const { return line > 0 ? path + ":" + std::to_string(line) : path; }

void fail(const Where& at, const std::string& what) { throw InputError(at.str() + ": " + what); }

std::optional<TextLine> Lines::next_raw() {
  if (pos_ >= text_.size()) return std::nullopt;
  const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
  std::string_view line = text_.substr(pos_, end - pos_);
  pos_ = end + 1;
  ++line_;
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  if (comment_ != '\0') line = line.substr(0, std::min(line.find(comment_), line.size()));
  return TextLine{line_, line};
}

std::optional<TextLine> Lines::next() {
  while (auto l = next_raw()) {
    if (std::any_of(l->text.begin(), l->text.end(), [](char c) { return !is_space(c); })) return l;
  }
  return std::nullopt;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

void split(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
}

std::optional<double> parse_double(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+') {
    token.remove_prefix(1);
  }
  double x = 0.0;
  const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), x);
  if (ptr != token.data() + token.size()) return std::nullopt;
  if (ec == std::errc::result_out_of_range) {
    // Overflow is refused; underflow reads as what strtod rounds it to (0 or a subnormal).
    const std::string copy(token);
    const double y = std::strtod(copy.c_str(), nullptr);
    if (std::isinf(y)) return std::nullopt;
    return y;
  }
  if (ec != std::errc{}) return std::nullopt;
  return x;
}

std::optional<std::int64_t> parse_integer(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+') {
    token.remove_prefix(1);
  }
  std::int64_t v = 0;
  const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
  if (ec != std::errc{} || ptr != token.data() + token.size()) return std::nullopt;
  return v;
}

namespace {

/// A decimal number too large for a double (e.g. 1e400).
bool overflows(std::string_view token) {
  const std::string copy(token);
  if (copy.empty() || copy.find_first_of("xXnN") != std::string::npos) return false;
  char* end = nullptr;
  const double y = std::strtod(copy.c_str(), &end);
  return end == copy.c_str() + copy.size() && std::isinf(y);
}

}  // namespace

double finite_number(const Where& at, const std::string& what, std::string_view token) {
  const auto x = parse_double(token);
  if (x && std::isfinite(*x)) return *x;
  std::string found = quote(token);
  if (!x && overflows(token)) found += " (beyond the range of a double)";
  fail(at, what + ": expected a finite number, found " + found);
}

std::int64_t integer(const Where& at, const std::string& what, std::string_view token) {
  const auto v = parse_integer(token);
  if (!v) fail(at, what + ": expected an integer, found " + quote(token));
  return *v;
}

std::int64_t integer_in(const Where& at, const std::string& what, std::string_view token,
                        std::int64_t lo, std::int64_t hi) {
  const auto v = parse_integer(token);
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!v) fail(at, what + ": expected an integer in " + range + ", found " + quote(token));
  if (*v < lo || *v > hi) {
    fail(at, what + ": expected an integer in " + range + ", found " + std::to_string(*v));
  }
  return *v;
}

int index_in(const Where& at, const std::string& what, std::string_view token, std::int64_t base,
             std::int64_t count) {
  const auto v = parse_integer(token);
  if (!v) fail(at, what + ": expected an integer, found " + quote(token));
  if (*v < base || *v - base >= count) {
    fail(at, what + " " + std::to_string(*v) + " out of range [" + std::to_string(base) + ", " +
                 std::to_string(base + count) + ")");
  }
  return static_cast<int>(*v - base);
}

void check_limit(const Where& at, const std::string& what, std::int64_t count, std::int64_t limit) {
  if (count > limit) {
    fail(at,
         what + ": " + std::to_string(count) + " exceeds the limit of " + std::to_string(limit));
  }
}

void add_polygon(const Where& at, const std::vector<int>& polygon, std::vector<Triangle>& faces) {
  const auto triangles = static_cast<std::int64_t>(polygon.size()) - 2;
  check_limit(at, "number of triangles", static_cast<std::int64_t>(faces.size()) + triangles,
              kMaxFaces);
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
    faces.push_back({polygon[0], polygon[k], polygon[k + 1]});
  }
}

namespace {

/// For each vertex, the smallest index of a vertex with the same coordinates.
std::vector<int> first_identical(const std::vector<Vec3>& v) {
  std::vector<int> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  // Lexicographic on the values (+0 == −0); stable, so each run of equal vertices starts with its
  // smallest index. All coordinates are finite: the readers refuse the others.
  const auto less = [&](int a, int b) {
    for (int c = 0; c < 3; ++c) {
      if (v[a][c] != v[b][c]) return v[a][c] < v[b][c];
    }
    return false;
  };
  std::stable_sort(order.begin(), order.end(), less);
  std::vector<int> first(v.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    first[order[k]] = k > 0 && !less(order[k - 1], order[k]) ? first[order[k - 1]] : order[k];
  }
  return first;
}

}  // namespace

void join_identical_vertices(Mesh& mesh) {
  const std::vector<int> first = first_identical(mesh.vertices);
  for (Triangle& t : mesh.faces) {
    for (int& c : t) c = first[c];
  }
}

void merge_identical_vertices(Mesh& mesh) {
  const std::vector<int> first = first_identical(mesh.vertices);
  std::vector<int> index(mesh.vertices.size(), -1);
  std::vector<Vec3> kept;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (first[i] == static_cast<int>(i)) {
      index[i] = static_cast<int>(kept.size());
      kept.push_back(mesh.vertices[i]);
    }
  }
  for (Triangle& t : mesh.faces) {
    for (int& c : t) c = index[first[c]];
  }
  mesh.vertices = std::move(kept);
}

}  // namespace newtop::io::detail
