// Built-in meshes. All are closed, outward-wound, centred at the origin, with
// analytic unit normals (the blob: smooth normals of the displaced surface).
#pragma once
#include "lab/mesh.hpp"

namespace snell::lab {

// UV sphere: `segments` around the Y axis (>= 3), `rings` from pole to pole (>= 2).
Mesh makeUvSphere(float radius, int segments, int rings);

// Icosahedron subdivided `subdivisions` times (0..8), vertices on the sphere:
// 20 * 4^subdivisions triangles.
Mesh makeIcosphere(float radius, int subdivisions);

// Torus around the Y axis: ring radius `majorRadius`, tube radius `minorRadius`
// (0 < minor < major), `majorSegments` x `minorSegments` quads (each >= 3).
Mesh makeTorus(float majorRadius, float minorRadius, int majorSegments, int minorSegments);

// Axis-aligned box with edge lengths `size` (each > 0): 12 triangles, 4 vertices per face with the face's
// normal (sharp edges: a pane, a cube).
Mesh makeBox(glm::vec3 size);

// The deforming blob: an icosphere whose radius is modulated by
//   r(p, t) = radius * (1 + amplitude * sin(f p.x + w t) sin(f p.y + 1.3 w t) sin(f p.z + 0.7 w t))
// with p the unit direction, f = frequency, w = speed (radians per time unit).
// Same topology for every t, so it is one deformable mesh animated over frames.
struct BlobParams {
  float radius = 1.0f;
  int subdivisions = 5;
  float amplitude = 0.15f;
  float frequency = 3.0f;
  float speed = 1.0f;
};
Mesh makeBlob(const BlobParams& params, float time);

}  // namespace snell::lab
