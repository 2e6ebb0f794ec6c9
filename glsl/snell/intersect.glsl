/* intersect/ family aggregator: every strategy for a ray against a depth buffer. */
#ifndef SNELL_INTERSECT_GLSL
#define SNELL_INTERSECT_GLSL
#include "intersect/hit.glsl"
#include "intersect/depth_surface.glsl"
#endif
