#include "lab/camera.hpp"

#include <snell/camera.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace snell::lab {

mat4 Camera::viewFromWorld() const { return glm::lookAt(position, target, up); }
mat4 Camera::worldFromView() const { return glm::inverse(viewFromWorld()); }
mat4 Camera::clipFromView() const { return snellPerspective(fovYRadians(), aspect(), zNear, zFar); }

Ray primaryRayAtUv(const Camera& camera, glm::dvec2 uv) {
  // Camera basis in double (glm::lookAt's, without the float rounding).
  const glm::dvec3 eye(camera.position), target(camera.target), up(camera.up);
  const glm::dvec3 f = glm::normalize(target - eye);
  const glm::dvec3 s = glm::normalize(glm::cross(f, up));
  const glm::dvec3 u = glm::cross(s, f);
  const double tanHalf = std::tan(0.5 * static_cast<double>(camera.fovYRadians()));
  const double aspect = static_cast<double>(camera.width) / static_cast<double>(camera.height);
  const double xv = (2.0 * uv.x - 1.0) * aspect * tanHalf;
  const double yv = (2.0 * uv.y - 1.0) * tanHalf;
  const glm::dvec3 dView(xv, yv, -1.0);
  const double len = glm::length(dView);
  Ray r;
  r.origin = eye;
  r.direction = (s * xv + u * yv + f) / len;
  // View depth along the ray grows as 1 / len per unit distance.
  r.tNear = static_cast<double>(camera.zNear) * len;
  r.tFar = static_cast<double>(camera.zFar) * len;
  return r;
}

Camera pannedCamera(const Camera& camera, vec2 pixels) {
  // The basis of glm::lookAt in double, as primaryRayAtUv builds it.
  const glm::dvec3 eye(camera.position), target(camera.target);
  const glm::dvec3 f = glm::normalize(target - eye);
  const glm::dvec3 s = glm::normalize(glm::cross(f, glm::dvec3(camera.up)));
  const glm::dvec3 u = glm::cross(s, f);
  // A pixel's height at the target's view depth (the target lies on the view axis, so its depth is its distance).
  const double pixel = 2.0 * glm::length(target - eye) * std::tan(0.5 * static_cast<double>(camera.fovYRadians())) /
                       static_cast<double>(camera.height);
  const glm::dvec3 shift = (s * static_cast<double>(pixels.x) + u * static_cast<double>(pixels.y)) * pixel;
  Camera moved = camera;
  moved.position = vec3(eye + shift);
  moved.target = vec3(target + shift);
  return moved;
}

namespace {
bool finiteMatrix(const mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}
bool finiteRay(const Ray& r) {
  return std::isfinite(r.origin.x) && std::isfinite(r.origin.y) && std::isfinite(r.origin.z) &&
         std::isfinite(r.direction.x) && std::isfinite(r.direction.y) && std::isfinite(r.direction.z) &&
         std::isfinite(r.tNear) && std::isfinite(r.tFar) && r.tNear >= 0.0 && r.tFar > r.tNear;
}
}  // namespace

std::string cameraProblem(const Camera& c) {
  if (c.width < 1 || c.height < 1) return "the resolution is empty";
  if (!finiteMatrix(c.viewFromWorld()) || !finiteMatrix(c.worldFromView()))
    return "the view matrix (float, from position, target and up) is not finite: the values are too large or too "
           "close together for float arithmetic";
  const mat4 clip = c.clipFromView();
  if (!finiteMatrix(clip) || clip[0][0] == 0.0f)
    return "the projection (float, from fov, near and far) is unusable: an entry would overflow or be denormal";
  for (int py : {0, c.height - 1})
    for (int px : {0, c.width - 1})
      if (!finiteRay(primaryRay(c, px, py)))
        return "the primary ray through pixel (" + std::to_string(px) + ", " + std::to_string(py) + ") is not finite";
  return "";
}

Ray primaryRay(const Camera& camera, int px, int py) {
  return primaryRayAtUv(camera, glm::dvec2((px + 0.5) / camera.width, (py + 0.5) / camera.height));
}

}  // namespace snell::lab
