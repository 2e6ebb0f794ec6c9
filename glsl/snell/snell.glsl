/* Aggregator: all of snell. GLSL users may include single files instead. */
#ifndef SNELL_SNELL_GLSL
#define SNELL_SNELL_GLSL
#include "optics.glsl"
#include "camera.glsl"
#include "intersect.glsl"
#include "shade.glsl"
#endif
