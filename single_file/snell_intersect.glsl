// snell 0.2.0, single-file GLSL: glsl/snell/intersect.glsl with every #include spliced in
// (snell-flatten --no-line). Generated: do not edit; regenerate with
// `cmake --build build --target single_file`. No #version line: put it, and on
// ES the precision statements, before this text.
/* intersect/ family aggregator: every strategy for a ray against a depth buffer. */
#ifndef SNELL_INTERSECT_GLSL
#define SNELL_INTERSECT_GLSL
/*
description: the result every intersection strategy returns: where a view-space
  ray meets a surface that exists only as a depth buffer.
use: SnellHit h = snellIntersect...(origin, dir, depthTex, surface, ...);
     if (h.valid) { vec4 n = SNELL_SAMPLE_LOD(normalTex, h.uv, 0.0f); ... }
  uv        the hit's projection, viewport uv (origin bottom-left, [0,1]^2)
  position  the hit point in view space (on the ray; z < 0)
  valid     false when no hit was found (see each strategy's contract)
  fetches   texel fetches spent (machine-independent cost; counted also when
            the search fails)
contract: snellHitMiss gives valid = false, uv = (0,0), position = (0,0,0) and the
  fetch count it is given: finite numbers always.
source: the common interface of DESIGN.md sec. 2 (intersect/).
*/
#ifndef SNELL_INTERSECT_HIT_GLSL
#define SNELL_INTERSECT_HIT_GLSL
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

struct SnellHit {
  vec2 uv;
  vec3 position;
  bool valid;
  int fetches;
};

SNELL_FN SnellHit snellHitMiss(int fetches) {
  SnellHit h;
  h.uv = vec2(0.0f, 0.0f);
  h.position = vec3(0.0f, 0.0f, 0.0f);
  h.valid = false;
  h.fetches = fetches;
  return h;
}

#endif
/*
description: how a depth texture describes a surface (the refractive object's
  back faces, or the opaque scene), and the one way every strategy reads it.
use: SnellDepthSurface s = snellDepthSurface(clipFromView, zNear, zFar, SNELL_DEPTH_GL, 0.0f);
     SnellSurfaceSample x = snellSampleSurface(depthTex, uv, s);   // x.viewZ < 0 when x.valid
     s = snellDepthSurfaceComplete(s);   // after filling or changing clipFromView, zNear, zFar, convention
     float v = snellSurfaceLinearDepth(s, depthValue);   // snellLinearizeDepth with s's validated terms
  The surface is per draw: build it once per invocation and pass it to every
  strategy; the per-step code reads its derived fields. In a shader, build it
  from the camera uniforms with the convention, and any lod, depthFilter and
  closed assignments, as constants: the compiler then folds the branches on
  them (on llvmpipe a single sample costs 271 instructions per pixel so, 436
  with the whole surface read from a uniform: benchmarks/kernels).
  clipFromView  the projection the depth texture was rendered with
  zNear, zFar   its clip distances; convention: SNELL_DEPTH_* (camera/conventions.glsl)
  emptyDepth    the texel value meaning "no surface here": the clear value (0.0f for
                back faces drawn with glDepthFunc(GL_GREATER) after clearing to 0,
                1.0f for a scene drawn with GL_LESS after clearing to 1)
  lod           the mip level the searches read (0 = full resolution); set the field
  depthFilter   how a depth is read (set the field; snellIntersectWith sets it from
                SnellIntersectOptions.depthFilter):
                SNELL_DEPTH_FILTER_NEAREST  0 (default) the texel containing uv
                SNELL_DEPTH_FILTER_BILINEAR 1 the window depth interpolated
                  bilinearly between the four texel centres around uv, where
                  all four hold a surface, else the nearest texel. Window depth
                  is affine in screen space over a plane (it is a + b / z), so
                  planes are read exactly between texel centres; at the
                  silhouette no surface is blended with an empty texel. Across a
                  depth discontinuity inside the buffer it still invents a
                  one-texel ramp (Oliveira & Brauwers 2007 sec. 3.1), which is
                  why it is not the default.
  closed        true (default): an empty texel beside the surface hides more of
                it (a closed object's back faces curve away behind the
                silhouette: the plane methods keep their last plane there,
                SNELL_PLANE_HOLD); false: empty texels are open space (the
                opaque scene: the environment shows there), set the field
  derived fields  validated and precomputed once from clipFromView, zNear, zFar and
                convention by snellDepthSurface, or by snellDepthSurfaceComplete for
                a surface filled in field by field or changed afterwards; the
                per-step reads trust them instead of re-checking the source
                fields on every read:
    perspective    true when clipFromView has the shape of a perspective
                   (columns (a,0,0,0) (0,b,0,0) (c,d,e,-1) (0,0,f,0): symmetric,
                   off-centre and jittered frusta). The strategies then project
                   and reconstruct without the products with the zero entries
                   (intersect/surface_projection.glsl: the same results up to
                   the sign of an exact zero)
    perspectiveDet a * b when perspective and that product is finite with
                   |a b| >= SNELL_FLT_MIN (the reconstruction's determinant), else 0
                   (then every reconstruction is invalid, without dividing by it)
    linearizable   zNear, zFar and convention linearize a depth (the conditions
                   of snellLinearizeDepth's contract), nearOverFar zNear / zFar (0
                   for the infinite conventions), depthReversed (REVERSED,
                   INFINITE_REVERSED), depthFarBelow (SNELL_FLT_MIN for
                   INFINITE_REVERSED: a smaller depth is the far plane; else 0),
                   depthFarLimit (zFar; SNELL_FLT_MAX for the infinite
                   conventions): snellSurfaceLinearDepth's terms
contract (snellDepthSurfaceComplete):
  - returns s with every derived field computed from its clipFromView, zNear,
    zFar and convention (snellDepthSurface's result for them); lod,
    depthFilter, closed and emptyDepth are kept. snellDepthSurface calls it.
  - an invalid depth range or convention gives a surface on which every depth
    read is invalid (linearizable false): every strategy misses, with finite
    outputs. A perspective-shaped clipFromView whose a b is not finite or
    below SNELL_FLT_MIN gives perspectiveDet 0: every reconstruction is
    invalid. (Any other matrix goes through the general path, which tests its
    own terms.)
  - a surface whose derived fields disagree with its source fields (filled in
    by hand, or changed without this call) is read through a mix of both (the
    derived terms, zNear for the clamp, clipFromView for the projection): its
    results are finite (never NaN or +-Inf) and flagged, and nothing more is
    promised (a hand-set denormal term may be flushed to 0 on a GPU and not
    in C++). Any field may be hostile (NaN, +-Inf, zero or negative ranges, a
    perspective flag on a general matrix): never a NaN output, never a crash.
    In C++ start such a surface value-initialized (SnellDepthSurface s{};):
    an uninitialized bool is undefined behaviour before any of this.
contract (snellSurfaceLinearDepth):
  - for a complete surface, exactly snellLinearizeDepth(depthValue, s.zNear,
    s.zFar, s.convention) (bit for bit: the same operations, with the
    conventions' branches folded into selects and zNear / zFar precomputed);
    0.0f when s.linearizable is false or depthValue is NaN.
  - for an inconsistent surface: 0.0f or a finite value > 0 (never NaN or
    +-Inf; no clamp with reversed or NaN bounds, whose result GLSL leaves
    undefined).
contract (snellSampleSurface):
  - NEAREST: reads the texel containing uv (no filtering: filtering depth
    invents surfaces between foreground and background, Oliveira & Brauwers
    2007 sec. 3.1) at level lod through SNELL_TEXEL_FETCH (SNELL_TEXEL_FETCH_IN_LEVEL:
    the same hook in GLSL and HLSL; in C++ without fetch's range tests), red channel, and
    costs one fetch. BILINEAR: the four texels (clamped to the edge) through
    SNELL_TEXEL_FETCH, counted as one fetch (one textureGather in a shader that
    has it); valid as NEAREST is (the texel containing uv decides);
    interpolated = true when the four were blended (false for NEAREST, at the
    silhouette and whenever valid is false);
  - valid = false (viewZ = 0) when uv lies outside [0,1]^2 (off screen: no
    information, never clamped to the edge), when uv is NaN, when the texel equals
    emptyDepth, or when the depth does not linearize (NaN, bad zNear/zFar);
  - otherwise viewZ = -snellSurfaceLinearDepth(s, texel) < 0 (finite for a
    complete surface).
source: Oliveira & Brauwers 2007 sec. 3.1 and Algorithm 2 ("invalid texels have
  depth = 0"); depth conventions in camera/linearize_depth.glsl.
*/
#ifndef SNELL_INTERSECT_DEPTH_SURFACE_GLSL
#define SNELL_INTERSECT_DEPTH_SURFACE_GLSL

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


#define SNELL_DEPTH_FILTER_NEAREST 0
#define SNELL_DEPTH_FILTER_BILINEAR 1

struct SnellDepthSurface {
  mat4 clipFromView;
  float zNear;
  float zFar;
  int convention;
  float emptyDepth;
  int lod;
  int depthFilter;
  bool closed;
  // Derived (snellDepthSurfaceComplete):
  bool perspective;
  float perspectiveDet;
  bool linearizable;
  bool depthReversed;
  float nearOverFar;
  float depthFarBelow;
  float depthFarLimit;
};

struct SnellSurfaceSample {
  float viewZ;
  bool valid;
  bool interpolated;  // BILINEAR and all four texels held a surface: viewZ is the depth at uv itself
};

SNELL_FN SnellDepthSurface snellDepthSurfaceComplete(SnellDepthSurface s) {
  vec4 c0 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 0);
  vec4 c1 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 1);
  vec4 c2 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 2);
  vec4 c3 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 3);
  s.perspective = c0.y == 0.0f && c0.z == 0.0f && c0.w == 0.0f && c1.x == 0.0f && c1.z == 0.0f &&
                  c1.w == 0.0f && c2.w == -1.0f && c3.x == 0.0f && c3.y == 0.0f && c3.w == 0.0f;
  float det = c0.x * c1.y;
  s.perspectiveDet = s.perspective && SNELL_FINITE(det) && abs(det) >= SNELL_FLT_MIN ? det : 0.0f;
  bool infinite = s.convention == SNELL_DEPTH_INFINITE_GL || s.convention == SNELL_DEPTH_INFINITE_REVERSED;
  s.linearizable = s.convention >= 0 && s.convention < SNELL_DEPTH_CONVENTION_COUNT && SNELL_FINITE(s.zNear) &&
                   s.zNear >= SNELL_FLT_MIN && (infinite || (SNELL_FINITE(s.zFar) && s.zFar > s.zNear));
  s.depthReversed = s.convention == SNELL_DEPTH_REVERSED || s.convention == SNELL_DEPTH_INFINITE_REVERSED;
  // Only read when linearizable: zFar is then finite and > zNear, or unused.
  s.nearOverFar = s.linearizable && !infinite ? s.zNear / s.zFar : 0.0f;
  s.depthFarBelow = s.convention == SNELL_DEPTH_INFINITE_REVERSED ? SNELL_FLT_MIN : 0.0f;
  s.depthFarLimit = infinite ? SNELL_FLT_MAX : (s.linearizable ? s.zFar : 0.0f);
  return s;
}

SNELL_FN SnellDepthSurface snellDepthSurface(mat4 clipFromView, float zNear, float zFar, int convention,
                                             float emptyDepth) {
  SnellDepthSurface s;
  s.clipFromView = clipFromView;
  s.zNear = zNear;
  s.zFar = zFar;
  s.convention = convention;
  s.emptyDepth = emptyDepth;
  s.lod = 0;
  s.depthFilter = SNELL_DEPTH_FILTER_NEAREST;
  s.closed = true;
  return snellDepthSurfaceComplete(s);
}

/* One division and the clamp of snellLinearizeDepth, the conventions as
   selects: GL and ZERO_ONE n / ((1 - d) + d (n / f)), REVERSED n / (d + (1 - d)
   (n / f)); the infinite ones add d 0 or (1 - d) 0 = +0 to the same first term
   (exact), and their far plane (d = 1 INFINITE_GL, d < SNELL_FLT_MIN
   INFINITE_REVERSED) has a zero denominator: SNELL_FLT_MAX, as the reference
   returns it. Equations in camera/linearize_depth.glsl. */
SNELL_FN_INLINE float snellSurfaceLinearDepth(SNELL_IN(SnellDepthSurface) s, float depthValue) {
  if (!s.linearizable || isnan(depthValue)) {
    return 0.0f;
  }
  float d = clamp(depthValue, 0.0f, 1.0f);
  float e = 1.0f - d;
  float a = s.depthReversed ? d : e;
  float b = s.depthReversed ? e : d;
  if (d < s.depthFarBelow) {
    a = 0.0f;
  }
  // den > 0 for a complete surface but at the infinite conventions' far plane
  // (and where n / f underflows), whose distance is the clamp's top:
  // SNELL_FLT_MAX there, as the reference returns it, without dividing by 0.
  float den = a + b * s.nearOverFar;
  float v = den > 0.0f ? s.zNear / den : SNELL_FLT_MAX;
  // A NaN (only from inconsistent terms) stops here: GPU compilers turn the
  // selects below into fmax / fmin, which would drop it.
  if (!(v > 0.0f)) {
    return 0.0f;
  }
  // clamp(v, zNear, depthFarLimit) as two selects: for a complete surface the
  // same value (zNear <= depthFarLimit); for an inconsistent one (reversed or
  // NaN bounds, where clamp is undefined) defined, and the last test keeps
  // only a finite result > 0.
  v = v < s.zNear ? s.zNear : v;
  v = v > s.depthFarLimit ? s.depthFarLimit : v;
  return v > 0.0f && v <= SNELL_FLT_MAX ? v : 0.0f;
}

/* SNELL_FN_INLINE: C++ inlines this read into every strategy and loop (by
   value, g++ inlined it only in some and left a copy of the surface per call
   elsewhere; by reference and always inlined it is cheaper in all,
   benchmarks/kernels). */
SNELL_FN_INLINE SnellSurfaceSample snellSampleSurface(SNELL_TEX2D depthTex, vec2 uv, SNELL_IN(SnellDepthSurface) s) {
  SnellSurfaceSample r;
  r.viewZ = 0.0f;
  r.valid = false;
  r.interpolated = false;
  // Written so NaN fails: every comparison with NaN is false.
  if (!(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f)) {
    return r;
  }
  ivec2 size = SNELL_TEXTURE_SIZE(depthTex, s.lod);
  if (size.x <= 0 || size.y <= 0) {
    return r;
  }
  // size > 0 (C++: s.lod is one of the texture's levels) and uv in [0,1]^2:
  // the texel is inside the level (SNELL_TEXEL_FETCH_IN_LEVEL's precondition).
  float d = SNELL_TEXEL_FETCH_IN_LEVEL(depthTex, SNELL_PIXEL_ON_SCREEN(uv, size), s.lod).x;
  if (d == s.emptyDepth) {
    return r;
  }
  if (s.depthFilter == SNELL_DEPTH_FILTER_BILINEAR) {
    // Texel-centre coordinates: texel i's centre sits at i + 0.5.
    SNELL_PRECISE float tx = uv.x * float(size.x) - 0.5f;
    SNELL_PRECISE float ty = uv.y * float(size.y) - 0.5f;
    float fx = floor(tx);
    float fy = floor(ty);
    int x0 = clamp(int(fx), 0, size.x - 1);
    int y0 = clamp(int(fy), 0, size.y - 1);
    int x1 = clamp(int(fx) + 1, 0, size.x - 1);
    int y1 = clamp(int(fy) + 1, 0, size.y - 1);
    float d00 = SNELL_TEXEL_FETCH(depthTex, ivec2(x0, y0), s.lod).x;
    float d10 = SNELL_TEXEL_FETCH(depthTex, ivec2(x1, y0), s.lod).x;
    float d01 = SNELL_TEXEL_FETCH(depthTex, ivec2(x0, y1), s.lod).x;
    float d11 = SNELL_TEXEL_FETCH(depthTex, ivec2(x1, y1), s.lod).x;
    if (d00 != s.emptyDepth && d10 != s.emptyDepth && d01 != s.emptyDepth && d11 != s.emptyDepth) {
      float wx = tx - fx;
      float wy = ty - fy;
      SNELL_PRECISE float d0 = d00 + wx * (d10 - d00);
      SNELL_PRECISE float d1 = d01 + wx * (d11 - d01);
      SNELL_PRECISE float dm = d0 + wy * (d1 - d0);
      d = dm;
      r.interpolated = true;
    }
  }
  float v = snellSurfaceLinearDepth(s, d);
  if (!(v > 0.0f)) {
    r.interpolated = false;
    return r;
  }
  r.viewZ = -v;
  r.valid = true;
  return r;
}

#endif
/*
description: a depth surface's projection and reconstruction, with the work a
  perspective projection does not need left out: the strategies project their
  points and rebuild their texels through these two.
use: SnellScreenPoint sp = snellSurfaceViewToUv(surface, pView);
     SnellViewPoint p = snellSurfaceUvZToView(surface, uv, viewZ);
contract:
  - surface.perspective false: exactly snellViewToUv(surface.clipFromView, pView)
    and snellUvZToView(surface.clipFromView, uv, viewZ).
  - surface.perspective true (snellDepthSurface sets it when clipFromView's
    columns are (a,0,0,0) (0,b,0,0) (c,d,e,-1) (0,0,f,0): the right-handed
    perspective of glm::perspective*, glFrustum and snellPerspective, off-centre
    and jittered ones included; any other matrix takes the general path): the
    same operations without the products with those zero entries, which add
    +-0 to a finite term and make a non-finite one NaN, and non-finite terms
    are invalid either way. The valid flags and values are the general path's
    (in C++ with -ffp-contract=off, bit for bit), except the sign of a
    coordinate that is exactly zero (uv never is: it is 0.5 ndc + 0.5) and of
    an exactly zero ndcZ; with +0 zero entries, as glm::perspective and
    snellPerspective write them, the reconstruction is bit-exact. GPU
    compilers may fold the kept zero products; the parity tolerances cover it.
  - the flag is the surface's promise: call snellDepthSurfaceComplete after
    giving clipFromView another shape (it recomputes the flag and
    perspectiveDet, the reconstruction's validated determinant: 0 makes every
    reconstruction invalid).
options:
  SNELL_PERSPECTIVE_ONLY  0 (default): a surface whose perspective flag is
                          false takes the general path above. 1: the general
                          path is not compiled in, and such a surface projects
                          and reconstructs nothing (valid = false: every
                          strategy misses on it); a perspective surface gives
                          exactly what it gives by default. For shaders whose
                          depth buffers all come from perspective cameras:
                          llvmpipe runs the general path beside the
                          perspective one although the flag is uniform
                          (benchmarks/kernels/gpu_kernel_table.sh: single
                          sample 10 %, normal plane (1 it.) 9 % fewer
                          instructions per pixel); C++ and GPU drivers that
                          branch on uniform values gain little.
source: OpenGL 4.5 core spec sec. 13.6 (clip -> NDC); the equations in
  camera/view_to_uv.glsl and camera/uv_z_to_view.glsl.
*/
#ifndef SNELL_INTERSECT_SURFACE_PROJECTION_GLSL
#define SNELL_INTERSECT_SURFACE_PROJECTION_GLSL

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

