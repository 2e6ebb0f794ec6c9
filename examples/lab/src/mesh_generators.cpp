#include "lab/mesh_generators.hpp"

#include "lab/error.hpp"

#include <cmath>
#include <map>
#include <utility>

namespace snell::lab {

namespace {
constexpr double kPi = 3.14159265358979323846;

std::uint32_t u32(std::size_t v) { return static_cast<std::uint32_t>(v); }

void requireArg(bool ok, const char* what) {
  if (!ok) throw Error(ErrorKind::Mesh, what);
}
}  // namespace

Mesh makeUvSphere(float radius, int segments, int rings) {
  requireArg(radius > 0.0f && segments >= 3 && rings >= 2,
             "sphere: needs radius > 0, segments >= 3, rings >= 2");
  Mesh m;
  // Poles are single vertices; ring r (1..rings-1) has `segments` vertices.
  m.positions.push_back(glm::vec3(0.0f, radius, 0.0f));
  m.normals.push_back(glm::vec3(0.0f, 1.0f, 0.0f));
  for (int r = 1; r < rings; ++r) {
    const double theta = kPi * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double phi = 2.0 * kPi * s / segments;
      const glm::dvec3 n(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
      m.normals.push_back(glm::vec3(n));
      m.positions.push_back(glm::vec3(n * static_cast<double>(radius)));
    }
  }
  const std::size_t south = m.positions.size();
  m.positions.push_back(glm::vec3(0.0f, -radius, 0.0f));
  m.normals.push_back(glm::vec3(0.0f, -1.0f, 0.0f));
  const auto ring = [&](int r, int s) { return u32(1 + static_cast<std::size_t>((r - 1) * segments + (s % segments))); };
  for (int s = 0; s < segments; ++s) m.indices.insert(m.indices.end(), {0u, ring(1, s), ring(1, s + 1)});
  for (int r = 1; r + 1 < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const std::uint32_t a = ring(r, s), b = ring(r, s + 1), c = ring(r + 1, s), d = ring(r + 1, s + 1);
      m.indices.insert(m.indices.end(), {a, c, d, a, d, b});
    }
  for (int s = 0; s < segments; ++s)
    m.indices.insert(m.indices.end(), {ring(rings - 1, s), u32(south), ring(rings - 1, s + 1)});
  orientOutward(m);
  return m;
}

Mesh makeIcosphere(float radius, int subdivisions) {
  requireArg(radius > 0.0f && subdivisions >= 0 && subdivisions <= 8,
             "icosphere: needs radius > 0 and 0 <= subdivisions <= 8");
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<glm::dvec3> p = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                               {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (glm::dvec3& v : p) v = glm::normalize(v);
  std::vector<std::uint32_t> idx = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4,
                                    11, 10, 2, 10, 7, 6, 7, 1, 8, 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8,
                                    3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      p.push_back(glm::normalize(p[a] + p[b]));
      const std::uint32_t i = u32(p.size() - 1);
      mid.emplace(key, i);
      return i;
    };
    std::vector<std::uint32_t> next;
    next.reserve(idx.size() * 4);
    for (std::size_t k = 0; k < idx.size(); k += 3) {
      const std::uint32_t a = idx[k], b = idx[k + 1], c = idx[k + 2];
      const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    idx.swap(next);
  }
  Mesh m;
  m.indices = std::move(idx);
  for (const glm::dvec3& v : p) {
    m.normals.push_back(glm::vec3(v));
    m.positions.push_back(glm::vec3(v * static_cast<double>(radius)));
  }
  orientOutward(m);
  return m;
}

Mesh makeTorus(float majorRadius, float minorRadius, int majorSegments, int minorSegments) {
  requireArg(minorRadius > 0.0f && majorRadius > minorRadius && majorSegments >= 3 && minorSegments >= 3,
             "torus: needs 0 < minor_radius < major_radius and segments >= 3");
  Mesh m;
  for (int i = 0; i < majorSegments; ++i) {
    const double u = 2.0 * kPi * i / majorSegments;
    const double R = static_cast<double>(majorRadius);
    const glm::dvec3 c(std::cos(u) * R, 0.0, std::sin(u) * R);
    for (int j = 0; j < minorSegments; ++j) {
      const double v = 2.0 * kPi * j / minorSegments;
      const glm::dvec3 n(std::cos(u) * std::cos(v), std::sin(v), std::sin(u) * std::cos(v));
      m.normals.push_back(glm::vec3(n));
      m.positions.push_back(glm::vec3(c + n * static_cast<double>(minorRadius)));
    }
  }
  const auto at = [&](int i, int j) {
    return u32(static_cast<std::size_t>((i % majorSegments) * minorSegments + (j % minorSegments)));
  };
  for (int i = 0; i < majorSegments; ++i)
    for (int j = 0; j < minorSegments; ++j) {
      const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i, j + 1), d = at(i + 1, j + 1);
      m.indices.insert(m.indices.end(), {a, c, d, a, d, b});
    }
  orientOutward(m);
  return m;
}

Mesh makeBox(glm::vec3 size) {
  requireArg(size.x > 0.0f && size.y > 0.0f && size.z > 0.0f, "box: needs every edge length > 0");
  const glm::vec3 h = 0.5f * size;
  Mesh m;
  // Each face: its outward normal n and two in-face axes u, v with u x v = n (counter-clockwise from outside).
  for (int axis = 0; axis < 3; ++axis)
    for (int side = -1; side <= 1; side += 2) {
      glm::vec3 n(0.0f), u(0.0f), v(0.0f);
      n[axis] = static_cast<float>(side);
      u[(axis + 1) % 3] = 1.0f;
      v = glm::cross(n, u);
      const auto base = u32(m.positions.size());
      for (const glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
        m.positions.push_back(h * (n + c.x * u + c.y * v));
        m.normals.push_back(n);
      }
      m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
  return m;
}

Mesh makeBlob(const BlobParams& params, float time) {
  requireArg(params.amplitude >= 0.0f && params.amplitude < 1.0f,
             "blob: needs 0 <= amplitude < 1 (the radius must stay positive)");
  Mesh m = makeIcosphere(params.radius, params.subdivisions);
  const double f = static_cast<double>(params.frequency), w = static_cast<double>(params.speed) * static_cast<double>(time);
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const glm::dvec3 d(m.normals[i]);  // unit direction of the undeformed vertex
    const double s = std::sin(f * d.x + w) * std::sin(f * d.y + 1.3 * w) * std::sin(f * d.z + 0.7 * w);
    m.positions[i] = glm::vec3(d * (static_cast<double>(params.radius) * (1.0 + static_cast<double>(params.amplitude) * s)));
  }
  orientOutward(m);
  computeSmoothNormals(m);
  return m;
}

}  // namespace snell::lab
