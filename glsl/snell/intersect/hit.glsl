/*
description: the result every intersection strategy returns: where a view-space
  ray meets a surface that exists only as a depth buffer.
use: SnellHit h = snellIntersect...(origin, dir, depthTex, surface, ...);
     if (h.valid) { vec4 n = SNELL_SAMPLE_LOD(normalTex, h.uv, 0.0f); ... }
  uv        the hit's projection, viewport uv (origin bottom-left, [0,1]^2)
  position  the hit point in view space (on the ray; z < 0)
  valid     false when no hit was found (see each strategy's contract)
  fetches   texel fetches spent (machine-independent cost; counted also when
            the search fails)
contract: snellHitMiss gives valid = false, uv = (0,0), position = (0,0,0) and the
  fetch count it is given: finite numbers always.
source: the common interface of DESIGN.md sec. 2 (intersect/).
*/
#ifndef SNELL_INTERSECT_HIT_GLSL
#define SNELL_INTERSECT_HIT_GLSL
#include "../prelude.glsl"

struct SnellHit {
  vec2 uv;
  vec3 position;
  bool valid;
  int fetches;
};

SNELL_FN SnellHit snellHitMiss(int fetches) {
  SnellHit h;
  h.uv = vec2(0.0f, 0.0f);
  h.position = vec3(0.0f, 0.0f, 0.0f);
  h.valid = false;
  h.fetches = fetches;
  return h;
}

#endif
