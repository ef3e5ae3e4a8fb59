#include "newtop/io/mesh.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <fstream>
#include <sstream>

namespace newtop::io {
namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// Non-comment, non-blank lines of a file, with their line numbers.
std::vector<std::pair<int, std::string>> data_lines(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot read the file (missing or unreadable)");
  std::vector<std::pair<int, std::string>> out;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    line = line.substr(0, line.find('#'));
    if (line.find_first_not_of(" \t\r,") != std::string::npos) out.emplace_back(n, line);
  }
  return out;
}

std::vector<double> numbers(const std::string& path, int n, const std::string& line) {
  std::string s = line;
  for (char& c : s) {
    if (c == ',') c = ' ';
  }
  std::istringstream is(s);
  std::vector<double> v;
  std::string tok;
  while (is >> tok) {
    std::size_t used = 0;
    double x = 0.0;
    try {
      x = std::stod(tok, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != tok.size()) {
      throw InputError(path + ":" + std::to_string(n) + ": expected a number, found \"" + tok +
                       "\"");
    }
    v.push_back(x);
  }
  return v;
}

Mesh read_tetgen(const std::string& stem) {
  Mesh m;
  const std::string node = stem + ".node", face = stem + ".face";
  auto nodes = data_lines(node);
  if (nodes.empty()) throw InputError(node + ": expected a header `count 3 …`, found nothing");
  const auto head = numbers(node, nodes[0].first, nodes[0].second);
  if (head.size() < 2 || head[1] != 3) {
    throw InputError(node + ":" + std::to_string(nodes[0].first) +
                     ": expected a header `count 3 attributes markers`");
  }
  const auto count = static_cast<std::size_t>(head[0]);
  if (nodes.size() < count + 1) {
    throw InputError(node + ": expected " + std::to_string(count) + " nodes, found " +
                     std::to_string(nodes.size() - 1));
  }
  int base = 0;
  for (std::size_t i = 1; i <= count; ++i) {
    const auto v = numbers(node, nodes[i].first, nodes[i].second);
    if (v.size() < 4)
      throw InputError(node + ":" + std::to_string(nodes[i].first) + ": expected `index x y z`");
    if (i == 1) base = static_cast<int>(v[0]);
    m.vertices.emplace_back(v[1], v[2], v[3]);
  }
  auto faces = data_lines(face);
  if (faces.empty()) throw InputError(face + ": expected a header `count markers`, found nothing");
  const auto fcount =
      static_cast<std::size_t>(numbers(face, faces[0].first, faces[0].second).at(0));
  if (faces.size() < fcount + 1) {
    throw InputError(face + ": expected " + std::to_string(fcount) + " faces, found " +
                     std::to_string(faces.size() - 1));
  }
  for (std::size_t i = 1; i <= fcount; ++i) {
    const auto v = numbers(face, faces[i].first, faces[i].second);
    if (v.size() < 4)
      throw InputError(face + ":" + std::to_string(faces[i].first) + ": expected `index i j k`");
    m.faces.push_back({static_cast<int>(v[1]) - base, static_cast<int>(v[2]) - base,
                       static_cast<int>(v[3]) - base});
  }
  return m;
}

Mesh read_assimp(const std::string& path) {
  Assimp::Importer importer;
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                  aiProcess_PreTransformVertices);
  if (!scene || !scene->HasMeshes()) {
    throw InputError(path + ": cannot read the mesh: " + std::string(importer.GetErrorString()));
  }
  Mesh m;
  for (unsigned k = 0; k < scene->mNumMeshes; ++k) {
    const aiMesh* mesh = scene->mMeshes[k];
    const int offset = static_cast<int>(m.vertices.size());
    for (unsigned i = 0; i < mesh->mNumVertices; ++i) {
      const aiVector3D& p = mesh->mVertices[i];
      m.vertices.emplace_back(p.x, p.y, p.z);
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) {
        throw InputError(path + ": expected triangles, found a face with " +
                         std::to_string(face.mNumIndices) + " vertices");
      }
      m.faces.push_back({offset + static_cast<int>(face.mIndices[0]),
                         offset + static_cast<int>(face.mIndices[1]),
                         offset + static_cast<int>(face.mIndices[2])});
    }
  }
  return m;
}

}  // namespace

Mesh read_mesh(const std::string& path) {
  if (ends_with(path, ".node") || ends_with(path, ".face")) {
    return read_tetgen(path.substr(0, path.size() - 5));
  }
  return read_assimp(path);
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

PointMasses read_point_masses(const std::string& path) {
  std::vector<double> masses;
  std::vector<Vec3> positions;
  const auto lines = data_lines(path);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const auto& [n, text] = lines[i];
    const bool header =
        i == 0 && text.find_first_of("abcdfghijklmnopqrstuvwxyzABCDFGHIJKLMNOPQRSTUVWXYZ") !=
                      std::string::npos;
    if (header) continue;
    const auto v = numbers(path, n, text);
    if (v.size() != 4) {
      throw InputError(path + ":" + std::to_string(n) +
                       ": expected 4 numbers `m, x, y, z`, found " + std::to_string(v.size()));
    }
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
