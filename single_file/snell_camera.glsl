// snell 0.2.0, single-file GLSL: glsl/snell/camera.glsl with every #include spliced in
// (snell-flatten --no-line). Generated: do not edit; regenerate with
// `cmake --build build --target single_file`. No #version line: put it, and on
// ES the precision statements, before this text.
/* camera/ family aggregator: every public function of glsl/snell/camera. */
#ifndef SNELL_CAMERA_GLSL
#define SNELL_CAMERA_GLSL
/*
description: the conventions every glsl/snell/camera file shares: spaces, the
  depth-buffer conventions (integer #defines passed as `int convention`), and two
  helper macros. No function is defined here.
use: #include "snell/camera/conventions.glsl" (every camera file does).
options:
  SNELL_DEPTH_GL                 glm::perspective / glFrustum: NDC z in [-1,1],
                                 stored as window depth 0.5 z_ndc + 0.5
                                 (glDepthRange(0,1), the default); near -> 0, far -> 1
  SNELL_DEPTH_ZERO_ONE           D3D / Vulkan / glClipControl(GL_ZERO_TO_ONE),
                                 glm::perspectiveZO: NDC z in [0,1] stored as is;
                                 near -> 0, far -> 1
  SNELL_DEPTH_REVERSED           reversed Z: NDC z in [0,1], near -> 1, far -> 0
  SNELL_DEPTH_INFINITE_GL        glm::infinitePerspective: GL NDC, far plane at
                                 infinity: depth 1 is "infinitely far"
  SNELL_DEPTH_INFINITE_REVERSED  reversed Z with an infinite far plane:
                                 depth = zNear / distance, 0 is "infinitely far"
  SNELL_DEPTH_CONVENTION_COUNT   number of conventions (valid values 0 .. COUNT-1)
  (SNELL_FINITE and SNELL_FLT_MIN, used by every family, are in prelude.glsl)
  SNELL_CAMERA_MAT4_COLUMNS(c0, c1, c2, c3)  a mat4 from four column vec4s in
                                 every language (GLSL/GLM constructors take
                                 columns, HLSL's take rows)
  SNELL_CAMERA_MAT_COLUMN(m, i)  column i of a mat4 (its i-th basis image) in
                                 every language, without a matrix product
contract:
  - view space is right-handed; the camera sits at the origin and looks down -Z,
    so points in front of it have z < 0. "View distance" is -z_view (> 0 in front).
  - clip = clipFromView * vec4(p, 1); NDC = clip.xyz / clip.w, defined for w > 0.
  - uv is [0,1]^2 over the viewport, origin bottom-left (GL window space):
    uv = 0.5 NDC.xy + 0.5; pixel (i, j) covers uv [i, i+1]/W x [j, j+1]/H and its
    centre is ((i + 0.5)/W, (j + 0.5)/H).
  - "depth value" always means what the depth buffer stores (window-space depth
    in [0,1]), never NDC z. For SNELL_DEPTH_GL window depth is 0.5 z_ndc + 0.5;
    for the other conventions window depth equals NDC z. The GL and ZERO_ONE
    conventions therefore store the same value for the same point,
    d = zFar (v - zNear) / (v (zFar - zNear)), v the view distance; they differ in
    the projection matrix and in NDC z only.
source: OpenGL 4.5 core spec sec. 13.6 (coordinate transformations, glDepthRange),
  sec. 13.7 (glClipControl); GLM 0.9.9 ext/matrix_clip_space.inl.
*/
#ifndef SNELL_CAMERA_CONVENTIONS_GLSL
#define SNELL_CAMERA_CONVENTIONS_GLSL
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

#define SNELL_DEPTH_GL 0
#define SNELL_DEPTH_ZERO_ONE 1
#define SNELL_DEPTH_REVERSED 2
#define SNELL_DEPTH_INFINITE_GL 3
#define SNELL_DEPTH_INFINITE_REVERSED 4
#define SNELL_DEPTH_CONVENTION_COUNT 5

/* isnan/isinf rather than comparison tricks: GPU compilers may rewrite !(a > b)
   into a <= b, which changes the NaN answer. */

#if defined(SNELL_LANG_HLSL)
#  define SNELL_CAMERA_MAT4_COLUMNS(c0, c1, c2, c3) transpose(float4x4(c0, c1, c2, c3))
#else
#  define SNELL_CAMERA_MAT4_COLUMNS(c0, c1, c2, c3) mat4(c0, c1, c2, c3)
#endif

/* GLSL and GLM index a matrix's columns, HLSL its rows. */
#if defined(SNELL_LANG_HLSL)
#  define SNELL_CAMERA_MAT_COLUMN(m, i) (transpose(m)[i])
#else
#  define SNELL_CAMERA_MAT_COLUMN(m, i) ((m)[i])
#endif

