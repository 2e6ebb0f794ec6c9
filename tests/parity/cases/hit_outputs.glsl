/* Shared by the plane and search families' parity cases: a SnellHit into the
   outputs uv, valid, fetches, position and texel (the hit uv's level-0 texel
   of a buffer of `size` texels), which the case's description lays out. */
#ifndef SNELL_PARITY_CASES_HIT_OUTPUTS_GLSL
#define SNELL_PARITY_CASES_HIT_OUTPUTS_GLSL
#include "snell/intersect.glsl"

#define CASE_SET_HIT(hit, size)                                    \
  SnellHit caseHit = hit;                                          \
  uv = caseHit.uv;                                                 \
  valid = caseHit.valid;                                           \
  fetches = caseHit.fetches;                                       \
  position = caseHit.position;                                     \
  texel = snellUvToPixel(caseHit.uv, size)

#endif
