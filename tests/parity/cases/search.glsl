/* Parity cases for the ray-vs-depth-buffer searches and marches of
   glsl/snell/intersect/ (search_segment, conservative_binary_search,
   binary_search (and its bisection), linear_binary_search, linear_march, dda_march): one entry per
   public function, run on the analytic scene buffers of
   tests/support/depth_scenes.hpp uploaded as textures.
   Inputs: a = (origin, option 1), b = (dir, option 2),
           c = (zNearest, zFarthest, option 3, scene), d = (A, B, C, D): the
           projection's four non-zero entries (x scale, y scale, z row), so the
           matrix is bit-identical on both sides (no tan on the GPU).
   scene 0: sphereBack (back-face buffer), 1: silhouette (opaque, empty texels);
   both GL convention, zNear/zFar as below, emptyDepth 0 / 1.
   A negative option 1 selects the overload with the #define defaults.
   Outputs: a = (uv, valid, fetches), b = (position, texel x),
            c = (texel y, 0, 0, 0): texel = snellUvToPixel(uv) of level 0. */
#include "snell/intersect.glsl"

#define SEARCH_PARITY_NEAR 0.5f
#define SEARCH_PARITY_FAR 40.0f

#if defined(SNELL_LANG_GLSL)
uniform sampler2D searchTexSphere;      /* sphereBack 256x256, NEAREST */
uniform sampler2D searchTexSilhouette;  /* silhouette 256x256, NEAREST */
#endif
#if defined(SNELL_LANG_HLSL)
Texture2D<float4> searchTexSphere;
Texture2D<float4> searchTexSilhouette;
#endif

SNELL_FN mat4 searchParityMatrix(vec4 d) {
  return SNELL_CAMERA_MAT4_COLUMNS(vec4(d.x, 0.0f, 0.0f, 0.0f), vec4(0.0f, d.y, 0.0f, 0.0f),
                                   vec4(0.0f, 0.0f, d.z, -1.0f), vec4(0.0f, 0.0f, d.w, 0.0f));
}

SNELL_FN SnellDepthSurface searchParitySurface(vec4 c, vec4 d) {
  return snellDepthSurface(searchParityMatrix(d), SEARCH_PARITY_NEAR, SEARCH_PARITY_FAR, SNELL_DEPTH_GL,
                           c.w > 0.5f ? 1.0f : 0.0f);
}

SNELL_FN SnellParityOut searchParityOut(SnellHit h) {
  ivec2 px = snellUvToPixel(h.uv, ivec2(256, 256));
  SnellParityOut o;
  o.a = vec4(h.uv.x, h.uv.y, h.valid ? 1.0f : 0.0f, float(h.fetches));
  o.b = vec4(h.position.x, h.position.y, h.position.z, float(px.x));
  o.c = vec4(float(px.y), 0.0f, 0.0f, 0.0f);
  o.d = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  return o;
}

/* out a = (S, valid), b = (E, k1), c = (t's, dt), d = (k2, 0, 0, 0) */
SNELL_FN SnellParityOut caseSnellSearchSegment(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellTexRay r = snellSearchSegment(vec3(a.x, a.y, a.z), vec3(b.x, b.y, b.z), c.x, c.y, searchParityMatrix(d));
  SnellParityOut o;
  o.a = vec4(r.s.x, r.s.y, r.s.z, r.valid ? 1.0f : 0.0f);
  o.b = vec4(r.e.x, r.e.y, r.e.z, r.k1);
  o.c = vec4(r.ts.x, r.ts.y, r.dt.x, r.dt.y);
  o.d = vec4(r.k2, 0.0f, 0.0f, 0.0f);
  return o;
}

/* option 1 = steps */
SNELL_FN SnellParityOut caseSnellConservativeBinarySearch(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDepthSurface s = searchParitySurface(c, d);
  vec3 o = vec3(a.x, a.y, a.z);
  vec3 v = vec3(b.x, b.y, b.z);
  SnellHit h;
  if (c.w > 0.5f) {
    h = a.w < 0.0f ? snellConservativeBinarySearch(o, v, searchTexSilhouette, s, c.x, c.y)
                   : snellConservativeBinarySearch(o, v, searchTexSilhouette, s, c.x, c.y, int(a.w));
  } else {
    h = a.w < 0.0f ? snellConservativeBinarySearch(o, v, searchTexSphere, s, c.x, c.y)
                   : snellConservativeBinarySearch(o, v, searchTexSphere, s, c.x, c.y, int(a.w));
  }
  return searchParityOut(h);
}

