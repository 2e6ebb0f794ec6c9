/*
description: the ice paper's cheap Fresnel term, f = (1 - |e.n|)^3: 0 looking
  straight at the surface, 1 at grazing angles.
use: float f = snellFresnelCubic(eye, normal);
  eye     the eye vector; either orientation works (the paper's e runs from the
          viewer to the vertex, the vertex-to-eye vector gives the same result)
  normal  surface normal, either orientation
  Neither needs to be normalized.
options: -
contract:
  - result in [0, 1]: f = (1 - c)^3 with c = |dot(normalize(eye),
    normalize(normal))| clamped to [0, 1];
  - sign convention: the paper writes (1 - e.n)^3 with e from the viewer to
    the vertex, which read literally gives values in [1, 8] on front faces
    (e.n < 0); the intended term (0 head-on, 1 at grazing) is (1 - cos)^3 with
    cos the unsigned cosine, which is what this computes;
  - eye or normal zero, denormal-small, NaN or infinite: treated as grazing,
    result 1.
source: "Real-Time Ice Rendering" (ice shader report), sec. 3.2, equation 4,
  f = (1 - e.n)^3, after Jensen & Golias 2001.
*/
#ifndef SNELL_OPTICS_FRESNEL_CUBIC_GLSL
#define SNELL_OPTICS_FRESNEL_CUBIC_GLSL
#include "../prelude.glsl"
#include "safe_normalize.glsl"

SNELL_FN float snellFresnelCubic(vec3 eye, vec3 normal) {
  vec3 e = snellSafeNormalize(eye);
  vec3 n = snellSafeNormalize(normal);
  if (dot(e, e) == 0.0f || dot(n, n) == 0.0f) {
    return 1.0f;
  }
  float c = min(abs(dot(e, n)), 1.0f);
  float m = 1.0f - c;
  return m * m * m;
}

#endif
