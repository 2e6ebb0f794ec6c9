#include "lab/environment.hpp"

#include <cmath>
#include <utility>

namespace snell::lab {

namespace {
constexpr double kPi = 3.14159265358979323846;

float smoothstepf(float e0, float e1, float x) {
  const float t = std::min(std::max((x - e0) / (e1 - e0), 0.0f), 1.0f);
  return t * t * (3.0f - 2.0f * t);
}
}  // namespace

vec2 directionToEquirectUv(vec3 d, float rotationDegrees) {
  const glm::dvec3 dd(d);
  const double len = glm::length(dd);
  if (!(len > 0.0)) return vec2(0.5f, 0.5f);
  const double phi = std::atan2(static_cast<double>(d.x), -static_cast<double>(d.z)) -
                     static_cast<double>(rotationDegrees) * kPi / 180.0;
  double u = phi / (2.0 * kPi) + 0.5;
  u -= std::floor(u);
  const double v = std::asin(std::max(-1.0, std::min(1.0, static_cast<double>(d.y) / len))) / kPi + 0.5;
  return vec2(static_cast<float>(u), static_cast<float>(v));
}

vec3 equirectUvToDirection(vec2 uv, float rotationDegrees) {
  const double phi = (static_cast<double>(uv.x) - 0.5) * 2.0 * kPi + static_cast<double>(rotationDegrees) * kPi / 180.0;
  const double lat = (static_cast<double>(uv.y) - 0.5) * kPi;
  return vec3(static_cast<float>(std::cos(lat) * std::sin(phi)), static_cast<float>(std::sin(lat)),
              static_cast<float>(-std::cos(lat) * std::cos(phi)));
}

vec3 skyRadiance(const SkyParams& sky, vec3 d) {
  const vec3 dir = normalize(d);
  const float up = dir.y;
  vec3 c;
  if (up >= 0.0f) {
    c = mix(sky.horizon, sky.zenith, std::pow(up, 0.6f));
  } else {
    c = mix(sky.horizon, sky.ground, smoothstepf(0.0f, 0.08f, -up));
  }
  if (sky.gridSpacingDegrees > 0.0f) {
    const float lat = std::asin(std::max(-1.0f, std::min(1.0f, up))) * 57.2957795f;
    const float lon = std::atan2(dir.x, -dir.z) * 57.2957795f;
    const auto lineWeight = [&](float angle, float scale) {
      const float s = sky.gridSpacingDegrees;
      const float m = angle / s - std::floor(angle / s + 0.5f);  // in [-0.5, 0.5)
      const float dist = std::abs(m) * s * scale;                // degrees on the sphere
      return 1.0f - smoothstepf(0.5f * sky.gridWidthDegrees, sky.gridWidthDegrees, dist);
    };
    const float cosLat = std::cos(std::asin(std::max(-1.0f, std::min(1.0f, up))));
    const float w = std::max(lineWeight(lat, 1.0f), std::abs(up) < 0.985f ? lineWeight(lon, cosLat) : 0.0f);
    c = mix(c, sky.gridColor, 0.8f * w);
  }
  if (sky.sunRadiusDegrees > 0.0f) {
    const float az = sky.sunAzimuthDegrees * 0.0174532925f, el = sky.sunElevationDegrees * 0.0174532925f;
    const vec3 sun(std::cos(el) * std::sin(az), std::sin(el), -std::cos(el) * std::cos(az));
    const float angle = std::acos(std::max(-1.0f, std::min(1.0f, dot(dir, sun)))) * 57.2957795f;
    c += sky.sunColor * (1.0f - smoothstepf(0.8f * sky.sunRadiusDegrees, sky.sunRadiusDegrees, angle));
  }
  return c;
}

Image bakeSky(const SkyParams& sky, int width, int height) {
  Image img(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const vec2 uv((static_cast<float>(x) + 0.5f) / static_cast<float>(width),
                    (static_cast<float>(y) + 0.5f) / static_cast<float>(height));
      img.at(x, y) = vec4(skyRadiance(sky, equirectUvToDirection(uv, 0.0f)), 1.0f);
    }
  return img;
}

Environment::Environment(Image equirect, float rotationDegrees, float intensity)
    : image_(std::move(equirect)), rotation_(rotationDegrees), intensity_(intensity) {}

Environment Environment::constant(vec3 color) { return Environment(Image(1, 1, vec4(color, 1.0f)), 0.0f, 1.0f); }

vec3 Environment::lookup(vec3 direction) const {
  const vec2 uv = directionToEquirectUv(direction, rotation_);
  const int w = image_.width, h = image_.height;
  // GL_LINEAR with GL_REPEAT in s and GL_CLAMP_TO_EDGE in t.
  const float us = uv.x * static_cast<float>(w) - 0.5f, vs = uv.y * static_cast<float>(h) - 0.5f;
  const float fu = std::floor(us), fv = std::floor(vs);
  const float a = us - fu, b = vs - fv;
  const int i0 = static_cast<int>(fu), j0 = static_cast<int>(fv);
  const auto wrapX = [w](int i) { return ((i % w) + w) % w; };
  const auto clampY = [h](int j) { return std::max(0, std::min(j, h - 1)); };
  const int x0 = wrapX(i0), x1 = wrapX(i0 + 1), y0 = clampY(j0), y1 = clampY(j0 + 1);
  const vec4 c = (1.0f - a) * (1.0f - b) * image_.at(x0, y0) + a * (1.0f - b) * image_.at(x1, y0) +
                 (1.0f - a) * b * image_.at(x0, y1) + a * b * image_.at(x1, y1);
  return vec3(c) * intensity_;
}

}  // namespace snell::lab
