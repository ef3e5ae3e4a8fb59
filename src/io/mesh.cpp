#include "newtop/io/mesh.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include "mesh_formats.hpp"
#include "mesh_input.hpp"

namespace newtop::io {
namespace {

/// The file's extension in lower case, with its dot ("" when there is none).
std::string extension_of(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

Mesh read_mesh(const std::string& path) {
  const std::string ext = extension_of(path);
  if (ext == ".node" || ext == ".face") {
    // The other file of the pair gets the same extension case as the one named (cube.FACE and
    // cube.NODE); the one named keeps its name.
    const std::string stem = path.substr(0, path.size() - ext.size());
    const bool upper = std::isupper(static_cast<unsigned char>(path[path.size() - 4])) != 0;
    std::string node_path = stem + (upper ? ".NODE" : ".node");
    std::string face_path = stem + (upper ? ".FACE" : ".face");
    (ext == ".node" ? node_path : face_path) = path;
    const std::string node_bytes = detail::read_input_file(node_path);
    const std::string face_bytes = detail::read_input_file(face_path);
    return detail::read_tetgen(node_path, node_bytes, face_path, face_bytes);
  }
  using Reader = Mesh (*)(const std::string&, std::string_view);
  Reader reader = nullptr;
  if (ext == ".off") reader = detail::read_off;
  if (ext == ".ply") reader = detail::read_ply;
  if (ext == ".stl") reader = detail::read_stl;
  if (ext == ".obj") reader = detail::read_obj;
  if (reader == nullptr) {
    detail::check_input_file(path);  // a missing file or a directory is named as such first
    throw InputError(path + ": unsupported mesh format " +
                     (ext.empty() ? std::string("(no extension)") : detail::quote(ext)) +
                     ": newtop reads .obj, .off, .ply, .stl and TetGen .node/.face (convert "
                     "other formats first, e.g. with `assimp export FILE out.ply`)");
  }
  const std::string bytes = detail::read_input_file(path);
  return reader(path, bytes);
}

Polyhedron load_polyhedron(const std::string& path, double density, double scale,
                           Orientation orientation) {
  if (!std::isfinite(scale) || !(scale > 0)) {
    throw InputError("scale: expected a finite number > 0, found " + format_number(scale));
  }
  Mesh m = read_mesh(path);
  for (Vec3& v : m.vertices) v *= scale;
  try {
    return Polyhedron::make(std::move(m.vertices), std::move(m.faces), density, orientation);
  } catch (const InputError& e) {
    const std::string msg = e.what();
    if (msg.rfind("mesh:", 0) == 0) throw InputError(path + ": " + msg);
    throw;
  }
}

}  // namespace newtop::io