#endif
/*
description: depth-buffer value <-> positive view distance, for every depth
  convention of conventions.glsl.
use: float v = snellLinearizeDepth(depthValue, zNear, zFar, SNELL_DEPTH_GL);
     float d = snellDelinearizeDepth(v, zNear, zFar, SNELL_DEPTH_REVERSED);
  depthValue    what the depth buffer stores (window-space depth, [0,1]), NOT NDC z
  viewDistance  -z_view of the point (> 0 in front of the camera)
  zNear, zFar   the camera's clip-plane distances (> 0); zFar is ignored by the
                two INFINITE conventions
  convention    SNELL_DEPTH_GL, _ZERO_ONE, _REVERSED, _INFINITE_GL, _INFINITE_REVERSED
contract (v = view distance, d = depth value, n = zNear, f = zFar):
  - GL, ZERO_ONE:     d = f (v - n) / (v (f - n)),  v = n / ((1 - d) + d n / f)
    REVERSED:         d = n (f - v) / (v (f - n)),  v = n / (d + (1 - d) n / f)
    INFINITE_GL:      d = 1 - n / v,                v = n / (1 - d)
    INFINITE_REVERSED d = n / v,                    v = n / d
    (each evaluated in a form without cancellation: every sum adds positive terms)
  - snellLinearizeDepth returns a value in [n, f] (finite conventions) or
    [n, SNELL_FLT_MAX] (infinite ones): depth out of [0,1] is clamped into it
    first; the far plane of an infinite convention (d = 1 INFINITE_GL, d = 0
    INFINITE_REVERSED) returns SNELL_FLT_MAX. Depth 0 (GL/ZERO_ONE) returns n, depth
    1 returns f (REVERSED: the other way round).
  - snellLinearizeDepth returns 0.0f (never a valid distance, every valid one is
    >= n > 0) when: depthValue is NaN, zNear is not a finite positive number, zFar
    is not finite or not > zNear (finite conventions only), or the convention is
    unknown. A denormal zNear or depthValue counts as 0 (GPUs may flush it).
  - snellDelinearizeDepth returns a value in [0,1]; the distance is clamped into
    [n, f] (finite conventions) or [n, +inf) first, so points nearer than the near
    plane, at or behind the camera (v <= 0), give the near-plane value and points
    beyond the far plane (or +Inf) the far-plane value. NaN distance or invalid
    zNear/zFar/convention (as above) give the far-plane value, i.e. the depth
    buffer's clear value "nothing there": 1.0f, or 0.0f for the REVERSED ones
    (1.0f for an unknown convention).
  - the maps are inverse to each other up to rounding (a few ulp relative in v).
source: the window depth of glm::perspective / perspectiveZO / infinitePerspective
  (GLM 0.9.9 ext/matrix_clip_space.inl) under glDepthRange(0,1) (OpenGL 4.5 core
  spec sec. 13.6.1); reversed Z: 1 - d of the ZERO_ONE mapping. Oliveira &
  Brauwers 2007 (Algorithm 2) use such a positive view distance ("recover a
  positive Z value") for the stored depth.
*/
#ifndef SNELL_CAMERA_LINEARIZE_DEPTH_GLSL
#define SNELL_CAMERA_LINEARIZE_DEPTH_GLSL



SNELL_FN_INLINE float snellLinearizeDepth(float depthValue, float zNear, float zFar, int convention) {
  bool infinite = convention == SNELL_DEPTH_INFINITE_GL || convention == SNELL_DEPTH_INFINITE_REVERSED;
  if (isnan(depthValue) || !SNELL_FINITE(zNear) || !(zNear >= SNELL_FLT_MIN)) {
    return 0.0f;
  }
  if (!infinite && (!SNELL_FINITE(zFar) || !(zFar > zNear))) {
    return 0.0f;
  }
  float d = clamp(depthValue, 0.0f, 1.0f);
  float v = 0.0f;
  if (convention == SNELL_DEPTH_GL || convention == SNELL_DEPTH_ZERO_ONE) {
    v = zNear / ((1.0f - d) + d * (zNear / zFar));
  } else if (convention == SNELL_DEPTH_REVERSED) {
    v = zNear / (d + (1.0f - d) * (zNear / zFar));
  } else if (convention == SNELL_DEPTH_INFINITE_GL) {
    v = d < 1.0f ? zNear / (1.0f - d) : SNELL_FLT_MAX;
  } else if (convention == SNELL_DEPTH_INFINITE_REVERSED) {
    v = d >= SNELL_FLT_MIN ? zNear / d : SNELL_FLT_MAX;  // a denormal depth is 0, the far plane
  } else {
    return 0.0f;
  }
  // Division results can overflow (n / denormal); clamp keeps them finite.
  return clamp(v, zNear, infinite ? SNELL_FLT_MAX : zFar);
}

SNELL_FN float snellDelinearizeDepth(float viewDistance, float zNear, float zFar, int convention) {
  bool reversed = convention == SNELL_DEPTH_REVERSED || convention == SNELL_DEPTH_INFINITE_REVERSED;
  bool infinite = convention == SNELL_DEPTH_INFINITE_GL || convention == SNELL_DEPTH_INFINITE_REVERSED;
  float farValue = reversed ? 0.0f : 1.0f;
  if (convention < 0 || convention >= SNELL_DEPTH_CONVENTION_COUNT || isnan(viewDistance) ||
      !SNELL_FINITE(zNear) || !(zNear >= SNELL_FLT_MIN)) {
    return farValue;
  }
  if (!infinite && (!SNELL_FINITE(zFar) || !(zFar > zNear))) {
    return farValue;
  }
  if (!(viewDistance > zNear)) {
    return reversed ? 1.0f : 0.0f;  // at or nearer than the near plane, or behind the camera
  }
  float v = viewDistance;
  if (infinite) {
    if (isinf(v)) {
      return farValue;
    }
  } else if (v >= zFar) {
    return farValue;
  }
  float d = 0.0f;
  if (convention == SNELL_DEPTH_GL || convention == SNELL_DEPTH_ZERO_ONE) {
    d = ((v - zNear) / v) * (zFar / (zFar - zNear));
  } else if (convention == SNELL_DEPTH_REVERSED) {
    d = (zNear / v) * ((zFar - v) / (zFar - zNear));
  } else if (convention == SNELL_DEPTH_INFINITE_GL) {
    d = (v - zNear) / v;
  } else {
    d = zNear / v;
  }
  return clamp(d, 0.0f, 1.0f);
}

#endif
/*
description: depth-buffer value <-> NDC z for a depth convention (the
  glDepthRange / viewport depth transform with its default range).
use: float zNdc = snellDepthToNdcZ(depthValue, SNELL_DEPTH_GL);
     float depthValue = snellNdcZToDepth(zNdc, SNELL_DEPTH_GL);
contract:
  - SNELL_DEPTH_GL and SNELL_DEPTH_INFINITE_GL: z_ndc = 2 d - 1, d = 0.5 z_ndc + 0.5;
    every other convention (ZERO_ONE, REVERSED, INFINITE_REVERSED, and unknown
    values) has NDC z in [0,1] and stores it unchanged.
  - inputs are clamped into their range first (depth [0,1]; NDC z [-1,1] or
    [0,1]), which is what a depth buffer (or GL_DEPTH_CLAMP) does with them;
    NaN is treated as the low end of the range. Results are always finite.
source: OpenGL 4.5 core spec sec. 13.6.1 (z_w = (f - n)/2 z_d + (n + f)/2 with the
  default glDepthRange(0,1)) and sec. 13.7 (glClipControl GL_ZERO_TO_ONE: z_w = z_d).
*/
#ifndef SNELL_CAMERA_DEPTH_TO_NDC_Z_GLSL
#define SNELL_CAMERA_DEPTH_TO_NDC_Z_GLSL



