// The study's fragment shader body (gpu_kernel_study.cpp puts #version and
// VARIANT in front of it): one ray per pixel (ray (y W + x) mod the ray
// count), VARIANT: 0 snell single sample, 1 snell normal plane (1 it., the
// poster's: no far start), 2 the same with the far start (snell's default, the
// lab's), 3 the kernel single sample, 4 the kernel normal plane (1 it.), 5 and
// 6: 0 and 1 with SNELL_PERSPECTIVE_ONLY 1, 7 snell CBS-5, 8 the kernel CBS-5,
// 9 snell linear march (32 steps, 4 refinements), 10 the kernel linear march,
// 11: 0 with the surface read from a uniform (built once by the C++
// snellDepthSurface) instead of built in the shader from constants and the
// kClipFromView and kClipRange uniforms; 12 snell's whole two-interface
// technique (snellTwoInterfaceRefraction, snellPresetPlaneNormal(2), the exit
// slot on the opaque scene) for one front-face fragment per pixel, 13 the
// kernel of the same (kTwoInterface).
#if VARIANT == 5 || VARIANT == 6
#  define SNELL_PERSPECTIVE_ONLY 1
#endif
#if VARIANT == 12
// Only the strategy the technique calls, as snell-lab compiles each technique
// (snellStrategiesUsed): 1 << SNELL_STRATEGY_PLANE_NORMAL.
#  define SNELL_INTERSECT_STRATEGIES (1 << 1)
#endif
#include "snell/snell.glsl"
#include "gpu_kernels.glsl"

layout(binding = 3) uniform sampler2D kRayOrigin;  // xyz, one ray per texel, row-major
layout(binding = 4) uniform sampler2D kRayDir;
layout(binding = 5) uniform sampler2D kFrontPosition;  // xyz, one front-face fragment per texel, row-major
layout(binding = 6) uniform sampler2D kFrontNormal;
uniform mat4 kClipFromView;
uniform vec2 kClipRange;  // zNear, zFar
uniform int kRayCount;
uniform int kFrontCount;
#if VARIANT == 11
uniform SnellDepthSurface kSurface;
#endif

layout(location = 0) out vec4 outPosition;  // xyz position
layout(location = 1) out vec4 outHit;       // uv, valid, fetches

void main() {
#if VARIANT == 12 || VARIANT == 13
  int frontWidth = textureSize(kFrontPosition, 0).x;
  int f = (int(gl_FragCoord.y) * 512 + int(gl_FragCoord.x)) % kFrontCount;
  ivec2 fat = ivec2(f % frontWidth, f / frontWidth);
  vec3 p1 = texelFetch(kFrontPosition, fat, 0).xyz;
  vec3 n1 = texelFetch(kFrontNormal, fat, 0).xyz;
#  if VARIANT == 12
  SnellDepthSurface back = snellDepthSurface(kClipFromView, kClipRange.x, kClipRange.y, SNELL_DEPTH_GL, 0.0);
  SnellDepthSurface scene = snellDepthSurface(kClipFromView, kClipRange.x, kClipRange.y, SNELL_DEPTH_GL, 1.0);
  scene.closed = false;
  SnellTechnique t = snellPresetPlaneNormal(2);
  t.exit.source = SNELL_SOURCE_BUFFERS;
  SnellMaterial m = snellMaterial();
  m.absorption = kAbsorption;
  // The front layer is never read without bounces, nor the scene's pyramid on an open surface: the back
  // buffers stand in for both.
  SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(p1, n1, 0.0, kDepth, kNormal, kPyramid, back, kDepth, kNormal,
                                                          back, kSceneDepth, kSceneNormal, kPyramid, kSceneColor, scene,
                                                          kEnvironment, t, m, snellView());
  outPosition = vec4(r.color, r.pathLength);
  outHit = vec4(r.fresnel, float(r.fetches), r.backHit ? 1.0 : 0.0, r.fellBack ? 1.0 : 0.0);
#  else
  KShade r = kTwoInterface(p1, n1);
  outPosition = vec4(r.color, r.pathLength);
  outHit = vec4(r.fresnel, float(r.fetches), r.backHit ? 1.0 : 0.0, r.fellBack ? 1.0 : 0.0);
#  endif
#else
  int width = textureSize(kRayOrigin, 0).x;
  int i = (int(gl_FragCoord.y) * 512 + int(gl_FragCoord.x)) % kRayCount;
  ivec2 at = ivec2(i % width, i / width);
  vec3 o = texelFetch(kRayOrigin, at, 0).xyz;
  vec3 d = texelFetch(kRayDir, at, 0).xyz;
#if VARIANT != 11
  SnellDepthSurface kSurface = snellDepthSurface(kClipFromView, kClipRange.x, kClipRange.y, SNELL_DEPTH_GL, 0.0);
#endif
#if VARIANT == 0 || VARIANT == 5 || VARIANT == 11
  SnellHit h = snellIntersectSingleSample(o, d, kDepth, kSurface);
#elif VARIANT == 1 || VARIANT == 2 || VARIANT == 6
  SnellHit h = snellIntersectPlaneNormal(o, d, kDepth, kNormal, kPyramid, kSurface, 0.0, 1, VARIANT == 2);
#elif VARIANT == 3
  KHit h = kSingleSample(o, d);
#elif VARIANT == 4
  KHit h = kPlaneNormal(o, d, 1);
#elif VARIANT == 7
  SnellHit h = snellConservativeBinarySearch(o, d, kDepth, kSurface, -4.0, -6.2, 5);
#elif VARIANT == 8
  KHit h = kCbs(o, d, -4.0, -6.2, 5);
#elif VARIANT == 9
  SnellHit h = snellLinearMarch(o, d, kDepth, kSurface, 5.0, 32, 4);
#else
  KHit h = kLinearMarch(o, d, 5.0, 32, 4);
#endif
  outPosition = vec4(h.position, 0.0);
  outHit = vec4(h.uv, h.valid ? 1.0 : 0.0, float(h.fetches));
#endif
}
