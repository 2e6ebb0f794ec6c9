// Compile-flag study (issue 14, docs/api.md "Compile flags for tools"): the same
// 20000 rays (plane-normal-1, or CBS-5 with -DCBS) through the back-face buffers of an
// analytic sphere; prints a hash of every output bit, so flags that change a
// result show. benchmarks/flags/flag_study.sh counts instructions per ray with callgrind.
#include <snell/snell.hpp>
#include <cstdio>
#include <cstring>
#include <cstdint>
using namespace glm;
#ifndef RAYS
#define RAYS 20000
#endif
int main() {
  const int W = 256;
  const mat4 P = snell::snellPerspective(radians(45.0f), 1.0f, 0.1f, 100.0f);
  snell::Image depth(W, W, vec4(0.0f)), normal(W, W, vec4(0.0f));
  for (int y = 0; y < W; ++y) for (int x = 0; x < W; ++x) {
    // back hemisphere of a unit sphere at z = -5 (analytic), GL depth
    vec2 ndc((x + 0.5f) / W * 2 - 1, (y + 0.5f) / W * 2 - 1);
    vec3 d = normalize(vec3(ndc.x * tan(radians(22.5f)), ndc.y * tan(radians(22.5f)), -1.0f));
    vec3 c(0, 0, -5); float b = dot(d, c); float disc = b * b - dot(c, c) + 1.0f;
    if (disc < 0) continue;
    float t = b + sqrt(disc); vec3 p = d * t; vec4 clip = P * vec4(p, 1.0f);
    depth.at(x, y) = vec4(clip.z / clip.w * 0.5f + 0.5f); normal.at(x, y) = vec4(-(p - c), 0.0f);
  }
  snell::Texture2D dt(depth), nt(normal, snell::Filter::Linear);
  snell::SnellDepthSurface s = snell::snellDepthSurface(P, 0.1f, 100.0f, SNELL_DEPTH_GL, 0.0f);
  std::uint64_t h = 1469598103934665603ull; int valid = 0;
  auto mix = [&](float f) { std::uint32_t u; std::memcpy(&u, &f, 4); h = (h ^ u) * 1099511628211ull; };
  for (int i = 0; i < RAYS; ++i) {
    float a = i * 0.61803f, r = 0.8f * ((i * 7919) % 1000) / 1000.0f;
    vec3 o(r * cos(a), r * sin(a), -4.0f);
    vec3 dir = normalize(vec3(-0.2f * o.x, -0.2f * o.y, -1.0f));
#ifdef CBS
    snell::SnellHit hit = snell::snellConservativeBinarySearch(o, dir, dt, s, -4.0f, -6.2f, 5);
#else
    snell::SnellHit hit = snell::snellIntersectPlaneNormal(o, dir, dt, nt, s, 0.0f, 1);
#endif
    mix(hit.position.x); mix(hit.position.y); mix(hit.position.z); mix(hit.uv.x); mix(hit.uv.y); mix(hit.valid ? 1.0f : 0.0f); valid += hit.valid;
  }
  std::printf("%016llx valid=%d\n", (unsigned long long)h, valid);
}