SNELL_FN float snellDepthToNdcZ(float depthValue, int convention) {
  float d = isnan(depthValue) ? 0.0f : clamp(depthValue, 0.0f, 1.0f);
  if (convention == SNELL_DEPTH_GL || convention == SNELL_DEPTH_INFINITE_GL) {
    return 2.0f * d - 1.0f;
  }
  return d;
}

SNELL_FN float snellNdcZToDepth(float ndcZ, int convention) {
  if (convention == SNELL_DEPTH_GL || convention == SNELL_DEPTH_INFINITE_GL) {
    float z = isnan(ndcZ) ? -1.0f : clamp(ndcZ, -1.0f, 1.0f);
    return 0.5f * z + 0.5f;
  }
  return isnan(ndcZ) ? 0.0f : clamp(ndcZ, 0.0f, 1.0f);
}

#endif
/*
description: symmetric perspective projection matrices (clipFromView) for each
  depth convention, and their exact analytic inverses (viewFromClip), built the
  same way in every language (so parity cases and users need only 4 scalars).
use: mat4 clipFromView = snellPerspective(fovy, aspect, zNear, zFar);   // = glm::perspective
     mat4 clipFromView = snellPerspectiveWithDepth(fovy, aspect, zNear, zFar, SNELL_DEPTH_REVERSED);
     mat4 viewFromClip = snellPerspectiveInverse(fovy, aspect, zNear, zFar, SNELL_DEPTH_REVERSED);
  fovy          full vertical field of view in radians, in (0, pi)
  aspect        viewport width / height (> 0)
  zNear, zFar   clip-plane distances (0 < zNear < zFar); zFar ignored by INFINITE_*
contract: with A = 1 / (aspect tan(fovy/2)), B = 1 / tan(fovy/2), the matrix maps
  (x, y, z, 1) to (A x, B y, C z + D, -z), so clip w = -z = view distance, and
    GL                 C = -(f + n)/(f - n)   D = -2 f n/(f - n)   (glm::perspective)
    ZERO_ONE           C = f/(n - f)          D = -f n/(f - n)     (glm::perspectiveZO)
    REVERSED           C = n/(f - n)          D = f n/(f - n)      (ZERO_ONE, near/far swapped)
    INFINITE_GL        C = -1                 D = -2 n             (glm::infinitePerspective)
    INFINITE_REVERSED  C = 0                  D = n
  The window depth each one produces is the one of linearize_depth.glsl.
  The inverse maps (xc, yc, zc, wc) to (xc/A, yc/B, -wc, (zc + C wc)/D) exactly
  (no general 4x4 inversion; HLSL has none).
  tan(fovy/2) is snell's own polynomial (Cephes tanf), within 1.7e-7 relative of
  tan on (0, pi/2) and the same on every runtime: glm::perspective's entries A
  and B are matched within 3 ulp, the others bit for bit.
  All three return the zero matrix (every projected point then has w = 0, so
  snellClipToNdc and friends report valid = false) when fovy is not in (0, pi),
  tan(fovy/2) is not finite positive, aspect or zNear are not finite positive,
  zFar is not finite or not > zNear (finite conventions), the convention is
  unknown, or an entry of the matrix returned (for the inverse, of the
  inverse), tan(fovy/2) or aspect tan(fovy/2) would overflow or be denormal (a
  GPU may flush it to 0); a denormal fovy or aspect counts as 0.
  GL is the convention of the paper's equations (Oliveira & Brauwers 2007, sec.
  3.2.1: "the projection matrix used by OpenGL", clip w = -z).
source: GLM 0.9.9 ext/matrix_clip_space.inl (perspectiveRH_NO, perspectiveRH_ZO,
  infinitePerspectiveRH_NO); OpenGL gluPerspective.
*/
#ifndef SNELL_CAMERA_PERSPECTIVE_GLSL
#define SNELL_CAMERA_PERSPECTIVE_GLSL



SNELL_FN mat4 snellPerspectiveWithDepth(float fovy, float aspect, float zNear, float zFar, int convention) {
  vec4 zero4 = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  mat4 zero = SNELL_CAMERA_MAT4_COLUMNS(zero4, zero4, zero4, zero4);
  bool infinite = convention == SNELL_DEPTH_INFINITE_GL || convention == SNELL_DEPTH_INFINITE_REVERSED;
  if (convention < 0 || convention >= SNELL_DEPTH_CONVENTION_COUNT || !SNELL_FINITE(fovy) ||
      !(fovy >= SNELL_FLT_MIN) || !(fovy < SNELL_PI) || !SNELL_FINITE(aspect) || !(aspect >= SNELL_FLT_MIN) ||
      !SNELL_FINITE(zNear) || !(zNear >= SNELL_FLT_MIN)) {
    return zero;
  }
  if (!infinite && (!SNELL_FINITE(zFar) || !(zFar > zNear))) {
    return zero;
  }
  // tan(fovy / 2) by snell's own polynomial, not tan(): GLSL leaves tan's precision to the
  // implementation, and WebGL 2 on SwiftShader is 6e-5 off, more than a projection can afford.
  // Cephes' tanf (S. L. Moshier): the polynomial on [0, pi/4] and tan x = 1 / tan(pi/2 - x)
  // above it, pi/2 in two parts so that pi/2 - x keeps its digits near pi/2.
  float halfFovy = fovy / 2.0f;
  bool upper = halfFovy > 0.78539818525f;  // float(pi/2) / 2: float(pi/2) - x is exact above it
  float r = halfFovy;
  if (upper) {
    r = (1.57079637050628662f - halfFovy) - 4.37113900018624283e-8f;
  }
  float r2 = r * r;
  float tanR = ((((((9.38540185543e-3f * r2 + 3.11992232697e-3f) * r2 + 2.44301354525e-2f) * r2 +
                   5.34112807005e-2f) * r2 + 1.33387994085e-1f) * r2 + 3.33331568548e-1f) * r2) * r + r;
  float tanHalfFovy = upper ? 1.0f / tanR : tanR;
  // A denormal tan(fovy/2) (fovy near FLT_MIN, halved) or aspect tan(fovy/2) is 0 on a GPU that flushes
  // denormals: the zero matrix there, so here too.
  if (!SNELL_FINITE(tanHalfFovy) || !(tanHalfFovy >= SNELL_FLT_MIN) || !(aspect * tanHalfFovy >= SNELL_FLT_MIN)) {
    return zero;
  }
  // Same operation order as glm::perspective: the GL matrix matches it within tan's error.
  float a = 1.0f / (aspect * tanHalfFovy);
  float b = 1.0f / tanHalfFovy;
  float c = 0.0f;
  float d = 0.0f;
  if (convention == SNELL_DEPTH_GL) {
    c = -(zFar + zNear) / (zFar - zNear);
    d = -(2.0f * zFar * zNear) / (zFar - zNear);
  } else if (convention == SNELL_DEPTH_ZERO_ONE) {
    c = zFar / (zNear - zFar);
    d = -(zFar * zNear) / (zFar - zNear);
  } else if (convention == SNELL_DEPTH_REVERSED) {
    c = zNear / (zFar - zNear);
    d = (zFar * zNear) / (zFar - zNear);
  } else if (convention == SNELL_DEPTH_INFINITE_GL) {
    c = -1.0f;
    d = -2.0f * zNear;
  } else {
    c = 0.0f;
    d = zNear;
  }
  // C is 0 exactly for INFINITE_REVERSED; REVERSED's n / (f - n) is denormal for a far plane past 1e38 n.
  if (!SNELL_FINITE(a) || !SNELL_FINITE(b) || !SNELL_FINITE(c) ||
      !SNELL_FINITE(d) || !(a >= SNELL_FLT_MIN) || !(b >= SNELL_FLT_MIN) ||
      !(abs(d) >= SNELL_FLT_MIN) || (c != 0.0f && !(abs(c) >= SNELL_FLT_MIN))) {
    return zero;
  }
  return SNELL_CAMERA_MAT4_COLUMNS(vec4(a, 0.0f, 0.0f, 0.0f), vec4(0.0f, b, 0.0f, 0.0f),
                                   vec4(0.0f, 0.0f, c, -1.0f), vec4(0.0f, 0.0f, d, 0.0f));
}

