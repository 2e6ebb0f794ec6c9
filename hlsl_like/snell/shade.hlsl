/*
description: HLSL entry for the shade/ family of snell: the composed techniques: two-interface refraction, Sousa perturbation with refraction mask, water, glass, ice, refractive texture mapping.
  The bridge (bridge.hlsl) maps GLSL names to HLSL, then the very GLSL bodies of
  glsl/snell/shade/ are included: one source, no HLSL twin to drift.
use: #include "snell/shade.hlsl"   (or snell/snell.hlsl for everything)
  The relative include below reaches glsl/snell/ both in the source tree and in
  the install tree (share/snell/hlsl_like/snell -> share/snell/glsl/snell).
  Conventions that differ from GL (uv origin top-left, depth 0..1 / reversed Z,
  mul order and matrix packing, left-handed views): see bridge.hlsl and
  hlsl_like/README.md.
*/
#ifndef SNELL_HLSL_SHADE
#define SNELL_HLSL_SHADE
#include "bridge.hlsl"
#include "../../glsl/snell/shade.glsl"
#endif
