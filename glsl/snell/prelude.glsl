/*
description: the language bridge. Every file in glsl/snell includes this first, so
  one body compiles as GLSL (330 core, 450 core, ES 310), as C++17 with GLM (through
  <snell/bridge.hpp>) and as HLSL (through hlsl_like/snell/bridge.hlsl).
use: GLSL: `#include "snell/prelude.glsl"` after your `#version` line (and, on ES,
  after `precision highp float; precision highp sampler2D;`).
options:
  SNELL_FN             qualifier before every function (C++: inline; else empty)
  SNELL_FN_INLINE      the qualifier of the small helpers every strategy calls per
                       step (C++: SNELL_FN plus always_inline; else SNELL_FN)
  SNELL_TEX2D          type of a texture parameter (GLSL sampler2D, C++ const
                       snell::Texture2D&, HLSL Texture2D<float4>)
  SNELL_TEXEL_FETCH(tex, px, lod)  vec4 at integer texel px (ivec2) of mip lod;
                       callers clamp px into the level first (GL leaves
                       out-of-range fetches undefined)
  SNELL_TEXEL_FETCH_IN_LEVEL(tex, px, lod)  the same for a texel the caller has
                       placed inside an existing level (default: SNELL_TEXEL_FETCH;
                       C++: Texture2D::fetchInLevel, without fetch's range tests)
  SNELL_SAMPLE_LOD(tex, uv, lod)   vec4 filtered by the texture's own
                       filter state at explicit mip level lod (float)
  SNELL_TEXTURE_SIZE(tex, lod)     ivec2 size of mip level lod (0 <= lod < levels;
                       base level 0)
  SNELL_IN(T)          a read-only struct parameter (C++: const T&; else T)
  Define any hook before this file to redirect reads (reversed-Z, linear depth,
  texture arrays, a Hi-Z chain).
contract: macros only; no function is defined here.
*/
#ifndef SNELL_PRELUDE_GLSL
#define SNELL_PRELUDE_GLSL
#include "version.glsl"

#if defined(__cplusplus)
#  ifndef SNELL_CXX_BRIDGE
#    error "C++: include <snell/snell.hpp> (or a family header), not a .glsl file"
#  endif
#  define SNELL_LANG_CXX 1
#elif defined(SNELL_HLSL)
#  define SNELL_LANG_HLSL 1
#else
#  define SNELL_LANG_GLSL 1
#endif

#ifndef SNELL_FN
#  if defined(SNELL_LANG_CXX)
#    define SNELL_FN inline
#  else
#    define SNELL_FN
#  endif
#endif
/* SNELL_FN_INLINE: SNELL_FN for the small functions every strategy calls per
   step (projection, reconstruction, depth read): C++ adds the bridge's
   always-inline attribute (SNELL_CXX_ALWAYS_INLINE, GCC/Clang), since g++'s
   heuristics otherwise decline to inline them for some callers; a redefined
   SNELL_FN still applies. GLSL/HLSL: SNELL_FN. */
#ifndef SNELL_FN_INLINE
#  if defined(SNELL_LANG_CXX)
#    define SNELL_FN_INLINE SNELL_FN SNELL_CXX_ALWAYS_INLINE
#  else
#    define SNELL_FN_INLINE SNELL_FN
#  endif
#endif

/* SNELL_PRECISE before a local declaration: its value is computed exactly as
   written (no fused multiply-add), so GPU and C++ agree to the last bit where a
   comparison downstream is sensitive to it. `precise` exists in desktop GLSL
   400+ and HLSL; elsewhere (GLSL 330, ES) it is empty. */
#ifndef SNELL_PRECISE
#  if defined(SNELL_LANG_HLSL)
#    define SNELL_PRECISE precise
#  elif defined(SNELL_LANG_GLSL)
#    if __VERSION__ >= 400 && !defined(GL_ES)
#      define SNELL_PRECISE precise
#    endif
#  endif
#endif
#ifndef SNELL_PRECISE
#  define SNELL_PRECISE
#endif

