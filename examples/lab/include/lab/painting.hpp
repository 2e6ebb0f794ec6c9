// Opaque "paintings": textured rectangles behind (or around) the refractive
// object. Unlit: a painting shows its texture's linear colour. Both sides show
// the texture. The tracer and the GL renderer sample the same texels
// (snell::Texture2D, GL_LINEAR, clamp-to-edge, no mipmaps).
#pragma once
#include "lab/mesh.hpp"

#include <snell/bridge.hpp>

#include <array>
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

struct Painting {
  vec3 center{0.0f};
  vec3 halfU{1.0f, 0.0f, 0.0f};  // from the centre to the right edge (uv u = 1)
  vec3 halfV{0.0f, 1.0f, 0.0f};  // from the centre to the top edge (uv v = 1)
  Texture2D texture;

  vec3 normal() const { return normalize(cross(halfU, halfV)); }  // the front side
  // Corners in uv order (0,0), (1,0), (1,1), (0,1); two triangles (0,1,2), (0,2,3).
  std::array<vec3, 4> corners() const;
  static std::array<vec2, 4> cornerUvs() { return {vec2(0.0f, 0.0f), vec2(1.0f, 0.0f), vec2(1.0f, 1.0f), vec2(0.0f, 1.0f)}; }
  vec3 colorAt(vec2 uv) const { return vec3(texture.sampleLod(uv, 0.0f)); }
};

// A painting of size (width, height) centred at `center`, facing +Z before the
// rotation (Euler degrees about X, then Y, then Z).
Painting makePainting(vec3 center, vec2 size, vec3 rotateDegrees, Image texture);

}  // namespace snell::lab
