#include "lab/obj_loader.hpp"

#include "lab/error.hpp"
#include "lab/file_util.hpp"

#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>

#include <cmath>
#include <map>
#include <utility>

namespace snell::lab {

Mesh parseObj(const std::string& text, const std::string& name) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  // Materials are ignored: the lab's object material is the scene's IOR.
  if (!reader.ParseFromString(text, std::string(), config)) {
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
