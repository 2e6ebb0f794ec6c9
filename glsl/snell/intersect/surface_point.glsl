/*
description: the view-space point a depth texture stores at a uv: the texel
  containing uv, reconstructed at that texel's CENTRE (the point the rasterizer
  actually sampled, by camera/uv_z_to_view.glsl). The plane strategies build
  their planes from these points.
use: SnellSurfacePoint b = snellSurfacePoint(depthTex, uv, surface);   // b.position, b.uv, b.valid
contract:
  - snellSurfacePoint: one snellSampleSurface at uv (one fetch, level s.lod);
    uv = the centre of the texel read (snellPixelToUv of snellUvToPixel at level
    s.lod), or uv itself when the sample was interpolated (s.depthFilter
    BILINEAR with four surface texels: the depth there is the surface's at uv),
    position = snellUvZToView(s.clipFromView, that uv, viewZ). valid
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
#include "../camera/uv_z_to_view.glsl"
#include "depth_surface.glsl"
#include "surface_projection.glsl"

struct SnellSurfacePoint {
  vec3 position;  // view space, on the texel centre's pixel ray
  vec2 uv;        // the texel centre
  bool valid;
};

SNELL_FN_INLINE SnellSurfacePoint snellSurfacePoint(SNELL_TEX2D depthTex, vec2 uv, SNELL_IN(SnellDepthSurface) s) {
  SnellSurfacePoint r;
  r.position = vec3(0.0f, 0.0f, 0.0f);
  r.uv = vec2(0.0f, 0.0f);
  r.valid = false;
  SnellSurfaceSample x = snellSampleSurface(depthTex, uv, s);
  if (!x.valid) {
    return r;
  }
  ivec2 size = SNELL_TEXTURE_SIZE(depthTex, s.lod);
  // x.valid: uv is on screen and size > 0 (the macros' domain)
  vec2 centre = uv;
  if (!x.interpolated) {
    ivec2 px = SNELL_PIXEL_ON_SCREEN(uv, size);
    centre = SNELL_PIXEL_CENTRE(px, size);
  }
  SnellViewPoint p = snellSurfaceUvZToView(s, centre, x.viewZ);
  if (!p.valid) {
    return r;
  }
  r.position = p.position;
  r.uv = centre;
  r.valid = true;
  return r;
}

#endif