SNELL_FN mat4 snellPerspective(float fovy, float aspect, float zNear, float zFar) {
  return snellPerspectiveWithDepth(fovy, aspect, zNear, zFar, SNELL_DEPTH_GL);
}

SNELL_FN mat4 snellPerspectiveInverse(float fovy, float aspect, float zNear, float zFar, int convention) {
  mat4 m = snellPerspectiveWithDepth(fovy, aspect, zNear, zFar, convention);
  // Entries read through SNELL_MUL (m[i] is a column in GLSL but a row in HLSL).
  float a = SNELL_MUL(m, vec4(1.0f, 0.0f, 0.0f, 0.0f)).x;
  float b = SNELL_MUL(m, vec4(0.0f, 1.0f, 0.0f, 0.0f)).y;
  float c = SNELL_MUL(m, vec4(0.0f, 0.0f, 1.0f, 0.0f)).z;
  float d = SNELL_MUL(m, vec4(0.0f, 0.0f, 0.0f, 1.0f)).z;
  vec4 zero4 = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  if (a == 0.0f) {
    return SNELL_CAMERA_MAT4_COLUMNS(zero4, zero4, zero4, zero4);
  }
  float ia = 1.0f / a;
  float ib = 1.0f / b;
  float id = 1.0f / d;
  float cd = c / d;
  // The inverse's own entries may be denormal where the matrix's are not (A near FLT_MAX): zero there, as
  // the contract says for every entry; C / D is 0 exactly for INFINITE_REVERSED.
  if (!SNELL_FINITE(ia) || !SNELL_FINITE(ib) || !SNELL_FINITE(id) || !SNELL_FINITE(cd) ||
      !(ia >= SNELL_FLT_MIN) || !(ib >= SNELL_FLT_MIN) || !(abs(id) >= SNELL_FLT_MIN) ||
      (cd != 0.0f && !(abs(cd) >= SNELL_FLT_MIN))) {
    return SNELL_CAMERA_MAT4_COLUMNS(zero4, zero4, zero4, zero4);
  }
  return SNELL_CAMERA_MAT4_COLUMNS(vec4(ia, 0.0f, 0.0f, 0.0f), vec4(0.0f, ib, 0.0f, 0.0f),
                                   vec4(0.0f, 0.0f, 0.0f, id), vec4(0.0f, 0.0f, -1.0f, cd));
}

#endif
/*
description: view space -> clip space -> NDC, with the perspective divide made
  safe for points at or behind the camera.
use: vec4 clip = snellViewToClip(clipFromView, pView);
     SnellNdc n = snellClipToNdc(clip);   // n.ndc, n.valid
contract:
  - snellViewToClip is clipFromView * vec4(pView, 1) (SNELL_MUL), nothing else:
    no check, NaN and Inf propagate as the matrix product makes them.
  - snellClipToNdc: valid is true exactly when all four clip components are
    finite and clip.w > 0, denormal w counting as 0 (for the perspective matrices of perspective.glsl,
    w = -z_view: the point is in front of the camera). Then ndc = clip.xyz / w,
    each component clamped to [-SNELL_FLT_MAX, SNELL_FLT_MAX] (a tiny w makes the
    quotient overflow). Otherwise (w <= 0: at or behind the camera's plane; NaN
    or Inf) valid is false and ndc is (0,0,0).
  - points outside the frustum but in front of the camera are valid; their NDC
    lie outside [-1,1].
source: OpenGL 4.5 core spec sec. 13.6 (perspective division).
*/
#ifndef SNELL_CAMERA_VIEW_TO_CLIP_GLSL
#define SNELL_CAMERA_VIEW_TO_CLIP_GLSL



struct SnellNdc {
  vec3 ndc;
  bool valid;
};

SNELL_FN vec4 snellViewToClip(mat4 clipFromView, vec3 pView) {
  return SNELL_MUL(clipFromView, vec4(pView.x, pView.y, pView.z, 1.0f));
}

SNELL_FN SnellNdc snellClipToNdc(vec4 clip) {
  SnellNdc r;
  r.ndc = vec3(0.0f, 0.0f, 0.0f);
  r.valid = false;
  if (!SNELL_FINITE(clip.x) || !SNELL_FINITE(clip.y) || !SNELL_FINITE(clip.z) ||
      !SNELL_FINITE(clip.w) || !(clip.w >= SNELL_FLT_MIN)) {
    return r;
  }
  vec3 q = vec3(clip.x, clip.y, clip.z) / clip.w;
  r.ndc = clamp(q, vec3(-SNELL_FLT_MAX, -SNELL_FLT_MAX, -SNELL_FLT_MAX),
                vec3(SNELL_FLT_MAX, SNELL_FLT_MAX, SNELL_FLT_MAX));
  r.valid = true;
  return r;
}

