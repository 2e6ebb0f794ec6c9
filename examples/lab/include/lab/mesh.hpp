// The triangle mesh shared by the reference tracer and the GL renderer:
// indexed triangles with one position and one (unit, smooth) normal per vertex.
// Winding is counter-clockwise seen from outside (outward geometric normals),
// so GL back-face culling and the tracer's inside/outside test agree.
#pragma once
#include <snell/bridge.hpp>  // snell::vec3 etc. (GLM types)

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace snell::lab {

struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;     // same size as positions, unit length
  std::vector<std::uint32_t> indices;  // 3 per triangle

  std::size_t vertexCount() const { return positions.size(); }
  std::size_t triangleCount() const { return indices.size() / 3; }
};

struct Bounds {
  glm::vec3 lo{0.0f};
  glm::vec3 hi{0.0f};
  glm::vec3 center() const { return 0.5f * (lo + hi); }
  float diagonal() const;
};

Bounds meshBounds(const Mesh& mesh);

// Signed volume (positive for a closed mesh with outward winding).
double signedVolume(const Mesh& mesh);

// The edges only one triangle uses, with vertices welded by position (a closed mesh has none): a window
// modelled as one quad has four, and rays through such holes find no back face.
std::size_t openEdges(const Mesh& mesh);

// Whether p lies inside a closed mesh: the parity of the triangles a ray from p crosses (double precision,
// along a direction no axis-aligned edge lies on). Outside the mesh's bounds: false without a test.
bool pointInsideMesh(const Mesh& closed, const glm::dvec3& p);

// Area-weighted smooth vertex normals from the triangles (replaces mesh.normals).
// Vertices that belong to no non-degenerate triangle get (0, 0, 1).
void computeSmoothNormals(Mesh& mesh);

// Throws Error(Mesh) naming `what` when the mesh is empty, has an index out of
// range, sizes that do not match, or a non-finite position/normal.
void validateMesh(const Mesh& mesh, const std::string& what);

// Reverses the winding of every triangle (normals are left alone).
void flipWinding(Mesh& mesh);

// Makes the winding outward when the mesh encloses a volume: flips every
// triangle when the signed volume is negative. Returns true when it flipped.
bool orientOutward(Mesh& mesh);

// Scale, then rotate (Euler angles in degrees, applied about X, then Y, then Z),
// then translate. The 4x4 matrix worldFromObject of that transform.
struct Transform {
  glm::vec3 translate{0.0f};
  glm::vec3 rotateDegrees{0.0f};
  glm::vec3 scale{1.0f};
  glm::mat4 matrix() const;
};

// Applies the transform to positions and (inverse-transpose) to normals, and
// keeps the winding outward when the transform mirrors (negative determinant).
void applyTransform(Mesh& mesh, const Transform& transform);

}  // namespace snell::lab
