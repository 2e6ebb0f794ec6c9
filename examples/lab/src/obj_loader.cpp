#include "lab/obj_loader.hpp"

#include "lab/error.hpp"
#include "lab/file_util.hpp"

#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace snell::lab {

namespace {

// tinyobjloader reads a number it cannot parse as 0 and an index past the int
// range wrapped around (atoi), so a truncated or corrupt file would load as a
// wrong mesh without a word; and it converts numbers of lines the lab never
// uses to int unchecked (a `vw` skin-weight joint id of 1e30 is undefined
// behaviour inside the library, found by fuzzing). This pass checks
// the lines the lab uses (v, vn, f) and names the line of the first bad one;
// it returns the only text tinyobjloader is given: those lines rebuilt from
// their checked tokens, with the texture-coordinate part of each face corner
// dropped (the lab ignores it), and every other line (vt, vw, l, p, s, o, g,
// usemtl, mtllib, t, anything unknown) left empty, so line numbers still match.
class ObjLineCheck {
 public:
  ObjLineCheck(const std::string& text, const std::string& name) : text_(text), name_(name) {}

  std::string run() {
    // Pass 1 counts: a positive index may refer to a vertex defined further down.
    forEachLine([this](const std::vector<std::string>& t) {
      if (t[0] == "v") ++total_[0];
      if (t[0] == "vt") ++total_[1];
      if (t[0] == "vn") ++total_[2];
    });
    std::string checked;
    checked.reserve(text_.size());
    std::size_t lines = 0;
    forEachLine([&](const std::vector<std::string>& t) {
      for (; lines + 1 < line_; ++lines) checked += '\n';
      if (t[0] == "v") {
        checkNumbers(t, "vertex");
        ++seen_[0];
        appendLine(checked, t);
      } else if (t[0] == "vt") {
        ++seen_[1];
      } else if (t[0] == "vn") {
        checkNumbers(t, "normal");
        ++seen_[2];
        appendLine(checked, t);
      } else if (t[0] == "f") {
        if (t.size() < 4)
          fail(ErrorKind::Parse, "face has " + std::to_string(t.size() - 1) + " vertices, expected at least 3");
        checked += 'f';
        for (std::size_t i = 1; i < t.size(); ++i) checked += ' ' + checkCorner(t[i]);
      }
      checked += '\n';
      ++lines;
    });
    return checked;
  }

 private:
  const std::string& text_;
  const std::string& name_;
  std::size_t line_ = 0;
  long long total_[3] = {0, 0, 0};  // v, vt, vn in the whole file
  long long seen_[3] = {0, 0, 0};   // ... up to the current line (negative indices count back from here)

  [[noreturn]] void fail(ErrorKind kind, const std::string& message) const {
    throw Error(kind, name_ + ":" + std::to_string(line_) + ": " + message);
  }

  // Calls f with the whitespace-separated tokens of each non-empty line (up to
  // a '#'). Line ends as tinyobjloader's: \n, \r\n or a lone \r.
  template <class F>
  void forEachLine(F f) {
    line_ = 0;
    std::vector<std::string> tokens;
    std::size_t i = 0;
    const std::size_t n = text_.size();
    while (i < n) {
      ++line_;
      tokens.clear();
      std::string token;
      for (; i < n && text_[i] != '\n' && text_[i] != '\r'; ++i) {
        const char c = text_[i];
        if (c == '#') {
          while (i < n && text_[i] != '\n' && text_[i] != '\r') ++i;
          break;
        }
        if (c == ' ' || c == '\t' || c == '\0') {
          if (!token.empty()) tokens.push_back(std::move(token));
          token.clear();
        } else {
          token += c;
        }
      }
      if (!token.empty()) tokens.push_back(std::move(token));
      if (i < n && text_[i] == '\r' && i + 1 < n && text_[i + 1] == '\n') ++i;
      ++i;
      if (!tokens.empty()) f(tokens);
    }
  }

  static void appendLine(std::string& out, const std::vector<std::string>& t) {
    for (std::size_t i = 0; i < t.size(); ++i) out += (i ? " " : "") + t[i];
  }

  void checkNumbers(const std::vector<std::string>& t, const char* what) const {
    if (t.size() < 4)
      fail(ErrorKind::Parse, std::string(what) + " has " + std::to_string(t.size() - 1) +
                                 " coordinates, expected 3 (truncated file?)");
    for (std::size_t i = 1; i < t.size(); ++i) {
      char* end = nullptr;
      const double v = std::strtod(t[i].c_str(), &end);
      // strtod alone would also take "nan", "inf" and hex, which tinyobjloader reads as 0.
      if (t[i].find_first_not_of("0123456789+-.eE") != std::string::npos || end != t[i].c_str() + t[i].size())
        fail(ErrorKind::Parse, std::string(what) + " coordinate '" + t[i] + "' is not a number");
      if (!(std::fabs(v) <= static_cast<double>(std::numeric_limits<float>::max())))
        fail(ErrorKind::Mesh, std::string(what) + " coordinate '" + t[i] + "' is not a finite float");
    }
  }

  // "v", "v/vt", "v//vn" or "v/vt/vn"; returns "v" or "v//vn".
  std::string checkCorner(const std::string& corner) const {
    if (std::count(corner.begin(), corner.end(), '/') > 2)
      fail(ErrorKind::Parse, "malformed face vertex '" + corner + "'");
    std::string kept[3];
    std::size_t start = 0;
    for (int part = 0; part < 3 && start <= corner.size(); ++part) {
      std::size_t slash = corner.find('/', start);
      if (slash == std::string::npos) slash = corner.size();
      const std::string index = corner.substr(start, slash - start);
      start = slash + 1;
      if (index.empty() && part > 0) continue;  // "1//3": no texture coordinate
      checkIndex(index, part, corner);
      kept[part] = index;
    }
    return kept[2].empty() ? kept[0] : kept[0] + "//" + kept[2];
  }

