#include "textures.hpp"

#include <cmath>

namespace snell::gallery {

namespace {
constexpr float kPi = 3.14159265358979f;
}

Image environmentImage(int height) {
  const int width = 2 * height;
  Image img(width, height);
  const vec3 sun = glm::normalize(vec3(0.4f, 0.55f, -0.7f));
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      // snellEquirectUv's inverse: u = 0.5 + atan2(x, -z) / 2pi, v = 0.5 + asin(y) / pi.
      const float phi = ((static_cast<float>(i) + 0.5f) / static_cast<float>(width) - 0.5f) * 2.0f * kPi;
      const float theta = ((static_cast<float>(j) + 0.5f) / static_cast<float>(height) - 0.5f) * kPi;
      const vec3 d(std::cos(theta) * std::sin(phi), std::sin(theta), -std::cos(theta) * std::cos(phi));
      vec3 c;
      if (d.y >= 0.0f) {
        c = glm::mix(vec3(0.75f, 0.85f, 0.95f), vec3(0.2f, 0.4f, 0.8f), std::pow(d.y, 0.6f));
        // Stripes of cloud, so reflections and refractions show their bending.
        const float cloud = 0.5f + 0.5f * std::sin(9.0f * phi + 4.0f * std::sin(3.0f * theta));
        c = glm::mix(c, vec3(0.95f), 0.35f * cloud * (1.0f - d.y));
      } else {
        const float checker =
            (std::fmod(std::floor(phi * 6.0f / kPi) + std::floor(theta * 12.0f / kPi) + 100.0f, 2.0f) > 0.5f) ? 1.0f
                                                                                                              : 0.0f;
        c = glm::mix(vec3(0.25f, 0.22f, 0.18f), vec3(0.45f, 0.4f, 0.3f), checker) * (0.6f - 0.4f * d.y);
      }
      const float s = std::max(glm::dot(d, sun), 0.0f);
      c += vec3(3.0f, 2.7f, 2.2f) * std::pow(s, 400.0f);
      img.at(i, j) = vec4(c, 1.0f);
    }
  return img;
}

Image bumpImage(int size) {
  Image img(size, size);
  // Integer wave numbers keep the height field periodic on [0,1]^2.
  const float k[4][2] = {{3, 1}, {-2, 5}, {7, -4}, {1, 9}};
  // Slopes up to about 0.3 per wave: Sousa's bump scales assume gentle normals.
  const float a[4] = {0.012f, 0.008f, 0.004f, 0.003f};
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const float x = (static_cast<float>(i) + 0.5f) / static_cast<float>(size);
      const float y = (static_cast<float>(j) + 0.5f) / static_cast<float>(size);
      float dx = 0.0f, dy = 0.0f;
      for (int w = 0; w < 4; ++w) {
        const float phase = 2.0f * kPi * (k[w][0] * x + k[w][1] * y) + static_cast<float>(w);
        dx += a[w] * 2.0f * kPi * k[w][0] * std::cos(phase);
        dy += a[w] * 2.0f * kPi * k[w][1] * std::cos(phase);
      }
      const vec3 n = glm::normalize(vec3(-dx, -dy, 1.0f));
      img.at(i, j) = vec4(n * 0.5f + 0.5f, 1.0f);
    }
  return img;
}

Image stainImage(int size) {
  Image img(size, size);
  const vec3 palette[5] = {
      {0.85f, 0.15f, 0.1f}, {0.1f, 0.35f, 0.85f}, {0.95f, 0.75f, 0.1f}, {0.15f, 0.7f, 0.3f}, {0.9f, 0.9f, 0.85f}};
  const int cells = 5;
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const float x = static_cast<float>(i) / static_cast<float>(size) * cells;
      const float y = static_cast<float>(j) / static_cast<float>(size) * cells;
      const int cx = static_cast<int>(x), cy = static_cast<int>(y);
      const float fx = x - static_cast<float>(cx), fy = y - static_cast<float>(cy);
      const bool lead = std::min(std::min(fx, 1.0f - fx), std::min(fy, 1.0f - fy)) < 0.05f;
      const vec3 c = lead ? vec3(0.05f) : palette[(cx * 3 + cy * 2) % 5];
      img.at(i, j) = vec4(c, 1.0f);
    }
  return img;
}

Image floorImage(int size) {
  Image img(size, size);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const float u = (static_cast<float>(i) + 0.5f) / static_cast<float>(size);
      const float v = (static_cast<float>(j) + 0.5f) / static_cast<float>(size);
      const float tu = u * 8.0f, tv = v * 8.0f;
      const float fu = tu - std::floor(tu), fv = tv - std::floor(tv);
      const bool odd = (static_cast<int>(tu) + static_cast<int>(tv)) % 2 == 1;
      vec3 c = odd ? vec3(0.8f, 0.85f, 0.9f) : vec3(0.55f, 0.75f, 0.85f);
      if (std::min(std::min(fu, 1.0f - fu), std::min(fv, 1.0f - fv)) < 0.03f) c = vec3(0.3f);
      const float r = std::hypot(u - 0.5f, v - 0.5f);
      if (std::fabs(r - 0.28f) < 0.025f) c = vec3(0.85f, 0.3f, 0.15f);
      const float du = std::fabs(fu - 0.5f), dv = std::fabs(fv - 0.5f);
      if (du * du + dv * dv < 0.01f) c = vec3(0.1f, 0.2f, 0.5f);
      img.at(i, j) = vec4(c, 1.0f);
    }
  return img;
}

}  // namespace snell::gallery