#endif
/*
description: project a view-space point to viewport uv ([0,1]^2, origin
  bottom-left) and NDC z, in one call.
use: SnellScreenPoint sp = snellViewToUv(clipFromView, pView);
     if (sp.valid) { vec4 c = SNELL_SAMPLE_LOD(tex, sp.uv, 0.0f); float d = snellNdcZToDepth(sp.ndcZ, conv); }
contract:
  - with clip = snellViewToClip(clipFromView, pView): uv = 0.5 clip.xy / clip.w
    + 0.5 and ndcZ = clip.z / clip.w, each quotient clamped to
    +-SNELL_FLT_MAX (as snellClipToNdc's ndc).
  - valid is false (uv = (0,0), ndcZ = 0) when clip x, y or w is NaN or Inf
    or clip w <= 0 (denormal w counting as 0): points at or behind the camera,
    NaN or Inf coordinates, NaN or Inf entries outside the matrix's third row;
    otherwise all results are finite, also for points off screen (uv outside
    [0,1]).
  - clip z decides nothing, so a caller that reads only uv does not pay for
    the matrix's third row: an infinite clip z (an Inf in that row, or an
    overflow) gives ndcZ = +-SNELL_FLT_MAX, a NaN one (a NaN in that row, or
    Inf - Inf, Inf * 0 there) ndcZ = 0; uv and valid are those of a clean
    row. (snellClipToNdc, which takes the clip point, still rejects a
    non-finite z.)
  - ndcZ is NDC z, not a depth-buffer value: snellNdcZToDepth converts it.
source: Oliveira & Brauwers 2007, Algorithm 1 (t' = 0.5 (S~.xy / S~.w) + 0.5).
*/
#ifndef SNELL_CAMERA_VIEW_TO_UV_GLSL
#define SNELL_CAMERA_VIEW_TO_UV_GLSL




struct SnellScreenPoint {
  vec2 uv;
  float ndcZ;
  bool valid;
};

SNELL_FN SnellScreenPoint snellViewToUv(mat4 clipFromView, vec3 pView) {
  vec4 clip = snellViewToClip(clipFromView, pView);
  SnellScreenPoint r;
  r.uv = vec2(0.0f, 0.0f);
  r.ndcZ = 0.0f;
  r.valid = false;
  // Clip z decides nothing: a caller that reads only uv lets the compiler
  // drop the matrix's third row.
  if (!SNELL_FINITE(clip.x) || !SNELL_FINITE(clip.y) || !SNELL_FINITE(clip.w) || !(clip.w >= SNELL_FLT_MIN)) {
    return r;
  }
  float ndcX = clamp(clip.x / clip.w, -SNELL_FLT_MAX, SNELL_FLT_MAX);
  float ndcY = clamp(clip.y / clip.w, -SNELL_FLT_MAX, SNELL_FLT_MAX);
  float ndcZ = clip.z / clip.w;
  r.uv = vec2(ndcX, ndcY) * 0.5f + 0.5f;
  r.ndcZ = isnan(ndcZ) ? 0.0f : clamp(ndcZ, -SNELL_FLT_MAX, SNELL_FLT_MAX);
  r.valid = true;
  return r;
}

#endif
/*
description: integer pixel <-> viewport uv (GL window conventions).
use: vec2 uv = snellPixelToUv(ivec2(gl_FragCoord.x, gl_FragCoord.y), size);   // pixel centre
     ivec2 px = snellUvToPixel(uv, size);   // ready for SNELL_TEXEL_FETCH
  size    viewport (or texture level) size in pixels, e.g. SNELL_TEXTURE_SIZE(tex, 0)
contract:
  - pixel (i, j) covers uv [i, i+1]/W x [j, j+1]/H, origin bottom-left (row 0 is
    the bottom row, as glReadPixels and texel fetches order it).
  - snellPixelToUv returns the pixel centre ((i + 0.5)/W, (j + 0.5)/H), not
    clamped: pixels outside the viewport give uv outside [0,1]. A size component
    <= 0 gives 0 for that component.
  - snellUvToPixel returns the pixel containing uv, floor(uv * size), clamped into
    [0, size - 1] (clamp-to-edge: uv outside [0,1] gives an edge pixel, so the
    result is always a legal texelFetch coordinate). A uv component on a pixel
    boundary belongs to the pixel above/right of it; uv = 1 to the last pixel.
    NaN uv gives pixel 0 in that component; a size with a component <= 0
    gives (0,0).
  - snellUvToPixel(snellPixelToUv(p, size), size) == p for every p inside the
    viewport (sizes up to 2^22).
  - SNELL_PIXEL_ON_SCREEN(uv, size) (a macro) == snellUvToPixel(uv, size) for
    uv in [0,1]^2 and 0 < size < 2^24, without the NaN test, the floor and the
    lower clamp; undefined elsewhere (int() of NaN), so only a caller that has
    just checked the domain uses it.
  - SNELL_PIXEL_CENTRE(px, size) (a macro) == snellPixelToUv(px, size) for
    size > 0, without its two size tests; it divides by size, so only a
    caller that knows size > 0 uses it.
source: OpenGL 4.5 core spec sec. 8.14.2 (texel coordinates u = s W), sec. 14.5
  (fragment centres at (i + 0.5, j + 0.5)).
*/
#ifndef SNELL_CAMERA_PIXEL_TO_UV_GLSL
#define SNELL_CAMERA_PIXEL_TO_UV_GLSL



SNELL_FN vec2 snellPixelToUv(ivec2 px, ivec2 size) {
  float u = size.x > 0 ? (float(px.x) + 0.5f) / float(size.x) : 0.0f;
  float v = size.y > 0 ? (float(px.y) + 0.5f) / float(size.y) : 0.0f;
  return vec2(u, v);
}

