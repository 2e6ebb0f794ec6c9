/*
description: HLSL entry for the camera/ family of snell: depth conventions (GL, ZERO_ONE, REVERSED, infinite), view <-> clip <-> uv, the perspective texture-space ray.
  The bridge (bridge.hlsl) maps GLSL names to HLSL, then the very GLSL bodies of
  glsl/snell/camera/ are included: one source, no HLSL twin to drift.
use: #include "snell/camera.hlsl"   (or snell/snell.hlsl for everything)
  The relative include below reaches glsl/snell/ both in the source tree and in
  the install tree (share/snell/hlsl_like/snell -> share/snell/glsl/snell).
  Conventions that differ from GL (uv origin top-left, depth 0..1 / reversed Z,
  mul order and matrix packing, left-handed views): see bridge.hlsl and
  hlsl_like/README.md.
*/
#ifndef SNELL_HLSL_CAMERA
#define SNELL_HLSL_CAMERA
#include "bridge.hlsl"
#include "../../glsl/snell/camera.glsl"
#endif
