/*
description: HLSL entry for the optics/ family of snell: refraction (Snell, TIR policies, approximate), Fresnel (exact, Schlick, bias/power, cubic), IOR/F0, normal blending, Beer absorption.
  The bridge (bridge.hlsl) maps GLSL names to HLSL, then the very GLSL bodies of
  glsl/snell/optics/ are included: one source, no HLSL twin to drift.
use: #include "snell/optics.hlsl"   (or snell/snell.hlsl for everything)
  The relative include below reaches glsl/snell/ both in the source tree and in
  the install tree (share/snell/hlsl_like/snell -> share/snell/glsl/snell).
  Conventions that differ from GL (uv origin top-left, depth 0..1 / reversed Z,
  mul order and matrix packing, left-handed views): see bridge.hlsl and
  hlsl_like/README.md.
*/
#ifndef SNELL_HLSL_OPTICS
#define SNELL_HLSL_OPTICS
#include "bridge.hlsl"
#include "../../glsl/snell/optics.glsl"
#endif
