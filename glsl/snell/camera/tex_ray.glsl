/*
description: the perspective texture-space parameterization of a view-space ray
  segment (Oliveira & Brauwers 2007, sec. 3.2.1, eqs. 3-10, Algorithm 1): the
  segment S-E of the refracted ray T1 between two constant-z planes, and for any
  point P on it, from P.z alone, the image-space parameter alpha and the uv where
  P projects, without a matrix product per step.
use: SnellTexRay r = snellTexRaySetup(p1, t1, zNearest, zFarthest, clipFromView);
     // march in 3D: P.z = mix(r.s.z, r.e.z, beta)  (eq. 5)
     vec2 uv = snellTexRayUv(r, pz);   float alpha = snellTexRayAlpha(r, pz);
  p1         view-space start of the ray (P1, the front-face hit)
  t1         ray direction T1 (need not be normalized: eqs. 3-4 divide by T1.z)
  zNearest   view-space z of the plane where the search starts, the back-face
             depth nearest to the camera (the paper's Zmin, a minimum *distance*;
             as a right-handed view-space z it is the LARGER, less negative value)
  zFarthest  view-space z of the plane where it ends (the paper's Zmax, the
             farthest back-face depth; the more negative value). Both are z
             values (< 0), not distances and not the camera's clip planes.
  clipFromView  the camera projection; eqs. 8-9 assume clip w = -z (true for every
             matrix of perspective.glsl, glm::perspective*, glFrustum).
contract:
  - S = P1 + ((zNearest - P1.z)/T1.z) T1 (eq. 3), E likewise with zFarthest (eq.
    4); S.z == zNearest and E.z == zFarthest exactly. S and E are the
    intersections of the LINE with the planes: when T1 points towards the camera
    (T1.z > 0) they lie behind P1 on the ray; the caller decides what that means.
  - k1 = 1/S.z, k2 = S.z E.z/(S.z - E.z) (eq. 9), ts = t's = 0.5 S~.xy/S~.w + 0.5,
    dt = t'e - t's (eq. 10, Algorithm 1).
  - snellTexRayAlpha(r, pz) = (1/pz - k1) k2 (eq. 9), evaluated as the equal
    ((S.z - pz)/pz) (k1 k2) = ((S.z - pz)/pz) E.z/(S.z - E.z), which has no
    cancellation when pz is close to S.z. alpha = 0 at S.z, 1 at E.z; pz outside
    [E.z, S.z] extrapolates along the line (alpha outside [0,1]); never clamped
    to [0,1], only to +-SNELL_FLT_MAX.
  - snellTexRayUv(r, pz) = ts + alpha dt (eq. 10): the uv where the point of the
    line with z = pz projects (equal to projecting P with clipFromView).
  - zNearest == zFarthest: the segment is a point: S == E, k2 = 0, dt = 0,
    alpha = 0 for every pz, uv = ts; valid is true.
  - valid = false, with every field 0 (so alpha = 0 and uv = (0,0)), when: any
    input is NaN or Inf (matrix included, but for its third row: clip z is
    never computed, the segment needs no depth of its ends); T1.z == 0 (the
    ray is parallel to the planes and never reaches them); zNearest >= 0 or
    zFarthest >= 0 (denormal values count as 0 throughout: GPUs may flush
    them); S or E project with clip w <= 0 or not finite; or any result
    overflows (e.g. T1.z so small that S is at infinity, or a clip w so small
    that S's or E's ndc does: no clamp keeps such a segment). A plane at or
    behind the eye (z >= 0) is rejected rather than clamped to the near
    plane: eq. 8 needs S~.w = -S.z > 0, the back-face depth extremes of a
    rendered object always lie in front of the near plane, so such input is a
    caller bug, and clamping would silently search a segment the caller did
    not ask for.
  - alpha (and uv) for a valid ray and pz >= 0 (or denormal), NaN or Inf (no
    projection): alpha 0,
    uv = ts, i.e. the search start.
source: M. M. Oliveira, M. Brauwers, "Real-Time Refraction Through Deformable
  Objects", I3D 2007, sec. 3.2.1, eqs. 3, 4, 5, 6, 8, 9, 10 and Algorithm 1.
*/
#ifndef SNELL_CAMERA_TEX_RAY_GLSL
#define SNELL_CAMERA_TEX_RAY_GLSL
#include "../prelude.glsl"
#include "conventions.glsl"

struct SnellTexRay {
  vec3 s;      // S, on the plane z = zNearest (eq. 3)
  vec3 e;      // E, on the plane z = zFarthest (eq. 4)
  float k1;    // 1 / S.z (eq. 9)
  float k2;    // S.z E.z / (S.z - E.z) (eq. 9); 0 when S.z == E.z
  vec2 ts;     // t's: uv of S (eq. 10)
  vec2 dt;     // t'e - t's (Algorithm 1)
  bool valid;
};

