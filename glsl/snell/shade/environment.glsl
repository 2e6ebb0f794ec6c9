/*
description: distant-environment lookups for the exit ray of a refraction
  technique: equirectangular (latitude-longitude) maps in a plain 2D texture,
  fully supported in every language, and cube maps through a hook. The
  techniques read the environment only through SNELL_SAMPLE_ENVIRONMENT, so an
  engine switches them to cube maps with two #defines.
use: vec2 uv = snellEquirectUv(dirWorld);
     vec4 c = snellSampleEquirect(envTex, dirWorld, lod);
     float a = snellAtan2(y, x);
  Cube maps (define before including snell, in GLSL or C++):
     #define SNELL_ENVIRONMENT_TEX SNELL_TEXCUBE
     #define SNELL_SAMPLE_ENVIRONMENT(tex, dir, lod) SNELL_SAMPLE_CUBE_LOD(tex, dir, lod)
     (C++: include <snell/texture_cube.hpp> first; it defines snell::TextureCube.)
options (hooks; define before this file to override):
  SNELL_TEXCUBE                        cube texture parameter type (GLSL samplerCube,
                                       C++ const snell::TextureCube&, HLSL TextureCube<float4>)
  SNELL_SAMPLE_CUBE_LOD(tex, dir, lod) vec4 of a cube map along dir at explicit lod
  SNELL_ENVIRONMENT_TEX                the environment parameter type of the
                                       techniques (default SNELL_TEX2D: equirectangular)
  SNELL_SAMPLE_ENVIRONMENT(tex, dir, lod)  the techniques' environment read
                                       (default snellSampleEquirect(tex, dir, lod))
contract:
  - snellAtan2(y, x): the angle of (x, y) in (-pi, pi], from an odd degree-9
    polynomial of the octant-reduced ratio (max error ~1e-5 rad) using only
    +, *, /, abs and comparisons, so every language computes the same value up
    to rounding (the builtin atan(y, x) differs between GLSL and HLSL in
    argument order and between drivers in precision). atan2(0, 0) = 0; y = 0,
    x < 0 gives pi (also for y = -0); NaN input gives 0; infinities are
    treated as the ratio 1 per octant.
  - snellEquirectUv(d): u = 0.5 + atan2(d.x, -d.z) / (2 pi) (the -Z view
    direction is the centre column, +X to the right, u increases clockwise seen
    from above), v = 0.5 + atan2(d.y, |(d.x, d.z)|) / pi (v = 1 straight up,
    +Y; GL row 0 is the bottom row = straight down). d need not be unit
    length. Zero, NaN or Inf directions give (0.5, 0.5).
  - snellSampleEquirect: SNELL_SAMPLE_LOD(env, snellEquirectUv(d), lod). The
    seam at u = 0/1 is filtered with the texture's own wrap mode (clamp to edge
    in snell::Texture2D: a one-texel seam; GL_REPEAT in s hides it on a GPU,
    but then C++ and GL differ at the seam).
source: equirectangular (plate carree) environment mapping, e.g. Pharr, Jakob
  & Humphreys, PBRT 3rd ed., sec. 12.6 (InfiniteAreaLight, spherical
  coordinates); atan polynomial: C. Hastings, "Approximations for Digital
  Computers" (1955), sheet 11 (odd minimax polynomial on [0, 1]); cube maps:
  environment_cube_face.glsl.
*/
#ifndef SNELL_SHADE_ENVIRONMENT_GLSL
#define SNELL_SHADE_ENVIRONMENT_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"
#include "environment_cube_face.glsl"

#if defined(SNELL_LANG_GLSL)
#  ifndef SNELL_TEXCUBE
#    define SNELL_TEXCUBE samplerCube
#  endif
#  ifndef SNELL_SAMPLE_CUBE_LOD
#    define SNELL_SAMPLE_CUBE_LOD(tex, dir, lod) textureLod(tex, dir, lod)
#  endif
#elif defined(SNELL_LANG_HLSL)
#  ifndef SNELL_TEXCUBE
#    define SNELL_TEXCUBE TextureCube<float4>
#  endif
#  ifndef SNELL_SAMPLE_CUBE_LOD
#    define SNELL_SAMPLE_CUBE_LOD(tex, dir, lod) ((tex).SampleLevel(SNELL_HLSL_SAMPLER, dir, lod))
#  endif
#else
#  ifndef SNELL_TEXCUBE
#    define SNELL_TEXCUBE const ::snell::TextureCube&
#  endif
#  ifndef SNELL_SAMPLE_CUBE_LOD
#    define SNELL_SAMPLE_CUBE_LOD(tex, dir, lod) ((tex).sampleLod(dir, lod))
#  endif
#endif

#ifndef SNELL_ENVIRONMENT_TEX
#  define SNELL_ENVIRONMENT_TEX SNELL_TEX2D
#endif
#ifndef SNELL_SAMPLE_ENVIRONMENT
#  define SNELL_SAMPLE_ENVIRONMENT(tex, dir, lod) snellSampleEquirect(tex, dir, lod)
#endif

/* Hastings 1955: atan(a) ~ a (c1 + c3 a^2 + c5 a^4 + c7 a^6 + c9 a^8) on [0, 1] */
SNELL_FN float snellAtan2(float y, float x) {
  if (isnan(x) || isnan(y)) {
    return 0.0f;
  }
  float ax = abs(x);
  float ay = abs(y);
  float hi = max(ax, ay);
  float lo = min(ax, ay);
  if (!(hi > 0.0f)) {
    return 0.0f;
  }
  float a = isinf(hi) ? (isinf(lo) ? 1.0f : 0.0f) : lo / hi;
  float s = a * a;
  float r = a * (0.9998660f + s * (-0.3302995f + s * (0.1801410f + s * (-0.0851330f + s * 0.0208351f))));
  if (ay > ax) {
    r = 1.57079632679f - r;
  }
  if (x < 0.0f) {
    r = 3.14159265359f - r;
  }
  if (y < 0.0f) {
    r = -r;
  }
  return r;
}

SNELL_FN vec2 snellEquirectUv(vec3 dir) {
  if (!SNELL_FINITE(dir.x) || !SNELL_FINITE(dir.y) || !SNELL_FINITE(dir.z)) {
    return vec2(0.5f, 0.5f);
  }
  float horizontal = sqrt(dir.x * dir.x + dir.z * dir.z);
  float u = 0.5f + snellAtan2(dir.x, -dir.z) * (0.5f / SNELL_PI);
  float v = 0.5f + snellAtan2(dir.y, horizontal) * (1.0f / SNELL_PI);
  return vec2(u, v);
}

SNELL_FN vec4 snellSampleEquirect(SNELL_TEX2D env, vec3 dir, float lod) {
  return SNELL_SAMPLE_LOD(env, snellEquirectUv(dir), lod);
}

#endif