/* SNELL_PIXEL_ON_SCREEN(uv, size): snellUvToPixel(uv, size), the same texel,
   for a uv already checked to lie in [0,1]^2 (so not NaN) and 0 < size < 2^24
   (any texture size; above, float(size) is inexact): there
   the truncation is the floor and only uv == 1 needs the clamp, which saves the
   NaN test, the floor and the lower clamp per read. A macro, not a function,
   because it is undefined outside that domain (int() of NaN): only code that
   has just checked the domain uses it (intersect/depth_surface.glsl,
   intersect/surface_point.glsl). One line: GLSL 330 has no line continuation. */
#define SNELL_PIXEL_ON_SCREEN(uv, size) ivec2(min(int((uv).x * float((size).x)), (size).x - 1), min(int((uv).y * float((size).y)), (size).y - 1))

/* SNELL_PIXEL_CENTRE(px, size): snellPixelToUv(px, size), the same operations,
   for size > 0 (intersect/surface_point.glsl, after a valid read of the
   level): the two size tests left out. One line, as above. */
#define SNELL_PIXEL_CENTRE(px, size) vec2((float((px).x) + 0.5f) / float((size).x), (float((px).y) + 0.5f) / float((size).y))

SNELL_FN ivec2 snellUvToPixel(vec2 uv, ivec2 size) {
  if (size.x <= 0 || size.y <= 0) {
    return ivec2(0, 0);
  }
  float x = isnan(uv.x) ? 0.0f : clamp(floor(uv.x * float(size.x)), 0.0f, float(size.x - 1));
  float y = isnan(uv.y) ? 0.0f : clamp(floor(uv.y * float(size.y)), 0.0f, float(size.y - 1));
  return ivec2(int(x), int(y));
}

#endif
/*
description: reconstruct the view-space position seen at a uv from a depth-buffer
  value (snellUvDepthToView) or from a linear view distance (snellUvDistanceToView).
use: SnellViewPoint p = snellUvDepthToView(uv, depthValue, viewFromClip, SNELL_DEPTH_GL);
     SnellViewPoint p = snellUvDistanceToView(uv, viewDistance, viewFromClip);
  viewFromClip  inverse of the projection (snellPerspectiveInverse, or your
                engine's inverse projection matrix)
  depthValue    the stored depth-buffer value ([0,1], window space), not NDC z
  viewDistance  -z_view (> 0), e.g. snellLinearizeDepth(...) or a linear depth texture
contract:
  - snellUvDepthToView: ndc = (2 uv - 1, snellDepthToNdcZ(depthValue, convention)),
    h = viewFromClip * vec4(ndc, 1), position = h.xyz / h.w. depthValue is clamped
    to [0,1]; uv outside [0,1] is allowed (the point is off screen).
  - snellUvDistanceToView: the point at z = -viewDistance on the ray from the eye
    through uv (found by unprojecting NDC z = 0.5, a finite point in front of the
    camera for every convention); position.z == -viewDistance exactly. Requires a
    perspective projection (eye at the view-space origin).
  - valid is true exactly when the result is finite and in front of the camera
    (position.z < 0). It is false, with position (0,0,0), for NaN/Inf inputs, an
    unknown convention, depth on the far plane of an infinite convention (depth 1
    INFINITE_GL, depth 0 INFINITE_REVERSED: h.w = 0, the point is at infinity, e.g.
    sky pixels), a zero/singular matrix (|h.w| below the smallest normal float),
    viewDistance <= 0 or denormal (at or behind the camera) or a reconstruction at or behind the camera plane.
source: OpenGL 4.5 core spec sec. 13.6, inverted; Oliveira & Brauwers 2007 sec.
  3.2.1 (camera-space points from depth maps under perspective projection).
*/
#ifndef SNELL_CAMERA_UV_DEPTH_TO_VIEW_GLSL
#define SNELL_CAMERA_UV_DEPTH_TO_VIEW_GLSL




struct SnellViewPoint {
  vec3 position;
  bool valid;
};

SNELL_FN SnellViewPoint snellUvDepthToView(vec2 uv, float depthValue, mat4 viewFromClip, int convention) {
  SnellViewPoint r;
  r.position = vec3(0.0f, 0.0f, 0.0f);
  r.valid = false;
  if (!SNELL_FINITE(uv.x) || !SNELL_FINITE(uv.y) || isnan(depthValue) || convention < 0 ||
      convention >= SNELL_DEPTH_CONVENTION_COUNT) {
    return r;
  }
  float zNdc = snellDepthToNdcZ(depthValue, convention);
  vec4 h = SNELL_MUL(viewFromClip, vec4(2.0f * uv.x - 1.0f, 2.0f * uv.y - 1.0f, zNdc, 1.0f));
  if (!SNELL_FINITE(h.w) || !(abs(h.w) >= SNELL_FLT_MIN)) {
    return r;
  }
  vec3 p = vec3(h.x, h.y, h.z) / h.w;
  if (!SNELL_FINITE(p.x) || !SNELL_FINITE(p.y) || !SNELL_FINITE(p.z) || !(p.z < 0.0f)) {
    return r;
  }
  r.position = p;
  r.valid = true;
  return r;
}

SNELL_FN SnellViewPoint snellUvDistanceToView(vec2 uv, float viewDistance, mat4 viewFromClip) {
  SnellViewPoint r;
  r.position = vec3(0.0f, 0.0f, 0.0f);
  r.valid = false;
  if (!SNELL_FINITE(uv.x) || !SNELL_FINITE(uv.y) || !SNELL_FINITE(viewDistance) ||
      !(viewDistance >= SNELL_FLT_MIN)) {
    return r;
  }
  vec4 h = SNELL_MUL(viewFromClip, vec4(2.0f * uv.x - 1.0f, 2.0f * uv.y - 1.0f, 0.5f, 1.0f));
  if (!SNELL_FINITE(h.w) || !(abs(h.w) >= SNELL_FLT_MIN)) {
    return r;
  }
  vec3 q = vec3(h.x, h.y, h.z) / h.w;
  if (!SNELL_FINITE(q.x) || !SNELL_FINITE(q.y) || !SNELL_FINITE(q.z) || !(q.z < 0.0f)) {
    return r;
  }
  float s = viewDistance / -q.z;
  vec3 p = vec3(q.x * s, q.y * s, -viewDistance);
  if (!SNELL_FINITE(p.x) || !SNELL_FINITE(p.y)) {
    return r;
  }
  r.position = p;
  r.valid = true;
  return r;
}