  void checkIndex(const std::string& index, int kind, const std::string& corner) const {
    static const char* const kWhat[3] = {"vertex", "texture coordinate", "normal"};
    static const char* const kPlural[3] = {"vertices", "texture coordinates", "normals"};
    const std::string what = kWhat[kind];
    const bool negative = !index.empty() && index[0] == '-';
    const std::size_t digits = index.size() - (negative || (!index.empty() && index[0] == '+') ? 1 : 0);
    if (digits == 0 || index.find_first_not_of("0123456789", index.size() - digits) != std::string::npos)
      fail(ErrorKind::Parse, "malformed face vertex '" + corner + "'");
    // Beyond 18 digits it is out of range anyway; stop before long long overflows.
    const long long value = digits > 18 ? std::numeric_limits<long long>::max() : std::llabs(std::stoll(index));
    if (value == 0) fail(ErrorKind::Parse, "face " + what + " index 0 in '" + corner + "' (OBJ indices start at 1)");
    if (kind == 1) return;  // the lab ignores texture coordinates: only their syntax matters
    // A negative index counts back from the last one defined so far.
    const long long available = negative ? seen_[kind] : total_[kind];
    if (value > available)
      fail(ErrorKind::Mesh, "face " + what + " index " + index + " is out of range: the file has " +
                                std::to_string(available) + " " + (available == 1 ? what : kPlural[kind]) +
                                (negative ? " before this line" : ""));
  }
};

}  // namespace

Mesh parseObj(const std::string& text, const std::string& name) {
  const std::string checked = ObjLineCheck(text, name).run();
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  // Materials are ignored: the lab's object material is the scene's IOR.
  if (!reader.ParseFromString(checked, std::string(), config)) {
    std::string msg = reader.Error();
    while (!msg.empty() && (msg.back() == '\n' || msg.back() == '\r')) msg.pop_back();
    throw Error(ErrorKind::Parse, name + ": not a valid OBJ file: " + (msg.empty() ? "parse error" : msg));
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const std::size_t positionCount = attrib.vertices.size() / 3;
  const std::size_t normalCount = attrib.normals.size() / 3;

  Mesh mesh;
  bool allHaveNormals = true;
  std::map<std::pair<int, int>, std::uint32_t> unify;  // (position, normal) -> vertex
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const auto& ix = shape.mesh.indices;
    std::size_t offset = 0;
    for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
      const std::size_t n = shape.mesh.num_face_vertices[f];
      if (n != 3) {
        throw Error(ErrorKind::Mesh, name + ": face " + std::to_string(f) + " of shape '" + shape.name +
                                         "' has " + std::to_string(n) + " vertices after triangulation");
      }
      for (std::size_t k = 0; k < 3; ++k) {
        const tinyobj::index_t& id = ix[offset + k];
        if (id.vertex_index < 0 || static_cast<std::size_t>(id.vertex_index) >= positionCount)
          throw Error(ErrorKind::Mesh, name + ": face " + std::to_string(f) + " refers to vertex " +
                                           std::to_string(id.vertex_index + 1) + ", but the file has " +
                                           std::to_string(positionCount) + " vertices");
        int normalIndex = id.normal_index;
        if (normalIndex >= 0 && static_cast<std::size_t>(normalIndex) >= normalCount)
          throw Error(ErrorKind::Mesh, name + ": face " + std::to_string(f) + " refers to normal " +
                                           std::to_string(normalIndex + 1) + ", but the file has " +
                                           std::to_string(normalCount) + " normals");
        if (normalIndex < 0) allHaveNormals = false;
        const auto key = std::make_pair(id.vertex_index, normalIndex);
        auto it = unify.find(key);
        if (it == unify.end()) {
          const std::size_t vi = static_cast<std::size_t>(id.vertex_index);
          mesh.positions.emplace_back(attrib.vertices[3 * vi], attrib.vertices[3 * vi + 1], attrib.vertices[3 * vi + 2]);
          glm::vec3 normal(0.0f);
          if (normalIndex >= 0) {
            const std::size_t ni = static_cast<std::size_t>(normalIndex);
            normal = glm::vec3(attrib.normals[3 * ni], attrib.normals[3 * ni + 1], attrib.normals[3 * ni + 2]);
          }
          mesh.normals.push_back(normal);
          it = unify.emplace(key, static_cast<std::uint32_t>(mesh.positions.size() - 1)).first;
        }
        mesh.indices.push_back(it->second);
      }
      offset += 3;
    }
  }
  if (mesh.indices.empty()) throw Error(ErrorKind::Mesh, name + ": the OBJ file has no faces (empty mesh)");

  // Outward winding first, so computed normals point out.
  orientOutward(mesh);
  if (!allHaveNormals) {
    computeSmoothNormals(mesh);
  } else {
    for (glm::vec3& n : mesh.normals) {
      const float len = glm::length(n);
      if (!(len > 0.0f) || !std::isfinite(len))
        throw Error(ErrorKind::Mesh, name + ": a vertex normal is zero or not finite");
      n /= len;
    }
  }
  validateMesh(mesh, name);
  return mesh;
}

Mesh loadObj(const std::string& path) { return parseObj(readTextFile(path, "mesh"), path); }

}  // namespace snell::lab
