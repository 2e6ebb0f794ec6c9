/* intersect/ family aggregator: every strategy for a ray against a depth buffer. */
#ifndef SNELL_INTERSECT_GLSL
#define SNELL_INTERSECT_GLSL
#include "intersect/hit.glsl"
#include "intersect/depth_surface.glsl"
#include "intersect/surface_projection.glsl"
#include "intersect/surface_point.glsl"
#include "intersect/single_sample.glsl"
#include "intersect/hit_on_surface.glsl"
#include "intersect/plane_refine.glsl"
#include "intersect/plane_far_start.glsl"
#include "intersect/plane_normal.glsl"
#include "intersect/plane_depth.glsl"
#include "intersect/depth_pyramid.glsl"
#include "intersect/depth_range.glsl"
#include "intersect/search_segment.glsl"
#include "intersect/conservative_binary_search.glsl"
#include "intersect/binary_search.glsl"
#include "intersect/linear_binary_search.glsl"
#include "intersect/linear_march.glsl"
#include "intersect/inside_march.glsl"
#include "intersect/dda_march.glsl"
#include "intersect/intersect_with.glsl"
#endif