#endif
/*
description: the inverse projection for a known view z: the view-space point
  on the pixel ray of a uv at a given depth, without an inverse matrix (the
  surface strategies reconstruct every depth texel through it).
use: SnellViewPoint p = snellUvZToView(clipFromView, uv, viewZ);
  uv            viewport uv ([0,1]^2, origin bottom-left)
  viewZ         view-space z (< 0) of the wanted point
  clipFromView  any projection with clip w = -z (perspective.glsl, glm::perspective*,
                glFrustum, off-centre frusta); no inverse matrix is needed
contract:
  - the point p with p.z == viewZ whose projection has NDC xy =
    2 uv - 1, from the 2x2 linear system clip.xy = ndc.xy clip.w (Cramer's rule on
    the matrix columns). valid =
    false, position (0,0,0), when an input is NaN/Inf, viewZ >= 0 or denormal, the
    system is singular (|det| below the smallest normal float) or the result
    overflows.
source: OpenGL 4.5 core spec sec. 13.6 (clip -> NDC).
*/
#ifndef SNELL_CAMERA_UV_Z_TO_VIEW_GLSL
#define SNELL_CAMERA_UV_Z_TO_VIEW_GLSL




SNELL_FN SnellViewPoint snellUvZToView(mat4 clipFromView, vec2 uv, float viewZ) {
  SnellViewPoint r;
  r.position = vec3(0.0f, 0.0f, 0.0f);
  r.valid = false;
  if (!SNELL_FINITE(uv.x) || !SNELL_FINITE(uv.y) || !SNELL_FINITE(viewZ) ||
      !(viewZ <= -SNELL_FLT_MIN)) {
    return r;
  }
  vec4 c0 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 0);
  vec4 c1 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 1);
  vec4 c2 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 2);
  vec4 c3 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 3);
  float nx = 2.0f * uv.x - 1.0f;
  float ny = 2.0f * uv.y - 1.0f;
  // x a00 + y a01 = b0,  x a10 + y a11 = b1
  float a00 = c0.x - nx * c0.w;
  float a01 = c1.x - nx * c1.w;
  float a10 = c0.y - ny * c0.w;
  float a11 = c1.y - ny * c1.w;
  float b0 = -(viewZ * (c2.x - nx * c2.w) + (c3.x - nx * c3.w));
  float b1 = -(viewZ * (c2.y - ny * c2.w) + (c3.y - ny * c3.w));
  float det = a00 * a11 - a01 * a10;
  if (!SNELL_FINITE(det) || !(abs(det) >= SNELL_FLT_MIN)) {
    return r;
  }
  float x = (b0 * a11 - a01 * b1) / det;
  float y = (a00 * b1 - b0 * a10) / det;
  if (!SNELL_FINITE(x) || !SNELL_FINITE(y)) {
    return r;
  }
  r.position = vec3(x, y, viewZ);
  r.valid = true;
  return r;
}

#endif
/*
description: the perspective texture-space parameterization of a view-space ray
  segment (Oliveira & Brauwers 2007, sec. 3.2.1, eqs. 3-10, Algorithm 1): the
  segment S-E of the refracted ray T1 between two constant-z planes, and for any
  point P on it, from P.z alone, the image-space parameter alpha and the uv where
  P projects, without a matrix product per step.
use: SnellTexRay r = snellTexRaySetup(p1, t1, zNearest, zFarthest, clipFromView);
     // march in 3D: P.z = mix(r.s.z, r.e.z, beta)  (eq. 5)
     vec2 uv = snellTexRayUv(r, pz);   float alpha = snellTexRayAlpha(r, pz);
  p1         view-space start of the ray (P1, the front-face hit)
  t1         ray direction T1 (need not be normalized: eqs. 3-4 divide by T1.z)
  zNearest   view-space z of the plane where the search starts, the back-face
             depth nearest to the camera (the paper's Zmin, a minimum *distance*;
             as a right-handed view-space z it is the LARGER, less negative value)
  zFarthest  view-space z of the plane where it ends (the paper's Zmax, the
             farthest back-face depth; the more negative value). Both are z
             values (< 0), not distances and not the camera's clip planes.
  clipFromView  the camera projection; eqs. 8-9 assume clip w = -z (true for every
             matrix of perspective.glsl, glm::perspective*, glFrustum).
contract:
  - S = P1 + ((zNearest - P1.z)/T1.z) T1 (eq. 3), E likewise with zFarthest (eq.
    4); S.z == zNearest and E.z == zFarthest exactly. S and E are the
    intersections of the LINE with the planes: when T1 points towards the camera
    (T1.z > 0) they lie behind P1 on the ray; the caller decides what that means.
  - k1 = 1/S.z, k2 = S.z E.z/(S.z - E.z) (eq. 9), ts = t's = 0.5 S~.xy/S~.w + 0.5,
    dt = t'e - t's (eq. 10, Algorithm 1).
  - snellTexRayAlpha(r, pz) = (1/pz - k1) k2 (eq. 9), evaluated as the equal
    ((S.z - pz)/pz) (k1 k2) = ((S.z - pz)/pz) E.z/(S.z - E.z), which has no
    cancellation when pz is close to S.z. alpha = 0 at S.z, 1 at E.z; pz outside
    [E.z, S.z] extrapolates along the line (alpha outside [0,1]); never clamped
    to [0,1], only to +-SNELL_FLT_MAX.
  - snellTexRayUv(r, pz) = ts + alpha dt (eq. 10): the uv where the point of the
    line with z = pz projects (equal to projecting P with clipFromView).
  - zNearest == zFarthest: the segment is a point: S == E, k2 = 0, dt = 0,
    alpha = 0 for every pz, uv = ts; valid is true.
  - valid = false, with every field 0 (so alpha = 0 and uv = (0,0)), when: any
    input is NaN or Inf (matrix included, but for its third row: clip z is
    never computed, the segment needs no depth of its ends); T1.z == 0 (the
    ray is parallel to the planes and never reaches them); zNearest >= 0 or
    zFarthest >= 0 (denormal values count as 0 throughout: GPUs may flush
    them); S or E project with clip w <= 0 or not finite; or any result
    overflows (e.g. T1.z so small that S is at infinity, or a clip w so small
    that S's or E's ndc does: no clamp keeps such a segment). A plane at or
    behind the eye (z >= 0) is rejected rather than clamped to the near
    plane: eq. 8 needs S~.w = -S.z > 0, the back-face depth extremes of a
    rendered object always lie in front of the near plane, so such input is a
    caller bug, and clamping would silently search a segment the caller did
    not ask for.
  - alpha (and uv) for a valid ray and pz >= 0 (or denormal), NaN or Inf (no
    projection): alpha 0,
    uv = ts, i.e. the search start.
source: M. M. Oliveira, M. Brauwers, "Real-Time Refraction Through Deformable
  Objects", I3D 2007, sec. 3.2.1, eqs. 3, 4, 5, 6, 8, 9, 10 and Algorithm 1.
*/
#ifndef SNELL_CAMERA_TEX_RAY_GLSL
#define SNELL_CAMERA_TEX_RAY_GLSL



