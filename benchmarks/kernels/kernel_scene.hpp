// The scene and ray set of the kernel study:
// an analytic sphere (back faces of a unit
// sphere at z = -5, 256x256, GL depth, emptyDepth 0, normals in a Linear-filtered
// Texture2D) and its 20000 rays, built once; plus the depth min/max pyramid for
// the depth-based plane. Both implementations read these very buffers: snell
// through snell::Texture2D, the kernels through the plain float arrays inside
// them (RGBA32F, texel (x, y) at 4 (y W + x)).
#ifndef KERNEL_SCENE_HPP
#define KERNEL_SCENE_HPP
#include <snell/camera.hpp>
#include <snell/intersect.hpp>
#include <snell/depth_pyramid.hpp>

#include "kernels.hpp"

#include <cmath>
#include <cstdint>
#include <vector>

namespace kscene {

constexpr int kW = 256;        // buffer size (square)
constexpr int kRays = 20000;   // the ray set

struct Ray {
  float o[3];  // view-space origin (z = -4)
  float d[3];  // unit direction (glm::normalize)
};

struct Scene {
  glm::mat4 P;
  snell::Texture2D depth, normal, pyramid;
  snell::SnellDepthSurface surface;
  std::vector<Ray> rays;
  std::vector<Ray> wide;  // CHECK only: a wider ray set (misses, rim rays, rays towards the camera)
  kern::Camera cam;  // what the kernels read: the entries of P and pointers into the textures
};

// Fills `sc` in place (the kernel pointers point into sc's textures). The pyramid
// and the wide ray set are built only when asked for (less setup under callgrind).
inline void build(Scene& sc, bool withPyramid = true, bool withWide = true) {
  using namespace glm;
  const int W = kW;
  sc.P = snell::snellPerspective(radians(45.0f), 1.0f, 0.1f, 100.0f);
  const mat4& P = sc.P;
  snell::Image depth(W, W, vec4(0.0f)), normal(W, W, vec4(0.0f));
  for (int y = 0; y < W; ++y)
    for (int x = 0; x < W; ++x) {
      // back hemisphere of a unit sphere at z = -5 (analytic), GL depth
      vec2 ndc((x + 0.5f) / W * 2 - 1, (y + 0.5f) / W * 2 - 1);
      vec3 d = normalize(vec3(ndc.x * tan(radians(22.5f)), ndc.y * tan(radians(22.5f)), -1.0f));
      vec3 c(0, 0, -5);
      float b = dot(d, c);
      float disc = b * b - dot(c, c) + 1.0f;
      if (disc < 0) continue;
      float t = b + sqrt(disc);
      vec3 p = d * t;
      vec4 clip = P * vec4(p, 1.0f);
      depth.at(x, y) = vec4(clip.z / clip.w * 0.5f + 0.5f);
      normal.at(x, y) = vec4(-(p - c), 0.0f);
    }
  sc.depth = snell::Texture2D(std::move(depth));
  sc.normal = snell::Texture2D(std::move(normal), snell::Filter::Linear);
  sc.surface = snell::snellDepthSurface(P, 0.1f, 100.0f, SNELL_DEPTH_GL, 0.0f);
  if (withPyramid) sc.pyramid = snell::snellBuildDepthPyramid(sc.depth, sc.surface);

  sc.rays.resize(kRays);
  for (int i = 0; i < kRays; ++i) {
    float a = i * 0.61803f, r = 0.8f * ((i * 7919) % 1000) / 1000.0f;
    vec3 o(r * cos(a), r * sin(a), -4.0f);
    vec3 dir = normalize(vec3(-0.2f * o.x, -0.2f * o.y, -1.0f));
    sc.rays[i] = Ray{{o.x, o.y, o.z}, {dir.x, dir.y, dir.z}};
  }

  // The wide set: origins over and beside the sphere at z in [-4.6, -3], directions
  // in a broad cone, some towards the camera (kernel_study -DCHECK checks it too).
  std::uint32_t seed = 12345u;
  auto uni = [&](float lo, float hi) {
    seed = seed * 1664525u + 1013904223u;
    return lo + (hi - lo) * static_cast<float>(seed >> 8) * (1.0f / 16777216.0f);
  };
  sc.wide.resize(withWide ? kRays : 0);
  for (int i = 0; i < static_cast<int>(sc.wide.size()); ++i) {
    vec3 o(uni(-1.6f, 1.6f), uni(-1.6f, 1.6f), uni(-4.6f, -3.0f));
    vec3 dir = normalize(vec3(uni(-0.6f, 0.6f), uni(-0.6f, 0.6f), uni(-1.0f, 0.3f)));
    sc.wide[i] = Ray{{o.x, o.y, o.z}, {dir.x, dir.y, dir.z}};
  }

  kern::Camera& k = sc.cam;
  k.a = P[0][0];
  k.b = P[1][1];
  k.c = P[2][2];
  k.d = P[3][2];
  k.det = k.a * k.b;  // snellUvZToView's det: a b - (+0)(+0)
  k.zNear = sc.surface.zNear;
  k.nearOverFar = sc.surface.zNear / sc.surface.zFar;  // snellLinearizeDepth's zNear / zFar
  k.depth = &sc.depth.level(0).texels[0].x;
  k.normal = &sc.normal.level(0).texels[0].x;
  k.levels = sc.pyramid.levelCount();
  for (int l = 0; l < k.levels && l < kern::kMaxLevels; ++l) k.pyramid[l] = &sc.pyramid.level(l).texels[0].x;
}

}  // namespace kscene
#endif  // KERNEL_SCENE_HPP
