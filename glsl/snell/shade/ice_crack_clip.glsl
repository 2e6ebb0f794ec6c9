/*
description: the ice shader's crack clipping, a screen-space Boolean
  intersection: a fragment of a generic crack surface is kept only when its
  depth lies inside the [front, back] depth interval of the (convex) ice
  object at that pixel, read from the object's front- and back-face depth
  textures.
use: if (!snellIceCrackKeep(gl_FragCoord.z, frontDepth, backDepth, SNELL_DEPTH_GL)) discard;
  crackDepth  depth-buffer value of the crack fragment
  frontDepth  the ice object's front-face depth at the pixel (nearest surface)
  backDepth   the ice object's back-face depth at the pixel (farthest surface)
  convention  depth convention of all three (camera/conventions.glsl): GL,
              ZERO_ONE, INFINITE_GL store near -> 0, REVERSED and
              INFINITE_REVERSED near -> 1
options: -
contract:
  - near -> 0 conventions: keep iff frontDepth <= crackDepth <= backDepth;
    reversed conventions: keep iff frontDepth >= crackDepth >= backDepth; the
    interval includes both ends.
  - false (the fragment is clipped) when any depth is NaN or outside [0, 1]
    (not a depth-buffer value), the convention is unknown, or the interval is
    empty (front behind back: no ice at the pixel when the front texture is
    cleared to the far value and the back texture to the near value).
source: "Real-Time Ice Rendering" (ice shader report), sec. 3.3 ("If the
  value is not contained within the interval of the two sampled values
  nothing is drawn"), Figure 5.
*/
#ifndef SNELL_SHADE_ICE_CRACK_CLIP_GLSL
#define SNELL_SHADE_ICE_CRACK_CLIP_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"

SNELL_FN bool snellIceCrackKeep(float crackDepth, float frontDepth, float backDepth, int convention) {
  if (isnan(crackDepth) || isnan(frontDepth) || isnan(backDepth)) {
    return false;
  }
  bool inRange = (crackDepth >= 0.0f && crackDepth <= 1.0f) && (frontDepth >= 0.0f && frontDepth <= 1.0f) &&
                 (backDepth >= 0.0f && backDepth <= 1.0f);
  if (!inRange) {
    return false;
  }
  if (convention == SNELL_DEPTH_GL || convention == SNELL_DEPTH_ZERO_ONE || convention == SNELL_DEPTH_INFINITE_GL) {
    return frontDepth <= crackDepth && crackDepth <= backDepth;
  }
  if (convention == SNELL_DEPTH_REVERSED || convention == SNELL_DEPTH_INFINITE_REVERSED) {
    return frontDepth >= crackDepth && crackDepth >= backDepth;
  }
  return false;
}

#endif
