/*
description: the depth min/max pyramid (Oliveira & Brauwers 2007, 2nd pass): a
  parallel reduction of a depth buffer in which every texel of level L+1 holds,
  for the block of level-0 texels below it, the nearest and farthest view
  distance (the search range Zmin, Zmax of their sec. 3.2), the mean depth value
  (a depth mip the plane strategies and any strategy can read through
  snellSampleSurface with surface.lod = L) and the covered fraction. Empty
  (invalid) texels are excluded; an all-empty block stays empty.
use: level 0, one pass over the depth buffer (fragment: px = ivec2(gl_FragCoord.xy)):
       out = snellDepthPyramidBase(SNELL_TEXEL_FETCH(depthTex, px, 0).x, surface);
     level L+1 from level L (fragment or compute pass, px the output texel):
       out = snellDepthMinMaxReduce(pyramidTex, L, px, surface.emptyDepth);
     C++: snell::snellBuildDepthPyramid(depthTexture, surface) (include/snell/depth_pyramid.hpp)
     zMin/zMax of the whole buffer: the top (1x1) level's y and z.
  A full GL pass is glsl/passes/depth_pyramid.frag (driven level by level by
  snell::gpu::DepthPyramidPass).
texel layout (RGBA32F):
  x  mean depth value (window depth, the buffer's own convention) of the valid
     children; emptyDepth when none is valid
  y  nearest view distance (min of -z_view, > 0) of the valid level-0 texels below
  z  farthest view distance (max), >= y
  w  coverage: the mean of the children's coverage (level 0: 1 valid, 0 empty);
     > 0 exactly when some level-0 texel below is valid
  Distances rather than depth values for y and z: they are what the searches
  need (view z = -distance), and "nearest" then does not depend on the
  convention (reversed Z stores the nearest point as the LARGEST depth value).
contract:
  - snellDepthPyramidBase: invalid when depthValue == surface.emptyDepth, NaN,
    infinite, or does not linearize (snellSurfaceLinearDepth <= 0: bad zNear/zFar/convention):
    vec4(emptyDepth, 0, 0, 0). Otherwise vec4(depthValue, v, v, 1), v =
    snellSurfaceLinearDepth(surface, depthValue) > 0 (snellLinearizeDepth's value).
  - snellDepthMinMaxReduce: level L has size (W, H) = SNELL_TEXTURE_SIZE(tex, L);
    level L+1 has (max(1, W/2), max(1, H/2)), and px must lie in it. The children
    are columns 2px.x .. 2px.x+1 (and 2px.x+2 for the last column when W is odd:
    GL's floor sizes drop no texel), column 0 alone when W == 1; rows likewise:
    2x2 texels, 3 x 2 / 2 x 3 / 3 x 3 at odd edges (fetches = their number, 1..9).
    A child is valid when its w > 0. Result: x = (sum of valid children's x) /
    (their count), y = min, z = max of their y / z, w = (sum of all children's w)
    / (number of children); with no valid child vec4(emptyDepth, 0, 0, 0).
  - the x channel is an unweighted mean of child means: equal to the mean over
    all level-0 texels below for full blocks of power-of-two sizes; for a planar
    surface it is the depth at the block centre (window depth is affine in
    screen space over a plane).
  - the sums run in a fixed order with no products, so the GPU pass and the C++
    build agree bit for bit (the parity test compares every level exactly).
source: M. M. Oliveira, M. Brauwers, "Real-Time Refraction Through Deformable
  Objects", I3D 2007, sec. 3 (2nd pass: "the minimum and maximum depth values
  from each group of four elements"), after M. Harris, "Mapping Computational
  Concepts to GPUs" (parallel reduction), GPU Gems 2 ch. 31 (2005).
*/
#ifndef SNELL_INTERSECT_DEPTH_PYRAMID_GLSL
#define SNELL_INTERSECT_DEPTH_PYRAMID_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"
#include "../camera/linearize_depth.glsl"
#include "depth_surface.glsl"

SNELL_FN vec4 snellDepthPyramidBase(float depthValue, SNELL_IN(SnellDepthSurface) s) {
  vec4 empty = vec4(s.emptyDepth, 0.0f, 0.0f, 0.0f);
  if (!SNELL_FINITE(depthValue) || depthValue == s.emptyDepth) {
    return empty;
  }
  float v = snellSurfaceLinearDepth(s, depthValue);
  if (!(v > 0.0f)) {
    return empty;
  }
  return vec4(depthValue, v, v, 1.0f);
}

SNELL_FN vec4 snellDepthMinMaxReduce(SNELL_TEX2D pyramidTex, int lod, ivec2 px, float emptyDepth) {
  ivec2 size = SNELL_TEXTURE_SIZE(pyramidTex, lod);
  int lastX = max(1, size.x / 2) - 1;
  int lastY = max(1, size.y / 2) - 1;
  int countX = size.x == 1 ? 1 : (px.x == lastX ? size.x - 2 * px.x : 2);
  int countY = size.y == 1 ? 1 : (px.y == lastY ? size.y - 2 * px.y : 2);
  float sum = 0.0f;
  float coverage = 0.0f;
  float nearest = 0.0f;
  float farthest = 0.0f;
  int valid = 0;
  int children = 0;
  for (int dy = 0; dy < 3; ++dy) {
    for (int dx = 0; dx < 3; ++dx) {
      if (dx < countX && dy < countY) {
        vec4 t = SNELL_TEXEL_FETCH(pyramidTex, ivec2(2 * px.x + dx, 2 * px.y + dy), lod);
        children += 1;
        coverage += t.w;
        if (t.w > 0.0f) {
          sum += t.x;
          nearest = valid == 0 ? t.y : min(nearest, t.y);
          farthest = valid == 0 ? t.z : max(farthest, t.z);
          valid += 1;
        }
      }
    }
  }
  if (valid == 0) {
    return vec4(emptyDepth, 0.0f, 0.0f, 0.0f);
  }
  return vec4(sum / float(valid), nearest, farthest, coverage / float(max(children, 1)));
}

#endif