#if defined(SNELL_LANG_GLSL)
#  ifndef SNELL_TEX2D
#    define SNELL_TEX2D sampler2D
#  endif
#  ifndef SNELL_TEXEL_FETCH
#    define SNELL_TEXEL_FETCH(tex, px, lod) texelFetch(tex, px, lod)
#  endif
#  ifndef SNELL_SAMPLE_LOD
#    define SNELL_SAMPLE_LOD(tex, uv, lod) textureLod(tex, uv, lod)
#  endif
#  ifndef SNELL_TEXTURE_SIZE
/* Level size from the base size: Mesa 22.3 llvmpipe evaluates textureSize with
   one invocation's lod for a whole SIMD batch when lod varies per invocation. */
#    define SNELL_TEXTURE_SIZE(tex, lod) max(textureSize(tex, 0) >> (lod), ivec2(1, 1))
#  endif
#endif

/* SNELL_TEXEL_FETCH_IN_LEVEL(tex, px, lod): SNELL_TEXEL_FETCH for a texel the
   caller has already placed inside level lod (0 <= lod, px inside the size
   SNELL_TEXTURE_SIZE gave, which is > 0). GLSL/HLSL: SNELL_TEXEL_FETCH (any
   hook included); C++: Texture2D::fetchInLevel, without fetch's level and
   bounds tests. */
#ifndef SNELL_TEXEL_FETCH_IN_LEVEL
#  define SNELL_TEXEL_FETCH_IN_LEVEL(tex, px, lod) SNELL_TEXEL_FETCH(tex, px, lod)
#endif

/* SNELL_IN(T) name: a read-only parameter of struct type T. GLSL and HLSL pass
   it by value; C++ by const reference, because a call the compiler does not
   inline would otherwise copy the whole struct (a SnellDepthSurface is 112
   bytes; at 92 the copies were 8 % of a plane ray's instructions). */
#ifndef SNELL_IN
#  if defined(SNELL_LANG_CXX)
#    define SNELL_IN(T) const T&
#  else
#    define SNELL_IN(T) T
#  endif
#endif

/* Matrix times column vector: GLSL and GLM write m * v, HLSL mul(m, v). */
#if defined(SNELL_LANG_HLSL)
#  define SNELL_MUL(m, v) mul(m, v)
#else
#  define SNELL_MUL(m, v) ((m) * (v))
#endif

/* Shared numeric constants: #defines, because a global `const` is a uniform in
   HLSL and has different linkage rules in C++. */
#define SNELL_PI 3.14159265358979f
#define SNELL_EPS 1e-6f
/* Largest finite float; results that would be infinite are clamped to it. A
   host may define it first with the same value in another spelling: the
   WebGPU prelude does (naga writes this literal with 39 digits, which Tint
   rejects as not representable). */
#ifndef SNELL_FLT_MAX
#  define SNELL_FLT_MAX 3.402823466e38f
#endif
/* Smallest normal float. Divisors and "positive" tests use it instead of 0:
   GPUs may flush denormals to zero, so a denormal parameter whose contract says so
   (eta, zNear, fovy, aspect, clip w, ...) is treated as 0 in every
   language (same flags on CPU and GPU). Denormal data (positions, directions,
   matrix entries) is not flushed, which would cost every call: a runtime that
   flushes (SwiftShader, most GPUs) gives the function's result on 0 there, one
   that keeps it (llvmpipe, the CPU) the result on the denormal, and the parity
   suite accepts either (and counts the cases: "flushed="). */
#define SNELL_FLT_MIN 1.175494351e-38f
/* True when the float x is neither NaN nor +-Inf. C++: std::isfinite, one
   test instead of isnan and isinf (7 % of a plane ray's instructions). GLSL
   and HLSL: the exponent's bits are not all ones, one mask and one compare,
   exact for every float and safe from a compiler that assumes no NaN (on
   llvmpipe 6 % fewer instructions per pixel than !isnan(x) && !isinf(x) for
   single sample, 5 % for the whole two-interface technique:
   benchmarks/kernels/gpu_kernel_table.sh). */
#if defined(SNELL_LANG_CXX)
#  define SNELL_FINITE(x) (std::isfinite(x))
#elif defined(SNELL_LANG_HLSL)
#  define SNELL_FINITE(x) ((asuint(x) & 0x7f800000u) != 0x7f800000u)
#else
#  define SNELL_FINITE(x) ((floatBitsToUint(x) & 0x7f800000u) != 0x7f800000u)
#endif

#endif