#ifndef SNELL_PERSPECTIVE_ONLY
#  define SNELL_PERSPECTIVE_ONLY 0
#endif

SNELL_FN_INLINE SnellScreenPoint snellSurfaceViewToUv(SNELL_IN(SnellDepthSurface) s, vec3 pView) {
#if !SNELL_PERSPECTIVE_ONLY
  if (!s.perspective) {
    return snellViewToUv(s.clipFromView, pView);
  }
#endif
  vec4 c0 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 0);
  vec4 c1 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 1);
  vec4 c2 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 2);
  vec4 c3 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 3);
  SnellScreenPoint r;
  r.uv = vec2(0.0f, 0.0f);
  r.ndcZ = 0.0f;
  r.valid = false;
#if SNELL_PERSPECTIVE_ONLY
  if (!s.perspective) {
    return r;
  }
#endif
  // A non-finite coordinate makes its own clip term non-finite here, where the
  // general product spreads it as NaN through a zero entry: invalid either way.
  float cx = c0.x * pView.x + c2.x * pView.z;
  float cy = c1.y * pView.y + c2.y * pView.z;
  float cz = c2.z * pView.z + c3.z;
  float cw = -pView.z;
  // cw's upper bound is implied by cx (c2.x times an infinite z is never
  // finite) unless a compiler folds a constant zero c2.x: tested outright.
  if (!SNELL_FINITE(cx) || !SNELL_FINITE(cy) || !(cw >= SNELL_FLT_MIN && cw <= SNELL_FLT_MAX)) {
    return r;
  }
  // Per component (the same operations as a vec3 clamp; C++ inlines them).
  float ndcX = clamp(cx / cw, -SNELL_FLT_MAX, SNELL_FLT_MAX);
  float ndcY = clamp(cy / cw, -SNELL_FLT_MAX, SNELL_FLT_MAX);
  float ndcZ = cz / cw;
  r.uv = vec2(ndcX, ndcY) * 0.5f + 0.5f;
  r.ndcZ = isnan(ndcZ) ? 0.0f : clamp(ndcZ, -SNELL_FLT_MAX, SNELL_FLT_MAX);
  r.valid = true;
  return r;
}

SNELL_FN_INLINE SnellViewPoint snellSurfaceUvZToView(SNELL_IN(SnellDepthSurface) s, vec2 uv, float viewZ) {
#if !SNELL_PERSPECTIVE_ONLY
  if (!s.perspective) {
    return snellUvZToView(s.clipFromView, uv, viewZ);
  }
#endif
  SnellViewPoint r;
  r.position = vec3(0.0f, 0.0f, 0.0f);
  r.valid = false;
#if SNELL_PERSPECTIVE_ONLY
  if (!s.perspective) {
    return r;
  }
#endif
  // A non-finite uv makes nx or ny non-finite: tested below.
  if (!SNELL_FINITE(viewZ) || !(viewZ <= -SNELL_FLT_MIN)) {
    return r;
  }
  vec4 c0 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 0);
  vec4 c1 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 1);
  vec4 c2 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 2);
  float nx = 2.0f * uv.x - 1.0f;
  float ny = 2.0f * uv.y - 1.0f;
  // 2 uv - 1 overflows for a huge uv; the general path then ends invalid
  // (its a01 = c1.x - n c1.w is NaN), and so does this test, early.
  if (!SNELL_FINITE(nx) || !SNELL_FINITE(ny)) {
    return r;
  }
  // c2.x - n c2.w with c2.w = -1 is c2.x + n; c3.x - n c3.w is a zero (+0 when
  // c3.x and c3.w are +0), added as +0.
  float b0 = -(viewZ * (c2.x + nx) + 0.0f);
  float b1 = -(viewZ * (c2.y + ny) + 0.0f);
  // The zero coefficients a01, a10 stay as products with +0: they decide the
  // sign of an exactly zero result as in the general path. perspectiveDet is
  // c0.x c1.y validated once, 0 when unusable.
  if (s.perspectiveDet == 0.0f) {
    return r;
  }
  float x = (b0 * c1.y - 0.0f * b1) / s.perspectiveDet;
  float y = (c0.x * b1 - b0 * 0.0f) / s.perspectiveDet;
  if (!SNELL_FINITE(x) || !SNELL_FINITE(y)) {
    return r;
  }
  r.position = vec3(x, y, viewZ);
  r.valid = true;
  return r;
}

#endif
/*
description: the view-space point a depth texture stores at a uv: the texel
  containing uv, reconstructed at that texel's CENTRE (the point the rasterizer
  actually sampled, by camera/uv_z_to_view.glsl). The plane strategies build
  their planes from these points.
use: SnellSurfacePoint b = snellSurfacePoint(depthTex, uv, surface);   // b.position, b.uv, b.valid
contract:
  - snellSurfacePoint: one snellSampleSurface at uv (one fetch, level s.lod);
    uv = the centre of the texel read (snellPixelToUv of snellUvToPixel at level
    s.lod), or uv itself when the sample was interpolated (s.depthFilter
    BILINEAR with four surface texels: the depth there is the surface's at uv),
    position = snellUvZToView(s.clipFromView, that uv, viewZ). valid
    = false (uv and position 0) when the sample is invalid (off screen, empty,
    NaN) or the reconstruction is. Costs one fetch whatever the outcome.
  - texel-centre reconstruction is what makes the plane strategies exact on
    planar surfaces: a depth texel is the surface depth at its centre.
source: OpenGL 4.5 core spec sec. 13.6 (clip -> NDC), sec. 14.5 (fragment
  centres); Mayer & Assarsson, "Constant-Time Light Refraction Simulation",
  step 2 (B, the point directly behind W, from the screen buffers).
*/
#ifndef SNELL_INTERSECT_SURFACE_POINT_GLSL
#define SNELL_INTERSECT_SURFACE_POINT_GLSL








struct SnellSurfacePoint {
  vec3 position;  // view space, on the texel centre's pixel ray
  vec2 uv;        // the texel centre
  bool valid;
};

SNELL_FN_INLINE SnellSurfacePoint snellSurfacePoint(SNELL_TEX2D depthTex, vec2 uv, SNELL_IN(SnellDepthSurface) s) {
  SnellSurfacePoint r;
  r.position = vec3(0.0f, 0.0f, 0.0f);
  r.uv = vec2(0.0f, 0.0f);
  r.valid = false;
  SnellSurfaceSample x = snellSampleSurface(depthTex, uv, s);
  if (!x.valid) {
    return r;
  }
  ivec2 size = SNELL_TEXTURE_SIZE(depthTex, s.lod);
  // x.valid: uv is on screen and size > 0 (the macros' domain)
  vec2 centre = uv;
  if (!x.interpolated) {
    ivec2 px = SNELL_PIXEL_ON_SCREEN(uv, size);
    centre = SNELL_PIXEL_CENTRE(px, size);
  }
  SnellViewPoint p = snellSurfaceUvZToView(s, centre, x.viewZ);
  if (!p.valid) {
    return r;
  }
  r.position = p.position;
  r.uv = centre;
  r.valid = true;
  return r;
}

#endif
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
/*
description: a view-space point accepted as a hit where a depth buffer has a
  surface at its projection: the last lookup of the plane methods (Mayer &
  Assarsson step 4) and of Wyman's distance estimate, which both produce a
  point first and ask the buffer afterwards.
use: SnellHit h = snellHitOnSurface(p, depthTex, surface, fetchesSoFar);
contract:
  - projects the view-space point p; the hit is (uv = its projection, position
    = p) and valid exactly when p is finite, in front of the camera, projects
    into [0,1]^2 and the depth texture has a surface at that uv
    (snellSampleSurface valid, level s.lod): the approximation landed on the
    surface, not in an empty texel or off screen.
  - fetches = fetchesSoFar + 1 when p projects (the step 4 lookup; an off-screen
    uv is counted though snellSampleSurface answers it without reading), else
    fetchesSoFar. A miss is snellHitMiss with that count.
source: C. Mayer, U. Assarsson, "Constant-Time Light Refraction Simulation",
  step 4.
*/
#ifndef SNELL_INTERSECT_HIT_ON_SURFACE_GLSL
#define SNELL_INTERSECT_HIT_ON_SURFACE_GLSL






SNELL_FN SnellHit snellHitOnSurface(vec3 p, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) s, int fetchesSoFar) {
  SnellScreenPoint sp = snellSurfaceViewToUv(s, p);
  if (!sp.valid) {
    return snellHitMiss(fetchesSoFar);
  }
  SnellSurfaceSample x = snellSampleSurface(depthTex, sp.uv, s);
  if (!x.valid) {
    return snellHitMiss(fetchesSoFar + 1);
  }
  SnellHit h;
  h.uv = sp.uv;
  h.position = p;
  h.valid = true;
  h.fetches = fetchesSoFar + 1;
  return h;
}

#endif
/*
description: what the two plane strategies (plane_normal.glsl, plane_depth.glsl)
  share: the iteration options of Mayer & Assarsson's step 5 ("iteratively
  refine the approximation, using P_e as the location to sample screen buffers
  and generate a new plane") and the final step 4 lookup that turns a plane
  hit into a SnellHit (snellPlaneHit, on intersect/hit_on_surface.glsl).
use: SnellHit h = snellPlaneHit(p, planeUv, depthTex, surface, fetchesSoFar);
options:
  SNELL_PLANE_ITERATIONS      refinement iterations callers pass by default (1);
                              0 is the constant-time method (one plane)
  SNELL_PLANE_MAX_ITERATIONS  compile-time bound of the refinement loops (8); a
                              per-call count is clamped to [0, this]
  SNELL_PLANE_FACING_FALLBACK 1 (default): when a ray does not meet plane k
                              ahead of its origin, plane k is replaced by the
                              plane through the same surface point B_k facing
                              the camera (normal = B_k, the line of sight);
                              0: plane k is a miss (k = 0) or ends the
                              refinement, as in the poster
contract (snellPlaneHit): the comment above the function.
source: C. Mayer, U. Assarsson, "Constant-Time Light Refraction Simulation",
  steps 4 and 5.
*/
#ifndef SNELL_INTERSECT_PLANE_REFINE_GLSL
#define SNELL_INTERSECT_PLANE_REFINE_GLSL








#ifndef SNELL_PLANE_ITERATIONS
#  define SNELL_PLANE_ITERATIONS 1
#endif
#ifndef SNELL_PLANE_MAX_ITERATIONS
#  define SNELL_PLANE_MAX_ITERATIONS 8
#endif
/* Why the facing fallback: near the silhouette of a convex object, the back
   face's tangent plane at B_0 (the point behind W) leans away from the
   refracted ray, which is bent inwards, so the ray never meets it and the
   poster's method has no hit at all for a band of rim pixels (21.8% of a
   glass sphere's non-TIR pixels, normal-based). The facing plane is the limit
   of Mayer & Assarsson's blurred normal level ("a more blurred mip level gives
   a more complete representation of the scene for drastic refraction
   effects"): a ray going deeper always meets it, and the refinement then walks
   along the back surface to tangent planes the ray does meet. Same fetches. */
#ifndef SNELL_PLANE_FACING_FALLBACK
#  define SNELL_PLANE_FACING_FALLBACK 1
#endif
/* 1: a plane hit whose projection lands on an empty texel is kept on the last
   valid plane (snellPlaneHit) on a surface whose emptiness hides more of it
   (SnellDepthSurface.closed, the default: a closed object's back faces curve
   away behind their silhouette); 0: it is a miss on every surface. */
#ifndef SNELL_PLANE_HOLD
#  define SNELL_PLANE_HOLD 1
#endif

/* The last step of both plane methods (Mayer & Assarsson steps 4-5): the plane
   hit p is accepted where the buffer has a surface at its projection. Where it has
   none (the tangent plane of a convex object's back face lies outside the object,
   so rim rays project past the silhouette), the plane itself is the best estimate
   left: with SNELL_PLANE_HOLD, on a closed surface (s.closed: an open one such
   as the opaque scene has nothing behind its empty texels but the
   environment), the hit stays at p, valid, with uv = planeUv, the
   texel the plane was built from, so a normal read at h.uv returns that plane's
   normal. Off-screen or behind-the-camera p is a miss either way, and so is a
   NaN or infinite planeUv (no texel: the hit's uv stays finite). */
SNELL_FN SnellHit snellPlaneHit(vec3 p, vec2 planeUv, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) s, int fetchesSoFar) {
  SnellHit h = snellHitOnSurface(p, depthTex, s, fetchesSoFar);
  if (h.valid || SNELL_PLANE_HOLD == 0 || !s.closed) {
    return h;
  }
  SnellScreenPoint sp = snellSurfaceViewToUv(s, p);
  if (!sp.valid || !(sp.uv.x >= 0.0f && sp.uv.x <= 1.0f && sp.uv.y >= 0.0f && sp.uv.y <= 1.0f) ||
      !SNELL_FINITE(planeUv.x) || !SNELL_FINITE(planeUv.y)) {
    return h;
  }
  h.uv = planeUv;
  h.position = p;
  h.valid = true;
  return h;
}

#endif
/*
description: the far start of the plane strategies on a closed surface (an
  object's back faces): a constant-depth plane at the farthest back-face
  distance that the depth min/max pyramid holds over the ray's way across the
  screen, a second candidate for the first plane next to Mayer & Assarsson's
  (built at B_0, the point behind the ray origin). snellIntersectPlaneNormal
  and snellIntersectPlaneDepth take the nearer of the two.
use: SnellFarPlane f = snellPlaneFarStart(origin, dir, originUv, pyramidTex, surface);
     if (f.valid && (!tangent.valid || f.t < tangent.t)) { ... f.position ... }
  origin, dir  the view-space ray (dir any length; t in units of |dir|)
  originUv     the origin's projection (snellSurfaceViewToUv(surface, origin).uv)
  pyramidTex   the surface's depth min/max pyramid (intersect/depth_pyramid.glsl
               layout, z = farthest view distance, w = coverage), full mip chain
  surface      the depth surface the pyramid was built from
options:
  SNELL_PLANE_FAR_START  1 (default): SnellIntersectOptions.planeFarStart is
                         true by default (intersect/intersect_with.glsl), for both
                         plane strategies; 0: false
contract:
  - step 1 (1 fetch): the top level's texel (0, 0): z_all, the farthest
    distance of the whole buffer. The ray meets the plane z = -z_all at G
    (snellRayPlane); its projection g.
  - step 2 (1 fetch): the level L whose texels are the smallest at least as
    wide as the ray's way from originUv to g (D = |g - originUv| in level-0
    texels; L = the least L with 2^L >= D, at most the top level), its texel
    at the way's midpoint m (clamped to [0,1]^2): min(int(m * size_L),
    size_L - 1), as a nearest read at level L picks it: z_L. The result is
    the ray's hit on the plane z = -z_L: t, position, valid, fetches 2.
  - invalid (t = 0, position 0): surface.closed false or originUv not finite
    (no fetch); the top texel empty (w <= 0) or its z not finite and
    positive (1 fetch); the ray
    not meeting z = -z_all ahead of origin (a ray towards the camera or one
    already beyond the object) or G at or behind the camera (1 fetch); the
    level texel empty or its z not finite and positive (2 fetches).
  - why it helps: on a convex object the tangent plane at B_0 lies beyond the
    exit, and near the silhouette the refracted ray, bent inwards, meets it
    far away or never (the facing fallback of plane_refine.glsl then starts at
    B_0's depth, next to the origin, and the refinement crawls). No exit lies
    deeper than the farthest back face under the ray's way: where the level's
    texel holds the whole way, the far plane is at or beyond the exit (a
    quarter of a sphere's refracted rays in the unit test, all of them at or
    beyond); elsewhere it is an estimate. The plane strategies take the nearer
    of the two candidates.
  - the level loop compares with powers of two (no log2), so C++ and the GPU
    pick the same level.
source: the search range of Oliveira & Brauwers 2007 (sec. 3.2: "Zmax", the
  min/max reduction) used as a plane of Mayer & Assarsson's method
  ("Constant-Time Light Refraction Simulation", step 2; "a more blurred mip
  level gives a more complete representation of the scene for drastic
  refraction effects"); snell's own combination.
*/
#ifndef SNELL_INTERSECT_PLANE_FAR_START_GLSL
#define SNELL_INTERSECT_PLANE_FAR_START_GLSL


/*
description: intersection of a ray with a plane given by a point and a normal.
use: SnellRayPlaneHit h = snellRayPlane(origin, dir, planePoint, planeNormal);
     if (h.valid) { ... h.position ... }
  origin       ray origin
  dir          ray direction (need not be normalized: h.t is measured in units
               of |dir|, h.position = origin + h.t * dir)
  planePoint   any point on the plane
  planeNormal  plane normal, either orientation, need not be normalized
options:
  SNELL_RAY_PLANE_PARALLEL_EPS  |cos| between dir and the plane normal below
                                which the ray counts as parallel (1e-6f)
contract:
  - valid hit: t = dot(planePoint - origin, n) / dot(dir, n) >= 0 (a ray
    starting on the plane hits at t = 0), point = origin + t dir;
  - h.valid is false, with h.t = 0 and h.position = (0,0,0) (finite, never NaN),
    when: the ray is parallel to the plane (within the epsilon above, also when
    it lies in it), the hit is behind the origin (t < 0), dir or planeNormal is
    zero, denormal-small, NaN or infinite, dir's squared length overflows a
    float (|dir| above about 1.8e19), origin or planePoint has a NaN or
    infinite component, or t or the point overflows.
source: the parametric line p = o + t d (G. Oliveira 2000, Equations 9-10)
  substituted into the plane equation dot(p - p0, n) = 0.
*/
#ifndef SNELL_OPTICS_RAY_PLANE_GLSL
#define SNELL_OPTICS_RAY_PLANE_GLSL

/*
description: normalize that never produces NaN or infinity.
use: vec3 n = snellSafeNormalize(v);
options: -
contract: returns v / |v| when every component is finite and |v|^2 is a normal
  float above 1e-30 and below FLT_MAX; otherwise (0,0,0) (zero, denormal-small,
  NaN, infinite, or so large that |v|^2 overflows). Callers test dot(n, n) == 0
  for "invalid".
source: -
*/
#ifndef SNELL_OPTICS_SAFE_NORMALIZE_GLSL
#define SNELL_OPTICS_SAFE_NORMALIZE_GLSL


SNELL_FN vec3 snellSafeNormalize(vec3 v) {
  float len2 = dot(v, v);
  // NaN fails every comparison; an infinite component makes len2 infinite.
  if (!(len2 > 1e-30f) || !(len2 < SNELL_FLT_MAX)) {
    return vec3(0.0f, 0.0f, 0.0f);
  }
  return v * inversesqrt(len2);
}

