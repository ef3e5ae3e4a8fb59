// Point masses from CSV `m, x, y, z`. A line holding a comma is split at its commas (each field
// trimmed of blanks), any other line at its blanks; `#` starts a comment. The first line may be a
// header: four names, each beginning with a letter or '_' (optionally in double quotes) and not
// a number — `inf` or `nan` in the first line is a bad number, not a name. Every other field is a
// finite number.

#include <string>
#include <vector>

#include "mesh_input.hpp"
#include "newtop/io/mesh.hpp"

namespace newtop::io {
namespace {

constexpr const char* kColumns[] = {"m", "x", "y", "z"};

std::string_view trim(std::string_view s) {
  while (!s.empty() && detail::is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && detail::is_space(s.back())) s.remove_suffix(1);
  return s;
}

void fields_of(std::string_view line, std::vector<std::string_view>& out) {
  if (line.find(',') == std::string_view::npos) {
    detail::split(line, out);
    return;
  }
  out.clear();
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    out.push_back(
        trim(line.substr(start, comma == std::string_view::npos ? comma : comma - start)));
    if (comma == std::string_view::npos) return;
    start = comma + 1;
  }
}

bool is_name(std::string_view f) {
  if (f.size() >= 2 && f.front() == '"' && f.back() == '"') f = f.substr(1, f.size() - 2);
  if (f.empty() || detail::parse_double(f)) return false;
  const char c = f.front();
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

}  // namespace

PointMasses read_point_masses(const std::string& path) {
  const std::string bytes = detail::read_input_file(path);
  detail::Lines lines(bytes, '#');
  std::vector<double> masses;
  std::vector<Vec3> positions;
  std::vector<std::string_view> fields;
  bool first = true;
  while (const auto l = lines.next()) {
    const detail::Where at{path, l->number};
    fields_of(l->text, fields);
    if (fields.size() != 4) {
      detail::fail(at, "expected 4 fields `m, x, y, z`, found " + std::to_string(fields.size()));
    }
    const bool header = first && is_name(fields[0]) && is_name(fields[1]) && is_name(fields[2]) &&
                        is_name(fields[3]);
    first = false;
    if (header) continue;
    double v[4];
    for (int c = 0; c < 4; ++c) {
      v[c] = detail::finite_number(at, "column " + std::to_string(c + 1) + " (" + kColumns[c] + ")",
                                   fields[c]);
    }
    // PointMasses checks this too, but cannot say on which line.
    if (!(v[0] > 0))
      detail::fail(at, "column 1 (m): expected a mass > 0, found " + format_number(v[0]));
    detail::check_limit(at, "number of point masses", static_cast<std::int64_t>(masses.size()) + 1,
                        kMaxPointMasses);
    masses.push_back(v[0]);
    positions.emplace_back(v[1], v[2], v[3]);
  }
  try {
    return PointMasses(std::move(masses), std::move(positions));
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}

}  // namespace newtop::io
