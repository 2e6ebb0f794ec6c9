// Opaque "paintings": textured surfaces behind, around or inside the refractive
// objects. Unlit: a painting shows its texture's linear colour. The tracer and the GL renderer sample the same texels
// (snell::Texture2D, GL_LINEAR, clamp-to-edge, no mipmaps).
#pragma once
#include "lab/mesh.hpp"

#include <snell/bridge.hpp>

#include <cstdint>
#include <vector>

namespace snell::lab {

// Procedural textures (linear RGB), row 0 at the bottom (uv v = 0).
Image makeCheckerTexture(int width, int height, ivec2 squares, vec3 colorA, vec3 colorB);
// Colours spread evenly along the direction: 0 horizontal (left to right),
// 1 vertical (bottom to top), 2 diagonal (bottom-left to top-right).
Image makeGradientTexture(int width, int height, const std::vector<vec3>& colors, int direction);
// A colourful test card: hue sweep, a fine checker overlay, concentric rings
// and a dark frame: high-frequency detail in every direction, so refraction
// errors show.
Image makePatternTexture(int width, int height);

// An opaque, unlit surface: indexed triangles with a uv and a normal per vertex
// and a texture. A scene file's painting is a quad (makePainting); a glTF
// asset's opaque mesh is any triangle mesh with its base colour baked into
// the texture. Both sides show the texture.
struct Painting {
  std::vector<vec3> positions;         // world space
  std::vector<vec3> normals;           // per vertex, the side the GL normal buffer reports (not unit for a quad)
  std::vector<vec2> uvs;               // per vertex; v = 0 is the texture's bottom row
  std::vector<std::uint32_t> indices;  // 3 per triangle
  Texture2D texture;

  std::size_t triangleCount() const { return indices.size() / 3; }
  // The uv at barycentric (u, v) of triangle t (Embree's convention: (1 - u - v) a + u b + v c).
  glm::dvec2 uvAt(std::size_t t, double u, double v) const;
  vec3 colorAt(vec2 uv) const { return vec3(texture.sampleLod(uv, 0.0f)); }
};

// A quad painting of size (width, height) centred at `center`, facing +Z before
// the rotation (Euler degrees about X, then Y, then Z): corners in uv order
// (0,0), (1,0), (1,1), (0,1), triangles (0,1,2) and (0,2,3), each vertex's
// normal the face's cross(c1 - c0, c3 - c0).
Painting makePainting(vec3 center, vec2 size, vec3 rotateDegrees, Image texture);

}  // namespace snell::lab
