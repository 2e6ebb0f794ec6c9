/*
description: HLSL aggregate entry: every public function of snell (optics,
  camera, intersect, shade), from the same GLSL bodies as the GL and C++ builds.
use: #include "snell/snell.hlsl" in a pixel or compute shader, with the folder
  that holds hlsl_like/snell on the include path (e.g. -I share/snell/hlsl_like).
  Define options (SNELL_HLSL_SAMPLER, SNELL_HLSL_FLIP_V, the texture hooks, loop
  counts such as SNELL_CBS_STEPS) before this include. Conventions that differ
  from GL: see bridge.hlsl and hlsl_like/README.md.
contract: the manifest test (tests/parity, ParityManifest.EveryPublicGlslFunctionHasAnHlslEntryAndRun)
  fails when a public GLSL function is not defined after preprocessing this file.
*/
#ifndef SNELL_HLSL_SNELL
#define SNELL_HLSL_SNELL
#include "bridge.hlsl"
#include "optics.hlsl"
#include "camera.hlsl"
#include "intersect.hlsl"
#include "shade.hlsl"
#endif
