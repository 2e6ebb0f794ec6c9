/*
description: conservative binary search (CBS): intersect a view-space ray with
  a depth-buffer surface by a binary search in texture space that only ever
  advances along the ray, and only onto texels that hold a surface, so the
  result never maps to an empty texel (no undefined normal at the silhouette).
use: SnellHit h = snellConservativeBinarySearch(origin, dir, depthTex, surface, zNearest, zFarthest);
     SnellHit h = snellConservativeBinarySearch(origin, dir, depthTex, surface, zNearest, zFarthest, steps);
     if (h.valid) { vec4 n2 = SNELL_TEXEL_FETCH(normalTex, snellUvToPixel(h.uv, size), 0); ... }
  origin, dir          view-space ray (P1 and T1 in the paper; dir need not be normalized)
  depthTex, surface    the depth buffer and how to read it (depth_surface.glsl);
                       back-face buffer or opaque scene buffer alike
  zNearest, zFarthest  the depth range to search, as view-space z (< 0): see
                       search_segment.glsl (min/max pyramid top level, or a
                       bounding volume; two numbers either way)
  steps                binary steps c (each one texel fetch)
options:
  SNELL_CBS_STEPS      default steps (5, the paper's choice: beta error <= 3.125%)
  SNELL_CBS_MAX_STEPS  compile-time loop bound (24); steps is clamped to
                       [0, SNELL_CBS_MAX_STEPS] (beyond ~24 halvings beta is
                       below float resolution anyway)
contract:
  - the segment S-E is snellSearchSegment(origin, dir, zNearest, zFarthest,
    surface.clipFromView); beta in [0,1] along it (eq. 5). Starting at beta = 0,
    step i (dBeta = 0.5^i) tests beta + dBeta: z = S.z + b (E.z - S.z), uv =
    snellTexRayUv (eqs. 9-10), one snellSampleSurface fetch; it advances (beta
    += dBeta) only when the texel is valid and the point is strictly in front of
    the surface (z > viewZ, Algorithm 2's -P.z < storedDepth); an empty or
    off-screen texel never lets it advance.
  - valid means: the returned point maps to a valid (non-empty, on-screen)
    texel. After at least one advance it is the last point that advanced (its uv
    is the uv that was fetched, so the texel is exactly the one tested). When
    no step advanced, the start S itself is tested with one more fetch (counted)
    and returned if its texel is valid: then the true crossing, if the ray
    crosses the surface once on S-E, has beta < 0.5^c (or the ray starts behind
    the surface).
  - precision: if the ray crosses the surface once on S-E (in front of it at S,
    behind it, or over an empty texel, at E), the returned beta is at most
    0.5^c before the crossing: beta_error = 0.5^c - 0.5^k <= 0.5^c for a
    crossing that needs k > c steps (the paper, sec. 3.3). After an advance the
    returned point is strictly in front of the surface at its texel (never past
    it); S is returned whatever its depth order (the ray may start behind).
  - a ray that stays in front of the surface up to E returns a point near E
    (the paper's behaviour: the search range is assumed to contain the hit).
  - position = S + beta (E - S), uv its texture coordinate; fetches = steps
    performed (+1 for the start test).
  - valid = false, with snellHitMiss numbers (finite), when the segment is
    invalid (dir.z >= 0: rays towards the camera; zNearest <= zFarthest
    including Zmin == Zmax; NaN/Inf inputs, but for the matrix's third row,
    which the segment does not read; planes at or behind the eye): 0
    fetches; or when nothing advanced and S maps to an empty or off-screen
    texel (rays leaving the screen, all-empty buffers).
source: M. M. Oliveira, M. Brauwers, "Real-Time Refraction Through Deformable
  Objects", I3D 2007, sec. 3.3, Algorithm 2, the error bound
  beta_error = 0.5^c - 0.5^k; eqs. 3-10 for the parameterization.
*/
#ifndef SNELL_INTERSECT_CONSERVATIVE_BINARY_SEARCH_GLSL
#define SNELL_INTERSECT_CONSERVATIVE_BINARY_SEARCH_GLSL
#include "../prelude.glsl"
#include "../camera/tex_ray.glsl"
#include "hit.glsl"
#include "depth_surface.glsl"
#include "search_segment.glsl"

#ifndef SNELL_CBS_STEPS
#  define SNELL_CBS_STEPS 5
#endif
#ifndef SNELL_CBS_MAX_STEPS
#  define SNELL_CBS_MAX_STEPS 24
#endif

/* Oliveira & Brauwers 2007, Algorithm 2 */
SNELL_FN SnellHit snellConservativeBinarySearch(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) surface,
                                                float zNearest, float zFarthest, int steps) {
  SnellTexRay r = snellSearchSegment(origin, dir, zNearest, zFarthest, surface.clipFromView);
  if (!r.valid) {
    return snellHitMiss(0);
  }
  int n = clamp(steps, 0, SNELL_CBS_MAX_STEPS);
  float dz = r.e.z - r.s.z;
  // snellTexRayUv with its per-step guards left out, the same results: every
  // step's z lies between r.s.z and r.e.z (both <= -SNELL_FLT_MIN), so alpha
  // is in [0, 1] up to rounding (never NaN, no clamp needed) and uv lies
  // between the segment's finite ends; its k2 == 0 case (k2 underflowed)
  // gives alpha 0 through k12 = 0; the product k1 k2 is taken once.
  float k12 = r.k2 == 0.0f ? 0.0f : r.k1 * r.k2;
  float beta = 0.0f;
  float dBeta = 1.0f;
  float zHit = r.s.z;
  vec2 uvHit = r.ts;
  bool advanced = false;
  int fetches = 0;
  for (int i = 0; n > 0 && i < SNELL_CBS_MAX_STEPS; ++i) {
    dBeta = dBeta * 0.5f;
    float b = beta + dBeta;
    float z = r.s.z + b * dz;
    vec2 uv = r.ts + (((r.s.z - z) / z) * k12) * r.dt;
    SnellSurfaceSample x = snellSampleSurface(depthTex, uv, surface);
    fetches = fetches + 1;
    if (x.valid && z > x.viewZ) {
      beta = b;
      zHit = z;
      uvHit = uv;
      advanced = true;
    }
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (i + 1 >= n) {
      break;
    }
  }
  if (!advanced) {
    SnellSurfaceSample x0 = snellSampleSurface(depthTex, uvHit, surface);
    fetches = fetches + 1;
    if (!x0.valid) {
      return snellHitMiss(fetches);
    }
  }
  SnellHit h;
  h.uv = uvHit;
  h.position = vec3(r.s.x + beta * (r.e.x - r.s.x), r.s.y + beta * (r.e.y - r.s.y), zHit);
  h.valid = true;
  h.fetches = fetches;
  return h;
}

SNELL_FN SnellHit snellConservativeBinarySearch(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) surface,
                                                float zNearest, float zFarthest) {
  return snellConservativeBinarySearch(origin, dir, depthTex, surface, zNearest, zFarthest, SNELL_CBS_STEPS);
}

#endif
