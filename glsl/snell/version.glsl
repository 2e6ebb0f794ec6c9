/*
description: snell's version, the one place it is written: CMake's project()
  reads it, and every language gets it through the prelude (C++, GLSL, HLSL).
  SNELL_VERSION is MAJOR * 10000 + MINOR * 100 + PATCH, for #if tests.
  Changes between versions: CHANGELOG.md.
contract: macros only.
*/
#ifndef SNELL_VERSION_GLSL
#define SNELL_VERSION_GLSL
#define SNELL_VERSION_MAJOR 0
#define SNELL_VERSION_MINOR 2
#define SNELL_VERSION_PATCH 0
#define SNELL_VERSION (SNELL_VERSION_MAJOR * 10000 + SNELL_VERSION_MINOR * 100 + SNELL_VERSION_PATCH)
#endif