#endif

#ifndef SNELL_RAY_PLANE_PARALLEL_EPS
#  define SNELL_RAY_PLANE_PARALLEL_EPS 1e-6f
#endif

struct SnellRayPlaneHit {
  float t;
  vec3 position;  // not "point": a reserved word in HLSL (geometry shader input)
  bool valid;
};

SNELL_FN SnellRayPlaneHit snellRayPlane(vec3 origin, vec3 dir, vec3 planePoint, vec3 planeNormal) {
  SnellRayPlaneHit h;
  h.t = 0.0f;
  h.position = vec3(0.0f, 0.0f, 0.0f);
  h.valid = false;
  vec3 n = snellSafeNormalize(planeNormal);
  float dirLen2 = dot(dir, dir);
  // dirLen2 = +inf is a dir too long to square; FLT_MAX itself is a finite length, sqrt and all.
  if (dot(n, n) == 0.0f || !(dirLen2 > 1e-30f) || !(dirLen2 <= SNELL_FLT_MAX)) {
    return h;
  }
  if (!SNELL_FINITE(origin.x) || !SNELL_FINITE(origin.y) || !SNELL_FINITE(origin.z) ||
      !SNELL_FINITE(planePoint.x) || !SNELL_FINITE(planePoint.y) || !SNELL_FINITE(planePoint.z)) {
    return h;
  }
  float denom = dot(dir, n);
  if (!(abs(denom) > SNELL_RAY_PLANE_PARALLEL_EPS * sqrt(dirLen2))) {
    return h;
  }
  float t = dot(planePoint - origin, n) / denom;
  if (!(t >= 0.0f) || !(t <= SNELL_FLT_MAX)) {
    return h;
  }
  vec3 p = origin + t * dir;
  if (!SNELL_FINITE(p.x) || !SNELL_FINITE(p.y) || !SNELL_FINITE(p.z)) {
    return h;
  }
  h.t = t;
  h.position = p;
  h.valid = true;
  return h;
}

#endif

/*
description: the depth range [zNearest, zFarthest] the texture-space searches
  (conservative binary search, binary, linear+binary) walk, from the two
  sources Oliveira & Brauwers name: the top level of the depth min/max pyramid
  (their 2nd pass, exact for the buffer) or the object's bounding box (their
  suggested speed-up: no reduction pass, a looser range). Plus the top mip
  level of a texture, which the range and the depth-based plane need.
use: SnellDepthRange r = snellDepthRangeFromPyramid(pyramidTex);
     SnellDepthRange r = snellDepthRangeFromBox(viewFromObject, boxMin, boxMax);
     int top = snellTextureTopLod(tex);
  pyramidTex      a depth min/max pyramid (intersect/depth_pyramid.glsl layout:
                  y nearest, z farthest view distance, w coverage), all levels
  viewFromObject  object-to-view transform (camera at the origin looking down -Z)
  boxMin, boxMax  the object-space axis-aligned bounding box
options:
  SNELL_DEPTH_RANGE_MARGIN  relative widening of the pyramid range (1e-3f):
                            zNearest * (1 - m), zFarthest * (1 + m), so a
                            fronto-parallel surface (Zmin == Zmax, which the
                            searches reject) still gets a range and the
                            surface lies strictly inside it
contract:
  - snellTextureTopLod: floor(log2(max(width, height))) of level 0 (the last
    level of a full GL mip chain); 0 for a 1x1 or size-0 texture.
  - snellDepthRangeFromPyramid: one SNELL_TEXEL_FETCH of texel (0, 0) at the
    top level; valid when its coverage w > 0 and 0 < y <= z are finite;
    zNearest = -y (1 - margin), zFarthest = -z (1 + margin). Invalid (all 0)
    for an empty buffer.
  - snellDepthRangeFromBox: the 8 corners transformed by viewFromObject
    (w = 1 assumed: an affine transform); zNearest = the largest corner z,
    zFarthest = the smallest, no fetch. Valid when every corner z is finite
    and zFarthest < 0; a box reaching to or behind the camera plane gets
    zNearest = -FLT_MIN (the searches then start at the ray origin). A flat box
    facing the camera (zNearest == zFarthest) is widened by
    SNELL_DEPTH_RANGE_MARGIN as for the pyramid. Invalid: all 0.
source: M. M. Oliveira, M. Brauwers, "Real-Time Refraction Through Deformable
  Objects", I3D 2007, sec. 3 (2nd pass: min/max reduction) and sec. 6
  ("using the limits of the object's bounding box as Zmin and Zmax").
*/
#ifndef SNELL_INTERSECT_DEPTH_RANGE_GLSL
#define SNELL_INTERSECT_DEPTH_RANGE_GLSL



#ifndef SNELL_DEPTH_RANGE_MARGIN
#  define SNELL_DEPTH_RANGE_MARGIN 1e-3f
#endif

struct SnellDepthRange {
  float zNearest;
  float zFarthest;
  bool valid;
};

SNELL_FN SnellDepthRange snellDepthRangeInvalid() {
  SnellDepthRange r;
  r.zNearest = 0.0f;
  r.zFarthest = 0.0f;
  r.valid = false;
  return r;
}

SNELL_FN int snellTextureTopLod(SNELL_TEX2D tex) {
  ivec2 size = SNELL_TEXTURE_SIZE(tex, 0);
  int m = max(size.x, size.y);
  int lod = 0;
  for (int i = 0; i < 31; ++i) {
    if (m <= 1) {
      break;
    }
    m = m / 2;
    lod = lod + 1;
  }
  return lod;
}

/* Oliveira & Brauwers 2007, sec. 3, 2nd pass: the top level of the min/max reduction */
SNELL_FN SnellDepthRange snellDepthRangeFromPyramid(SNELL_TEX2D pyramidTex) {
  int top = snellTextureTopLod(pyramidTex);
  vec4 t = SNELL_TEXEL_FETCH(pyramidTex, ivec2(0, 0), top);
  if (!(t.w > 0.0f) || !(t.y > 0.0f) || !(t.z >= t.y) || !SNELL_FINITE(t.z)) {
    return snellDepthRangeInvalid();
  }
  SnellDepthRange r;
  r.zNearest = -t.y * (1.0f - SNELL_DEPTH_RANGE_MARGIN);
  r.zFarthest = -t.z * (1.0f + SNELL_DEPTH_RANGE_MARGIN);
  r.valid = true;
  return r;
}

/* Oliveira & Brauwers 2007, sec. 6: the bounding box as Zmin, Zmax */
SNELL_FN SnellDepthRange snellDepthRangeFromBox(mat4 viewFromObject, vec3 boxMin, vec3 boxMax) {
  float zNearest = -SNELL_FLT_MAX;
  float zFarthest = SNELL_FLT_MAX;
  for (int i = 0; i < 8; ++i) {
    float x = (i == 1 || i == 3 || i == 5 || i == 7) ? boxMax.x : boxMin.x;
    float y = (i == 2 || i == 3 || i == 6 || i == 7) ? boxMax.y : boxMin.y;
    float z = i >= 4 ? boxMax.z : boxMin.z;
    vec4 p = SNELL_MUL(viewFromObject, vec4(x, y, z, 1.0f));
    if (!SNELL_FINITE(p.z)) {
      return snellDepthRangeInvalid();
    }
    zNearest = max(zNearest, p.z);
    zFarthest = min(zFarthest, p.z);
  }
  if (!(zFarthest < 0.0f)) {
    return snellDepthRangeInvalid();
  }
  SnellDepthRange r;
  r.zNearest = min(zNearest, -SNELL_FLT_MIN);
  r.zFarthest = zFarthest;
  if (!(r.zFarthest < r.zNearest)) {
    r.zNearest = r.zNearest * (1.0f - SNELL_DEPTH_RANGE_MARGIN);
    r.zFarthest = r.zFarthest * (1.0f + SNELL_DEPTH_RANGE_MARGIN);
  }
  r.valid = true;
  return r;
}

#endif


/* 1 (default): snellIntersectOptions sets planeFarStart (the plane
   strategies' far start on closed surfaces); 0: the poster's first plane. */
#ifndef SNELL_PLANE_FAR_START
#  define SNELL_PLANE_FAR_START 1
#endif

struct SnellFarPlane {
  float t;
  vec3 position;
  bool valid;
  int fetches;
};