struct SnellTexRay {
  vec3 s;      // S, on the plane z = zNearest (eq. 3)
  vec3 e;      // E, on the plane z = zFarthest (eq. 4)
  float k1;    // 1 / S.z (eq. 9)
  float k2;    // S.z E.z / (S.z - E.z) (eq. 9); 0 when S.z == E.z
  vec2 ts;     // t's: uv of S (eq. 10)
  vec2 dt;     // t'e - t's (Algorithm 1)
  bool valid;
};

SNELL_FN_INLINE SnellTexRay snellTexRaySetup(vec3 p1, vec3 t1, float zNearest, float zFarthest, mat4 clipFromView) {
  SnellTexRay r;
  r.s = vec3(0.0f, 0.0f, 0.0f);
  r.e = vec3(0.0f, 0.0f, 0.0f);
  r.k1 = 0.0f;
  r.k2 = 0.0f;
  r.ts = vec2(0.0f, 0.0f);
  r.dt = vec2(0.0f, 0.0f);
  r.valid = false;
  if (!SNELL_FINITE(p1.x) || !SNELL_FINITE(p1.y) || !SNELL_FINITE(p1.z) ||
      !SNELL_FINITE(t1.x) || !SNELL_FINITE(t1.y) || !SNELL_FINITE(t1.z) ||
      !SNELL_FINITE(zNearest) || !SNELL_FINITE(zFarthest)) {
    return r;
  }
  if (!(abs(t1.z) >= SNELL_FLT_MIN) || !(zNearest <= -SNELL_FLT_MIN) ||
      !(zFarthest <= -SNELL_FLT_MIN)) {
    return r;
  }
  float ls = (zNearest - p1.z) / t1.z;
  float le = (zFarthest - p1.z) / t1.z;
  vec3 s = vec3(p1.x + ls * t1.x, p1.y + ls * t1.y, zNearest);
  vec3 e = vec3(p1.x + le * t1.x, p1.y + le * t1.y, zFarthest);
  // Clip x, y and w only: the segment never needs its ends' depth, so the z
  // row is neither computed nor tested. The sums keep SNELL_MUL's association
  // in GLM, (c0 x + c1 y) + (c2 z + c3), so the C++ bits are the product's.
  // Written out rather than through snellViewToClip: llvmpipe drops the
  // unused row either way, g++ keeps the whole product (CBS-5 in C++: 1071
  // instead of 996 instructions per ray, benchmarks/kernels/kernel_table.sh).
  vec4 c0 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 0);
  vec4 c1 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 1);
  vec4 c2 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 2);
  vec4 c3 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 3);
  vec3 cs = vec3((c0.x * s.x + c1.x * s.y) + (c2.x * s.z + c3.x), (c0.y * s.x + c1.y * s.y) + (c2.y * s.z + c3.y),
                 (c0.w * s.x + c1.w * s.y) + (c2.w * s.z + c3.w));
  vec3 ce = vec3((c0.x * e.x + c1.x * e.y) + (c2.x * e.z + c3.x), (c0.y * e.x + c1.y * e.y) + (c2.y * e.z + c3.y),
                 (c0.w * e.x + c1.w * e.y) + (c2.w * e.z + c3.w));
  // w finite and >= FLT_MIN; a non-finite x or y, or an ndc that overflows,
  // leaves ts or dt non-finite: rejected below.
  if (!SNELL_FINITE(s.x) || !SNELL_FINITE(s.y) || !SNELL_FINITE(e.x) || !SNELL_FINITE(e.y) ||
      !(cs.z >= SNELL_FLT_MIN && cs.z <= SNELL_FLT_MAX) || !(ce.z >= SNELL_FLT_MIN && ce.z <= SNELL_FLT_MAX)) {
    return r;
  }
  vec2 ts = vec2(cs.x, cs.y) / cs.z * 0.5f + 0.5f;
  vec2 te = vec2(ce.x, ce.y) / ce.z * 0.5f + 0.5f;
  vec2 dt = te - ts;
  float k1 = 1.0f / zNearest;
  float k2 = zNearest == zFarthest ? 0.0f : (zNearest * zFarthest) / (zNearest - zFarthest);
  if (!SNELL_FINITE(ts.x) || !SNELL_FINITE(ts.y) || !SNELL_FINITE(dt.x) ||
      !SNELL_FINITE(dt.y) || !SNELL_FINITE(k1) || !SNELL_FINITE(k2) ||
      !SNELL_FINITE(k1 * k2)) {
    return r;
  }
  r.s = s;
  r.e = e;
  r.k1 = k1;
  r.k2 = k2;
  r.ts = ts;
  r.dt = dt;
  r.valid = true;
  return r;
}

SNELL_FN float snellTexRayAlpha(SnellTexRay r, float pz) {
  if (!r.valid || r.k2 == 0.0f || !SNELL_FINITE(pz) || !(pz <= -SNELL_FLT_MIN)) {
    return 0.0f;
  }
  float alpha = ((r.s.z - pz) / pz) * (r.k1 * r.k2);
  // pz denormal-small: inf * (a product that underflowed to 0) is NaN.
  return isnan(alpha) ? 0.0f : clamp(alpha, -SNELL_FLT_MAX, SNELL_FLT_MAX);
}

SNELL_FN vec2 snellTexRayUv(SnellTexRay r, float pz) {
  float alpha = snellTexRayAlpha(r, pz);
  vec2 uv = r.ts + alpha * r.dt;
  return clamp(uv, vec2(-SNELL_FLT_MAX, -SNELL_FLT_MAX), vec2(SNELL_FLT_MAX, SNELL_FLT_MAX));
}

#endif
#endif
