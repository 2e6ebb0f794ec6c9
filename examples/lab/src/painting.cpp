#include "lab/painting.hpp"

#include <cmath>
#include <utility>

namespace snell::lab {

Image makeCheckerTexture(int width, int height, ivec2 squares, vec3 colorA, vec3 colorB) {
  Image img(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int cx = x * squares.x / width, cy = y * squares.y / height;
      img.at(x, y) = vec4(((cx + cy) % 2 == 0) ? colorA : colorB, 1.0f);
    }
  return img;
}

Image makeGradientTexture(int width, int height, const std::vector<vec3>& colors, int direction) {
  Image img(width, height);
  const int n = static_cast<int>(colors.size());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(width);
      const float v = (static_cast<float>(y) + 0.5f) / static_cast<float>(height);
      float t = direction == 0 ? u : direction == 1 ? v : 0.5f * (u + v);
      vec3 c = colors.front();
      if (n > 1) {
        const float s = t * static_cast<float>(n - 1);
        const int i = std::min(static_cast<int>(s), n - 2);
        c = mix(colors[static_cast<std::size_t>(i)], colors[static_cast<std::size_t>(i + 1)], s - static_cast<float>(i));
      }
      img.at(x, y) = vec4(c, 1.0f);
    }
  return img;
}

Image makePatternTexture(int width, int height) {
  Image img(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(width);
      const float v = (static_cast<float>(y) + 0.5f) / static_cast<float>(height);
      // Hue sweep along u, brightness along v.
      const float h = u * 6.0f;
      vec3 hue(std::abs(h - 3.0f) - 1.0f, 2.0f - std::abs(h - 2.0f), 2.0f - std::abs(h - 4.0f));
      hue = clamp(hue, vec3(0.0f), vec3(1.0f));
      vec3 c = mix(vec3(0.15f), hue, 0.35f + 0.6f * v);
      // Fine checker overlay: 16 x 16 squares.
      const int cx = static_cast<int>(u * 16.0f), cy = static_cast<int>(v * 16.0f);
      if ((cx + cy) % 2 == 0) c *= 0.55f;
      // Concentric rings around the centre.
      const float r = std::sqrt((u - 0.5f) * (u - 0.5f) + (v - 0.5f) * (v - 0.5f));
      const float ring = std::abs(std::sin(r * 60.0f));
      if (ring < 0.18f) c = vec3(0.95f, 0.95f, 0.9f);
      // Dark frame.
      if (u < 0.03f || u > 0.97f || v < 0.03f || v > 0.97f) c = vec3(0.08f, 0.05f, 0.03f);
      img.at(x, y) = vec4(c, 1.0f);
    }
  return img;
}

glm::dvec2 Painting::uvAt(std::size_t t, double u, double v) const {
  const glm::dvec2 a(uvs[indices[3 * t]]), b(uvs[indices[3 * t + 1]]), c(uvs[indices[3 * t + 2]]);
  return (1.0 - u - v) * a + u * b + v * c;
}

Painting makePainting(vec3 center, vec2 size, vec3 rotateDegrees, Image texture) {
  Transform t;
  t.rotateDegrees = rotateDegrees;
  const mat3 r(t.matrix());
  const vec3 halfU = r * vec3(0.5f * size.x, 0.0f, 0.0f);
  const vec3 halfV = r * vec3(0.0f, 0.5f * size.y, 0.0f);
  Painting p;
  p.positions = {center - halfU - halfV, center + halfU - halfV, center + halfU + halfV, center - halfU + halfV};
  const vec3 n = cross(p.positions[1] - p.positions[0], p.positions[3] - p.positions[0]);
  p.normals = {n, n, n, n};
  p.uvs = {vec2(0.0f, 0.0f), vec2(1.0f, 0.0f), vec2(1.0f, 1.0f), vec2(0.0f, 1.0f)};
  p.indices = {0, 1, 2, 0, 2, 3};
  p.texture = Texture2D(std::move(texture), Filter::Linear, MipFilter::None);
  return p;
}

}  // namespace snell::lab
