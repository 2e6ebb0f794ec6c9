/*
description: the single-sample baseline that Mayer & Assarsson compare their
  plane methods against (the "GPU Gems" row of their table): ONE depth lookup,
  no search. The surface point B directly behind the ray origin W gives a
  distance d = |B - W|, and the hit is taken d further along the ray (the
  thickness approximation of Wyman 2005 and Sousa 2005: the ray travels as far
  as the surface is behind its start).
use: SnellHit h = snellIntersectSingleSample(origin, dir, depthTex, surface);
  origin    view-space ray start W (z < 0): the front-face point for the back-face
            buffer, the exit point for the opaque scene buffer
  dir       ray direction (any length; normalized inside)
  depthTex  the depth texture `surface` describes (read at level surface.lod)
contract:
  - uvW = projection of W; B = snellSurfacePoint(depthTex, uvW, surface) (the
    texel centre point); d = |B - W|; position = W + d normalize(dir); uv = its
    projection. fetches = 1 always.
  - valid is true exactly when B exists and the position lies in front of the
    camera and projects into [0,1]^2. It says nothing about whether the surface
    exists at uv (no second lookup: that is the baseline's point); exact when
    dir points from W straight at B (d is then the true distance).
  - any direction is accepted, also one towards the camera (the answer is then
    the point d towards the camera, which the caller asked for).
  - valid = false (snellHitMiss): origin or dir NaN/Inf, |dir|^2 below 1e-30 or
    overflowing, origin at or behind the camera plane (no projection): fetches 0;
    W projecting off screen, B empty/invalid, the position off screen or behind
    the camera: fetches 1 (the lookup is counted once W projects, as a shader
    would issue it).
source: C. Mayer, U. Assarsson, "Constant-Time Light Refraction Simulation"
  (the single-sample row of the results table, step 2 for B); T. Sousa, "Generic
  Refraction Simulation", GPU Gems 2 ch. 19 (2005); C. Wyman, "An Approximate
  Image-Space Approach for Interactive Refraction", SIGGRAPH 2005 (P2 ~ P1 + d T1).
*/
#ifndef SNELL_INTERSECT_SINGLE_SAMPLE_GLSL
#define SNELL_INTERSECT_SINGLE_SAMPLE_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"
#include "../camera/view_to_uv.glsl"
#include "hit.glsl"
#include "depth_surface.glsl"
#include "surface_projection.glsl"
#include "surface_point.glsl"

SNELL_FN SnellHit snellIntersectSingleSample(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) s) {
  float len2 = dot(dir, dir);
  if (!SNELL_FINITE(origin.x) || !SNELL_FINITE(origin.y) || !SNELL_FINITE(origin.z) ||
      !SNELL_FINITE(len2) || !(len2 >= 1e-30f)) {
    return snellHitMiss(0);
  }
  SnellScreenPoint w = snellSurfaceViewToUv(s, origin);
  if (!w.valid) {
    return snellHitMiss(0);
  }
  SnellSurfacePoint b = snellSurfacePoint(depthTex, w.uv, s);
  if (!b.valid) {
    return snellHitMiss(1);
  }
  vec3 toB = b.position - origin;
  float d = sqrt(dot(toB, toB));
  vec3 p = origin + (d / sqrt(len2)) * dir;
  SnellScreenPoint sp = snellSurfaceViewToUv(s, p);
  if (!sp.valid || !(sp.uv.x >= 0.0f && sp.uv.x <= 1.0f && sp.uv.y >= 0.0f && sp.uv.y <= 1.0f)) {
    return snellHitMiss(1);
  }
  SnellHit h;
  h.uv = sp.uv;
  h.position = p;
  h.valid = true;
  h.fetches = 1;
  return h;
}

#endif
