/*
description: integer pixel <-> viewport uv (GL window conventions).
use: vec2 uv = snellPixelToUv(ivec2(gl_FragCoord.x, gl_FragCoord.y), size);   // pixel centre
     ivec2 px = snellUvToPixel(uv, size);   // ready for SNELL_TEXEL_FETCH
  size    viewport (or texture level) size in pixels, e.g. SNELL_TEXTURE_SIZE(tex, 0)
contract:
  - pixel (i, j) covers uv [i, i+1]/W x [j, j+1]/H, origin bottom-left (row 0 is
    the bottom row, as glReadPixels and texel fetches order it).
  - snellPixelToUv returns the pixel centre ((i + 0.5)/W, (j + 0.5)/H), not
    clamped: pixels outside the viewport give uv outside [0,1]. A size component
    <= 0 gives 0 for that component.
  - snellUvToPixel returns the pixel containing uv, floor(uv * size), clamped into
    [0, size - 1] (clamp-to-edge: uv outside [0,1] gives an edge pixel, so the
    result is always a legal texelFetch coordinate). A uv component on a pixel
    boundary belongs to the pixel above/right of it; uv = 1 to the last pixel.
    NaN uv gives pixel 0 in that component; a size with a component <= 0
    gives (0,0).
  - snellUvToPixel(snellPixelToUv(p, size), size) == p for every p inside the
    viewport (sizes up to 2^22).
  - SNELL_PIXEL_ON_SCREEN(uv, size) (a macro) == snellUvToPixel(uv, size) for
    uv in [0,1]^2 and 0 < size < 2^24, without the NaN test, the floor and the
    lower clamp; undefined elsewhere (int() of NaN), so only a caller that has
    just checked the domain uses it.
  - SNELL_PIXEL_CENTRE(px, size) (a macro) == snellPixelToUv(px, size) for
    size > 0, without its two size tests; it divides by size, so only a
    caller that knows size > 0 uses it.
source: OpenGL 4.5 core spec sec. 8.14.2 (texel coordinates u = s W), sec. 14.5
  (fragment centres at (i + 0.5, j + 0.5)).
*/
#ifndef SNELL_CAMERA_PIXEL_TO_UV_GLSL
#define SNELL_CAMERA_PIXEL_TO_UV_GLSL
#include "../prelude.glsl"
#include "conventions.glsl"

SNELL_FN vec2 snellPixelToUv(ivec2 px, ivec2 size) {
  float u = size.x > 0 ? (float(px.x) + 0.5f) / float(size.x) : 0.0f;
  float v = size.y > 0 ? (float(px.y) + 0.5f) / float(size.y) : 0.0f;
  return vec2(u, v);
}

/* SNELL_PIXEL_ON_SCREEN(uv, size): snellUvToPixel(uv, size), the same texel,
   for a uv already checked to lie in [0,1]^2 (so not NaN) and 0 < size < 2^24
   (any texture size; above, float(size) is inexact): there
   the truncation is the floor and only uv == 1 needs the clamp, which saves the
   NaN test, the floor and the lower clamp per read. A macro, not a function,
   because it is undefined outside that domain (int() of NaN): only code that
   has just checked the domain uses it (intersect/depth_surface.glsl,
   intersect/surface_point.glsl). One line: GLSL 330 has no line continuation. */
#define SNELL_PIXEL_ON_SCREEN(uv, size) ivec2(min(int((uv).x * float((size).x)), (size).x - 1), min(int((uv).y * float((size).y)), (size).y - 1))

/* SNELL_PIXEL_CENTRE(px, size): snellPixelToUv(px, size), the same operations,
   for size > 0 (intersect/surface_point.glsl, after a valid read of the
   level): the two size tests left out. One line, as above. */
#define SNELL_PIXEL_CENTRE(px, size) vec2((float((px).x) + 0.5f) / float((size).x), (float((px).y) + 0.5f) / float((size).y))

SNELL_FN ivec2 snellUvToPixel(vec2 uv, ivec2 size) {
  if (size.x <= 0 || size.y <= 0) {
    return ivec2(0, 0);
  }
  float x = isnan(uv.x) ? 0.0f : clamp(floor(uv.x * float(size.x)), 0.0f, float(size.x - 1));
  float y = isnan(uv.y) ? 0.0f : clamp(floor(uv.y * float(size.y)), 0.0f, float(size.y - 1));
  return ivec2(int(x), int(y));
}

#endif
