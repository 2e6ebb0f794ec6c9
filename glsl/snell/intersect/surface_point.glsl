/*
description: the view-space point a depth texture stores at a uv: the texel
  containing uv, reconstructed at that texel's CENTRE (the point the rasterizer
  actually sampled), plus the inverse projection it needs for a known view z.
  The plane strategies build their planes from these points.
use: SnellSurfacePoint b = snellSurfacePoint(depthTex, uv, surface);   // b.position, b.uv, b.valid
     SnellViewPoint p = snellUvZToView(clipFromView, uv, viewZ);
  uv            viewport uv ([0,1]^2, origin bottom-left)
  viewZ         view-space z (< 0) of the wanted point
  clipFromView  any projection with clip w = -z (perspective.glsl, glm::perspective*,
                glFrustum, off-centre frusta); no inverse matrix is needed
contract:
  - snellUvZToView: the point p with p.z == viewZ whose projection has NDC xy =
    2 uv - 1, from the 2x2 linear system clip.xy = ndc.xy clip.w (Cramer's rule on
    the matrix columns). valid =
    false, position (0,0,0), when an input is NaN/Inf, viewZ >= 0 or denormal, the
    system is singular (|det| below the smallest normal float) or the result
    overflows.
  - snellSurfacePoint: one snellSampleSurface at uv (one fetch, level s.lod);
    uv = the centre of the texel read (snellPixelToUv of snellUvToPixel at level
    s.lod), position = snellUvZToView(s.clipFromView, that centre, viewZ). valid
    = false (uv and position 0) when the sample is invalid (off screen, empty,
    NaN) or the reconstruction is. Costs one fetch whatever the outcome.
  - texel-centre reconstruction is what makes the plane strategies exact on
    planar surfaces: a depth texel is the surface depth at its centre.
source: OpenGL 4.5 core spec sec. 13.6 (clip -> NDC), sec. 14.5 (fragment
  centres); Mayer & Assarsson, "Constant-Time Light Refraction Simulation",
  step 2 (B, the point directly behind W, from the screen buffers).
*/
#ifndef SNELL_INTERSECT_SURFACE_POINT_GLSL
#define SNELL_INTERSECT_SURFACE_POINT_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"
#include "../camera/pixel_to_uv.glsl"
#include "../camera/uv_depth_to_view.glsl"
#include "depth_surface.glsl"

/* Column i of a matrix (the matrix's i-th basis image) without a matrix product:
   GLSL and GLM index columns, HLSL rows. */
#if defined(SNELL_LANG_HLSL)
#  define SNELL_INTERSECT_MAT_COLUMN(m, i) (transpose(m)[i])
#else
#  define SNELL_INTERSECT_MAT_COLUMN(m, i) ((m)[i])
#endif

struct SnellSurfacePoint {
  vec3 position;  // view space, on the texel centre's pixel ray
  vec2 uv;        // the texel centre
  bool valid;
};

SNELL_FN SnellViewPoint snellUvZToView(mat4 clipFromView, vec2 uv, float viewZ) {
  SnellViewPoint r;
  r.position = vec3(0.0f, 0.0f, 0.0f);
  r.valid = false;
  if (!SNELL_CAMERA_FINITE(uv.x) || !SNELL_CAMERA_FINITE(uv.y) || !SNELL_CAMERA_FINITE(viewZ) ||
      !(viewZ <= -SNELL_CAMERA_FLT_MIN)) {
    return r;
  }
  vec4 c0 = SNELL_INTERSECT_MAT_COLUMN(clipFromView, 0);
  vec4 c1 = SNELL_INTERSECT_MAT_COLUMN(clipFromView, 1);
  vec4 c2 = SNELL_INTERSECT_MAT_COLUMN(clipFromView, 2);
  vec4 c3 = SNELL_INTERSECT_MAT_COLUMN(clipFromView, 3);
  float nx = 2.0f * uv.x - 1.0f;
  float ny = 2.0f * uv.y - 1.0f;
  // x a00 + y a01 = b0,  x a10 + y a11 = b1
  float a00 = c0.x - nx * c0.w;
  float a01 = c1.x - nx * c1.w;
  float a10 = c0.y - ny * c0.w;
  float a11 = c1.y - ny * c1.w;
  float b0 = -(viewZ * (c2.x - nx * c2.w) + (c3.x - nx * c3.w));
  float b1 = -(viewZ * (c2.y - ny * c2.w) + (c3.y - ny * c3.w));
  float det = a00 * a11 - a01 * a10;
  if (!SNELL_CAMERA_FINITE(det) || !(abs(det) >= SNELL_CAMERA_FLT_MIN)) {
    return r;
  }
  float x = (b0 * a11 - a01 * b1) / det;
  float y = (a00 * b1 - b0 * a10) / det;
  if (!SNELL_CAMERA_FINITE(x) || !SNELL_CAMERA_FINITE(y)) {
    return r;
  }
  r.position = vec3(x, y, viewZ);
  r.valid = true;
  return r;
}

SNELL_FN SnellSurfacePoint snellSurfacePoint(SNELL_TEX2D depthTex, vec2 uv, SnellDepthSurface s) {
  SnellSurfacePoint r;
  r.position = vec3(0.0f, 0.0f, 0.0f);
  r.uv = vec2(0.0f, 0.0f);
  r.valid = false;
  SnellSurfaceSample x = snellSampleSurface(depthTex, uv, s);
  if (!x.valid) {
    return r;
  }
  ivec2 size = SNELL_TEXTURE_SIZE(depthTex, s.lod);
  vec2 centre = snellPixelToUv(snellUvToPixel(uv, size), size);
  SnellViewPoint p = snellUvZToView(s.clipFromView, centre, x.viewZ);
  if (!p.valid) {
    return r;
  }
  r.position = p.position;
  r.uv = centre;
  r.valid = true;
  return r;
}

#endif