SNELL_FN_INLINE SnellTexRay snellTexRaySetup(vec3 p1, vec3 t1, float zNearest, float zFarthest, mat4 clipFromView) {
  SnellTexRay r;
  r.s = vec3(0.0f, 0.0f, 0.0f);
  r.e = vec3(0.0f, 0.0f, 0.0f);
  r.k1 = 0.0f;
  r.k2 = 0.0f;
  r.ts = vec2(0.0f, 0.0f);
  r.dt = vec2(0.0f, 0.0f);
  r.valid = false;
  if (!SNELL_FINITE(p1.x) || !SNELL_FINITE(p1.y) || !SNELL_FINITE(p1.z) ||
      !SNELL_FINITE(t1.x) || !SNELL_FINITE(t1.y) || !SNELL_FINITE(t1.z) ||
      !SNELL_FINITE(zNearest) || !SNELL_FINITE(zFarthest)) {
    return r;
  }
  if (!(abs(t1.z) >= SNELL_FLT_MIN) || !(zNearest <= -SNELL_FLT_MIN) ||
      !(zFarthest <= -SNELL_FLT_MIN)) {
    return r;
  }
  float ls = (zNearest - p1.z) / t1.z;
  float le = (zFarthest - p1.z) / t1.z;
  vec3 s = vec3(p1.x + ls * t1.x, p1.y + ls * t1.y, zNearest);
  vec3 e = vec3(p1.x + le * t1.x, p1.y + le * t1.y, zFarthest);
  // Clip x, y and w only: the segment never needs its ends' depth, so the z
  // row is neither computed nor tested. The sums keep SNELL_MUL's association
  // in GLM, (c0 x + c1 y) + (c2 z + c3), so the C++ bits are the product's.
  // Written out rather than through snellViewToClip: llvmpipe drops the
  // unused row either way, g++ keeps the whole product (CBS-5 in C++: 1071
  // instead of 996 instructions per ray, benchmarks/kernels/kernel_table.sh).
  vec4 c0 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 0);
  vec4 c1 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 1);
  vec4 c2 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 2);
  vec4 c3 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 3);
  vec3 cs = vec3((c0.x * s.x + c1.x * s.y) + (c2.x * s.z + c3.x), (c0.y * s.x + c1.y * s.y) + (c2.y * s.z + c3.y),
                 (c0.w * s.x + c1.w * s.y) + (c2.w * s.z + c3.w));
  vec3 ce = vec3((c0.x * e.x + c1.x * e.y) + (c2.x * e.z + c3.x), (c0.y * e.x + c1.y * e.y) + (c2.y * e.z + c3.y),
                 (c0.w * e.x + c1.w * e.y) + (c2.w * e.z + c3.w));
  // w finite and >= FLT_MIN; a non-finite x or y, or an ndc that overflows,
  // leaves ts or dt non-finite: rejected below.
  if (!SNELL_FINITE(s.x) || !SNELL_FINITE(s.y) || !SNELL_FINITE(e.x) || !SNELL_FINITE(e.y) ||
      !(cs.z >= SNELL_FLT_MIN && cs.z <= SNELL_FLT_MAX) || !(ce.z >= SNELL_FLT_MIN && ce.z <= SNELL_FLT_MAX)) {
    return r;
  }
  vec2 ts = vec2(cs.x, cs.y) / cs.z * 0.5f + 0.5f;
  vec2 te = vec2(ce.x, ce.y) / ce.z * 0.5f + 0.5f;
  vec2 dt = te - ts;
  float k1 = 1.0f / zNearest;
  float k2 = zNearest == zFarthest ? 0.0f : (zNearest * zFarthest) / (zNearest - zFarthest);
  if (!SNELL_FINITE(ts.x) || !SNELL_FINITE(ts.y) || !SNELL_FINITE(dt.x) ||
      !SNELL_FINITE(dt.y) || !SNELL_FINITE(k1) || !SNELL_FINITE(k2) ||
      !SNELL_FINITE(k1 * k2)) {
    return r;
  }
  r.s = s;
  r.e = e;
  r.k1 = k1;
  r.k2 = k2;
  r.ts = ts;
  r.dt = dt;
  r.valid = true;
  return r;
}

SNELL_FN float snellTexRayAlpha(SnellTexRay r, float pz) {
  if (!r.valid || r.k2 == 0.0f || !SNELL_FINITE(pz) || !(pz <= -SNELL_FLT_MIN)) {
    return 0.0f;
  }
  float alpha = ((r.s.z - pz) / pz) * (r.k1 * r.k2);
  // pz denormal-small: inf * (a product that underflowed to 0) is NaN.
  return isnan(alpha) ? 0.0f : clamp(alpha, -SNELL_FLT_MAX, SNELL_FLT_MAX);
}

SNELL_FN vec2 snellTexRayUv(SnellTexRay r, float pz) {
  float alpha = snellTexRayAlpha(r, pz);
  vec2 uv = r.ts + alpha * r.dt;
  return clamp(uv, vec2(-SNELL_FLT_MAX, -SNELL_FLT_MAX), vec2(SNELL_FLT_MAX, SNELL_FLT_MAX));
}

#endif
