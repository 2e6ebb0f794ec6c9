#include "lab/mesh.hpp"

#include "lab/error.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

namespace snell::lab {

float Bounds::diagonal() const { return glm::length(hi - lo); }

Bounds meshBounds(const Mesh& mesh) {
  Bounds b;
  if (mesh.positions.empty()) return b;
  b.lo = b.hi = mesh.positions.front();
  for (const glm::vec3& p : mesh.positions) {
    b.lo = glm::min(b.lo, p);
    b.hi = glm::max(b.hi, p);
  }
  return b;
}

std::size_t openEdges(const Mesh& mesh) {
  std::map<std::tuple<float, float, float>, std::uint32_t> weld;
  std::vector<std::uint32_t> id(mesh.positions.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const vec3& p = mesh.positions[i];
    id[i] = weld.emplace(std::make_tuple(p.x, p.y, p.z), static_cast<std::uint32_t>(weld.size())).first->second;
  }
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    for (std::size_t e = 0; e < 3; ++e) {
      const std::uint32_t a = id[mesh.indices[t + e]], b = id[mesh.indices[t + (e + 1) % 3]];
      if (a != b) ++uses[std::minmax(a, b)];
    }
  return static_cast<std::size_t>(std::count_if(uses.begin(), uses.end(), [](const auto& u) { return u.second == 1; }));
}

double signedVolume(const Mesh& mesh) {
  double v = 0.0;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::dvec3 a(mesh.positions[mesh.indices[t]]);
    const glm::dvec3 b(mesh.positions[mesh.indices[t + 1]]);
    const glm::dvec3 c(mesh.positions[mesh.indices[t + 2]]);
    v += glm::dot(a, glm::cross(b, c));
  }
  return v / 6.0;
}

bool pointInsideMesh(const Mesh& closed, const glm::dvec3& p) {
  const Bounds b = meshBounds(closed);
  if (!(p.x > double(b.lo.x) && p.y > double(b.lo.y) && p.z > double(b.lo.z) && p.x < double(b.hi.x) &&
        p.y < double(b.hi.y) && p.z < double(b.hi.z)))
    return false;
  const glm::dvec3 d = glm::normalize(glm::dvec3(0.5773, 0.5779, 0.5769));
  int crossings = 0;
  for (std::size_t t = 0; t + 2 < closed.indices.size(); t += 3) {
    const glm::dvec3 a(closed.positions[closed.indices[t]]);
    const glm::dvec3 e1 = glm::dvec3(closed.positions[closed.indices[t + 1]]) - a;
    const glm::dvec3 e2 = glm::dvec3(closed.positions[closed.indices[t + 2]]) - a;
    // Moller-Trumbore.
    const glm::dvec3 q = glm::cross(d, e2);
    const double det = glm::dot(e1, q);
    if (std::abs(det) < 1e-300) continue;
    const glm::dvec3 s = p - a;
    const double u = glm::dot(s, q) / det;
    if (u < 0.0 || u > 1.0) continue;
    const glm::dvec3 r = glm::cross(s, e1);
    const double v = glm::dot(d, r) / det;
    if (v < 0.0 || u + v > 1.0) continue;
    if (glm::dot(e2, r) / det > 0.0) ++crossings;
  }
  return crossings % 2 == 1;
}

void computeSmoothNormals(Mesh& mesh) {
  std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0.0));
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
    const glm::dvec3 a(mesh.positions[i0]), b(mesh.positions[i1]), c(mesh.positions[i2]);
    const glm::dvec3 n = glm::cross(b - a, c - a);  // length = 2 * area: area weighting
    sum[i0] += n;
    sum[i1] += n;
    sum[i2] += n;
  }
  mesh.normals.resize(mesh.positions.size());
  for (std::size_t i = 0; i < sum.size(); ++i) {
    const double len = glm::length(sum[i]);
    mesh.normals[i] = len > 0.0 ? glm::vec3(sum[i] / len) : glm::vec3(0.0f, 0.0f, 1.0f);
  }
}

static bool finite3(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void validateMesh(const Mesh& mesh, const std::string& what) {
  if (mesh.positions.empty() || mesh.indices.empty())
    throw Error(ErrorKind::Mesh, what + ": the mesh is empty (no triangles)");
  if (mesh.indices.size() % 3 != 0)
    throw Error(ErrorKind::Mesh, what + ": index count is not a multiple of 3");
  if (mesh.normals.size() != mesh.positions.size())
    throw Error(ErrorKind::Mesh, what + ": " + std::to_string(mesh.normals.size()) + " normals for " +
                                     std::to_string(mesh.positions.size()) + " positions");
  for (std::size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] >= mesh.positions.size())
      throw Error(ErrorKind::Mesh, what + ": triangle " + std::to_string(i / 3) + " uses vertex " +
                                       std::to_string(mesh.indices[i]) + " of " +
                                       std::to_string(mesh.positions.size()));
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    if (!finite3(mesh.positions[i]) || !finite3(mesh.normals[i]))
      throw Error(ErrorKind::Mesh, what + ": vertex " + std::to_string(i) + " is not finite");
  double area = 0.0;
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    const glm::dvec3 a(mesh.positions[mesh.indices[t]]), b(mesh.positions[mesh.indices[t + 1]]),
        c(mesh.positions[mesh.indices[t + 2]]);
    area += glm::length(glm::cross(b - a, c - a));
  }
  if (!(area > 0.0)) throw Error(ErrorKind::Mesh, what + ": every triangle is degenerate (zero area)");
}

void flipWinding(Mesh& mesh) {
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
}

bool orientOutward(Mesh& mesh) {
  if (signedVolume(mesh) < 0.0) {
    flipWinding(mesh);
    return true;
  }
  return false;
}

glm::mat4 Transform::matrix() const {
  glm::mat4 m(1.0f);
  m = glm::translate(m, translate);
  m = glm::rotate(m, glm::radians(rotateDegrees.z), glm::vec3(0.0f, 0.0f, 1.0f));
  m = glm::rotate(m, glm::radians(rotateDegrees.y), glm::vec3(0.0f, 1.0f, 0.0f));
  m = glm::rotate(m, glm::radians(rotateDegrees.x), glm::vec3(1.0f, 0.0f, 0.0f));
  m = glm::scale(m, scale);
  return m;
}

void applyTransform(Mesh& mesh, const Transform& transform) {
  const glm::mat4 m = transform.matrix();
  // In float, as the lab always computed it (every result of a scene depends on
  // these bits); in double where float overflows or underflows: with a scale
  // of 1e-20 or 1e20 (finite floats) the float inverse's determinant does, and
  // every normal became NaN.
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(m)));
  const glm::dmat3 normalMatrixDouble = glm::transpose(glm::inverse(glm::dmat3(glm::mat3(m))));
  for (glm::vec3& p : mesh.positions) p = glm::vec3(m * glm::vec4(p, 1.0f));
  for (glm::vec3& n : mesh.normals) {
    const glm::vec3 t = normalMatrix * n;
    const float len = glm::length(t);
    if (std::isfinite(len) && std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z)) {
      n = len > 0.0f ? t / len : glm::vec3(0.0f, 0.0f, 1.0f);
    } else {
      const glm::dvec3 d = normalMatrixDouble * glm::dvec3(n);
      const double dlen = glm::length(d);
      n = dlen > 0.0 && std::isfinite(dlen) ? glm::vec3(d / dlen) : glm::vec3(0.0f, 0.0f, 1.0f);
    }
  }
  if (glm::determinant(glm::mat3(m)) < 0.0f) flipWinding(mesh);
}

}  // namespace snell::lab
