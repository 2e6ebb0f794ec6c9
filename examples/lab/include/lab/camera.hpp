// The scene camera and its primary rays, in the conventions of
// glsl/snell/camera/conventions.glsl: right-handed view space looking down -Z,
// GL clip space (snellPerspective), uv origin at the bottom-left, pixel (i, j)
// centred at uv ((i + 0.5) / W, (j + 0.5) / H), image row 0 at the bottom. A
// primary ray through a pixel centre therefore hits exactly what a rasterizer
// shades at that pixel.
#pragma once
#include <snell/bridge.hpp>

#include <glm/glm.hpp>

#include <string>

namespace snell::lab {

// Render sizes the lab accepts, from a scene's camera.resolution or --size:
// below 8 the depth pyramids and panels have nothing to show.
inline constexpr int kMinRenderSize = 8;
inline constexpr int kMaxRenderSize = 8192;

struct Camera {
  vec3 position{0.0f, 0.0f, 5.0f};
  vec3 target{0.0f};
  vec3 up{0.0f, 1.0f, 0.0f};
  float fovYDegrees = 45.0f;  // full vertical field of view
  int width = 512;
  int height = 512;
  float zNear = 0.1f;
  float zFar = 100.0f;

  float aspect() const { return static_cast<float>(width) / static_cast<float>(height); }
  float fovYRadians() const { return glm::radians(fovYDegrees); }
  mat4 viewFromWorld() const;  // glm::lookAt
  mat4 worldFromView() const;
  mat4 clipFromView() const;   // snellPerspective (GL depth convention)
};

struct Ray {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0, 0.0, -1.0};  // unit
  double tNear = 0.0;
  double tFar = 1e30;
};

// Why `camera` cannot render ("" when it can): its view and projection
// matrices, in float as GL gets them, must be finite (snellPerspective's zero
// matrix counts as unusable), and the primary rays through the corner pixels,
// in double as the tracer builds them, finite. The scene loader refuses such
// a camera naming the field; the tracer and the GL passes check again so that
// neither Embree nor GL ever sees a non-finite ray.
std::string cameraProblem(const Camera& camera);

// `camera` moved parallel to its image plane, position and target together,
// by `pixels` (x right, y up in the picture) measured at the target's distance:
// the target then shows `pixels` away from where it was, the other way (the
// picture pans with the camera). Points nearer than the target move more,
// farther ones less (parallax), as a real camera dolly's would.
Camera pannedCamera(const Camera& camera, vec2 pixels);

// The ray through the centre of pixel (px, py) (py = 0 is the bottom row),
// from the camera position, clipped to the near and far planes (tNear/tFar are
// the distances along the ray to those planes).
Ray primaryRay(const Camera& camera, int px, int py);

// The same for an arbitrary uv in [0, 1]^2.
Ray primaryRayAtUv(const Camera& camera, glm::dvec2 uv);

}  // namespace snell::lab