SNELL_FN SnellFarPlane snellPlaneFarStart(vec3 origin, vec3 dir, vec2 originUv, SNELL_TEX2D pyramidTex,
                                          SNELL_IN(SnellDepthSurface) s) {
  SnellFarPlane f;
  f.t = 0.0f;
  f.position = vec3(0.0f, 0.0f, 0.0f);
  f.valid = false;
  f.fetches = 0;
  if (!s.closed || !SNELL_FINITE(originUv.x) || !SNELL_FINITE(originUv.y)) {
    return f;
  }
  int top = snellTextureTopLod(pyramidTex);
  vec4 whole = SNELL_TEXEL_FETCH(pyramidTex, ivec2(0, 0), top);
  f.fetches = 1;
  if (!(whole.w > 0.0f) || !(whole.z > 0.0f) || !SNELL_FINITE(whole.z)) {
    return f;
  }
  vec3 facing = vec3(0.0f, 0.0f, 1.0f);
  SnellRayPlaneHit g = snellRayPlane(origin, dir, vec3(0.0f, 0.0f, -whole.z), facing);
  SnellScreenPoint gp = snellSurfaceViewToUv(s, g.position);
  if (!g.valid || !gp.valid) {
    return f;
  }
  vec2 size0 = vec2(SNELL_TEXTURE_SIZE(pyramidTex, 0));
  vec2 way = (gp.uv - originUv) * size0;
  float d = sqrt(dot(way, way));
  int level = 0;
  for (int k = 0; k < 31; ++k) {
    // !(<) also ends the loop for a NaN way, at level 0
    if (level >= top || !(float(1 << level) < d)) {
      break;
    }
    level += 1;
  }
  vec2 mid = clamp(0.5f * (gp.uv + originUv), vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
  ivec2 sizeL = SNELL_TEXTURE_SIZE(pyramidTex, level);
  ivec2 px = min(ivec2(mid * vec2(sizeL)), sizeL - ivec2(1, 1));
  vec4 under = SNELL_TEXEL_FETCH(pyramidTex, px, level);
  f.fetches = 2;
  if (!(under.w > 0.0f) || !(under.z > 0.0f) || !SNELL_FINITE(under.z)) {
    return f;
  }
  SnellRayPlaneHit h = snellRayPlane(origin, dir, vec3(0.0f, 0.0f, -under.z), facing);
  f.t = h.t;
  f.position = h.position;
  f.valid = h.valid;
  return f;
}

#endif
/*
description: Mayer & Assarsson's planar approximation, method 1 (normal-based):
  the depth and normal stored behind the ray origin define a plane; the ray is
  intersected with it, the intersection projected and the buffers sampled
  there; optionally the plane is rebuilt at that sample and the ray
  re-intersected, N times (step 5). Constant time for a fixed N.
use: SnellHit h = snellIntersectPlaneNormal(origin, dir, depthTex, normalTex, pyramidTex,
                                            surface, normalLod, SNELL_PLANE_ITERATIONS, true);
  origin     view-space ray start W (z < 0): front-face point (back-face buffer)
             or exit point (opaque scene buffer)
  dir        ray direction (any length)
  depthTex   the depth texture `surface` describes (read at level surface.lod)
  normalTex  view-space normals (xyz, any length, either orientation) matching
             depthTex texel for texel at level 0; it may be mipmapped and filtered
             (Mayer & Assarsson: "a more blurred mip level gives a more complete
             representation of the scene for drastic refraction effects")
  pyramidTex depthTex's min/max pyramid (intersect/depth_pyramid.glsl), read by
             the far start only (any texture when farStart is false)
  normalLod  the level normals are read at (SNELL_SAMPLE_LOD, the texture's filters)
  iterations refinement iterations, clamped to [0, SNELL_PLANE_MAX_ITERATIONS]
  farStart   true: on a closed surface (surface.closed, an object's back faces),
             plane 0's hit is the nearer of the poster's (below) and the far
             start's (intersect/plane_far_start.glsl: the farthest back face the
             pyramid holds under the ray's way); false: the poster's method
contract:
  - plane k (k = 0 .. N): uv_0 = projection of W, uv_k = projection of P_(k-1);
    B_k = snellSurfacePoint(depthTex, uv_k, surface) (texel centre point),
    n_k = xyz of SNELL_SAMPLE_LOD(normalTex, B_k.uv, normalLod) (the same texel
    centre); P_k = snellRayPlane(W, dir, B_k, n_k), or, when the ray does not
    meet that plane ahead of W and SNELL_PLANE_FACING_FALLBACK is 1 (default),
    P_k = snellRayPlane(W, dir, B_k, B_k): the plane through B_k facing the
    camera (normal along the line of sight through B_k), see plane_refine.glsl.
    With farStart and a valid far start F (snellPlaneFarStart) at k = 0,
    P_0 = F.position when the plane at B_0 is not met or meets the ray further
    than F (F.t < t); the facing fallback then applies only when neither is
    met; refinements are unchanged. The hit is
    snellPlaneHit(P_N): position P_N (on the ray), uv its projection, valid
    when the surface exists there. A refinement step that cannot build its plane
    (B_k empty or off screen, ray parallel) stops the refinement at P_(k-1).
    With SNELL_PLANE_HOLD (default 1), a final P whose projection lands on an
    empty texel stays valid on the last plane, uv = that plane's texel
    (plane_refine.glsl): rim rays of convex objects keep their bend instead of
    being dropped.
  - exact (up to float rounding) for a planar surface with exact normals, for
    every N >= 0 (farStart false or an open surface) or N >= 1 (with the far
    start: plane 0 may be the far plane, and the first refinement returns to
    the surface's plane): every other plane is the surface's plane.
  - fetches = 2 (N + 1) + 1 on success (a depth and a normal read per plane,
    one final depth read), plus the far start's (0-2, with farStart); on
    failure the reads issued so far (lookups at an off-screen uv included).
  - rays towards the camera are accepted: the plane is intersected wherever it
    lies ahead of W (t >= 0).
  - valid = false (snellHitMiss, finite): origin/dir NaN/Inf, |dir|^2 below 1e-30
    or overflowing, W at or behind the camera plane (fetches 0); B_k empty or off
    screen; for the first plane: n_k zero/NaN, the ray parallel to it or the
    plane behind W (snellRayPlane invalid), and with the fallback also the
    facing plane (a ray that does not go deeper than B_0), and no far start;
    P behind the camera or off
    screen; the final sample empty with SNELL_PLANE_HOLD 0.
source: C. Mayer, U. Assarsson, "Constant-Time Light Refraction Simulation",
  steps 1-5 and "Method 1: Normal-based"; plane intersection in
  optics/ray_plane.glsl; the far start is snell's (plane_far_start.glsl).
*/
#ifndef SNELL_INTERSECT_PLANE_NORMAL_GLSL
#define SNELL_INTERSECT_PLANE_NORMAL_GLSL











SNELL_FN SnellHit snellIntersectPlaneNormal(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_TEX2D normalTex,
                                            SNELL_TEX2D pyramidTex, SNELL_IN(SnellDepthSurface) s, float normalLod,
                                            int iterations, bool farStart) {
  float len2 = dot(dir, dir);
  if (!SNELL_FINITE(origin.x) || !SNELL_FINITE(origin.y) || !SNELL_FINITE(origin.z) ||
      !SNELL_FINITE(len2) || !(len2 >= 1e-30f)) {
    return snellHitMiss(0);
  }
  SnellScreenPoint w = snellSurfaceViewToUv(s, origin);
  if (!w.valid) {
    return snellHitMiss(0);
  }
  int n = clamp(iterations, 0, SNELL_PLANE_MAX_ITERATIONS);
  // Plane 0 (W's texel, the far start, the facing fallback), then the
  // refinements: the loop holds only what every refinement does. With plane 0
  // inside it, llvmpipe spent 58% more instructions on the normal plane (1 it.)
  // with the far start and 10% more without (benchmarks/kernels/gpu_kernel_table.sh).
  SnellSurfacePoint b = snellSurfacePoint(depthTex, w.uv, s);
  int fetches = 1;
  if (!b.valid) {
    return snellHitMiss(fetches);
  }
  vec4 nt = SNELL_SAMPLE_LOD(normalTex, b.uv, normalLod);
  fetches += 1;
  SnellRayPlaneHit ph = snellRayPlane(origin, dir, b.position, vec3(nt.x, nt.y, nt.z));
  if (farStart) {
    SnellFarPlane f = snellPlaneFarStart(origin, dir, w.uv, pyramidTex, s);
    fetches += f.fetches;
    if (f.valid && (!ph.valid || f.t < ph.t)) {
      ph.t = f.t;
      ph.position = f.position;
      ph.valid = true;
    }
  }
#if SNELL_PLANE_FACING_FALLBACK
  if (!ph.valid) {
    ph = snellRayPlane(origin, dir, b.position, b.position);
  }
#endif
  if (!ph.valid) {
    return snellHitMiss(fetches);
  }
  vec3 p = ph.position;
  vec2 planeUv = b.uv;
  for (int k = 1; n > 0 && k <= SNELL_PLANE_MAX_ITERATIONS; ++k) {
    SnellScreenPoint sp = snellSurfaceViewToUv(s, p);
    if (!sp.valid) {
      break;  // keep P_(k-1) on plane k-1
    }
    SnellSurfacePoint bk = snellSurfacePoint(depthTex, sp.uv, s);
    fetches += 1;
    if (!bk.valid) {
      break;
    }
    vec4 nk = SNELL_SAMPLE_LOD(normalTex, bk.uv, normalLod);
    fetches += 1;
    SnellRayPlaneHit hk = snellRayPlane(origin, dir, bk.position, vec3(nk.x, nk.y, nk.z));
#if SNELL_PLANE_FACING_FALLBACK
    if (!hk.valid) {
      hk = snellRayPlane(origin, dir, bk.position, bk.position);
    }
#endif
    if (!hk.valid) {
      break;
    }
    p = hk.position;
    planeUv = bk.uv;
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (k >= n) {
      break;
    }
  }
  return snellPlaneHit(p, planeUv, depthTex, s, fetches);
}

#endif
/*
description: Mayer & Assarsson's planar approximation, method 2 (depth-based):
  no normal buffer; three surface points define the plane: B directly behind
  the ray's reference point, the surface seen at the point d = |B - W| further
  along the ray, and a neighbouring texel (the "screen-space derivative" of B,
  taken as a texel offset so the method works outside fragment shaders too),
  all read at the mip level whose texels span the region the points cover.
  Optional refinement as in plane_normal.glsl.
use: SnellHit h = snellIntersectPlaneDepth(origin, dir, depthMips, surface, maxLod,
                                           SNELL_PLANE_ITERATIONS, true);
  origin, dir  view-space ray (origin z < 0; dir any length)
  depthMips    a depth texture whose level L holds, in .x, a depth value
               representative of each 2^L x 2^L block, emptyDepth where the block
               is empty: the depth pyramid of depth_pyramid.glsl (.x = mean depth
               of the valid texels; snellBuildDepthPyramid in C++), or a plain
               one-level depth texture with maxLod = surface.lod
  surface      its camera and conventions; surface.lod is the finest level read
  maxLod       the coarsest level that exists (and may be read)
  iterations   refinement iterations, clamped to [0, SNELL_PLANE_MAX_ITERATIONS]
  farStart     true: on a closed surface (surface.closed), once B0 was read, the
               first plane's hit is the nearer of the one below and the far
               start's (intersect/plane_far_start.glsl; depthMips must then be
               the min/max pyramid: it reads its .z and .w); false: the poster's
options:
  SNELL_PLANE_DEPTH_MAX_SPAN_LOD  the level chosen is at most surface.lod + this (6)
contract (one plane, built around a reference point Q on the ray: Q = W for the
  first plane, Q = P_(k-1) when refining):
  - uvQ = projection of Q; B0 = snellSurfacePoint(depthMips, uvQ) at level
    surface.lod (1 fetch); d = |B0 - Q|; Q2 = Q + d dir/|dir|, or Q - d dir/|dir|
    when Q is deeper than B0 (Q.z < B0.z: the ray is past the surface);
    uv2 = projection of Q2 (uvQ when Q2 does not project).
  - span = largest |uv2 - uvQ| component in texels of level surface.lod; level L =
    surface.lod + ceil(log2(span)) (0 for span <= 1), clamped to
    [surface.lod, min(maxLod, surface.lod + SNELL_PLANE_DEPTH_MAX_SPAN_LOD)].
  - texels at level L: pB containing uvQ, pC containing uv2 (clamped to the
    level); a = the unit step along the larger component of pC - pB (+x when
    pC == pB, and pC is then pB + a), b = the perpendicular unit step (+y or +x).
    B = texel-centre point of pB (B0 reused when L == surface.lod, else 1
    fetch); C = point of pC, or of pB - a when pC is empty (1-2 fetches); D =
    point of pB + b, or of pB - b when empty (1-2 fetches). The three texels are
    never collinear in the image, so the plane is defined whenever they are valid.
  - P = snellRayPlane(W, dir, B, cross(C - B, D - B)). With
    SNELL_PLANE_FACING_FALLBACK 1 (default), when B was read but C or D is
    empty, the three points are degenerate, or the ray does not meet their plane
    ahead of W, the plane through B facing the camera is used instead:
    P = snellRayPlane(W, dir, B, B) (plane_refine.glsl). With farStart and a
    valid far start F for the first plane (B0 read), P_0 = F.position when
    the plane of B, C, D is not met or meets the ray further than F (before the
    facing fallback, as in plane_normal.glsl). After N refinements the
    hit is snellHitOnSurface(P_N) (position on the ray, valid when the surface
    exists at its projection).
  - exact (up to float rounding) on a planar surface (with the far start:
    for N >= 1, as in plane_normal.glsl) at every level whose
    texels hold the depth at their centre: level 0 always; the pyramid's mean
    levels for power-of-two sizes and fully covered blocks (window depth is
    affine in screen space over a plane, so a block mean is its centre value).
  - fetches per plane 3..6 (1 for B0, 1 for B when L > surface.lod, 1-2 each for
    C and D), plus the far start's 0-2 for the first plane, plus 1 final
    lookup; on failure the reads issued so far.
  - valid = false (snellHitMiss, finite): origin/dir NaN/Inf, |dir|^2 below 1e-30
    or overflowing, W at or behind the camera plane (fetches 0); B0 or B empty or
    off screen; C or D empty after the fallback, a degenerate plane, the ray
    parallel to it or the plane behind W (with SNELL_PLANE_FACING_FALLBACK 0,
    or when the facing plane is not met either); P behind the camera; the final lookup
    empty or off screen. Rays towards the camera are accepted as in
    plane_normal.glsl.
source: C. Mayer, U. Assarsson, "Constant-Time Light Refraction Simulation",
  "Method 2: Depth-based" ("sample all three points using the mipmap level that
  encompasses the entire region these three points span") and step 5; the
  far start is snell's (plane_far_start.glsl).
*/
#ifndef SNELL_INTERSECT_PLANE_DEPTH_GLSL
#define SNELL_INTERSECT_PLANE_DEPTH_GLSL












#ifndef SNELL_PLANE_DEPTH_MAX_SPAN_LOD
#  define SNELL_PLANE_DEPTH_MAX_SPAN_LOD 6
#endif

/* One plane around the reference point q (see the contract); valid false when
   it cannot be built. fetches: the reads spent. */
struct SnellDepthPlane {
  vec2 uv;        // where B was read
  vec3 position;  // B once it was read (also when C or D was not), else 0
  vec3 normal;    // cross(C - B, D - B), not normalized; 0 unless valid
  bool valid;
  int fetches;
};

SNELL_FN SnellDepthPlane snellDepthPlaneAt(vec3 q, vec3 dirN, SNELL_TEX2D depthMips, SNELL_IN(SnellDepthSurface) s, int maxLod) {
  SnellDepthPlane r;
  r.uv = vec2(0.0f, 0.0f);
  r.position = vec3(0.0f, 0.0f, 0.0f);
  r.normal = vec3(0.0f, 0.0f, 0.0f);
  r.valid = false;
  r.fetches = 0;
  SnellScreenPoint sq = snellSurfaceViewToUv(s, q);
  if (!sq.valid) {
    return r;
  }
  SnellSurfacePoint b0 = snellSurfacePoint(depthMips, sq.uv, s);
  r.fetches = 1;
  if (!b0.valid) {
    return r;
  }
  r.uv = b0.uv;
  vec3 toB = b0.position - q;
  float d = sqrt(dot(toB, toB));
  vec3 q2 = q.z < b0.position.z ? q - d * dirN : q + d * dirN;
  SnellScreenPoint s2 = snellSurfaceViewToUv(s, q2);
  vec2 uv2 = s2.valid ? s2.uv : sq.uv;
  ivec2 size0 = SNELL_TEXTURE_SIZE(depthMips, s.lod);
  float span = max(abs(uv2.x - sq.uv.x) * float(size0.x), abs(uv2.y - sq.uv.y) * float(size0.y));
  int top = min(maxLod, s.lod + SNELL_PLANE_DEPTH_MAX_SPAN_LOD);
  int level = s.lod;
  if (span > 1.0f && SNELL_FINITE(span)) {
    level = s.lod + int(ceil(log2(span)));
  }
  level = max(s.lod, min(level, top));
  SnellDepthSurface sl = s;
  sl.lod = level;
  ivec2 size = SNELL_TEXTURE_SIZE(depthMips, level);
  ivec2 pb = snellUvToPixel(sq.uv, size);
  ivec2 pc = snellUvToPixel(uv2, size);
  ivec2 a = ivec2(1, 0);
  ivec2 dpc = pc - pb;
  if (abs(dpc.y) > abs(dpc.x)) {
    a = ivec2(0, dpc.y > 0 ? 1 : -1);
  } else if (dpc.x != 0) {
    a = ivec2(dpc.x > 0 ? 1 : -1, 0);
  }
  if (dpc.x == 0 && dpc.y == 0) {
    pc = pb + a;
  }
  ivec2 b = a.x != 0 ? ivec2(0, 1) : ivec2(1, 0);
  vec3 pB = b0.position;
  if (level != s.lod) {
    SnellSurfacePoint bl = snellSurfacePoint(depthMips, snellPixelToUv(pb, size), sl);
    r.fetches += 1;
    if (!bl.valid) {
      return r;
    }
    pB = bl.position;
  }
  r.position = pB;
  // C (at pc, else on the other side of B) and D (across the way, else its opposite) through one read in
  // the code, as WebGL's compilers inline every call: t = 0 C at pc, 1 C at pb - a (pc empty), 2 D at
  // pb + b, 3 D at pb - b (pb + b empty). Both candidates of a point empty: no plane.
  vec3 pC = vec3(0.0f, 0.0f, 0.0f);
  vec3 pD = vec3(0.0f, 0.0f, 0.0f);
  int found = 0;
  for (int t = 0; t < 4; ++t) {
    if (t == 1 && found == 1) {
      continue;
    }
    if (t == 3 && found == 2) {
      break;
    }
    ivec2 px = pc;
    if (t == 1) {
      px = pb - a;
    } else if (t == 2) {
      px = pb + b;
    } else if (t == 3) {
      px = pb - b;
    }
    SnellSurfacePoint n = snellSurfacePoint(depthMips, snellPixelToUv(px, size), sl);
    r.fetches += 1;
    if (n.valid) {
      if (found == 0) {
        pC = n.position;
      } else {
        pD = n.position;
      }
      found += 1;
    } else if (t == 1 || t == 3) {
      return r;
    }
  }
  r.normal = cross(pC - pB, pD - pB);
  r.valid = true;
  return r;
}

SNELL_FN SnellHit snellIntersectPlaneDepth(vec3 origin, vec3 dir, SNELL_TEX2D depthMips, SNELL_IN(SnellDepthSurface) s,
                                           int maxLod, int iterations, bool farStart) {
  float len2 = dot(dir, dir);
  if (!SNELL_FINITE(origin.x) || !SNELL_FINITE(origin.y) || !SNELL_FINITE(origin.z) ||
      !SNELL_FINITE(len2) || !(len2 >= 1e-30f)) {
    return snellHitMiss(0);
  }
  SnellScreenPoint w = snellSurfaceViewToUv(s, origin);
  if (!w.valid) {
    return snellHitMiss(0);
  }
  vec3 dirN = dir / sqrt(len2);
  int n = clamp(iterations, 0, SNELL_PLANE_MAX_ITERATIONS);
  // Plane 0 (at W, with the far start and the facing fallback), then the refinements, in one loop: the
  // plane's construction (up to six depth reads) appears once in the code, which halves what WebGL's
  // compilers inline and compile.
  vec3 p = origin;
  vec2 planeUv = vec2(0.0f, 0.0f);
  int fetches = 0;
  for (int k = 0; k <= SNELL_PLANE_MAX_ITERATIONS; ++k) {
    SnellDepthPlane plk = snellDepthPlaneAt(p, dirN, depthMips, s, maxLod);
    fetches += plk.fetches;
    // An unbuilt plane has a zero normal, so the ray misses it; its facing plane exists
    // only when B was read (position 0, the camera, gives no plane either). B read has
    // z = viewZ <= -zNear <= -FLT_MIN, which no runtime flushes; its squared length
    // underflows to 0 for a surface within 2^-75 of the eye, which zNear allows.
    SnellRayPlaneHit hk = snellRayPlane(origin, dir, plk.position, plk.normal);
    if (k == 0 && farStart && plk.position.z < 0.0f) {
      SnellFarPlane f = snellPlaneFarStart(origin, dir, w.uv, depthMips, s);
      fetches += f.fetches;
      if (f.valid && (!hk.valid || f.t < hk.t)) {
        hk.t = f.t;
        hk.position = f.position;
        hk.valid = true;
      }
    }
#if SNELL_PLANE_FACING_FALLBACK
    if (!hk.valid) {
      hk = snellRayPlane(origin, dir, plk.position, plk.position);
    }
#endif
    if (!hk.valid) {
      if (k == 0) {
        return snellHitMiss(fetches);
      }
      break;  // keep P_(k-1) on plane k-1
    }
    p = hk.position;
    planeUv = plk.uv;
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (k >= n) {
      break;
    }
  }
  return snellPlaneHit(p, planeUv, depthMips, s, fetches);
}

#endif
/*
description: the depth min/max pyramid (Oliveira & Brauwers 2007, 2nd pass): a
  parallel reduction of a depth buffer in which every texel of level L+1 holds,
  for the block of level-0 texels below it, the nearest and farthest view
  distance (the search range Zmin, Zmax of their sec. 3.2), the mean depth value
  (a depth mip the plane strategies and any strategy can read through
  snellSampleSurface with surface.lod = L) and the covered fraction. Empty
  (invalid) texels are excluded; an all-empty block stays empty.
use: level 0, one pass over the depth buffer (fragment: px = ivec2(gl_FragCoord.xy)):
       out = snellDepthPyramidBase(SNELL_TEXEL_FETCH(depthTex, px, 0).x, surface);
     level L+1 from level L (fragment or compute pass, px the output texel):
       out = snellDepthMinMaxReduce(pyramidTex, L, px, surface.emptyDepth);
     C++: snell::snellBuildDepthPyramid(depthTexture, surface) (include/snell/depth_pyramid.hpp)
     zMin/zMax of the whole buffer: the top (1x1) level's y and z.
  A full GL pass is glsl/passes/depth_pyramid.frag (driven level by level by
  snell::gpu::DepthPyramidPass).
texel layout (RGBA32F):
  x  mean depth value (window depth, the buffer's own convention) of the valid
     children; emptyDepth when none is valid
  y  nearest view distance (min of -z_view, > 0) of the valid level-0 texels below
  z  farthest view distance (max), >= y
  w  coverage: the mean of the children's coverage (level 0: 1 valid, 0 empty);
     > 0 exactly when some level-0 texel below is valid
  Distances rather than depth values for y and z: they are what the searches
  need (view z = -distance), and "nearest" then does not depend on the
  convention (reversed Z stores the nearest point as the LARGEST depth value).
contract:
  - snellDepthPyramidBase: invalid when depthValue == surface.emptyDepth, NaN,
    infinite, or does not linearize (snellSurfaceLinearDepth <= 0: bad zNear/zFar/convention):
    vec4(emptyDepth, 0, 0, 0). Otherwise vec4(depthValue, v, v, 1), v =
    snellSurfaceLinearDepth(surface, depthValue) > 0 (snellLinearizeDepth's value).
  - snellDepthMinMaxReduce: level L has size (W, H) = SNELL_TEXTURE_SIZE(tex, L);
    level L+1 has (max(1, W/2), max(1, H/2)), and px must lie in it. The children
    are columns 2px.x .. 2px.x+1 (and 2px.x+2 for the last column when W is odd:
    GL's floor sizes drop no texel), column 0 alone when W == 1; rows likewise:
    2x2 texels, 3 x 2 / 2 x 3 / 3 x 3 at odd edges (fetches = their number, 1..9).
    A child is valid when its w > 0. Result: x = (sum of valid children's x) /
    (their count), y = min, z = max of their y / z, w = (sum of all children's w)
    / (number of children); with no valid child vec4(emptyDepth, 0, 0, 0).
  - the x channel is an unweighted mean of child means: equal to the mean over
    all level-0 texels below for full blocks of power-of-two sizes; for a planar
    surface it is the depth at the block centre (window depth is affine in
    screen space over a plane).
  - the sums run in a fixed order with no products, so the GPU pass and the C++
    build agree bit for bit (the parity test compares every level exactly).
source: M. M. Oliveira, M. Brauwers, "Real-Time Refraction Through Deformable
  Objects", I3D 2007, sec. 3 (2nd pass: "the minimum and maximum depth values
  from each group of four elements"), after M. Harris, "Mapping Computational
  Concepts to GPUs" (parallel reduction), GPU Gems 2 ch. 31 (2005).
*/
#ifndef SNELL_INTERSECT_DEPTH_PYRAMID_GLSL
#define SNELL_INTERSECT_DEPTH_PYRAMID_GLSL





SNELL_FN vec4 snellDepthPyramidBase(float depthValue, SNELL_IN(SnellDepthSurface) s) {
  vec4 empty = vec4(s.emptyDepth, 0.0f, 0.0f, 0.0f);
  if (!SNELL_FINITE(depthValue) || depthValue == s.emptyDepth) {
    return empty;
  }
  float v = snellSurfaceLinearDepth(s, depthValue);
  if (!(v > 0.0f)) {
    return empty;
  }
  return vec4(depthValue, v, v, 1.0f);
}

SNELL_FN vec4 snellDepthMinMaxReduce(SNELL_TEX2D pyramidTex, int lod, ivec2 px, float emptyDepth) {
  ivec2 size = SNELL_TEXTURE_SIZE(pyramidTex, lod);
  int lastX = max(1, size.x / 2) - 1;
  int lastY = max(1, size.y / 2) - 1;
  int countX = size.x == 1 ? 1 : (px.x == lastX ? size.x - 2 * px.x : 2);
  int countY = size.y == 1 ? 1 : (px.y == lastY ? size.y - 2 * px.y : 2);
  float sum = 0.0f;
  float coverage = 0.0f;
  float nearest = 0.0f;
  float farthest = 0.0f;
  int valid = 0;
  int children = 0;
  for (int dy = 0; dy < 3; ++dy) {
    for (int dx = 0; dx < 3; ++dx) {
      if (dx < countX && dy < countY) {
        vec4 t = SNELL_TEXEL_FETCH(pyramidTex, ivec2(2 * px.x + dx, 2 * px.y + dy), lod);
        children += 1;
        coverage += t.w;
        if (t.w > 0.0f) {
          sum += t.x;
          nearest = valid == 0 ? t.y : min(nearest, t.y);
          farthest = valid == 0 ? t.z : max(farthest, t.z);
          valid += 1;
        }
      }
    }
  }
  if (valid == 0) {
    return vec4(emptyDepth, 0.0f, 0.0f, 0.0f);
  }
  return vec4(sum / float(valid), nearest, farthest, coverage / float(max(children, 1)));
}

#endif

/*
description: the ray segment the texture-space searches walk (conservative
  binary search, binary search, linear+binary search): the part of a view-space
  ray between two constant-z planes that bound the surface in depth, in the
  perspective texture-space parameterization of Oliveira & Brauwers 2007.
use: SnellTexRay r = snellSearchSegment(origin, dir, zNearest, zFarthest, surface.clipFromView);
     // beta in [0,1] along S-E (eq. 5): z = r.s.z + beta (r.e.z - r.s.z), uv = snellTexRayUv(r, z)
  origin     view-space ray origin (P1: the front-face hit for the back-face
             buffer, the back-face exit point for the opaque scene buffer)
  dir        ray direction (need not be normalized)
  zNearest   view-space z (< 0) of the nearest surface point, the paper's Zmin as
             a z value (the LARGER, less negative one); zFarthest: of the farthest
             (the paper's Zmax, more negative). Where they come from is the
             caller's business, both are just two numbers: the top level of the
             depth min/max pyramid (exact for the buffer), or the object's
             bounding box / bounding sphere transformed to view space (looser,
             so more steps for the same precision, never wrong).
contract:
  - the segment starts at S on the plane z = min(zNearest, origin.z): where the
    ray meets zNearest, or at the origin itself when the origin is already
    deeper than zNearest (a search never runs backwards along the ray); it ends
    at E on the plane z = zFarthest. k1, k2, ts, dt as snellTexRaySetup.
  - valid = false (every field 0, finite) when: any input is NaN or Inf (matrix
    included, but for its third row, which snellTexRaySetup does not read);
    dir.z >= 0 or denormal (the ray points towards the camera or runs parallel
    to the image plane: it never reaches deeper planes); zNearest <=
    zFarthest (Zmin == Zmax, swapped or empty range); the origin is at or beyond
    zFarthest (nothing left to search); and every case snellTexRaySetup
    rejects (a plane at or behind the eye, S or E not projectable, overflow).
source: Oliveira & Brauwers 2007, sec. 3.2.1, eqs. 3-4 (S and E), Figure 5
  (Zmin, Zmax); camera/tex_ray.glsl for eqs. 5-10.
*/
#ifndef SNELL_INTERSECT_SEARCH_SEGMENT_GLSL
#define SNELL_INTERSECT_SEARCH_SEGMENT_GLSL


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

SNELL_FN_INLINE SnellTexRay snellSearchSegment(vec3 origin, vec3 dir, float zNearest, float zFarthest, mat4 clipFromView) {
  SnellTexRay bad;
  bad.s = vec3(0.0f, 0.0f, 0.0f);
  bad.e = vec3(0.0f, 0.0f, 0.0f);
  bad.k1 = 0.0f;
  bad.k2 = 0.0f;
  bad.ts = vec2(0.0f, 0.0f);
  bad.dt = vec2(0.0f, 0.0f);
  bad.valid = false;
  if (!SNELL_FINITE(origin.z) || !SNELL_FINITE(dir.z) || !SNELL_FINITE(zNearest) ||
      !SNELL_FINITE(zFarthest)) {
    return bad;
  }
  if (!(dir.z <= -SNELL_FLT_MIN) || !(zNearest > zFarthest) || !(origin.z > zFarthest)) {
    return bad;
  }
  float zStart = origin.z < zNearest ? origin.z : zNearest;
  return snellTexRaySetup(origin, dir, zStart, zFarthest, clipFromView);
}

#endif
/*
description: conservative binary search (CBS): intersect a view-space ray with
  a depth-buffer surface by a binary search in texture space that only ever
  advances along the ray, and only onto texels that hold a surface, so the
  result never maps to an empty texel (no undefined normal at the silhouette).
use: SnellHit h = snellConservativeBinarySearch(origin, dir, depthTex, surface, zNearest, zFarthest);
     SnellHit h = snellConservativeBinarySearch(origin, dir, depthTex, surface, zNearest, zFarthest, steps);
     if (h.valid) { vec4 n2 = SNELL_TEXEL_FETCH(normalTex, snellUvToPixel(h.uv, size), 0); ... }
  origin, dir          view-space ray (P1 and T1 in the paper; dir need not be normalized)
  depthTex, surface    the depth buffer and how to read it (depth_surface.glsl);
                       back-face buffer or opaque scene buffer alike
  zNearest, zFarthest  the depth range to search, as view-space z (< 0): see
                       search_segment.glsl (min/max pyramid top level, or a
                       bounding volume; two numbers either way)
  steps                binary steps c (each one texel fetch)
options:
  SNELL_CBS_STEPS      default steps (5, the paper's choice: beta error <= 3.125%)
  SNELL_CBS_MAX_STEPS  compile-time loop bound (24); steps is clamped to
                       [0, SNELL_CBS_MAX_STEPS] (beyond ~24 halvings beta is
                       below float resolution anyway)
contract:
  - the segment S-E is snellSearchSegment(origin, dir, zNearest, zFarthest,
    surface.clipFromView); beta in [0,1] along it (eq. 5). Starting at beta = 0,
    step i (dBeta = 0.5^i) tests beta + dBeta: z = S.z + b (E.z - S.z), uv =
    snellTexRayUv (eqs. 9-10), one snellSampleSurface fetch; it advances (beta
    += dBeta) only when the texel is valid and the point is strictly in front of
    the surface (z > viewZ, Algorithm 2's -P.z < storedDepth); an empty or
    off-screen texel never lets it advance.
  - valid means: the returned point maps to a valid (non-empty, on-screen)
    texel. After at least one advance it is the last point that advanced (its uv
    is the uv that was fetched, so the texel is exactly the one tested). When
    no step advanced, the start S itself is tested with one more fetch (counted)
    and returned if its texel is valid: then the true crossing, if the ray
    crosses the surface once on S-E, has beta < 0.5^c (or the ray starts behind
    the surface).
  - precision: if the ray crosses the surface once on S-E (in front of it at S,
    behind it, or over an empty texel, at E), the returned beta is at most
    0.5^c before the crossing: beta_error = 0.5^c - 0.5^k <= 0.5^c for a
    crossing that needs k > c steps (the paper, sec. 3.3). After an advance the
    returned point is strictly in front of the surface at its texel (never past
    it); S is returned whatever its depth order (the ray may start behind).
  - a ray that stays in front of the surface up to E returns a point near E
    (the paper's behaviour: the search range is assumed to contain the hit).
  - position = S + beta (E - S), uv its texture coordinate; fetches = steps
    performed (+1 for the start test).
  - valid = false, with snellHitMiss numbers (finite), when the segment is
    invalid (dir.z >= 0: rays towards the camera; zNearest <= zFarthest
    including Zmin == Zmax; NaN/Inf inputs, but for the matrix's third row,
    which the segment does not read; planes at or behind the eye): 0
    fetches; or when nothing advanced and S maps to an empty or off-screen
    texel (rays leaving the screen, all-empty buffers).
source: M. M. Oliveira, M. Brauwers, "Real-Time Refraction Through Deformable
  Objects", I3D 2007, sec. 3.3, Algorithm 2, the error bound
  beta_error = 0.5^c - 0.5^k; eqs. 3-10 for the parameterization.
*/
#ifndef SNELL_INTERSECT_CONSERVATIVE_BINARY_SEARCH_GLSL
#define SNELL_INTERSECT_CONSERVATIVE_BINARY_SEARCH_GLSL






#ifndef SNELL_CBS_STEPS
#  define SNELL_CBS_STEPS 5
#endif
#ifndef SNELL_CBS_MAX_STEPS
#  define SNELL_CBS_MAX_STEPS 24
#endif

/* Oliveira & Brauwers 2007, Algorithm 2 */
SNELL_FN SnellHit snellConservativeBinarySearch(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) surface,
                                                float zNearest, float zFarthest, int steps) {
  SnellTexRay r = snellSearchSegment(origin, dir, zNearest, zFarthest, surface.clipFromView);
  if (!r.valid) {
    return snellHitMiss(0);
  }
  int n = clamp(steps, 0, SNELL_CBS_MAX_STEPS);
  float dz = r.e.z - r.s.z;
  // snellTexRayUv with its per-step guards left out, the same results: every
  // step's z lies between r.s.z and r.e.z (both <= -SNELL_FLT_MIN), so alpha
  // is in [0, 1] up to rounding (never NaN, no clamp needed) and uv lies
  // between the segment's finite ends; its k2 == 0 case (k2 underflowed)
  // gives alpha 0 through k12 = 0; the product k1 k2 is taken once.
  float k12 = r.k2 == 0.0f ? 0.0f : r.k1 * r.k2;
  float beta = 0.0f;
  float dBeta = 1.0f;
  float zHit = r.s.z;
  vec2 uvHit = r.ts;
  bool advanced = false;
  int fetches = 0;
  for (int i = 0; n > 0 && i < SNELL_CBS_MAX_STEPS; ++i) {
    dBeta = dBeta * 0.5f;
    float b = beta + dBeta;
    float z = r.s.z + b * dz;
    vec2 uv = r.ts + (((r.s.z - z) / z) * k12) * r.dt;
    SnellSurfaceSample x = snellSampleSurface(depthTex, uv, surface);
    fetches = fetches + 1;
    if (x.valid && z > x.viewZ) {
      beta = b;
      zHit = z;
      uvHit = uv;
      advanced = true;
    }
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (i + 1 >= n) {
      break;
    }
  }
  if (!advanced) {
    SnellSurfaceSample x0 = snellSampleSurface(depthTex, uvHit, surface);
    fetches = fetches + 1;
    if (!x0.valid) {
      return snellHitMiss(fetches);
    }
  }
  SnellHit h;
  h.uv = uvHit;
  h.position = vec3(r.s.x + beta * (r.e.x - r.s.x), r.s.y + beta * (r.e.y - r.s.y), zHit);
  h.valid = true;
  h.fetches = fetches;
  return h;
}

