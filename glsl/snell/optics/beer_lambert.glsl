/*
description: Beer-Lambert absorption: the transmittance exp(-sigma d) of a
  homogeneous medium with absorption coefficient sigma (per colour channel)
  over a path of length d.
use: vec3 T = snellBeerLambert(absorption, dist); color *= T;
  absorption  sigma_a per channel, in inverse distance units (>= 0)
  dist        path length inside the medium, same units
options: -
contract:
  - result components in [0, 1]; never NaN;
  - dist negative or NaN is treated as 0 (result (1,1,1)); +inf is clamped
    to FLT_MAX;
  - each absorption component negative or NaN is treated as 0 (that channel
    is 1: a medium never amplifies); +inf is clamped to FLT_MAX, so
    0 * inf never occurs (zero distance always gives 1);
  - very large sigma d gives 0 (exp underflow; a GPU may flush the denormal
    tail to 0 earlier than the C++ build); the exponent is clamped to 1e30
    (exp(-1e30) is already 0), which keeps it finite on drivers that fold
    exp's log2(e) factor into sigma or d (FLT_MAX * 1.44 overflows, and
    times a zero distance would give NaN; llvmpipe does: docs/DESIGN.md).
source: Beer-Lambert law, T = exp(-sigma_a d) (e.g. Pharr, Jakob & Humphreys,
  PBRT 3rd ed., sec. 11.1, transmittance of a homogeneous medium).
*/
#ifndef SNELL_OPTICS_BEER_LAMBERT_GLSL
#define SNELL_OPTICS_BEER_LAMBERT_GLSL
#include "../prelude.glsl"

SNELL_FN vec3 snellBeerLambert(vec3 absorption, float dist) {
  // Comparisons rather than clamp()/max(): they are undefined for NaN in GLSL.
  float d = dist > 0.0f ? min(dist, SNELL_FLT_MAX) : 0.0f;
  vec3 s = vec3(absorption.x > 0.0f ? min(absorption.x, SNELL_FLT_MAX) : 0.0f,
                absorption.y > 0.0f ? min(absorption.y, SNELL_FLT_MAX) : 0.0f,
                absorption.z > 0.0f ? min(absorption.z, SNELL_FLT_MAX) : 0.0f);
  // The min() on the product, not only on the factors: llvmpipe lowers exp(x)
  // to exp2(x * log2(e)) and reassociates that constant onto a factor,
  // (s * log2(e)) * d, which is inf * 0 = NaN for s = FLT_MAX, d = 0. A min()
  // in between keeps the constant off s and d; no NaN can reach it (s, d >= 0).
  return exp(-min(s * d, vec3(1e30f)));
}

#endif
