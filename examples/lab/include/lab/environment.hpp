// The distant environment: an equirectangular (latitude-longitude) linear RGB
// image, loaded from a file or baked from a procedural sky, looked up by
// direction. The tracer and the GL renderer sample the same texels the same
// way (bilinear, longitude wraps, latitude clamps), so the environment adds no
// error of its own to the comparison.
//
// Mapping (world space, +Y up; `rotation` turns the environment about +Y):
//   phi   = atan2(d.x, -d.z) - radians(rotation)     (0: looking down -Z)
//   u     = phi / (2 pi) + 0.5, wrapped into [0, 1)
//   v     = asin(d.y) / pi + 0.5                        (0: nadir, 1: zenith)
// Texel (i, j) of the image (row 0 at the bottom = nadir) has its centre at
// ((i + 0.5) / W, (j + 0.5) / H). In GLSL: sample a GL_REPEAT (s) /
// GL_CLAMP_TO_EDGE (t) GL_LINEAR texture at (u, v), without mipmaps.
#pragma once
#include <snell/bridge.hpp>

namespace snell::lab {

struct SkyParams {
  vec3 zenith{0.12f, 0.30f, 0.75f};
  vec3 horizon{0.75f, 0.85f, 0.95f};
  vec3 ground{0.20f, 0.18f, 0.16f};
  float sunAzimuthDegrees = 30.0f;    // phi of the sun (same convention as above)
  float sunElevationDegrees = 35.0f;  // above the horizon
  vec3 sunColor{1.0f, 0.9f, 0.7f};    // linear radiance added inside the disc
  float sunRadiusDegrees = 2.5f;      // 0: no sun
  float gridSpacingDegrees = 15.0f;   // latitude/longitude lines every N degrees; 0: none
  vec3 gridColor{0.05f, 0.05f, 0.08f};
  float gridWidthDegrees = 0.6f;
};

// The procedural sky at direction d (unit), before baking: vertical gradient
// zenith <- horizon -> ground (smooth across the horizon), sun disc, and grid
// lines (they make refraction distortion visible).
vec3 skyRadiance(const SkyParams& sky, vec3 direction);

// Bakes the sky into a width x height equirectangular image, one sample per
// texel centre (rotation 0).
Image bakeSky(const SkyParams& sky, int width, int height);

vec2 directionToEquirectUv(vec3 direction, float rotationDegrees);
vec3 equirectUvToDirection(vec2 uv, float rotationDegrees);

class Environment {
 public:
  Environment() = default;
  Environment(Image equirect, float rotationDegrees, float intensity = 1.0f);
  // A constant-colour environment (a 1x1 image).
  static Environment constant(vec3 color);

  // Bilinear lookup with longitude wrap, times `intensity`.
  vec3 lookup(vec3 direction) const;

  const Image& image() const { return image_; }  // what the GPU uploads (before intensity)
  float rotationDegrees() const { return rotation_; }
  float intensity() const { return intensity_; }

 private:
  Image image_{1, 1, vec4(0.0f, 0.0f, 0.0f, 1.0f)};
  float rotation_ = 0.0f;
  float intensity_ = 1.0f;
};

}  // namespace snell::lab