SNELL_FN SnellHit snellConservativeBinarySearch(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) surface,
                                                float zNearest, float zFarthest) {
  return snellConservativeBinarySearch(origin, dir, depthTex, surface, zNearest, zFarthest, SNELL_CBS_STEPS);
}

#endif
/*
description: plain binary search of a view-space ray against a depth-buffer
  surface, in texture space along S-E (Policarpo et al. 2005's refinement, with
  Oliveira & Brauwers' perspective parameterization). It may end on an empty
  texel: the failure conservative_binary_search.glsl exists to avoid. Kept as a
  baseline so tests and the lab can show it.
use: SnellHit h = snellBinarySearch(origin, dir, depthTex, surface, zNearest, zFarthest);
     SnellHit h = snellBinarySearch(origin, dir, depthTex, surface, zNearest, zFarthest, steps);
     SnellHit h = snellBisectTexRay(r, depthTex, surface, lo, hi, steps, hitSoFar);
  arguments as snellConservativeBinarySearch; steps = binary steps (one fetch each)
options:
  SNELL_BINARY_SEARCH_STEPS      default steps (5)
  SNELL_BINARY_SEARCH_MAX_STEPS  compile-time loop bound (24); steps is clamped
                                 to [0, SNELL_BINARY_SEARCH_MAX_STEPS]
contract:
  - segment S-E and beta as snellConservativeBinarySearch. Bracket [lo, hi] =
    [0, 1]; each step tests mid = (lo + hi) / 2 (one fetch): a valid texel with
    the point strictly in front of the surface (z > viewZ) moves lo to mid,
    anything else (behind the surface, or an empty / off-screen texel, which the
    paper's depth-0 storage makes look like "behind") moves hi to mid.
  - the result is the last point tested (Figure 6's point 4), uv its texture
    coordinate, position S + beta (E - S); steps = 0 tests S itself (one fetch).
  - valid = whether that last texel was valid (non-empty, on screen). When it
    is not, uv and position still report where the search ended (finite), so
    the failure can be seen and counted: that is this function's point.
  - precision: for a ray crossing the surface once on S-E, |beta - beta*| <=
    0.5^c (the last midpoint is an end of the final bracket, of width 0.5^c).
  - valid = false with snellHitMiss numbers and 0 fetches when the segment is
    invalid (rays towards the camera, Zmin == Zmax, NaN: see search_segment.glsl).
  - snellBisectTexRay(r, depthTex, surface, lo, hi, steps, h): the loop itself,
    for a valid segment r (snellSearchSegment) and a bracket [lo, hi] in beta,
    each clamped to [0, 1]: clamp(steps, 0, SNELL_BINARY_SEARCH_MAX_STEPS)
    steps of the rule above; after each, h = the point tested (uv, position,
    valid as above) with h.fetches + 1. With 0 steps, or a NaN lo or hi, h is
    returned as given.
source: F. Policarpo, M. M. Oliveira, J. Comba, "Real-Time Relief Mapping on
  Arbitrary Polygonal Surfaces", I3D 2005 (binary search); Oliveira & Brauwers
  2007, sec. 3.3 and Figure 6 (why it can end on an invalid texel), eqs. 3-10.
*/
#ifndef SNELL_INTERSECT_BINARY_SEARCH_GLSL
#define SNELL_INTERSECT_BINARY_SEARCH_GLSL






#ifndef SNELL_BINARY_SEARCH_STEPS
#  define SNELL_BINARY_SEARCH_STEPS 5
#endif
#ifndef SNELL_BINARY_SEARCH_MAX_STEPS
#  define SNELL_BINARY_SEARCH_MAX_STEPS 24
#endif

/* The bisection loop of Policarpo et al. 2005, shared by snellBinarySearch and
   the refinement of snellLinearBinarySearch (see the contract). */
SNELL_FN SnellHit snellBisectTexRay(SnellTexRay r, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) surface, float lo,
                                    float hi, int steps, SnellHit h) {
  if (isnan(lo) || isnan(hi)) {
    return h;
  }
  // Outside [0, 1] the midpoints would extrapolate past S or E.
  lo = clamp(lo, 0.0f, 1.0f);
  hi = clamp(hi, 0.0f, 1.0f);
  int n = clamp(steps, 0, SNELL_BINARY_SEARCH_MAX_STEPS);
  float dz = r.e.z - r.s.z;
  for (int i = 0; n > 0 && i < SNELL_BINARY_SEARCH_MAX_STEPS; ++i) {
    float beta = 0.5f * (lo + hi);
    float z = r.s.z + beta * dz;
    vec2 uv = snellTexRayUv(r, z);
    SnellSurfaceSample x = snellSampleSurface(depthTex, uv, surface);
    h.uv = uv;
    h.position = vec3(r.s.x + beta * (r.e.x - r.s.x), r.s.y + beta * (r.e.y - r.s.y), z);
    h.valid = x.valid;
    h.fetches = h.fetches + 1;
    if (x.valid && z > x.viewZ) {
      lo = beta;
    } else {
      hi = beta;
    }
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (i + 1 >= n) {
      break;
    }
  }
  return h;
}

/* Policarpo et al. 2005 binary search on Oliveira & Brauwers 2007, eqs. 5-10 */
SNELL_FN SnellHit snellBinarySearch(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) surface,
                                    float zNearest, float zFarthest, int steps) {
  SnellTexRay r = snellSearchSegment(origin, dir, zNearest, zFarthest, surface.clipFromView);
  if (!r.valid) {
    return snellHitMiss(0);
  }
  SnellHit h;
  h.uv = r.ts;
  h.position = r.s;
  h.valid = false;
  h.fetches = 0;
  if (steps <= 0) {
    h.valid = snellSampleSurface(depthTex, r.ts, surface).valid;
    h.fetches = 1;
    return h;
  }
  return snellBisectTexRay(r, depthTex, surface, 0.0f, 1.0f, steps, h);
}

SNELL_FN SnellHit snellBinarySearch(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) surface,
                                    float zNearest, float zFarthest) {
  return snellBinarySearch(origin, dir, depthTex, surface, zNearest, zFarthest, SNELL_BINARY_SEARCH_STEPS);
}

#endif
/*
description: linear-then-binary search (relief mapping) of a view-space ray
  against a depth-buffer surface, in texture space along S-E: equal steps in
  beta until the first sample that is not in front of the surface, then a plain
  binary search inside that step. Finds thin structures the pure binary searches
  skip, at the cost of the linear steps; like snellBinarySearch it may end on an
  empty texel.
use: SnellHit h = snellLinearBinarySearch(origin, dir, depthTex, surface, zNearest, zFarthest);
     SnellHit h = snellLinearBinarySearch(origin, dir, depthTex, surface, zNearest, zFarthest,
                                          linearSteps, binarySteps);
  arguments as snellConservativeBinarySearch
  linearSteps   number of equal beta steps (1/linearSteps each, one fetch each)
  binarySteps   binary steps inside the bracketing step (one fetch each)
options:
  SNELL_LINEAR_SEARCH_STEPS      default linearSteps (10, relief mapping's usual)
  SNELL_LINEAR_SEARCH_MAX_STEPS  compile-time bound (256); linearSteps is
                                 clamped to [1, SNELL_LINEAR_SEARCH_MAX_STEPS]
  SNELL_BINARY_SEARCH_STEPS, SNELL_BINARY_SEARCH_MAX_STEPS  (binary_search.glsl):
                                 default and bound of binarySteps (clamped to [0, max])
contract:
  - segment S-E and beta as snellConservativeBinarySearch. Linear phase: beta_i
    = i / linearSteps, i = 1 .. linearSteps; it stops at the first sample that
    is not (valid texel and strictly in front of the surface, z > viewZ): behind
    the surface or an empty / off-screen texel (relief mapping's depth-0 rule).
  - no such sample up to E: valid = false, snellHitMiss numbers, fetches spent.
  - binary phase: bracket [beta_(i-1), beta_i], the rule of snellBinarySearch;
    the result is the last point tested (the linear sample itself when
    binarySteps = 0); valid = that point's texel is valid; when not, uv and
    position still report where the search ended (finite), as snellBinarySearch.
  - precision: for a ray crossing the surface once on S-E, |beta - beta*| <=
    0.5^binarySteps / linearSteps.
  - invalid segment (rays towards the camera, Zmin == Zmax, NaN: see
    search_segment.glsl): valid = false, snellHitMiss numbers, 0 fetches.
source: F. Policarpo, M. M. Oliveira, J. Comba, "Real-Time Relief Mapping on
  Arbitrary Polygonal Surfaces", I3D 2005 (linear then binary search);
  Oliveira & Brauwers 2007, sec. 3.3 (why refraction can skip the linear
  phase), eqs. 3-10.
*/
#ifndef SNELL_INTERSECT_LINEAR_BINARY_SEARCH_GLSL
#define SNELL_INTERSECT_LINEAR_BINARY_SEARCH_GLSL







#ifndef SNELL_LINEAR_SEARCH_STEPS
#  define SNELL_LINEAR_SEARCH_STEPS 10
#endif
#ifndef SNELL_LINEAR_SEARCH_MAX_STEPS
#  define SNELL_LINEAR_SEARCH_MAX_STEPS 256
#endif

/* Policarpo et al. 2005, linear + binary search, on Oliveira & Brauwers 2007 eqs. 5-10 */
SNELL_FN SnellHit snellLinearBinarySearch(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) surface,
                                          float zNearest, float zFarthest, int linearSteps, int binarySteps) {
  SnellTexRay r = snellSearchSegment(origin, dir, zNearest, zFarthest, surface.clipFromView);
  if (!r.valid) {
    return snellHitMiss(0);
  }
  int nl = clamp(linearSteps, 1, SNELL_LINEAR_SEARCH_MAX_STEPS);
  int nb = clamp(binarySteps, 0, SNELL_BINARY_SEARCH_MAX_STEPS);
  float dz = r.e.z - r.s.z;
  float stepBeta = 1.0f / float(nl);
  int fetches = 0;
  int found = -1;
  float beta = 0.0f;
  float z = r.s.z;
  vec2 uv = r.ts;
  bool lastValid = false;
  for (int i = 1; i <= SNELL_LINEAR_SEARCH_MAX_STEPS; ++i) {
    beta = float(i) * stepBeta;
    z = r.s.z + beta * dz;
    uv = snellTexRayUv(r, z);
    SnellSurfaceSample x = snellSampleSurface(depthTex, uv, surface);
    fetches = fetches + 1;
    if (!(x.valid && z > x.viewZ)) {
      found = i;
      lastValid = x.valid;
      break;
    }
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (i >= nl) {
      break;
    }
  }
  if (found < 0) {
    return snellHitMiss(fetches);
  }
  SnellHit h;
  h.uv = uv;
  h.position = vec3(r.s.x + beta * (r.e.x - r.s.x), r.s.y + beta * (r.e.y - r.s.y), z);
  h.valid = lastValid;
  h.fetches = fetches;
  return snellBisectTexRay(r, depthTex, surface, float(found - 1) * stepBeta, beta, nb, h);
}