/* option 1 = steps */
SNELL_FN SnellParityOut caseSnellBinarySearch(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDepthSurface s = searchParitySurface(c, d);
  vec3 o = vec3(a.x, a.y, a.z);
  vec3 v = vec3(b.x, b.y, b.z);
  SnellHit h;
  if (c.w > 0.5f) {
    h = a.w < 0.0f ? snellBinarySearch(o, v, searchTexSilhouette, s, c.x, c.y)
                   : snellBinarySearch(o, v, searchTexSilhouette, s, c.x, c.y, int(a.w));
  } else {
    h = a.w < 0.0f ? snellBinarySearch(o, v, searchTexSphere, s, c.x, c.y)
                   : snellBinarySearch(o, v, searchTexSphere, s, c.x, c.y, int(a.w));
  }
  return searchParityOut(h);
}

/* option 1 = steps, option 2 = lo, option 3 = hi; the hit so far is a miss
   (its uv and position mark "not moved") */
SNELL_FN SnellParityOut caseSnellBisectTexRay(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDepthSurface s = searchParitySurface(c, d);
  SnellTexRay r = snellSearchSegment(vec3(a.x, a.y, a.z), vec3(b.x, b.y, b.z), c.x, c.y, s.clipFromView);
  SnellHit h = snellHitMiss(0);
  if (r.valid) {
    h = c.w > 0.5f ? snellBisectTexRay(r, searchTexSilhouette, s, b.w, c.z, int(a.w), h)
                   : snellBisectTexRay(r, searchTexSphere, s, b.w, c.z, int(a.w), h);
  }
  return searchParityOut(h);
}

/* option 1 = linearSteps, option 2 = binarySteps */
SNELL_FN SnellParityOut caseSnellLinearBinarySearch(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDepthSurface s = searchParitySurface(c, d);
  vec3 o = vec3(a.x, a.y, a.z);
  vec3 v = vec3(b.x, b.y, b.z);
  SnellHit h;
  if (c.w > 0.5f) {
    h = a.w < 0.0f ? snellLinearBinarySearch(o, v, searchTexSilhouette, s, c.x, c.y)
                   : snellLinearBinarySearch(o, v, searchTexSilhouette, s, c.x, c.y, int(a.w), int(b.w));
  } else {
    h = a.w < 0.0f ? snellLinearBinarySearch(o, v, searchTexSphere, s, c.x, c.y)
                   : snellLinearBinarySearch(o, v, searchTexSphere, s, c.x, c.y, int(a.w), int(b.w));
  }
  return searchParityOut(h);
}

/* option 1 = steps, option 2 = refineSteps, option 3 = maxDistance */
SNELL_FN SnellParityOut caseSnellLinearMarch(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDepthSurface s = searchParitySurface(c, d);
  vec3 o = vec3(a.x, a.y, a.z);
  vec3 v = vec3(b.x, b.y, b.z);
  SnellHit h;
  if (c.w > 0.5f) {
    h = a.w < 0.0f ? snellLinearMarch(o, v, searchTexSilhouette, s)
                   : snellLinearMarch(o, v, searchTexSilhouette, s, c.z, int(a.w), int(b.w));
  } else {
    h = a.w < 0.0f ? snellLinearMarch(o, v, searchTexSphere, s)
                   : snellLinearMarch(o, v, searchTexSphere, s, c.z, int(a.w), int(b.w));
  }
  return searchParityOut(h);
}

/* option 1 = steps, option 2 = stride, option 3 = maxDistance, c.x = thickness */
SNELL_FN SnellParityOut caseSnellDdaMarch(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDepthSurface s = searchParitySurface(c, d);
  vec3 o = vec3(a.x, a.y, a.z);
  vec3 v = vec3(b.x, b.y, b.z);
  SnellHit h;
  if (c.w > 0.5f) {
    h = a.w < 0.0f ? snellDdaMarch(o, v, searchTexSilhouette, s)
                   : snellDdaMarch(o, v, searchTexSilhouette, s, c.z, c.x, b.w, int(a.w));
  } else {
    h = a.w < 0.0f ? snellDdaMarch(o, v, searchTexSphere, s)
                   : snellDdaMarch(o, v, searchTexSphere, s, c.z, c.x, b.w, int(a.w));
  }
  return searchParityOut(h);
}
