/*
description: HLSL entry for the intersect/ family of snell: ray vs. depth buffer: single sample, plane (normal/depth) with refinement, conservative binary search, linear+binary, DDA march.
  The bridge (bridge.hlsl) maps GLSL names to HLSL, then the very GLSL bodies of
  glsl/snell/intersect/ are included: one source, no HLSL twin to drift.
use: #include "snell/intersect.hlsl"   (or snell/snell.hlsl for everything)
  The relative include below reaches glsl/snell/ both in the source tree and in
  the install tree (share/snell/hlsl_like/snell -> share/snell/glsl/snell).
  Conventions that differ from GL (uv origin top-left, depth 0..1 / reversed Z,
  mul order and matrix packing, left-handed views): see bridge.hlsl and
  hlsl_like/README.md.
*/
#ifndef SNELL_HLSL_INTERSECT
#define SNELL_HLSL_INTERSECT
#include "bridge.hlsl"
#include "../../glsl/snell/intersect.glsl"
#endif