SNELL_FN SnellHit snellLinearBinarySearch(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) surface,
                                          float zNearest, float zFarthest) {
  return snellLinearBinarySearch(origin, dir, depthTex, surface, zNearest, zFarthest, SNELL_LINEAR_SEARCH_STEPS,
                                 SNELL_BINARY_SEARCH_STEPS);
}

#endif
/*
description: linear march in view space with binary refinement: the screen-space
  ray-marching baseline. Equal steps along the view-space ray, each projected
  with the depth buffer's camera and compared with the stored surface; the
  first step behind the surface is refined by bisection.
use: SnellHit h = snellLinearMarch(origin, dir, depthTex, surface);
     SnellHit h = snellLinearMarch(origin, dir, depthTex, surface, maxDistance, steps, refineSteps);
  origin, dir        view-space ray (dir need not be normalized)
  depthTex, surface  the depth buffer and how to read it (depth_surface.glsl)
  maxDistance        view-space length of the marched part of the ray
  steps              equal steps of maxDistance / steps (one fetch each)
  refineSteps        bisection steps inside the step that crossed (one fetch
                     each while on screen)
options:
  SNELL_LINEAR_MARCH_STEPS              default steps (32)
  SNELL_LINEAR_MARCH_MAX_STEPS          compile-time bound (512); steps is clamped to [1, max]
  SNELL_LINEAR_MARCH_REFINE_STEPS       default refineSteps (4)
  SNELL_LINEAR_MARCH_MAX_REFINE_STEPS   compile-time bound (24); refineSteps clamped to [0, max]
  SNELL_LINEAR_MARCH_MAX_DISTANCE       default maxDistance (10.0f view-space units)
contract:
  - the ray is marched over t in (0, tMax], tMax = maxDistance / |dir|, cut at
    the near plane z = -surface.zNear when dir.z > 0 (a ray towards the camera
    is marched until it would leave the frustum through the near plane).
    Samples t_i = i tMax / steps, i = 1 .. steps (the origin itself is not
    tested); each is projected with surface.clipFromView (snellViewToUv).
  - a sample "crosses" when its texel is valid and the point is on or behind the
    surface (z <= viewZ): the surface is a solid height field (infinitely thick).
    Empty texels do not stop the march (no surface there).
  - the first sample that projects off screen (uv outside [0,1]^2, or not
    projectable) ends the march: valid = false (the ray left the screen).
  - refinement: bracket [t_(i-1), t_i]; a midpoint that crosses moves hi, any
    other (in front, empty, off screen: no fetch then) moves lo. The result is
    hi: a point on or behind the surface at a valid texel, never in front of
    the crossing; uv = the uv that was fetched there. Error along the ray <=
    (tMax / steps) 0.5^refineSteps for a single crossing (plus the depth
    buffer's own discretization).
  - valid = false with snellHitMiss numbers (finite) and the fetches spent when
    no sample crosses; with 0 fetches when: an input is NaN or Inf, |dir| is 0
    or denormal-small, maxDistance <= 0, or the origin is at or in front of
    the near plane with dir.z > 0 (the whole ray is outside the frustum).
source: the classic screen-space ray march (e.g. Sousa, "Crysis 2", 2011;
  Policarpo et al. 2005 for linear + binary search), here in view space with
  the Oliveira & Brauwers 2007 (sec. 3.1) depth-surface reading.
*/
#ifndef SNELL_INTERSECT_LINEAR_MARCH_GLSL
#define SNELL_INTERSECT_LINEAR_MARCH_GLSL







#ifndef SNELL_LINEAR_MARCH_STEPS
#  define SNELL_LINEAR_MARCH_STEPS 32
#endif
#ifndef SNELL_LINEAR_MARCH_MAX_STEPS
#  define SNELL_LINEAR_MARCH_MAX_STEPS 512
#endif
#ifndef SNELL_LINEAR_MARCH_REFINE_STEPS
#  define SNELL_LINEAR_MARCH_REFINE_STEPS 4
#endif
#ifndef SNELL_LINEAR_MARCH_MAX_REFINE_STEPS
#  define SNELL_LINEAR_MARCH_MAX_REFINE_STEPS 24
#endif
#ifndef SNELL_LINEAR_MARCH_MAX_DISTANCE
#  define SNELL_LINEAR_MARCH_MAX_DISTANCE 10.0f
#endif

/* screen-space ray march: equal view-space steps, then bisection */
SNELL_FN SnellHit snellLinearMarch(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) surface,
                                   float maxDistance, int steps, int refineSteps) {
  if (!SNELL_FINITE(origin.x) || !SNELL_FINITE(origin.y) || !SNELL_FINITE(origin.z) ||
      !SNELL_FINITE(dir.x) || !SNELL_FINITE(dir.y) || !SNELL_FINITE(dir.z) ||
      !SNELL_FINITE(maxDistance) || !(maxDistance > 0.0f)) {
    return snellHitMiss(0);
  }
  float len = length(dir);
  if (!SNELL_FINITE(len) || !(len >= SNELL_FLT_MIN)) {
    return snellHitMiss(0);
  }
  float tMax = maxDistance / len;
  if (dir.z > 0.0f) {
    float tNear = (-surface.zNear - origin.z) / dir.z;
    // tNear is finite or +-inf here (a finite numerator over dir.z > 0): +inf is a near plane too far along
    // the ray for a float, never reached, and leaves tMax; -inf (the origin is before the plane) ends it.
    tMax = isnan(tNear) ? 0.0f : min(tMax, tNear);
  }
  if (!SNELL_FINITE(tMax) || !(tMax > 0.0f)) {
    return snellHitMiss(0);
  }
  int n = clamp(steps, 1, SNELL_LINEAR_MARCH_MAX_STEPS);
  int nr = clamp(refineSteps, 0, SNELL_LINEAR_MARCH_MAX_REFINE_STEPS);
  float dt = tMax / float(n);
  int fetches = 0;
  bool found = false;
  float tHit = 0.0f;
  vec2 uvHit = vec2(0.0f, 0.0f);
  for (int i = 1; i <= SNELL_LINEAR_MARCH_MAX_STEPS; ++i) {
    float t = float(i) * dt;
    vec3 p = origin + t * dir;
    SnellScreenPoint sp = snellSurfaceViewToUv(surface, p);
    if (!sp.valid || !(sp.uv.x >= 0.0f && sp.uv.x <= 1.0f && sp.uv.y >= 0.0f && sp.uv.y <= 1.0f)) {
      return snellHitMiss(fetches);
    }
    SnellSurfaceSample x = snellSampleSurface(depthTex, sp.uv, surface);
    fetches = fetches + 1;
    if (x.valid && p.z <= x.viewZ) {
      found = true;
      tHit = t;
      uvHit = sp.uv;
      break;
    }
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (i >= n) {
      break;
    }
  }
  if (!found) {
    return snellHitMiss(fetches);
  }
  float lo = tHit - dt;
  for (int j = 0; nr > 0 && j < SNELL_LINEAR_MARCH_MAX_REFINE_STEPS; ++j) {
    float mid = 0.5f * (lo + tHit);
    vec3 q = origin + mid * dir;
    SnellScreenPoint sq = snellSurfaceViewToUv(surface, q);
    bool crosses = false;
    if (sq.valid && sq.uv.x >= 0.0f && sq.uv.x <= 1.0f && sq.uv.y >= 0.0f && sq.uv.y <= 1.0f) {
      SnellSurfaceSample y = snellSampleSurface(depthTex, sq.uv, surface);
      fetches = fetches + 1;
      crosses = y.valid && q.z <= y.viewZ;
    }
    if (crosses) {
      tHit = mid;
      uvHit = sq.uv;
    } else {
      lo = mid;
    }
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (j + 1 >= nr) {
      break;
    }
  }
  SnellHit h;
  h.uv = uvHit;
  h.position = origin + tHit * dir;
  h.valid = true;
  h.fetches = fetches;
  return h;
}

SNELL_FN SnellHit snellLinearMarch(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) surface) {
  return snellLinearMarch(origin, dir, depthTex, surface, SNELL_LINEAR_MARCH_MAX_DISTANCE, SNELL_LINEAR_MARCH_STEPS,
                          SNELL_LINEAR_MARCH_REFINE_STEPS);
}

#endif
/*
description: where a ray inside a closed object leaves it, in image space:
  a linear march with bisection between the object's two depth layers as the
  camera sees them, its front faces and its back faces. A point is inside
  while it lies between the two (behind the front depth, in front of the
  back depth); the first step outside is refined by bisection and names the
  layer the ray crossed. Davis & Wyman 2007 bounce inside with a binary
  search between front and back depth maps; Oliveira & Brauwers 2007 (sec. 7)
  sketch the same for TIR: front- and back-facing depth and normals, the ray
  intersection procedure run again.
use: SnellInsideHit h = snellInsideMarch(origin, dir, backDepth, back, frontDepth, front,
                                         maxDistance, steps, refineSteps);
     SnellInsideBracket b = snellInsideBracket(origin, dir, backDepth, back, frontDepth, front,
                                               maxDistance, steps);   // the march alone
  origin, dir        view-space ray starting inside the object (a point of
                     the back or front layer after a total internal
                     reflection, say); dir need not be normalized
  backDepth, back    the back-face depth (GL_GREATER after clearing to the
                     near value) and how to read it (depth_surface.glsl)
  frontDepth, front  the front-face depth (GL_LESS after clearing to the far
                     value), how to read it
  maxDistance        view-space length of the marched part of the ray (the
                     object's extent)
  steps              equal steps of maxDistance / steps (two fetches each)
  refineSteps        bisection steps inside the step that left (two fetches
                     each while on screen)
options: the linear march's bounds, SNELL_LINEAR_MARCH_MAX_STEPS (512) and
  SNELL_LINEAR_MARCH_MAX_REFINE_STEPS (24): steps is clamped to [1, max],
  refineSteps to [0, max]; SNELL_INSIDE_FIRST_STEP_HALVINGS (3): the
  samples that halve a first step that has already left.
contract:
  - samples t_i = i tMax / steps, i = 1 .. steps, tMax = maxDistance / |dir|,
    cut at the near plane z = -back.zNear when dir.z > 0 (the origin itself
    is not tested), each projected with back.clipFromView and read in both
    layers at that uv (the two layers share the camera and the size).
  - a sample is outside when it is on or behind the back layer (valid back
    texel, z <= back viewZ: left through the back faces), on or in front of
    the front layer (valid front texel, z >= front viewZ: left through the
    front faces), or where both texels are empty (beside the silhouette).
    The ray leaves at the first outside sample after an inside one: samples
    before the first inside sample do not count (a ray that starts on a layer,
    as after a reflection there, reads as outside within that layer's texel).
    When the first sample t_1 is outside, the first step is halved first:
    t_1 / 2, t_1 / 4, ... up to SNELL_INSIDE_FIRST_STEP_HALVINGS (3) samples
    (2 fetches each); the halving ends at a sample off screen or less than a
    texel (of backDepth at back.lod, in x and in y) from the origin's
    projection (not read: there the layer the ray starts on reads as
    outside), or when the origin does not project. The first inside one is
    the last inside sample and the halving sample before it (t_1 at first)
    the outside one: a chord shorter than a step is still found. When none
    is inside, the march goes on from t_2 as above.
  - the first sample that projects off screen ends the march: valid = false
    (the exit is not in the buffers).
  - refinement brackets [last inside t, first outside t after it]; a midpoint outside moves hi, any other
    (inside, off screen: no fetch) moves lo; the hit is hi: position, uv.
    front = true when hi crossed the front layer only, or both texels are
    empty and dir.z > 0 (a ray heading towards the camera leaves beside the
    silhouette through the front); false for the back layer (both crossed: the
    layer whose depth is nearer the point along z).
  - valid = false with snellHitMiss numbers when no inside sample is followed
    by an outside one (the ray stays inside over maxDistance, or never gets
    inside); with 0 fetches when an input is NaN
    or Inf, |dir| is 0 or denormal-small, maxDistance <= 0, or the whole ray
    lies in front of the near plane.
  - fetches: 2 per sample read, both layers.
  - snellInsideBracket: the samples above without the refinement: valid, lo
    (the last inside sample's t), hi (the first outside one's), uv and side
    (1 back, 2 front: snellInsideSide at hi), loUv (lo's uv) and fetches as
    above; on every miss valid = false, lo = hi = 0, both uvs 0, side 0,
    fetches those read.
source: C. Davis & C. Wyman, "Interactive Refractions with Total Internal
  Reflection", Graphics Interface 2007 (bounces between front and back depth
  maps); M. M. Oliveira & M. Brauwers, "Real-Time Refraction Through
  Deformable Objects", I3D 2007, sec. 7 (TIR as future work: front- and
  back-facing buffers, the same intersection procedure); the linear march of
  linear_march.glsl.
*/
#ifndef SNELL_INTERSECT_INSIDE_MARCH_GLSL
#define SNELL_INTERSECT_INSIDE_MARCH_GLSL







#ifndef SNELL_INSIDE_FIRST_STEP_HALVINGS
#  define SNELL_INSIDE_FIRST_STEP_HALVINGS 3
#endif

struct SnellInsideHit {
  SnellHit hit;
  bool front;  // left through the front layer (else the back layer)
};

/* Which side of the object a point is on at uv: 0 inside, 1 through the back layer, 2 through the front layer
   (an off-screen uv reads as empty in both layers: beside the silhouette) */
SNELL_FN int snellInsideSide(vec3 p, vec2 uv, SNELL_TEX2D backDepth, SNELL_IN(SnellDepthSurface) back,
                             SNELL_TEX2D frontDepth, SNELL_IN(SnellDepthSurface) front, float dirZ) {
  SnellSurfaceSample b = snellSampleSurface(backDepth, uv, back);
  SnellSurfaceSample f = snellSampleSurface(frontDepth, uv, front);
  bool behindBack = b.valid && p.z <= b.viewZ;
  bool beforeFront = f.valid && p.z >= f.viewZ;
  if (behindBack && beforeFront) {
    return (b.viewZ - p.z) <= (p.z - f.viewZ) ? 1 : 2;
  }
  if (behindBack) {
    return 1;
  }
  if (beforeFront) {
    return 2;
  }
  if (!b.valid && !f.valid) {
    return dirZ > 0.0f ? 2 : 1;
  }
  return 0;
}

/* Where the ray leaves, to within one step: the last inside sample (lo) and the first outside one after it (hi) */
struct SnellInsideBracket {
  float lo;      // t of the last inside sample (in units of |dir|)
  float hi;      // t of the first outside sample after it
  vec2 uv;       // hi's uv
  vec2 loUv;     // lo's uv (on the object: both layers hold a surface there)
  int side;      // snellInsideSide at hi: 1 back layer, 2 front layer
  int fetches;
  bool valid;    // false: no inside sample followed by an outside one (or bad input, off screen)
};

/* The march part of snellInsideMarch (its contract's samples, before the refinement), shared with
   snellInsidePlane */
SNELL_FN SnellInsideBracket snellInsideBracket(vec3 origin, vec3 dir, SNELL_TEX2D backDepth,
                                               SNELL_IN(SnellDepthSurface) back, SNELL_TEX2D frontDepth,
                                               SNELL_IN(SnellDepthSurface) front, float maxDistance, int steps) {
  SnellInsideBracket b;
  b.lo = 0.0f;
  b.hi = 0.0f;
  b.uv = vec2(0.0f, 0.0f);
  b.loUv = vec2(0.0f, 0.0f);
  b.side = 0;
  b.fetches = 0;
  b.valid = false;
  if (!SNELL_FINITE(origin.x) || !SNELL_FINITE(origin.y) || !SNELL_FINITE(origin.z) ||
      !SNELL_FINITE(dir.x) || !SNELL_FINITE(dir.y) || !SNELL_FINITE(dir.z) ||
      !SNELL_FINITE(maxDistance) || !(maxDistance > 0.0f)) {
    return b;
  }
  float len = length(dir);
  if (!SNELL_FINITE(len) || !(len >= SNELL_FLT_MIN)) {
    return b;
  }
  float tMax = maxDistance / len;
  if (dir.z > 0.0f) {
    float tNear = (-back.zNear - origin.z) / dir.z;
    // As in the linear march: +inf is a near plane never reached in float and leaves tMax; -inf ends it.
    tMax = isnan(tNear) ? 0.0f : min(tMax, tNear);
  }
  if (!SNELL_FINITE(tMax) || !(tMax > 0.0f)) {
    return b;
  }
  int n = clamp(steps, 1, SNELL_LINEAR_MARCH_MAX_STEPS);
  float dt = tMax / float(n);
  bool wasInside = false;
  for (int i = 1; i <= SNELL_LINEAR_MARCH_MAX_STEPS; ++i) {
    float t = float(i) * dt;
    vec3 p = origin + t * dir;
    SnellScreenPoint sp = snellSurfaceViewToUv(back, p);
    if (!sp.valid || !(sp.uv.x >= 0.0f && sp.uv.x <= 1.0f && sp.uv.y >= 0.0f && sp.uv.y <= 1.0f)) {
      b.lo = 0.0f;
      b.loUv = vec2(0.0f, 0.0f);
      return b;
    }
    int side = snellInsideSide(p, sp.uv, backDepth, back, frontDepth, front, dir.z);
    b.fetches = b.fetches + 2;
    if (side == 0) {
      wasInside = true;
      b.lo = t;
      b.loUv = sp.uv;
    } else if (wasInside) {
      b.hi = t;
      b.uv = sp.uv;
      b.side = side;
      b.valid = true;
      return b;
    } else if (i == 1) {
      // The first sample has already left (a chord shorter than a step, at a corner or a thin part): the first
      // step is halved until a sample is inside, so a coarse march still brackets the exit.
      // Only while the sample is a texel or more from the origin's pixel: within it, the layer the ray
      // starts on reads as outside (the march's rule above), and an inside reading there is noise.
      float hiT = t;
      vec2 hiUv = sp.uv;
      int hiSide = side;
      SnellScreenPoint so = snellSurfaceViewToUv(back, origin);
      vec2 texels = vec2(SNELL_TEXTURE_SIZE(backDepth, back.lod));
      for (int h = 1; h <= SNELL_INSIDE_FIRST_STEP_HALVINGS; ++h) {
        float th = 0.5f * hiT;
        vec3 q = origin + th * dir;
        SnellScreenPoint sq = snellSurfaceViewToUv(back, q);
        if (!so.valid || !sq.valid || !(sq.uv.x >= 0.0f && sq.uv.x <= 1.0f && sq.uv.y >= 0.0f && sq.uv.y <= 1.0f)) {
          break;
        }
        vec2 away = abs(sq.uv - so.uv) * texels;
        if (!(max(away.x, away.y) >= 1.0f)) {
          break;
        }
        int s = snellInsideSide(q, sq.uv, backDepth, back, frontDepth, front, dir.z);
        b.fetches = b.fetches + 2;
        if (s == 0) {
          b.lo = th;
          b.loUv = sq.uv;
          b.hi = hiT;
          b.uv = hiUv;
          b.side = hiSide;
          b.valid = true;
          return b;
        }
        hiT = th;
        hiUv = sq.uv;
        hiSide = s;
      }
    }
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (i >= n) {
      break;
    }
  }
  b.lo = 0.0f;
  b.loUv = vec2(0.0f, 0.0f);
  return b;
}

/* Davis & Wyman 2007: a ray inside the object, marched between the front and back depth layers */
SNELL_FN SnellInsideHit snellInsideMarch(vec3 origin, vec3 dir, SNELL_TEX2D backDepth, SNELL_IN(SnellDepthSurface) back,
                                         SNELL_TEX2D frontDepth, SNELL_IN(SnellDepthSurface) front, float maxDistance,
                                         int steps, int refineSteps) {
  SnellInsideHit r;
  r.front = false;
  SnellInsideBracket b = snellInsideBracket(origin, dir, backDepth, back, frontDepth, front, maxDistance, steps);
  r.hit = snellHitMiss(b.fetches);
  if (!b.valid) {
    return r;
  }
  int nr = clamp(refineSteps, 0, SNELL_LINEAR_MARCH_MAX_REFINE_STEPS);
  int fetches = b.fetches;
  int side = b.side;
  float lo = b.lo;
  float tHit = b.hi;
  vec2 uvHit = b.uv;
  for (int j = 0; nr > 0 && j < SNELL_LINEAR_MARCH_MAX_REFINE_STEPS; ++j) {
    float mid = 0.5f * (lo + tHit);
    vec3 q = origin + mid * dir;
    SnellScreenPoint sq = snellSurfaceViewToUv(back, q);
    int s = 0;
    if (sq.valid && sq.uv.x >= 0.0f && sq.uv.x <= 1.0f && sq.uv.y >= 0.0f && sq.uv.y <= 1.0f) {
      s = snellInsideSide(q, sq.uv, backDepth, back, frontDepth, front, dir.z);
      fetches = fetches + 2;
    }
    if (s > 0) {
      tHit = mid;
      uvHit = sq.uv;
      side = s;
    } else {
      lo = mid;
    }
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (j + 1 >= nr) {
      break;
    }
  }
  r.hit.uv = uvHit;
  r.hit.position = origin + tHit * dir;
  r.hit.valid = true;
  r.hit.fetches = fetches;
  r.front = side == 2;
  return r;
}

#endif
/*
description: where a ray inside a closed object leaves it, with Mayer &
  Assarsson's normal-based plane in place of the bisection: a coarse march
  between the object's two depth layers brackets the exit (the last inside
  sample, the first outside one: snellInsideBracket), then the layer the ray
  crossed is read at the outside sample (depth and normal) and the ray is
  intersected with that tangent plane, re-read where it lands and
  intersected again, `iterations` times (their step 5). Exact on planar
  faces from the first plane; a few march steps replace the march's
  bisections. Why the plane is not started at the ray origin as on the back
  slot: a ray inside starts on a layer (the point of the last total internal
  reflection), so the layer at its own pixel is the face it leaves from,
  whose plane it meets at t = 0; its exit lies elsewhere on screen, which
  only a search finds.
use: SnellInsideHit h = snellInsidePlane(origin, dir, backDepth, backNormal, back,
                                         frontDepth, frontNormal, front, maxDistance, steps, iterations);
  origin, dir        view-space ray starting inside the object; dir any length
  backDepth, backNormal, back    the back-face depth (GL_GREATER after
                     clearing to the near value), its view-space normals
                     (xyz, any length, either orientation; read at level 0
                     with the texture's filter) and how to read the depth
  frontDepth, frontNormal, front the front faces' (GL_LESS after clearing to
                     the far value)
  maxDistance        view-space length of the marched part of the ray
  steps              march steps (snellInsideMarch's), clamped to
                     [1, SNELL_LINEAR_MARCH_MAX_STEPS]
  iterations         planes, clamped to [0, SNELL_PLANE_MAX_ITERATIONS]; 0 is
                     the bracket's outside sample
contract:
  - the bracket is snellInsideBracket(origin, dir, ..., maxDistance, steps)
    (inside_march.glsl); when it is invalid: valid = false, snellHitMiss with
    its fetches.
  - plane k (k = 1 .. iterations) on the layer the bracket crossed (its side):
    B_k = snellSurfacePoint of that layer's depth at uv_(k-1) (uv_0 the
    bracket's uv, the outside sample's pixel; when plane 1 read there is not
    kept, it is read again at the bracket's loUv, the last inside sample's
    pixel, where the object is, and then on the other layer at loUv, whose
    plane, when kept, makes that layer the side; then each kept hit's
    projection), n_k = xyz of its normals read at
    B_k's texel centre, level 0 (SNELL_SAMPLE_LOD); t_k = snellRayPlane(origin,
    dir, B_k, n_k).t. The plane is kept only when it is met inside the
    bracket, lo <= t_k <= hi (a tangent plane met outside it describes another
    part of the layer) and t_k's point projects on screen; otherwise the
    iterations stop at the last kept t (the bracket's hi at first).
  - the hit: position origin + t dir, uv its projection (the bracket's uv when
    no plane was kept), valid = true, front = the side is the front layer (the
    bracket's side, or the other layer's when its plane 1 was kept).
  - fetches: the bracket's, plus 2 per plane read (depth and normal; 1 when
    the depth texel is empty), plane 1's second and third reads included.
  - bad input (NaN or Inf, zero dir, maxDistance <= 0): the bracket's miss,
    0 fetches; never NaN.
source: C. Mayer, U. Assarsson, "Constant-Time Light Refraction Simulation",
  "Method 1: Normal-based" and step 5; C. Davis & C. Wyman, "Interactive
  Refractions with Total Internal Reflection", Graphics Interface 2007 (the
  search between front and back depth maps).
*/
#ifndef SNELL_INTERSECT_INSIDE_PLANE_GLSL
#define SNELL_INTERSECT_INSIDE_PLANE_GLSL









/* Mayer & Assarsson's normal plane on the layer a march between the two layers crossed (Davis & Wyman 2007) */
SNELL_FN SnellInsideHit snellInsidePlane(vec3 origin, vec3 dir, SNELL_TEX2D backDepth, SNELL_TEX2D backNormal,
                                         SNELL_IN(SnellDepthSurface) back, SNELL_TEX2D frontDepth,
                                         SNELL_TEX2D frontNormal, SNELL_IN(SnellDepthSurface) front,
                                         float maxDistance, int steps, int iterations) {
  SnellInsideHit r;
  r.front = false;
  SnellInsideBracket b = snellInsideBracket(origin, dir, backDepth, back, frontDepth, front, maxDistance, steps);
  r.hit = snellHitMiss(b.fetches);
  if (!b.valid) {
    return r;
  }
  bool onFront = b.side == 2;
  int n = clamp(iterations, 0, SNELL_PLANE_MAX_ITERATIONS);
  int fetches = b.fetches;
  float t = b.hi;
  vec2 uv = b.uv;
  // Plane 1 is read at the outside sample's pixel, else at the last inside one's, else on the other layer
  // there: beside the silhouette the outside pixel holds neither layer (and the side is the guess of
  // snellInsideSide), near an edge of the object the inside pixel may hold the face the ray comes from.
  vec2 readUv = b.uv;
  bool readFront = onFront;
  int planes = 0;
  int misses = 0;
  for (int k = 1; n > 0 && k <= SNELL_PLANE_MAX_ITERATIONS + 2; ++k) {
    SnellSurfacePoint s;  // not ?: : WebGL rejects it on structs
    if (readFront) {
      s = snellSurfacePoint(frontDepth, readUv, front);
    } else {
      s = snellSurfacePoint(backDepth, readUv, back);
    }
    fetches = fetches + 1;
    bool kept = false;
    if (s.valid) {
      vec4 nk = readFront ? SNELL_SAMPLE_LOD(frontNormal, s.uv, 0.0f) : SNELL_SAMPLE_LOD(backNormal, s.uv, 0.0f);
      fetches = fetches + 1;
      SnellRayPlaneHit ph = snellRayPlane(origin, dir, s.position, vec3(nk.x, nk.y, nk.z));
      if (ph.valid && ph.t >= b.lo && ph.t <= b.hi) {
        SnellScreenPoint sp = snellSurfaceViewToUv(back, ph.position);
        if (sp.valid && sp.uv.x >= 0.0f && sp.uv.x <= 1.0f && sp.uv.y >= 0.0f && sp.uv.y <= 1.0f) {
          t = ph.t;
          uv = sp.uv;
          readUv = sp.uv;
          onFront = readFront;
          planes = planes + 1;
          kept = true;
        }
      }
    }
    if (!kept) {
      if (planes > 0 || misses >= 2) {
        break;
      }
      misses = misses + 1;
      readUv = b.loUv;
      readFront = misses == 1 ? onFront : !onFront;
    }
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (planes >= n) {
      break;
    }
  }
  r.hit.position = origin + t * dir;
  r.hit.uv = uv;
  r.hit.valid = true;
  r.hit.fetches = fetches;
  r.front = onFront;
  return r;
}

#endif
/*
description: perspective-correct march in pixel space (a DDA): the view-space
  ray segment is projected once, then walked in equal pixel steps along its
  major screen axis, every pixel on the way (stride 1) or every stride-th one,
  with the ray's depth recovered per step by homogeneous (1/w) interpolation,
  so no matrix product per step and no pixel skipped or visited twice.
use: SnellHit h = snellDdaMarch(origin, dir, depthTex, surface);
     SnellHit h = snellDdaMarch(origin, dir, depthTex, surface, maxDistance, thickness, stride, steps);
  origin, dir        view-space ray (dir need not be normalized)
  depthTex, surface  the depth buffer and how to read it (depth_surface.glsl);
                     the pixel grid is that of level surface.lod
  maxDistance        view-space length of the marched segment
  thickness          assumed view-space thickness of the surface: a step hits
                     when the ray's depth interval over the step overlaps
                     [viewZ - thickness, viewZ]
  stride             pixels per step along the major axis (>= 1)
  steps              maximum number of steps (one fetch each)
options:
  SNELL_DDA_STEPS         default steps (256)
  SNELL_DDA_MAX_STEPS     compile-time bound (1024); steps is clamped to [1, max]
  SNELL_DDA_STRIDE        default stride (1.0f)
  SNELL_DDA_THICKNESS     default thickness (SNELL_FLT_MAX: a solid height
                          field, as the other strategies assume; use a finite
                          value for opaque scenes with objects in front of
                          others, so rays can pass behind them)
  SNELL_DDA_MAX_DISTANCE  default maxDistance (10.0f view-space units)
contract:
  - segment: origin to end = origin + (min(maxDistance, 1e30)/|dir|) dir, cut
    at the near plane z = -surface.zNear when dir.z > 0 (beyond 1e30 view
    units the end's projection no longer moves for any scene-scale origin; the
    cap keeps 1/w of the end a normal float, so maxDistance = SNELL_FLT_MAX
    works as "unbounded"). Both ends are projected with surface.clipFromView:
    uv0, uv1 and k = 1/w; Q = p/w and k are linear in screen space, so the view
    point at screen parameter s in [0,1] is
    (Q0 (1 - s) + Q1 s) / (k0 (1 - s) + k1 s) (perspective-correct; this form
    is exact at both ends and never cancels, as k0, k1 > 0).
  - step i (i = 0, 1, ...) samples uv0 + s_i (uv1 - uv0), s_i = min(i ds, 1),
    ds = stride / (length of the segment along its major axis in pixels), or
    ds = 1 when the whole segment spans at most stride pixels (a ray along the
    line of sight: two steps, both halves of its depth range at one pixel); it
    owns s in [(i - 1/2) ds, (i + 1/2) ds] clipped to [0,1], whose ends give the
    ray's depth interval [zFar, zNear] for that step. The walk ends after the
    step owning s = 1.
  - a step hits when its texel is valid and zNear >= viewZ - thickness and
    zFar <= viewZ. Empty texels do not stop the march.
  - hit: uv = the uv that was fetched (its texel is the hit texel), position =
    the point of the ray within the step whose z is clamp(viewZ, zFar, zNear)
    (the crossing, when it lies in the step), on the ray, finite.
  - the first step whose uv is off screen ends the walk: valid = false.
  - valid = false with snellHitMiss numbers (finite) and the fetches spent when
    no step hits within steps; with 0 fetches when: an input is NaN or Inf
    (a NaN thickness uses the default, a NaN stride 1), |dir| is 0 or
    denormal-small, maxDistance <= 0, the origin is in front of the near plane
    (z > -surface.zNear) or on it with dir.z > 0 (no part of the ray is inside
    the frustum), an end does not project to a normal 1/w (clip w <= 0,
    below FLT_MIN or above 1/FLT_MIN) or to a finite Q, or the level has no
    texels. thickness < 0 counts as 0, stride < 1 as 1.
source: M. McGuire, M. Mara, "Efficient GPU Screen-Space Ray Tracing", JCGT
  3(4), 2014 (pixel-space march with homogeneous interpolation of 1/w and a
  depth interval per step); our own formulation (per-step parameter instead of
  accumulated increments, exact crossing inside the hit step).
*/
#ifndef SNELL_INTERSECT_DDA_MARCH_GLSL
#define SNELL_INTERSECT_DDA_MARCH_GLSL






#ifndef SNELL_DDA_STEPS
#  define SNELL_DDA_STEPS 256
#endif
#ifndef SNELL_DDA_MAX_STEPS
#  define SNELL_DDA_MAX_STEPS 1024
#endif
#ifndef SNELL_DDA_STRIDE
#  define SNELL_DDA_STRIDE 1.0f
#endif
#ifndef SNELL_DDA_THICKNESS
#  define SNELL_DDA_THICKNESS SNELL_FLT_MAX
#endif
#ifndef SNELL_DDA_MAX_DISTANCE
#  define SNELL_DDA_MAX_DISTANCE 10.0f
#endif

/* McGuire & Mara 2014: pixel-space march, z from homogeneous interpolation of 1/w */
/* The surface by value, not SNELL_IN: in C++ the march's loop then keeps its
   fields in registers across the library calls it makes (floorf, sqrtf); by
   reference it reloads them every step (8 % more instructions, benchmarks/kernels). */
SNELL_FN SnellHit snellDdaMarch(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SnellDepthSurface surface,
                                float maxDistance, float thickness, float stride, int steps) {
  if (!SNELL_FINITE(origin.x) || !SNELL_FINITE(origin.y) || !SNELL_FINITE(origin.z) ||
      !SNELL_FINITE(dir.x) || !SNELL_FINITE(dir.y) || !SNELL_FINITE(dir.z) ||
      !SNELL_FINITE(maxDistance) || !(maxDistance > 0.0f) || !SNELL_FINITE(surface.zNear)) {
    return snellHitMiss(0);
  }
  float thick = isnan(thickness) ? SNELL_DDA_THICKNESS : clamp(thickness, 0.0f, SNELL_FLT_MAX);
  float px = isnan(stride) ? 1.0f : clamp(stride, 1.0f, SNELL_FLT_MAX);
  float len = length(dir);
  if (!SNELL_FINITE(len) || !(len >= SNELL_FLT_MIN) || !(origin.z <= -surface.zNear)) {
    return snellHitMiss(0);
  }
  float tMax = min(maxDistance, 1e30f) / len;
  if (dir.z > 0.0f) {
    float tNear = (-surface.zNear - origin.z) / dir.z;
    // tNear is finite or +-inf here (a finite numerator over dir.z > 0): +inf is a near plane too far along
    // the ray for a float, never reached, and leaves tMax; -inf (the origin is before the plane) ends it.
    tMax = isnan(tNear) ? 0.0f : min(tMax, tNear);
  }
  if (!SNELL_FINITE(tMax) || !(tMax > 0.0f)) {
    return snellHitMiss(0);
  }
  vec3 end = origin + tMax * dir;
  vec4 h0 = snellViewToClip(surface.clipFromView, origin);
  vec4 h1 = snellViewToClip(surface.clipFromView, end);
  ivec2 size = SNELL_TEXTURE_SIZE(depthTex, surface.lod);
  if (!SNELL_FINITE(end.x) || !SNELL_FINITE(end.y) || !SNELL_FINITE(end.z) ||
      !SNELL_FINITE(h0.x) || !SNELL_FINITE(h0.y) || !SNELL_FINITE(h0.w) ||
      !SNELL_FINITE(h1.x) || !SNELL_FINITE(h1.y) || !SNELL_FINITE(h1.w) ||
      !(h0.w >= SNELL_FLT_MIN) || !(h1.w >= SNELL_FLT_MIN) ||
      !(h0.w <= 1.0f / SNELL_FLT_MIN) || !(h1.w <= 1.0f / SNELL_FLT_MIN) || size.x <= 0 || size.y <= 0) {
    return snellHitMiss(0);
  }
  // Homogeneous end points: k = 1/w and Q = p k are linear in screen space.
  // They are interpolated as a (1 - s) + b s, not a + s (b - a): for a far end
  // (k1 below the ulp of k0) k0 + s (k1 - k0) cancels to 0 at s = 1. Written
  // out rather than mix(), which drivers may lower to the cancelling form.
  float k0 = 1.0f / h0.w;
  float k1 = 1.0f / h1.w;
  vec3 q0 = origin * k0;
  vec3 q1 = end * k1;
  vec2 uv0 = vec2(h0.x * k0, h0.y * k0) * 0.5f + 0.5f;
  vec2 duv = vec2(h1.x * k1, h1.y * k1) * 0.5f + 0.5f - uv0;
  float major = max(abs(duv.x * float(size.x)), abs(duv.y * float(size.y)));
  if (!SNELL_FINITE(major) || !SNELL_FINITE(q0.x) || !SNELL_FINITE(q0.y) ||
      !SNELL_FINITE(q0.z) || !SNELL_FINITE(q1.x) || !SNELL_FINITE(q1.y) ||
      !SNELL_FINITE(q1.z)) {
    return snellHitMiss(0);
  }
  float ds = major > px ? px / major : 1.0f;
  int n = clamp(steps, 1, SNELL_DDA_MAX_STEPS);
  int fetches = 0;
  float sA = 0.0f;
  float zA = origin.z;
  for (int i = 0; i < SNELL_DDA_MAX_STEPS; ++i) {
    float sC = min(float(i) * ds, 1.0f);
    float sB = min((float(i) + 0.5f) * ds, 1.0f);
    float zB = (q0.z * (1.0f - sB) + q1.z * sB) / (k0 * (1.0f - sB) + k1 * sB);
    vec2 uv = uv0 + sC * duv;
    if (!(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f)) {
      return snellHitMiss(fetches);
    }
    SnellSurfaceSample x = snellSampleSurface(depthTex, uv, surface);
    fetches = fetches + 1;
    float zNearRay = max(zA, zB);
    float zFarRay = min(zA, zB);
    if (x.valid && zNearRay >= x.viewZ - thick && zFarRay <= x.viewZ) {
      // The point of the ray inside this step at depth clamp(viewZ, zFar, zNear).
      float zHit = clamp(x.viewZ, zFarRay, zNearRay);
      vec3 pA = (q0 * (1.0f - sA) + q1 * sA) / (k0 * (1.0f - sA) + k1 * sA);
      vec3 pB = (q0 * (1.0f - sB) + q1 * sB) / (k0 * (1.0f - sB) + k1 * sB);
      float f = pB.z != pA.z ? clamp((zHit - pA.z) / (pB.z - pA.z), 0.0f, 1.0f) : 0.5f;
      SnellHit h;
      h.uv = uv;
      h.position = pA + f * (pB - pA);
      h.valid = true;
      h.fetches = fetches;
      return h;
    }
    sA = sB;
    zA = zB;
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (i + 1 >= n || sA >= 1.0f) {
      break;
    }
  }
  return snellHitMiss(fetches);
}

SNELL_FN SnellHit snellDdaMarch(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SnellDepthSurface surface) {
  return snellDdaMarch(origin, dir, depthTex, surface, SNELL_DDA_MAX_DISTANCE, SNELL_DDA_THICKNESS, SNELL_DDA_STRIDE,
                       SNELL_DDA_STEPS);
}

#endif
/*
description: any intersection strategy of intersect/, chosen at run time: the
  strategy ids, one options struct whose fields are named after the strategy
  they belong to, and the dispatcher, so a technique's back-face, exit and
  reflection slots are interchangeable (GLSL has no function pointers: a
  strategy is an int constant that snellIntersectWith branches on).
use: SnellIntersectOptions o = snellIntersectOptions(SNELL_STRATEGY_CBS);
     o.cbsSteps = 8;
     SnellHit h = snellIntersectWith(origin, dir, depthTex, normalTex, pyramidTex, surface, o);
  origin, dir view-space ray (P1, T1 for the back faces; P2, T2 for the scene)
  depthTex    the depth buffer `surface` describes
  normalTex   its view-space normals (PLANE_NORMAL only; any texture otherwise)
  pyramidTex  its depth min/max pyramid (intersect/depth_pyramid.glsl), full mip
              chain: the search range of CBS / BINARY / LINEAR_BINARY when
              o.rangeSource is SNELL_RANGE_PYRAMID, and the depth mips of
              PLANE_DEPTH (its .x is the mean depth value)
  o           the strategy and its parameters
options (strategy ids, the values of SnellIntersectOptions.strategy):
  SNELL_STRATEGY_SINGLE         0  snellIntersectSingleSample (1 fetch)
  SNELL_STRATEGY_PLANE_NORMAL   1  snellIntersectPlaneNormal
  SNELL_STRATEGY_PLANE_DEPTH    2  snellIntersectPlaneDepth (the pyramid's
                                   levels as depth mips)
  SNELL_STRATEGY_CBS            3  snellConservativeBinarySearch
  SNELL_STRATEGY_BINARY         4  snellBinarySearch
  SNELL_STRATEGY_LINEAR_BINARY  5  snellLinearBinarySearch
  SNELL_STRATEGY_LINEAR_MARCH   6  snellLinearMarch
  SNELL_STRATEGY_DDA            7  snellDdaMarch
  SNELL_STRATEGY_COUNT          8  the number of strategies (ids 0 .. COUNT - 1;
                                   any other id misses)
  range sources of the searches: SNELL_RANGE_PYRAMID 0 (the pyramid's top
  level, snellDepthRangeFromPyramid, 1 fetch), SNELL_RANGE_EXPLICIT 1 (o.range
  as given, e.g. snellDepthRangeFromBox: Oliveira & Brauwers' bounding box)
  SNELL_INTERSECT_STRATEGIES  bit mask of the strategies compiled in (bit k =
                              strategy k; all SNELL_STRATEGY_COUNT of them,
                              the default). Every
                              technique call inlines the dispatcher, and with
                              it every strategy: a shader that uses one or two
                              presets compiles much faster (llvmpipe: minutes
                              -> seconds) with only their bits, e.g.
                              #define SNELL_INTERSECT_STRATEGIES ((1 << SNELL_STRATEGY_CBS) | 1)
                              A strategy left out answers snellHitMiss(0).
  The fields of SnellIntersectOptions, by the strategy that reads them, with
  their defaults (each default is the strategy file's own macro):
  every strategy  depthFilter = SNELL_DEPTH_FILTER_NEAREST (how the strategy
                  reads depth: intersect/depth_surface.glsl; it replaces the
                  surface's depthFilter field)
  PLANE_NORMAL, PLANE_DEPTH  planeIterations = SNELL_PLANE_ITERATIONS
                  (refinements after the first plane), planeFarStart =
                  SNELL_PLANE_FAR_START != 0 (true: on a closed surface the
                  first plane may start at the farthest back face the pyramid
                  holds under the ray, intersect/plane_far_start.glsl; false:
                  the poster's first plane)
  PLANE_NORMAL    planeNormalLod = 0 (the normal texture's level)
  PLANE_DEPTH     planeMaxLod = -1 (the coarsest depth mip: the pyramid's top
                  level, snellTextureTopLod)
  CBS             cbsSteps = SNELL_CBS_STEPS
  BINARY, LINEAR_BINARY  binarySteps = SNELL_BINARY_SEARCH_STEPS (bisections)
  LINEAR_BINARY   linearSteps = SNELL_LINEAR_SEARCH_STEPS
  CBS, BINARY, LINEAR_BINARY  rangeSource = SNELL_RANGE_PYRAMID, range =
                  snellDepthRangeInvalid() (read under SNELL_RANGE_EXPLICIT only)
  LINEAR_MARCH    marchSteps = SNELL_LINEAR_MARCH_STEPS, marchBisections =
                  SNELL_LINEAR_MARCH_REFINE_STEPS, marchMaxDistance =
                  SNELL_LINEAR_MARCH_MAX_DISTANCE
  DDA             ddaSteps = SNELL_DDA_STEPS, ddaMaxDistance =
                  SNELL_DDA_MAX_DISTANCE, ddaThickness = SNELL_DDA_THICKNESS,
                  ddaStride = SNELL_DDA_STRIDE
contract:
  - snellIntersectOptions(strategy): the strategy as given (an unknown one is
    stored too, and answered with a miss) and every field's default above.
  - snellIntersectWith, by o.strategy:
    SINGLE: snellIntersectSingleSample(origin, dir, depthTex, surface).
    PLANE_NORMAL: snellIntersectPlaneNormal(.., normalTex, pyramidTex, surface,
    o.planeNormalLod, o.planeIterations, o.planeFarStart).
    PLANE_DEPTH: snellIntersectPlaneDepth(origin, dir, pyramidTex, surface,
    maxLod, o.planeIterations, o.planeFarStart), maxLod = o.planeMaxLod, or
    snellTextureTopLod(pyramidTex) when o.planeMaxLod < 0.
    CBS / BINARY / LINEAR_BINARY: the range is snellDepthRangeFromPyramid(
    pyramidTex) (1 fetch, counted in h.fetches) or o.range; an invalid range is
    a miss (with the pyramid's fetch); then the strategy with o.cbsSteps,
    o.binarySteps, or o.linearSteps and o.binarySteps.
    LINEAR_MARCH: snellLinearMarch(.., o.marchMaxDistance, o.marchSteps,
    o.marchBisections). DDA: snellDdaMarch(.., o.ddaMaxDistance,
    o.ddaThickness, o.ddaStride, o.ddaSteps).
    Any other strategy: snellHitMiss(0).
  - every result is the strategy's own SnellHit (contracts in intersect/), with
    the range fetch added; each strategy clamps its own counts.
source: DESIGN.md sec. 2 ("every intersector is interchangeable in both
  slots"); Oliveira & Brauwers 2007 sec. 3 and sec. 6 (the two range sources);
  the strategies' own sources.
*/
#ifndef SNELL_INTERSECT_INTERSECT_WITH_GLSL
#define SNELL_INTERSECT_INTERSECT_WITH_GLSL














#define SNELL_STRATEGY_SINGLE 0
#define SNELL_STRATEGY_PLANE_NORMAL 1
#define SNELL_STRATEGY_PLANE_DEPTH 2
#define SNELL_STRATEGY_CBS 3
#define SNELL_STRATEGY_BINARY 4
#define SNELL_STRATEGY_LINEAR_BINARY 5
#define SNELL_STRATEGY_LINEAR_MARCH 6
#define SNELL_STRATEGY_DDA 7
#define SNELL_STRATEGY_COUNT 8

#define SNELL_RANGE_PYRAMID 0
#define SNELL_RANGE_EXPLICIT 1

#ifndef SNELL_INTERSECT_STRATEGIES
#  define SNELL_INTERSECT_STRATEGIES ((1 << SNELL_STRATEGY_COUNT) - 1)
#endif
/* true when strategy k is compiled in (a constant expression: the branch folds away) */
#define SNELL_INTERSECT_HAS(k) ((SNELL_INTERSECT_STRATEGIES & (1 << (k))) != 0)

struct SnellIntersectOptions {
  int strategy;
  int depthFilter;
  int planeIterations;
  float planeNormalLod;
  bool planeFarStart;
  int planeMaxLod;
  int cbsSteps;
  int binarySteps;
  int linearSteps;
  int rangeSource;
  SnellDepthRange range;
  int marchSteps;
  int marchBisections;
  float marchMaxDistance;
  int ddaSteps;
  float ddaMaxDistance;
  float ddaThickness;
  float ddaStride;
};

SNELL_FN SnellIntersectOptions snellIntersectOptions(int strategy) {
  SnellIntersectOptions o;
  o.strategy = strategy;
  o.depthFilter = SNELL_DEPTH_FILTER_NEAREST;
  o.planeIterations = SNELL_PLANE_ITERATIONS;
  o.planeNormalLod = 0.0f;
  o.planeFarStart = SNELL_PLANE_FAR_START != 0;
  o.planeMaxLod = -1;
  o.cbsSteps = SNELL_CBS_STEPS;
  o.binarySteps = SNELL_BINARY_SEARCH_STEPS;
  o.linearSteps = SNELL_LINEAR_SEARCH_STEPS;
  o.rangeSource = SNELL_RANGE_PYRAMID;
  o.range = snellDepthRangeInvalid();
  o.marchSteps = SNELL_LINEAR_MARCH_STEPS;
  o.marchBisections = SNELL_LINEAR_MARCH_REFINE_STEPS;
  o.marchMaxDistance = SNELL_LINEAR_MARCH_MAX_DISTANCE;
  o.ddaSteps = SNELL_DDA_STEPS;
  o.ddaMaxDistance = SNELL_DDA_MAX_DISTANCE;
  o.ddaThickness = SNELL_DDA_THICKNESS;
  o.ddaStride = SNELL_DDA_STRIDE;
  return o;
}

SNELL_FN SnellHit snellIntersectWith(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_TEX2D normalTex,
                                     SNELL_TEX2D pyramidTex, SNELL_IN(SnellDepthSurface) readAs, SnellIntersectOptions o) {
  SnellDepthSurface surface = readAs;
  surface.depthFilter = o.depthFilter;
  int strategy = o.strategy;
  if (SNELL_INTERSECT_HAS(SNELL_STRATEGY_SINGLE) && strategy == SNELL_STRATEGY_SINGLE) {
    return snellIntersectSingleSample(origin, dir, depthTex, surface);
  }
  if (SNELL_INTERSECT_HAS(SNELL_STRATEGY_PLANE_NORMAL) && strategy == SNELL_STRATEGY_PLANE_NORMAL) {
    return snellIntersectPlaneNormal(origin, dir, depthTex, normalTex, pyramidTex, surface, o.planeNormalLod, o.planeIterations, o.planeFarStart);
  }
  if (SNELL_INTERSECT_HAS(SNELL_STRATEGY_PLANE_DEPTH) && strategy == SNELL_STRATEGY_PLANE_DEPTH) {
    int maxLod = o.planeMaxLod >= 0 ? o.planeMaxLod : snellTextureTopLod(pyramidTex);
    return snellIntersectPlaneDepth(origin, dir, pyramidTex, surface, maxLod, o.planeIterations, o.planeFarStart);
  }
  if (SNELL_INTERSECT_HAS(SNELL_STRATEGY_LINEAR_MARCH) && strategy == SNELL_STRATEGY_LINEAR_MARCH) {
    return snellLinearMarch(origin, dir, depthTex, surface, o.marchMaxDistance, o.marchSteps, o.marchBisections);
  }
  if (SNELL_INTERSECT_HAS(SNELL_STRATEGY_DDA) && strategy == SNELL_STRATEGY_DDA) {
    return snellDdaMarch(origin, dir, depthTex, surface, o.ddaMaxDistance, o.ddaThickness, o.ddaStride, o.ddaSteps);
  }
  bool cbs = SNELL_INTERSECT_HAS(SNELL_STRATEGY_CBS) && strategy == SNELL_STRATEGY_CBS;
  bool binary = SNELL_INTERSECT_HAS(SNELL_STRATEGY_BINARY) && strategy == SNELL_STRATEGY_BINARY;
  bool linearBinary = SNELL_INTERSECT_HAS(SNELL_STRATEGY_LINEAR_BINARY) && strategy == SNELL_STRATEGY_LINEAR_BINARY;
  if (!cbs && !binary && !linearBinary) {
    return snellHitMiss(0);
  }
  SnellDepthRange range = o.range;
  int rangeFetches = 0;
  if (o.rangeSource != SNELL_RANGE_EXPLICIT) {
    range = snellDepthRangeFromPyramid(pyramidTex);
    rangeFetches = 1;
  }
  if (!range.valid) {
    return snellHitMiss(rangeFetches);
  }
  SnellHit h;
  if (cbs) {
    h = snellConservativeBinarySearch(origin, dir, depthTex, surface, range.zNearest, range.zFarthest, o.cbsSteps);
  } else if (binary) {
    h = snellBinarySearch(origin, dir, depthTex, surface, range.zNearest, range.zFarthest, o.binarySteps);
  } else {
    h = snellLinearBinarySearch(origin, dir, depthTex, surface, range.zNearest, range.zFarthest, o.linearSteps,
                                o.binarySteps);
  }
  h.fetches = h.fetches + rangeFetches;
  return h;
}

#endif
/*
description: the foreground rule of every slot that reads the opaque scene's
  buffers: a hit never shows a surface nearer the camera than the ray that
  found it. The scene buffer holds, at each pixel, only the nearest surface;
  where something opaque stands between the camera and the refractive object
  (a pillar in front of the glass), that is the pillar, and a strategy that
  lands on such a pixel would show the pillar's colour inside the glass. The
  rule reads the depth at the hit once more and refuses the hit when the
  surface there lies in front of every point of the ray from its origin to
  the hit: no point of that segment can be on it, so its colour belongs to a
  foreground the ray passed behind. The slot then takes its fallback.
use: h = snellRejectForeground(h, origin, depthTex, surface, SNELL_FOREGROUND_TOLERANCE);
  h         the strategy's hit for the ray (origin, any direction)
  origin    the ray's view-space start (z < 0): P2 for the exit slot, P1 for
            the reflect slot
  depthTex, surface  the buffer the strategy read and how it describes the
            depth (its depthFilter is not used: the rule reads the texel
            containing the hit, SNELL_DEPTH_FILTER_NEAREST, so that a
            bilinear read across a foreground's silhouette does not blend
            its depth with the background's and let it through)
  tolerance the share of the ray's nearest distance by which the surface must
            be nearer to count as foreground: it absorbs the depth read's own
            error (a texel's footprint on a sloped surface, depth
            quantization)
options:
  SNELL_FOREGROUND_TOLERANCE  the tolerance snellTwoInterfaceExit passes
            (default 0.01: a surface 1 % nearer than the ray's nearest point)
contract:
  - h invalid: h unchanged (no fetch).
  - origin.z or h.position.z not finite (no strategy returns such a hit):
    snellHitMiss(h.fetches) (no fetch), so that no runtime's NaN-ignoring
    min decides.
  - else one read x = snellSampleSurface(depthTex, h.uv, surface with
    depthFilter SNELL_DEPTH_FILTER_NEAREST) (fetches h.fetches + 1). dNear = min(-origin.z, -h.position.z), the distance of the
    segment's nearest point along the view axis (a ray's view depth is affine
    in its parameter, so the segment is nowhere nearer). When x is valid and
    -x.viewZ < dNear (1 - t), t = tolerance clamped to [0, 1] (NaN and
    negative values: 0), the hit is refused: snellHitMiss(h.fetches + 1).
    Otherwise h with fetches + 1 (an empty texel is no foreground).
  - what it does not catch: a surface between the origin's depth and the
    hit's, at the hit's pixel, on a ray heading away from the camera (the
    searches find such a crossing first; an approximate strategy such as the
    single sample may step past it), and everything the buffer does not hold
    (the surface behind the foreground: that needs a scene layer without it,
    docs/recipes.md).
source: the no-foreground-leak rule of DESIGN.md sec. 2; the leak the engines
  fix with a depth compare (Godot 4's refraction depth test, Bevy's
  transmission prepass depth test: a scene sample nearer than the surface is
  replaced by the environment).
*/
#ifndef SNELL_INTERSECT_FOREGROUND_GLSL
#define SNELL_INTERSECT_FOREGROUND_GLSL




#ifndef SNELL_FOREGROUND_TOLERANCE
#  define SNELL_FOREGROUND_TOLERANCE 0.01f
#endif

SNELL_FN SnellHit snellRejectForeground(SnellHit h, vec3 origin, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) s,
                                        float tolerance) {
  if (!h.valid) {
    return h;
  }
  if (!SNELL_FINITE(origin.z) || !SNELL_FINITE(h.position.z)) {
    return snellHitMiss(h.fetches);
  }
  SnellDepthSurface texel = s;
  texel.depthFilter = SNELL_DEPTH_FILTER_NEAREST;
  SnellSurfaceSample x = snellSampleSurface(depthTex, h.uv, texel);
  h.fetches = h.fetches + 1;
  float t = tolerance > 0.0f ? min(tolerance, 1.0f) : 0.0f;
  float dNear = min(-origin.z, -h.position.z);
  if (x.valid && -x.viewZ < dNear * (1.0f - t)) {
    return snellHitMiss(h.fetches);
  }
  return h;
}

#endif
#endif
