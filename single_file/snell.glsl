// snell 0.2.0, single-file GLSL: glsl/snell/snell.glsl with every #include spliced in
// (snell-flatten --no-line). Generated: do not edit; regenerate with
// `cmake --build build --target single_file`. No #version line: put it, and on
// ES the precision statements, before this text.
/* Aggregator: all of snell. GLSL users may include single files instead. */
#ifndef SNELL_SNELL_GLSL
#define SNELL_SNELL_GLSL
/* optics/ family aggregator: every public function of glsl/snell/optics. */
#ifndef SNELL_OPTICS_GLSL
#define SNELL_OPTICS_GLSL
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

SNELL_FN vec3 snellSafeNormalize(vec3 v) {
  float len2 = dot(v, v);
  // NaN fails every comparison; an infinite component makes len2 infinite.
  if (!(len2 > 1e-30f) || !(len2 < SNELL_FLT_MAX)) {
    return vec3(0.0f, 0.0f, 0.0f);
  }
  return v * inversesqrt(len2);
}

#endif
/*
description: Snell refraction of a direction at an interface, with an explicit
  policy for total internal reflection (TIR).
use: SnellRefraction r = snellRefract(incident, normal, eta, SNELL_TIR_CRITICAL);
  incident  direction of travel towards the surface (need not be normalized)
  normal    surface normal (need not be normalized); flipped to face the
            incident ray when it points away from it
  eta       n_incident / n_transmitted (1.0f / 1.5f entering glass from air)
  policy    SNELL_TIR_ZERO      direction (0,0,0) on TIR, as GLSL refract()
            SNELL_TIR_CRITICAL  transmission angle clamped to the critical angle:
                                the ray tangent to the surface (Wyman 2005,
                                Oliveira & Brauwers 2007 sec. 5)
            SNELL_TIR_REFLECT   mirror reflection on TIR
contract:
  - r.direction is unit length, or (0,0,0) exactly when r.valid is false or
    (TIR and SNELL_TIR_ZERO);
  - r.tir is true when eta^2 (1 - cos_i^2) > 1, evaluated as
    (1 - eta^2) + eta^2 cos_i^2 < 0 for eta < 8 (every pair of real
    materials), and as eta |i + cos_i n| > 1 from 8 up (so normal incidence
    never reflects): there the first form loses about eta^2 2^-23 of
    cos_t^2 to the rounding of cos_i, and past 4096 1 - eta^2 itself rounds;
  - eta = 1 returns the normalized incident direction (up to rounding);
  - r.valid is false (direction 0, tir false) when incident or normal is zero,
    denormal-small, NaN or infinite, or eta is not a finite positive normal
    number (a denormal eta counts as 0, the prelude's rule: a runtime that
    flushes denormals, SwiftShader's WebGL 2 among them, sees 0 there);
  - at normal incidence under CRITICAL the tangent is undefined, but TIR cannot
    happen there (sin_i = 0), so the case does not arise.
source: Snell's law in vector form: t = eta i + (eta cos_i - cos_t) n with
  cos_t = sqrt(1 - eta^2 (1 - cos_i^2)) (GLSL 4.50 spec, refract()).
*/
#ifndef SNELL_OPTICS_REFRACT_GLSL
#define SNELL_OPTICS_REFRACT_GLSL



#define SNELL_TIR_ZERO 0
#define SNELL_TIR_CRITICAL 1
#define SNELL_TIR_REFLECT 2

struct SnellRefraction {
  vec3 direction;
  bool tir;
  bool valid;
};

SNELL_FN SnellRefraction snellRefract(vec3 incident, vec3 normal, float eta, int policy) {
  SnellRefraction r;
  r.direction = vec3(0.0f, 0.0f, 0.0f);
  r.tir = false;
  r.valid = false;
  vec3 i = snellSafeNormalize(incident);
  vec3 n = snellSafeNormalize(normal);
  // eta >= FLT_MIN is false for NaN, 0 and denormals; eta <= FLT_MAX is false for +Inf.
  if (dot(i, i) == 0.0f || dot(n, n) == 0.0f || !(eta >= SNELL_FLT_MIN) || !(eta <= SNELL_FLT_MAX)) {
    return r;
  }
  r.valid = true;
  float cosI = -dot(n, i);
  if (cosI < 0.0f) {
    n = -n;
    cosI = -cosI;
  }
  cosI = min(cosI, 1.0f);
  // cos_t^2 = 1 - eta^2 (1 - cos_i^2), written as (1 - eta^2) + eta^2 cos_i^2: the
  // same value, but exact for eta = 1 and accurate near grazing incidence, where
  // 1 - cos_i^2 would round away the small cos_i^2.
  // From eta = 8 up the float cos_i near 1 (its ulp 2^-24, and the rounding before) costs about eta^2 2^-23
  // of cos_t^2, and above 4096 1 - eta^2 rounds (at normal incidence cos_t^2 came out 0 and the direction
  // cancelled to zero): there sin_t = eta |i_t| from i's tangent part i_t = i + cos_i n (exactly 0 at
  // normal incidence), and t = eta i_t - cos_t n. eta^2 is not formed there: it overflows from 1.8e19.
  vec3 tangent = i + cosI * n;
  bool large = eta >= 8.0f;
  float cos2T = 0.0f;
  if (large) {
    float sinT = eta * length(tangent);
    cos2T = (1.0f - sinT) * (1.0f + sinT);
  } else {
    float eta2 = eta * eta;
    cos2T = (1.0f - eta2) + eta2 * (cosI * cosI);
  }
  if (cos2T < 0.0f) {
    r.tir = true;
    if (policy == SNELL_TIR_REFLECT) {
      r.direction = snellSafeNormalize(i + (2.0f * cosI) * n);
    } else if (policy == SNELL_TIR_CRITICAL) {
      // sin_t = 1: the transmitted ray grazes the surface along i's tangent part.
      r.direction = snellSafeNormalize(tangent);
    }
    return r;
  }
  float cosT = sqrt(cos2T);
  r.direction = large ? snellSafeNormalize(eta * tangent - cosT * n) : snellSafeNormalize(eta * i + (eta * cosI - cosT) * n);
  return r;
}

#endif
/*
description: refraction at a rough (GGX) interface as one ray: Snell's law
  about the mean normal, with cos_t^2 replaced by its mean over the
  microfacets' slopes, so that the transmitted direction turns smoothly
  through the critical angle instead of snapping to the surface's tangent.
use: SnellRefraction r = snellRefractRough(incident, normal, eta, alpha, SNELL_TIR_CRITICAL);
  incident, normal, eta, policy  as snellRefract (optics/refract.glsl)
  alpha     the GGX width of the interface's microfacet slopes
            (snellRoughConeSlope(roughness), shade/rough_cone.glsl); below
            SNELL_FLT_MIN (0, negative, denormal: GPUs may flush them) or
            NaN: a smooth interface
contract:
  - alpha below SNELL_FLT_MIN or NaN, an invalid r, TIR under ZERO or
    REFLECT, or eta >= 8 (no pair of real materials): exactly
    r = snellRefract(incident, normal, eta, policy), bit for bit.
  - otherwise r.valid and r.tir are snellRefract's (TIR about the mean normal,
    so that a caller's choice between leaving and reflecting is unchanged),
    and r.direction is the unit vector
      t = eta i + (eta cos_i - sqrt(c')) n,  c' = min(1, (c + sqrt(c^2 + w^2)) / 2),
    with i, n, cos_i as snellRefract forms them (n facing i), the smooth
    c = cos_t^2 = (1 - eta^2) + eta^2 cos_i^2 (negative under TIR) and
    w = 2 eta^2 sin_i cos_i min(alpha, 1);
    (c + sqrt(c^2 + w^2)) / 2 is evaluated as w^2 / (2 (sqrt(c^2 + w^2) - c))
    for c < 0, where the first form cancels.
  - c' >= max(c, 0): the rough ray leaves at least as near the normal as the
    smooth one where Snell allows it, and leaves the surface (c' > 0) under
    TIR, where the smooth ray grazes; c' -> max(c, 0) far from the critical angle (|c| >> w), and
    c' = max(c, 0) at normal and grazing incidence (w = 0); t is a continuous function of the
    incidence with a bounded derivative at the critical angle (the smooth
    cos_t = sqrt(c) has an infinite one there: a ray near it swings over the
    scene behind as the object or the camera moves by a fraction of a pixel).
  - every output is finite; never NaN.
derivation: a microfacet tilted by slope x in the plane of incidence meets
  the ray at the incidence angle theta_i - atan(x), so to first order in x its
  cos_t^2 is c + k x, k = dc/dtheta_i = -2 eta^2 sin_i cos_i. GGX's slopes
  (Walter et al. 2007, eq. 33 written over slopes: P(x, y) = 1 / (pi alpha^2
  (1 + (x^2 + y^2) / alpha^2)^2)) have the marginal p(x) = alpha^2 / (2 (x^2 +
  alpha^2)^(3/2)) in the plane, a Student's t with 2 degrees of freedom, and
  for it the mean of max(c + k x, 0) (a facet past TIR leaves along the
  surface, as SNELL_TIR_CRITICAL has it) is exactly (c + sqrt(c^2 + w^2)) / 2
  with w = |k| alpha (its second derivative in c is the density of k x,
  w^2 / (2 (c^2 + w^2)^(3/2))). The direction is the
  one whose cos_t^2 is that mean. First order in the tilt: against the exact
  mean over both slopes (tests/unit/optics_refract_rough_test.cpp) c' is
  0.002 high at the critical angle for alpha 0.0225 (roughness 0.15), 0.026
  for alpha 0.09 (0.3), 0.14 for alpha 0.25 (0.5), where the concave c and the
  tilts across the plane of incidence pull the exact mean lower.
source: B. Walter, S. Marschner, H. Li, K. Torrance, "Microfacet Models for
  Refraction through Rough Surfaces", EGSR 2007, eq. 33 (GGX) and eq. 40
  (refraction about a microfacet normal); Snell's law as optics/refract.glsl.
*/
#ifndef SNELL_OPTICS_REFRACT_ROUGH_GLSL
#define SNELL_OPTICS_REFRACT_ROUGH_GLSL




SNELL_FN SnellRefraction snellRefractRough(vec3 incident, vec3 normal, float eta, float alpha, int policy) {
  SnellRefraction r = snellRefract(incident, normal, eta, policy);
  if (!(alpha >= SNELL_FLT_MIN) || !r.valid || (r.tir && policy != SNELL_TIR_CRITICAL) || eta >= 8.0f) {
    return r;
  }
  vec3 i = snellSafeNormalize(incident);
  vec3 n = snellSafeNormalize(normal);
  float cosI = -dot(n, i);
  if (cosI < 0.0f) {
    n = -n;
    cosI = -cosI;
  }
  cosI = min(cosI, 1.0f);
  float sinI = length(i + cosI * n);
  float eta2 = eta * eta;
  float c = (1.0f - eta2) + eta2 * (cosI * cosI);
  float w = 2.0f * eta2 * sinI * cosI * min(alpha, 1.0f);
  float root = sqrt(c * c + w * w);
  float mean = c < 0.0f ? (w * w) / (2.0f * (root - c)) : 0.5f * (c + root);
  r.direction = snellSafeNormalize(eta * i + (eta * cosI - sqrt(min(mean, 1.0f))) * n);
  return r;
}

#endif
/*
description: G. Oliveira's approximate refracted ray: the incident direction
  plus the inverted normal weighted by a made-up "refraction factor",
  normalized. No angles, no square root of Snell's law; the factor has nothing
  to do with an index of refraction (0: no bending, large: straight down -N).
use: vec3 t = snellApproxRefract(incident, normal, factor);
  incident  direction of travel towards the surface (need not be normalized);
            the paper's camera_ray is its negation (vertex to eye)
  normal    surface normal (need not be normalized); flipped to face the
            incident ray when it points away from it, as in snellRefract
  factor    refraction factor >= 0 (the paper's refraction_coeff)
options: -
contract:
  - returns normalize(i - factor * n) with i = normalize(incident) and n the
    unit normal facing the incident ray (dot(i, n) <= 0): a unit vector;
  - factor 0 returns i (up to rounding); a negative or NaN factor is treated
    as 0;
    as factor grows the result tends to -n; factor = +inf returns -n;
    for factor > 1 it is evaluated as normalize(i / factor - n) so huge
    factors never overflow;
  - the sum never vanishes: for factor > 0 its component along n is
    dot(i, n) - factor < 0, and for factor 0 it is i itself;
  - returns (0,0,0) when incident or normal is zero, denormal-small, NaN or
    infinite.
source: G. Oliveira, "Refractive Texture Mapping, Part Two", Gamasutra 2000,
  Equation 8 ("adding the incident ray with the inverted normal and
  multiplying a factor to the normal") and Listing 4
  (refracted = -(normal * refraction_coeff + camera_ray), normalized).
*/
#ifndef SNELL_OPTICS_APPROX_REFRACT_GLSL
#define SNELL_OPTICS_APPROX_REFRACT_GLSL



SNELL_FN vec3 snellApproxRefract(vec3 incident, vec3 normal, float factor) {
  vec3 i = snellSafeNormalize(incident);
  vec3 n = snellSafeNormalize(normal);
  if (dot(i, i) == 0.0f || dot(n, n) == 0.0f) {
    return vec3(0.0f, 0.0f, 0.0f);
  }
  if (dot(i, n) > 0.0f) {
    n = -n;
  }
  // A comparison, not max(): max() with a NaN operand is undefined in GLSL.
  float k = factor > 0.0f ? factor : 0.0f;
  if (k > 1.0f) {
    return snellSafeNormalize(i * (1.0f / k) - n);
  }
  return snellSafeNormalize(i - k * n);
}

#endif
/*
description: exact Fresnel reflectance of a smooth dielectric interface for
  unpolarized light: the average of the s- and p-polarized reflectances, 1
  under total internal reflection.
use: float F = snellFresnelDielectric(cosI, eta);
  cosI  cosine of the angle between the incident ray and the normal; its sign
        is ignored (either orientation of the normal works)
  eta   n_incident / n_transmitted (1.0f / 1.5f entering glass from air);
        snellIorToEta(nI, nT) builds it
options: -
contract:
  - result in [0, 1]; never NaN;
  - |cosI| is clamped to [0, 1]; a NaN cosI is treated as 0 (grazing), so the
    result is 1;
  - TIR (eta^2 (1 - cos_i^2) >= 1, evaluated as cos_t^2 = (1 - eta^2) +
    eta^2 cos_i^2 <= 0, as in snellRefract) gives exactly 1; at sin_t = 1 the formula's
    limit is 1 as well, so the switch is continuous;
  - eta NaN, below 1e-30 (zero, negative, denormal: GPUs may flush them) or
    +inf gives 1 (treated as an opaque mirror: nothing is
    transmitted); finite positive eta is clamped to [1e-6, 1e6], far outside
    any physical ratio, so that no product overflows;
  - eta = 1 gives 0 except at grazing incidence (cosI = 0), where it is 1
    (the TIR branch: sin_t = 1).
source: Fresnel equations for dielectrics (e.g. Born & Wolf, Principles of
  Optics, sec. 1.5.2; Pharr, Jakob & Humphreys, PBRT 3rd ed., sec. 8.2.1):
  r_s = (eta cos_i - cos_t) / (eta cos_i + cos_t),
  r_p = (cos_i - eta cos_t) / (cos_i + eta cos_t),
  F = (r_s^2 + r_p^2) / 2, cos_t = sqrt(1 - eta^2 (1 - cos_i^2)),
  written with eta = n_i / n_t (each ratio divided through by n_t).
*/
#ifndef SNELL_OPTICS_FRESNEL_DIELECTRIC_GLSL
#define SNELL_OPTICS_FRESNEL_DIELECTRIC_GLSL


SNELL_FN float snellFresnelDielectric(float cosI, float eta) {
  // Comparisons are false for NaN; eta < FLT_MAX is false for +inf.
  if (!(eta >= 1e-30f) || !(eta < SNELL_FLT_MAX)) {
    return 1.0f;
  }
  float e = min(max(eta, 1e-6f), 1e6f);
  float c = abs(cosI);
  // NaN: grazing. Tested before min(): GPUs return 1 for min(NaN, 1) (llvmpipe),
  // GLM returns NaN; and not as `c > 0 ? .. : 0`, which compilers rewrite as
  // cosI != 0, true for NaN.
  if (!(c >= 0.0f)) {
    return 1.0f;
  }
  c = min(c, 1.0f);
  // cos_t^2 = 1 - eta^2 (1 - cos_i^2), as (1 - eta^2) + eta^2 cos_i^2 (exact for
  // eta = 1, accurate at grazing incidence), the same form as snellRefract.
  float e2 = e * e;
  float cos2T = (1.0f - e2) + e2 * (c * c);
  if (cos2T <= 0.0f) {
    return 1.0f;
  }
  float cosT = sqrt(cos2T);  // > 0 here, so no denominator vanishes
  float rs = (e * c - cosT) / (e * c + cosT);
  float rp = (c - e * cosT) / (c + e * cosT);
  return 0.5f * (rs * rs + rp * rp);
}

#endif
/*
description: Schlick's approximation of the Fresnel reflectance,
  F = f0 + (1 - f0) (1 - cos_i)^5.
use: float F = snellFresnelSchlick(cosI, f0);
  cosI  cosine of the angle between the incident ray and the normal; its sign
        is ignored
  f0    reflectance at normal incidence, e.g. snellIorToF0(1.0f, 1.5f) = 0.04f
  Leaving a denser medium (n_i > n_t) Schlick knows nothing about TIR: pass the
  cosine of the transmitted angle there, or use snellFresnelDielectric.
options: -
contract:
  - result in [f0, 1] (so in [0, 1]); never NaN;
  - |cosI| is clamped to [0, 1]; a NaN cosI is treated as 0 (grazing): 1;
  - f0 is clamped to [0, 1]; a NaN f0 is treated as 1 (result 1);
  - the fifth power is written as multiplications (no pow), so GLSL, HLSL and
    C++ round it identically.
source: C. Schlick, "An Inexpensive BRDF Model for Physically-based
  Rendering", Computer Graphics Forum 13(3), 1994, eq. 24.
*/
#ifndef SNELL_OPTICS_FRESNEL_SCHLICK_GLSL
#define SNELL_OPTICS_FRESNEL_SCHLICK_GLSL


SNELL_FN float snellFresnelSchlick(float cosI, float f0) {
  float c = abs(cosI);
  // NaN: grazing, result 1. Tested before min(): GPUs return 1 for min(NaN, 1)
  // (llvmpipe), GLM returns NaN; and not as `c > 0 ? .. : 0`, which compilers
  // rewrite as cosI != 0, true for NaN.
  if (!(c >= 0.0f)) {
    return 1.0f;
  }
  c = min(c, 1.0f);
  // Comparisons rather than clamp(): clamp() of a NaN is undefined in GLSL.
  float f = f0 > 0.0f ? min(f0, 1.0f) : (f0 <= 0.0f ? 0.0f : 1.0f);
  float m = 1.0f - c;
  float m2 = m * m;
  return f + (1.0f - f) * (m2 * m2 * m);
}

#endif
/*
description: Sousa's artist-tuned Fresnel term for water and glass,
  max(bias + (1 - bias) (1 - N.L)^power, 0).
use: float F = snellFresnelBiasPower(nDotL, bias, power);
  nDotL  cosine between the unit normal and the unit vector towards the eye
         (Sousa: NdotL = max(dot(vEye, vReflBump), 0))
  bias   reflectance at normal incidence (Sousa: 0.2 water, 0.4 glass)
  power  falloff exponent (Sousa: 5.0 for both)
options: -
contract:
  - nDotL is saturated to [0, 1] as the water listing does with max(.., 0) (and
    the upper clamp keeps pow() off a negative base); a NaN nDotL is treated
    as 0 (facing = 1);
  - power is clamped to [0, 1e6]; power below 1e-30 (0, negative, denormal)
    or NaN makes the pow term exactly 1 (x^0 = 1; GLSL leaves pow(0, 0) undefined); a base of exactly 0
    with power > 0 gives 0 without calling pow;
  - bias is clamped to [-1e6, 1e6]; a NaN bias is treated as 1;
  - result = max(bias + (1 - bias) t, 0) with t in [0, 1]: in [bias, 1] for
    bias in [0, 1]; Sousa's formula does not cap bias > 1 and neither does
    this; never NaN or infinite.
source: T. Sousa, "Generic Refraction Simulation", GPU Gems 2, ch. 19 (2005),
  Example 19-3 (Fresnel(NdotL, fresnelBias, fresnelPow)), used with
  (0.2, 5.0) in Example 19-4 (water) and (0.4, 5.0) in Example 19-5 (glass).
*/
#ifndef SNELL_OPTICS_FRESNEL_BIAS_POWER_GLSL
#define SNELL_OPTICS_FRESNEL_BIAS_POWER_GLSL


SNELL_FN float snellFresnelBiasPower(float nDotL, float bias, float power) {
  // Comparisons rather than clamp()/max(): they are undefined for NaN in GLSL.
  float c = nDotL > 0.0f ? min(nDotL, 1.0f) : 0.0f;
  float facing = 1.0f - c;
  // Below 1e-30 counts as 0: GPUs may flush denormals, and pow(0, tiny) is 0.
  float p = power >= 1e-30f ? min(power, 1e6f) : 0.0f;
  float b = bias >= -1e6f ? min(bias, 1e6f) : (bias < 0.0f ? -1e6f : 1.0f);
  float t = 1.0f;
  if (p > 0.0f) {
    t = facing > 0.0f ? pow(facing, p) : 0.0f;
  }
  return max(b + (1.0f - b) * t, 0.0f);
}

#endif
/*
description: the ice paper's cheap Fresnel term, f = (1 - |e.n|)^3: 0 looking
  straight at the surface, 1 at grazing angles.
use: float f = snellFresnelCubic(eye, normal);
  eye     the eye vector; either orientation works (the paper's e runs from the
          viewer to the vertex, the vertex-to-eye vector gives the same result)
  normal  surface normal, either orientation
  Neither needs to be normalized.
options: -
contract:
  - result in [0, 1]: f = (1 - c)^3 with c = |dot(normalize(eye),
    normalize(normal))| clamped to [0, 1];
  - sign convention: the paper writes (1 - e.n)^3 with e from the viewer to
    the vertex, which read literally gives values in [1, 8] on front faces
    (e.n < 0); the intended term (0 head-on, 1 at grazing) is (1 - cos)^3 with
    cos the unsigned cosine, which is what this computes;
  - eye or normal zero, denormal-small, NaN or infinite: treated as grazing,
    result 1.
source: "Real-Time Ice Rendering" (ice shader report), sec. 3.2, equation 4,
  f = (1 - e.n)^3, after Jensen & Golias 2001.
*/
#ifndef SNELL_OPTICS_FRESNEL_CUBIC_GLSL
#define SNELL_OPTICS_FRESNEL_CUBIC_GLSL



SNELL_FN float snellFresnelCubic(vec3 eye, vec3 normal) {
  vec3 e = snellSafeNormalize(eye);
  vec3 n = snellSafeNormalize(normal);
  if (dot(e, e) == 0.0f || dot(n, n) == 0.0f) {
    return 1.0f;
  }
  float c = min(abs(dot(e, n)), 1.0f);
  float m = 1.0f - c;
  return m * m * m;
}

#endif
/*
description: relative index of refraction eta = n_incident / n_transmitted, the
  eta that snellRefract and snellFresnelDielectric take.
use: float eta = snellIorToEta(1.0f, 1.5f);  // air into glass: 0.6667
  iorIncident     absolute IOR of the medium the ray travels in
  iorTransmitted  absolute IOR of the medium it enters
options: -
contract:
  - either IOR NaN, below 1e-30 (zero, negative, denormal: GPUs may flush
    denormals to 0, so they cannot count as valid) or +inf: returns 1 (no
    bending, no reflection: the interface is ignored);
  - otherwise iorIncident / iorTransmitted clamped to [1e-6, 1e6] (finite,
    positive, and far outside any physical ratio), so the result is always a
    valid eta for snellRefract.
source: Snell's law n_1 sin(theta_1) = n_2 sin(theta_2) (G. Oliveira 2000,
  Equation 7), so sin(theta_2) = (n_1 / n_2) sin(theta_1).
*/
#ifndef SNELL_OPTICS_IOR_TO_ETA_GLSL
#define SNELL_OPTICS_IOR_TO_ETA_GLSL


SNELL_FN float snellIorToEta(float iorIncident, float iorTransmitted) {
  if (!(iorIncident >= 1e-30f) || !(iorIncident < SNELL_FLT_MAX) || !(iorTransmitted >= 1e-30f) ||
      !(iorTransmitted < SNELL_FLT_MAX)) {
    return 1.0f;
  }
  return min(max(iorIncident / iorTransmitted, 1e-6f), 1e6f);
}

#endif
/*
description: reflectance at normal incidence from two indices of refraction,
  f0 = ((n1 - n2) / (n1 + n2))^2 (0.04 for air/glass 1.5), the f0 of
  snellFresnelSchlick.
use: float f0 = snellIorToF0(1.0f, 1.5f);
options: -
contract:
  - exactly symmetric in its arguments; result in [0, 1];
  - evaluated as ((n1/2 - n2/2) / (n1/2 + n2/2))^2: halving is exact, keeps the
    sum from overflowing, and the difference of close IORs stays exact (a form
    through eta = n1 / n2 would lose digits there);
  - either IOR invalid for snellIorToEta (NaN, below 1e-30, +inf): 0 (no
    reflection), matching snellIorToEta's eta = 1.
source: normal-incidence limit of the Fresnel equations (cos_i = cos_t = 1 in
  r_s, r_p); Schlick 1994, eq. 24's f0.
*/
#ifndef SNELL_OPTICS_IOR_TO_F0_GLSL
#define SNELL_OPTICS_IOR_TO_F0_GLSL


SNELL_FN float snellIorToF0(float iorIncident, float iorTransmitted) {
  if (!(iorIncident >= 1e-30f) || !(iorIncident < SNELL_FLT_MAX) || !(iorTransmitted >= 1e-30f) ||
      !(iorTransmitted < SNELL_FLT_MAX)) {
    return 0.0f;
  }
  float a = 0.5f * iorIncident;
  float b = 0.5f * iorTransmitted;
  float r = (a - b) / (a + b);
  return r * r;
}

#endif
/*
description: two-sided refraction on the cheap: blend the front-face normal
  with the (negated) back-face normal, then refract once with the result
  instead of refracting at both interfaces. Not physically correct; fine for
  strongly distorting materials such as ice.
use: vec3 nr = snellIceNormalBlend(frontNormal, backNormal, a);
     vec3 nr = snellIceNormalBlend(frontNormal, backNormal);  // a = SNELL_ICE_NORMAL_BLEND
     then snellRefract(eye, nr, eta, policy) (the paper's equation 2).
  frontNormal  outward normal of the front face at the pixel
  backNormal   outward normal of the back face at the pixel, as stored by a
               back-face normal pass (it points away from the viewer; the
               equation negates it). Neither needs to be normalized.
  a            share of the back-face normal in [0, 1]
options:
  SNELL_ICE_NORMAL_BLEND  default a (0.33f, the value used in the paper)
contract:
  - returns normalize((1 - a) nf - a nb) with nf, nb the normalized inputs: a
    unit vector, or (0,0,0) when frontNormal is invalid;
  - a is clamped to [0, 1]; a NaN a uses SNELL_ICE_NORMAL_BLEND;
  - a = 0 returns nf; a = 1 returns -nb;
  - frontNormal zero, denormal-small, NaN or infinite: (0,0,0);
  - backNormal invalid (same tests): nf (one-sided refraction);
  - the blend vanishes (nb = nf with a = 0.5, or a direction lost to
    cancellation): nf.
source: "Real-Time Ice Rendering", sec. 3.2, equation 1,
  n_r = (1 - a) n_f - a n_b, a = 0.33.
*/
#ifndef SNELL_OPTICS_ICE_NORMAL_BLEND_GLSL
#define SNELL_OPTICS_ICE_NORMAL_BLEND_GLSL



#ifndef SNELL_ICE_NORMAL_BLEND
#  define SNELL_ICE_NORMAL_BLEND 0.33f
#endif

SNELL_FN vec3 snellIceNormalBlend(vec3 frontNormal, vec3 backNormal, float a) {
  vec3 nf = snellSafeNormalize(frontNormal);
  if (dot(nf, nf) == 0.0f) {
    return vec3(0.0f, 0.0f, 0.0f);
  }
  vec3 nb = snellSafeNormalize(backNormal);
  if (dot(nb, nb) == 0.0f) {
    return nf;
  }
  // Comparisons rather than clamp(): clamp() of a NaN is undefined in GLSL.
  float w = a >= 0.0f ? min(a, 1.0f) : (a < 0.0f ? 0.0f : SNELL_ICE_NORMAL_BLEND);
  vec3 r = snellSafeNormalize((1.0f - w) * nf - w * nb);
  if (dot(r, r) == 0.0f) {
    return nf;
  }
  return r;
}

SNELL_FN vec3 snellIceNormalBlend(vec3 frontNormal, vec3 backNormal) {
  return snellIceNormalBlend(frontNormal, backNormal, SNELL_ICE_NORMAL_BLEND);
}

#endif
/*
description: Beer-Lambert absorption: the transmittance exp(-sigma d) of a
  homogeneous medium with absorption coefficient sigma (per colour channel)
  over a path of length d.
use: vec3 T = snellBeerLambert(absorption, dist); color *= T;
  absorption  sigma_a per channel, in inverse distance units (>= 0)
  dist        path length inside the medium, same units
options: -
contract:
  - result components in [0, 1]; never NaN;
  - dist negative or NaN is treated as 0 (result (1,1,1)); +inf is clamped
    to FLT_MAX;
  - each absorption component negative or NaN is treated as 0 (that channel
    is 1: a medium never amplifies); +inf is clamped to FLT_MAX, so
    0 * inf never occurs (zero distance always gives 1);
  - very large sigma d gives 0 (exp underflow; a GPU may flush the denormal
    tail to 0 earlier than the C++ build); the exponent is clamped to 1e30
    (exp(-1e30) is already 0), which keeps it finite on drivers that fold
    exp's log2(e) factor into sigma or d (FLT_MAX * 1.44 overflows, and
    times a zero distance would give NaN; llvmpipe does: docs/DESIGN.md).
source: Beer-Lambert law, T = exp(-sigma_a d) (e.g. Pharr, Jakob & Humphreys,
  PBRT 3rd ed., sec. 11.1, transmittance of a homogeneous medium).
*/
#ifndef SNELL_OPTICS_BEER_LAMBERT_GLSL
#define SNELL_OPTICS_BEER_LAMBERT_GLSL


SNELL_FN vec3 snellBeerLambert(vec3 absorption, float dist) {
  // Comparisons rather than clamp()/max(): they are undefined for NaN in GLSL.
  float d = dist > 0.0f ? min(dist, SNELL_FLT_MAX) : 0.0f;
  vec3 s = vec3(absorption.x > 0.0f ? min(absorption.x, SNELL_FLT_MAX) : 0.0f,
                absorption.y > 0.0f ? min(absorption.y, SNELL_FLT_MAX) : 0.0f,
                absorption.z > 0.0f ? min(absorption.z, SNELL_FLT_MAX) : 0.0f);
  // The min() on the product, not only on the factors: llvmpipe lowers exp(x)
  // to exp2(x * log2(e)) and reassociates that constant onto a factor,
  // (s * log2(e)) * d, which is inf * 0 = NaN for s = FLT_MAX, d = 0. A min()
  // in between keeps the constant off s and d; no NaN can reach it (s, d >= 0).
  return exp(-min(s * d, vec3(1e30f)));
}

#endif
/*
description: the angle between two directions, in radians [0, pi], accurate
  for tiny and near-pi angles and identical on every backend.
use: float theta = snellAngleBetween(a, b);  // neither needs to be normalized
options: -
contract:
  - theta = 2 asin(|u - v| / 2) for the unit vectors u, v (or pi - 2 asin(|u + v|
    / 2) when that argument is smaller), which keeps full relative precision
    for small angles where acos(dot(u, v)) loses it all;
  - asin is evaluated here with plain arithmetic and sqrt (Taylor series to
    x^17 on [0, 1/2], error < 5e-8, and asin(x) = pi/2 - 2 asin(sqrt((1 - x) / 2))
    above), because GPU drivers lower the asin builtin to cheap polynomials
    (absolute error ~1e-4 on Mesa), which ruins ratios of small angles such as
    Wyman's theta_t / theta_i;
  - a or b zero, denormal-small, NaN or infinite: 0.
source: the half-chord identity |u - v| = 2 sin(theta / 2) for unit vectors;
  Maclaurin series of asin (Abramowitz & Stegun, eq. 4.4.40).
*/
#ifndef SNELL_OPTICS_ANGLE_BETWEEN_GLSL
#define SNELL_OPTICS_ANGLE_BETWEEN_GLSL



SNELL_FN float snellAngleBetween(vec3 a, vec3 b) {
  vec3 u = snellSafeNormalize(a);
  vec3 v = snellSafeNormalize(b);
  if (dot(u, u) == 0.0f || dot(v, v) == 0.0f) {
    return 0.0f;
  }
  float chordMinus = length(u - v);
  float chordPlus = length(u + v);
  // chordMinus^2 + chordPlus^2 = 4, so the smaller half-chord is <= sqrt(2)/2.
  float x = min(0.5f * min(chordMinus, chordPlus), 1.0f);
  // asin(x): series on [0, 1/2]; above, reduce with w = sqrt((1 - x) / 2) <= 1/2.
  bool reduced = x > 0.5f;
  float y = reduced ? sqrt(0.5f * (1.0f - x)) : x;
  float y2 = y * y;
  float p = 0.0115518009f;
  p = p * y2 + 0.0139648438f;
  p = p * y2 + 0.0173527644f;
  p = p * y2 + 0.0223721591f;
  p = p * y2 + 0.0303819444f;
  p = p * y2 + 0.0446428571f;
  p = p * y2 + 0.075f;
  p = p * y2 + 0.166666667f;
  float asinY = y + y * y2 * p;
  float asinX = reduced ? 0.5f * SNELL_PI - 2.0f * asinY : asinY;
  return chordMinus <= chordPlus ? 2.0f * asinX : SNELL_PI - 2.0f * asinX;
}

#endif
/*
description: Wyman's estimate of the distance a refracted ray travels inside an
  object before it reaches the back surface: interpolate between the thickness
  along the view direction (dV) and along the inverted normal (dN) by the
  ratio of the transmission and incidence angles. Then P2 ~ P1 + d T1
  (equation 1).
use: float d = snellWymanDistance(thetaT, thetaI, dV, dN);
     float d = snellWymanDistanceVec(incident, normal, refracted, dV, dN);
  thetaT     angle between the refracted ray T1 and -N1, radians
  thetaI     angle between the incident (view) ray V and -N1, radians
  dV         thickness along the view ray (back depth minus front depth)
  dN         thickness along -N1 (per vertex, precomputed)
  incident   direction of travel of V (need not be normalized)
  normal     N1, either orientation (flipped to face the incident ray)
  refracted  T1, e.g. snellRefract(...).direction
options: -
contract:
  - snellWymanDistance returns r dV + (1 - r) dN, evaluated as
    dN + r (dV - dN), with r = thetaT / thetaI;
  - angles are taken by absolute value; r is clamped to [0, 1], the range the
    heuristic is defined on (entering a denser medium: eta = n_i / n_t <= 1, so
    thetaT <= thetaI; r = 1 means eta = 1: d = dV; r = 0 an infinite IOR:
    d = dN); leaving a denser medium (r > 1) is clamped to dV rather than
    extrapolated;
  - normal incidence (|thetaI| < 1e-30, which also covers denormals that GPUs
    may flush to 0) or a NaN ratio: r = 1, d = dV. The limit of thetaT /
    thetaI there is eta, but at normal incidence the view ray runs
    along -N1, so dV and dN measure the same segment and any r gives the same
    d; dV is the measured one;
  - dV, dN negative or NaN are treated as 0, +inf is clamped to FLT_MAX; the
    result lies between them, so it is finite and >= 0;
  - snellWymanDistanceVec measures the angles with snellAngleBetween
    (thetaI = angle(V, -N1), thetaT = angle(T1, -N1)); if any of the three
    vectors is zero, denormal-small, NaN or infinite (e.g. a TIR result of
    SNELL_TIR_ZERO) it returns the normal-incidence value, d = dV.
source: M. M. Oliveira & M. Brauwers, "Real-Time Refraction Through
  Deformable Objects", I3D 2007, sec. 2, equations 1 and 2 (after C. Wyman,
  "An Approximate Image-Space Approach for Interactive Refraction",
  SIGGRAPH 2005): d~ = (theta_t / theta_i) d_V + (1 - theta_t / theta_i) d_N.
*/
#ifndef SNELL_OPTICS_WYMAN_DISTANCE_GLSL
#define SNELL_OPTICS_WYMAN_DISTANCE_GLSL




SNELL_FN float snellWymanDistance(float thetaT, float thetaI, float dV, float dN) {
  float ti = abs(thetaI);
  float tt = abs(thetaT);
  float r = 1.0f;
  if (ti >= 1e-30f) {
    float q = tt / ti;
    // Comparisons rather than clamp(): clamp() of a NaN is undefined in GLSL.
    r = q >= 0.0f ? min(q, 1.0f) : 1.0f;
  }
  float v = dV > 0.0f ? min(dV, SNELL_FLT_MAX) : 0.0f;
  float n = dN > 0.0f ? min(dN, SNELL_FLT_MAX) : 0.0f;
  return n + r * (v - n);
}

SNELL_FN float snellWymanDistanceVec(vec3 incident, vec3 normal, vec3 refracted, float dV, float dN) {
  vec3 i = snellSafeNormalize(incident);
  vec3 n = snellSafeNormalize(normal);
  vec3 t = snellSafeNormalize(refracted);
  if (dot(i, i) == 0.0f || dot(n, n) == 0.0f || dot(t, t) == 0.0f) {
    return snellWymanDistance(0.0f, 0.0f, dV, dN);
  }
  if (dot(i, n) > 0.0f) {
    n = -n;
  }
  return snellWymanDistance(snellAngleBetween(t, -n), snellAngleBetween(i, -n), dV, dN);
}

#endif
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
#endif
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
/* shade/ family aggregator: the composed refraction techniques. */
#ifndef SNELL_SHADE_GLSL
#define SNELL_SHADE_GLSL
/*
description: Sousa's screen-space refraction, basic form: perturb the projected
  uv of the refracting pixel by a normal map's xy scaled by a small value, then
  read the scene colour (rendered without the refractive meshes) there.
use: vec3 bump = snellUnpackBump(vec3(t.x, t.y, t.z));      // t: normal-map texel
     vec2 uvP = snellPerturbUv(uv, vec2(bump.x, bump.y), 0.05f);
     vec2 uvP = snellPerturbUv(uv, vec2(bump.x, bump.y));   // scale SNELL_PERTURB_SCALE
     vec4 c = snellPerturbSample(sceneColor, uv, vec2(bump.x, bump.y), 0.05f);
  uv          projected viewport uv of the fragment (screenPos.xy / screenPos.w of
              the listing; e.g. snellPixelToUv(gl_FragCoord) or snellViewToUv)
  bump        the normal map's xy, unpacked to [-1, 1]
  scale       displacement per unit of bump, in uv units
  sceneColor  texture S: the scene without the refractive meshes (SNELL_TEX2D),
              read at mip level 0 with its own filter
options:
  SNELL_PERTURB_SCALE  default scale (0.05f, the value the chapter suggests)
contract:
  - snellUnpackBump(t) = 2 t - 1 (the listing's 2.0 * tex2D(..) - 1.0), nothing
    else: NaN propagates.
  - snellPerturbUv(uv, bump, scale) = uv + scale * bump (component-wise), with:
    a NaN or infinite uv component replaced by 0.5 (screen centre); a NaN or
    infinite displacement component scale * bump replaced by 0 (no
    perturbation); the sum clamped to [-SNELL_FLT_MAX, SNELL_FLT_MAX]. Off-screen
    results (outside [0,1]) are returned as they are: finite, never NaN.
  - snellPerturbSample reads sceneColor at snellPerturbUv(..) clamped to [0,1]^2
    (explicit clamp-to-edge, so the result does not depend on the sampler's
    wrap mode), lod 0.
source: T. Sousa, "Generic Refraction Simulation", GPU Gems 2, ch. 19 (2005),
  sec. 19.1 and Example 19-1 (newUV = screenPos.xy / screenPos.w + bumpTex.xy *
  vScale.xy).
*/
#ifndef SNELL_SHADE_PERTURB_GLSL
#define SNELL_SHADE_PERTURB_GLSL



#ifndef SNELL_PERTURB_SCALE
#  define SNELL_PERTURB_SCALE 0.05f
#endif

SNELL_FN vec3 snellUnpackBump(vec3 texel) {
  return texel * 2.0f - 1.0f;
}

SNELL_FN vec2 snellPerturbUv(vec2 uv, vec2 bump, float scale) {
  float u = SNELL_FINITE(uv.x) ? uv.x : 0.5f;
  float v = SNELL_FINITE(uv.y) ? uv.y : 0.5f;
  float du = scale * bump.x;
  float dv = scale * bump.y;
  du = SNELL_FINITE(du) ? du : 0.0f;
  dv = SNELL_FINITE(dv) ? dv : 0.0f;
  return clamp(vec2(u + du, v + dv), vec2(-SNELL_FLT_MAX, -SNELL_FLT_MAX), vec2(SNELL_FLT_MAX, SNELL_FLT_MAX));
}

SNELL_FN vec2 snellPerturbUv(vec2 uv, vec2 bump) {
  return snellPerturbUv(uv, bump, SNELL_PERTURB_SCALE);
}

SNELL_FN vec4 snellPerturbSample(SNELL_TEX2D sceneColor, vec2 uv, vec2 bump, float scale) {
  vec2 p = clamp(snellPerturbUv(uv, bump, scale), vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
  return SNELL_SAMPLE_LOD(sceneColor, p, 0.0f);
}

#endif
/*
description: screen-edge fade for perturbed (or reflected) screen-space lookups:
  1 well inside the viewport, falling linearly to 0 at its border, 0 off
  screen. Blend the perturbed sample towards the unperturbed one with it, so
  refraction does not smear the clamped edge texels.
use: float w = snellScreenEdgeFade(uvPerturbed, 0.05f);
     float w = snellScreenEdgeFade(uvPerturbed);   // width SNELL_SCREEN_EDGE_FADE
     vec4 c = mix(unperturbedColor, perturbedColor, w);
  uv     viewport uv, origin bottom-left, [0,1]^2 on screen
  width  width of the fade band, in uv units, measured inwards from each edge
options:
  SNELL_SCREEN_EDGE_FADE  default width (0.05f)
contract:
  - with e = min(u, 1 - u, v, 1 - v) (the uv distance to the nearest edge,
    negative off screen): result = clamp(e / width, 0, 1); in [0, 1], never
    NaN;
  - width is clamped to at most 0.5f; width <= 0, denormal (below the smallest
    normal float) or NaN: a hard cut, 1 on [0,1]^2 (borders included), else 0;
  - a NaN or infinite uv component: 0.
source: common screen-space reflection practice (edge attenuation of
  screen-space hits), e.g. McGuire & Mara, "Efficient GPU Screen-Space Ray
  Tracing", JCGT 3(4), 2014; applied here to Sousa's perturbed uv (GPU Gems 2,
  ch. 19, sec. 19.2, on perturbations that leave the refractive object's area).
*/
#ifndef SNELL_SHADE_PERTURB_EDGE_FADE_GLSL
#define SNELL_SHADE_PERTURB_EDGE_FADE_GLSL



#ifndef SNELL_SCREEN_EDGE_FADE
#  define SNELL_SCREEN_EDGE_FADE 0.05f
#endif

SNELL_FN float snellScreenEdgeFade(vec2 uv, float width) {
  if (!SNELL_FINITE(uv.x) || !SNELL_FINITE(uv.y)) {
    return 0.0f;
  }
  float e = min(min(uv.x, 1.0f - uv.x), min(uv.y, 1.0f - uv.y));
  if (isnan(width) || !(width >= SNELL_FLT_MIN)) {
    return e >= 0.0f ? 1.0f : 0.0f;
  }
  float w = min(width, 0.5f);
  return clamp(e / w, 0.0f, 1.0f);
}

SNELL_FN float snellScreenEdgeFade(vec2 uv) {
  return snellScreenEdgeFade(uv, SNELL_SCREEN_EDGE_FADE);
}

#endif
/*
description: Sousa's refraction mask: S's alpha is cleared to white (1) and the
  refractive meshes are written black (0) into it, so a perturbed read that
  leaves the refractive object's screen area (for example onto an occluder in
  front of it) is replaced by the unperturbed read.
use: vec4 c = snellRefractionMaskBlend(refrA, refrB);
     vec4 c = snellRefractionMasked(sceneColor, uv, vec2(bump.x, bump.y), 0.05f);
  refrA       S read at the perturbed uv (its alpha is the mask there)
  refrB       S read at the unperturbed uv
  sceneColor, uv, bump, scale  as in snellPerturbSample (perturb.glsl)
options: -
contract:
  - snellRefractionMaskBlend = refrB * w + (refrA.rgb, w) * (1 - w) with w =
    refrA.w clamped to [0, 1] (Example 19-2's vRefrB * vRefrA.w + vRefrA * (1 -
    vRefrA.w), identical for a mask in [0, 1], the result's alpha included);
    alpha 1 (outside every refractive mesh) gives refrB, alpha 0 (inside)
    gives refrA. A NaN alpha counts as 1 (unperturbed). Colours are blended
    as given (NaN colours propagate).
  - snellRefractionMasked reads S at snellPerturbUv(uv, bump, scale) and at uv,
    both clamped to [0,1]^2 (a NaN or infinite uv component reads the screen
    centre, as in snellPerturbUv), lod 0, and blends them as above.
source: T. Sousa, "Generic Refraction Simulation", GPU Gems 2, ch. 19 (2005),
  sec. 19.2 and Example 19-2.
*/
#ifndef SNELL_SHADE_REFRACTION_MASK_GLSL
#define SNELL_SHADE_REFRACTION_MASK_GLSL



SNELL_FN vec4 snellRefractionMaskBlend(vec4 refrA, vec4 refrB) {
  // isnan first: min/max/clamp of a NaN differ between GPUs and GLM.
  float w = isnan(refrA.w) ? 1.0f : clamp(refrA.w, 0.0f, 1.0f);
  return refrB * w + vec4(refrA.x, refrA.y, refrA.z, w) * (1.0f - w);
}

SNELL_FN vec4 snellRefractionMasked(SNELL_TEX2D sceneColor, vec2 uv, vec2 bump, float scale) {
  vec2 uvA = clamp(snellPerturbUv(uv, bump, scale), vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
  vec2 uvB = clamp(snellPerturbUv(uv, vec2(0.0f, 0.0f), 0.0f), vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
  vec4 refrA = SNELL_SAMPLE_LOD(sceneColor, uvA, 0.0f);
  vec4 refrB = SNELL_SAMPLE_LOD(sceneColor, uvB, 0.0f);
  return snellRefractionMaskBlend(refrA, refrB);
}

#endif
/*
description: a depth-aware refraction mask (a modern variant of Sousa's alpha
  mask): the perturbed read is rejected when the opaque scene there lies in
  front of the refracting surface (an occluder would leak into the
  refraction); otherwise it is kept even outside the refractive object's
  screen area, so no mask has to be written into S's alpha.
use: bool ok = snellRefractionDepthAccept(sceneDepth, surfaceDepth, SNELL_DEPTH_GL);
     vec4 c = snellRefractionMaskedDepth(sceneColor, sceneDepthTex, uv,
                                         vec2(bump.x, bump.y), 0.05f,
                                         gl_FragCoord.z, SNELL_DEPTH_GL);
  sceneDepth     depth-buffer value of the opaque scene at the perturbed uv
  surfaceDepth   depth-buffer value of the refracting surface at this fragment
                 (gl_FragCoord.z)
  convention     depth convention of both values (camera/conventions.glsl):
                 GL, ZERO_ONE, INFINITE_GL store near -> 0; REVERSED,
                 INFINITE_REVERSED near -> 1
  sceneDepthTex  the opaque scene's depth buffer as a texture (depth in .x),
                 read with SNELL_SAMPLE_LOD at lod 0: use NEAREST filtering
                 (a filtered depth blends silhouettes)
  sceneColor, uv, bump, scale  as in snellPerturbSample (perturb.glsl)
options: -
contract:
  - snellRefractionDepthAccept is true exactly when sceneDepth is not in front
    of surfaceDepth: sceneDepth >= surfaceDepth (near -> 0 conventions) or
    sceneDepth <= surfaceDepth (reversed conventions); equal depths accept. It
    is false when either depth is NaN or the convention is unknown. Depths are
    compared as given (no range check: both come from the same buffer format).
  - snellRefractionMaskedDepth returns S at the perturbed uv when the scene
    depth read at that same uv is accepted, else S at the unperturbed uv; uvs
    as in snellRefractionMasked (clamped to [0,1]^2, NaN -> screen centre),
    lod 0. Colours are returned as read (alpha untouched).
source: T. Sousa, "Generic Refraction Simulation", GPU Gems 2, ch. 19 (2005),
  sec. 19.2 (the leakage problem and the alpha mask, Example 19-2), with the
  mask replaced by a depth comparison (snell's variant; the chapter notes
  that the alpha mask is inaccurate where refraction would show objects not
  directly behind the refractive one: those reads are kept here).
*/
#ifndef SNELL_SHADE_REFRACTION_MASK_DEPTH_GLSL
#define SNELL_SHADE_REFRACTION_MASK_DEPTH_GLSL




SNELL_FN bool snellRefractionDepthAccept(float sceneDepth, float surfaceDepth, int convention) {
  if (isnan(sceneDepth) || isnan(surfaceDepth)) {
    return false;
  }
  if (convention == SNELL_DEPTH_GL || convention == SNELL_DEPTH_ZERO_ONE || convention == SNELL_DEPTH_INFINITE_GL) {
    return sceneDepth >= surfaceDepth;
  }
  if (convention == SNELL_DEPTH_REVERSED || convention == SNELL_DEPTH_INFINITE_REVERSED) {
    return sceneDepth <= surfaceDepth;
  }
  return false;
}

SNELL_FN vec4 snellRefractionMaskedDepth(SNELL_TEX2D sceneColor, SNELL_TEX2D sceneDepthTex, vec2 uv, vec2 bump,
                                         float scale, float surfaceDepth, int convention) {
  vec2 uvA = clamp(snellPerturbUv(uv, bump, scale), vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
  vec2 uvB = clamp(snellPerturbUv(uv, vec2(0.0f, 0.0f), 0.0f), vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
  float sceneDepth = SNELL_SAMPLE_LOD(sceneDepthTex, uvA, 0.0f).x;
  if (snellRefractionDepthAccept(sceneDepth, surfaceDepth, convention)) {
    return SNELL_SAMPLE_LOD(sceneColor, uvA, 0.0f);
  }
  return SNELL_SAMPLE_LOD(sceneColor, uvB, 0.0f);
}

#endif
/*
description: Sousa's refractive/reflective water in one pass: four animated
  bump layers averaged into one normal, the masked screen-space refraction of
  S, a planar reflection map read at a (less) perturbed uv, a per-pixel
  bias/power Fresnel term, and the deep-water colour blended in by distance.
use: SnellWaterParams p = snellWaterParams();   // the chapter's constants
     vec3 n = snellWaterBumpAverage(t0, t1, t2, t3);   // four bump texels, [0,1]
     vec4 c = snellWater(sceneColor, reflectionMap, uv, n, eyeTs, viewDistance, p);
  With refraction read your own way (for example the depth-aware mask of
  refraction_mask_depth.glsl instead of the alpha mask), compose the two reads:
     vec4 c = snellWaterCompose(reflection, refraction, n, eyeTs, viewDistance, p);
  t0..t3         the bump map read at the four wave coordinates (rgb, [0,1])
  sceneColor     texture S: the scene without the water, refraction mask in
                 alpha (water written as 0, the rest 1; see refraction_mask.glsl)
  reflectionMap  the scene mirrored through the water plane
  uv             projected viewport uv of the fragment (ScreenPos.xy / ScreenPos.w)
  bumpNormal     the averaged bump normal, tangent space (z up); need not be unit
  eye            fragment-to-eye vector in the same tangent space (the
                 listing's Eye); need not be unit
  viewDistance   the listing's Wave0.w: the fragment's distance from the eye
  reflection, refraction  (snellWaterCompose) the reflection map and scene
                 colours as read; snellWater reads them as described below
options: -
contract:
  SnellWaterParams fields (snellWaterParams() defaults, Example 19-4):
    refractionBumpScale (0.075, 0.075, 1)  bump scale for the refraction read
    reflectionBumpScale (0.02, 0.02, 1)    bump scale for the reflection read and
                                           the Fresnel term
    fresnelBias 0.2, fresnelPower 5        snellFresnelBiasPower (Example 19-3)
    deepDistance 10                        fDistScale = saturate(10 / Wave0.w)
    waterColor (0, 0.15, 0.115)            colour blended in by facing
    deepColor (0, 0.15, 0.115)             colour blended in by distance
  - snellWaterBumpAverage = normalize(2 (t0 + t1 + t2 + t3) - 4) (the average of
    the four unpacked normals, normalized); (0,0,1) when that vanishes or is not
    finite.
  - snellWater computes, with n = normalize(bumpNormal) ((0,0,1) when bumpNormal
    is zero, NaN or infinite), e = normalize(eye) ((0,0,0) likewise):
      refrBump = n * refractionBumpScale, reflBump = n * reflectionBumpScale
      reflection = reflectionMap(uv + reflBump.xy)
      refraction = snellRefractionMaskBlend(S(uv + refrBump.xy), S(uv))
      NdotL = saturate(dot(e, reflBump)) (0 when NaN), facing = 1 - NdotL
      fresnel = snellFresnelBiasPower(NdotL, fresnelBias, fresnelPower)
      fDist = saturate(deepDistance / viewDistance); 1 when viewDistance is
              NaN, <= 0 or denormal, or the quotient is NaN
      deep = refraction.rgb fDist + (1 - fDist) deepColor
      water = waterColor facing + deep (1 - facing)
      result = vec4(fresnel reflection.rgb + water, 1)
  - snellWaterCompose(reflection, refraction, bumpNormal, eye, viewDistance, p)
    is everything above after the two reads (n, e, reflBump, NdotL, fresnel,
    fDist, deep, water, result), with the given colours; snellWater returns
    snellWaterCompose of its own reads.
    Reads use snellPerturbUv (NaN uv -> screen centre, NaN displacement -> 0),
    clamped to [0,1]^2, lod 0. reflBump is not renormalized, as in the listing.
    Colours (parameters and texels) are used as given.
source: T. Sousa, "Generic Refraction Simulation", GPU Gems 2, ch. 19 (2005),
  sec. 19.3.1, Examples 19-3 and 19-4.
*/
#ifndef SNELL_SHADE_WATER_GLSL
#define SNELL_SHADE_WATER_GLSL







struct SnellWaterParams {
  vec3 refractionBumpScale;
  vec3 reflectionBumpScale;
  float fresnelBias;
  float fresnelPower;
  float deepDistance;
  vec3 waterColor;
  vec3 deepColor;
};

SNELL_FN SnellWaterParams snellWaterParams() {
  SnellWaterParams p;
  p.refractionBumpScale = vec3(0.075f, 0.075f, 1.0f);
  p.reflectionBumpScale = vec3(0.02f, 0.02f, 1.0f);
  p.fresnelBias = 0.2f;
  p.fresnelPower = 5.0f;
  p.deepDistance = 10.0f;
  p.waterColor = vec3(0.0f, 0.15f, 0.115f);
  p.deepColor = vec3(0.0f, 0.15f, 0.115f);
  return p;
}

SNELL_FN vec3 snellWaterBumpAverage(vec3 t0, vec3 t1, vec3 t2, vec3 t3) {
  vec3 n = snellSafeNormalize((t0 + t1 + t2 + t3) * 2.0f - 4.0f);
  if (dot(n, n) == 0.0f) {
    return vec3(0.0f, 0.0f, 1.0f);
  }
  return n;
}

SNELL_FN vec4 snellWaterCompose(vec4 reflection, vec4 refraction, vec3 bumpNormal, vec3 eye, float viewDistance,
                                SnellWaterParams p) {
  vec3 n = snellSafeNormalize(bumpNormal);
  if (dot(n, n) == 0.0f) {
    n = vec3(0.0f, 0.0f, 1.0f);
  }
  vec3 e = snellSafeNormalize(eye);
  vec3 reflBump = n * p.reflectionBumpScale;
  // isnan first: min/max/clamp of a NaN differ between GPUs and GLM.
  float nDotL = dot(e, reflBump);
  nDotL = isnan(nDotL) ? 0.0f : clamp(nDotL, 0.0f, 1.0f);
  float facing = 1.0f - nDotL;
  float fresnel = snellFresnelBiasPower(nDotL, p.fresnelBias, p.fresnelPower);
  float distScale = 1.0f;
  if (!isnan(viewDistance) && viewDistance >= SNELL_FLT_MIN) {
    float q = p.deepDistance / viewDistance;
    distScale = isnan(q) ? 1.0f : clamp(q, 0.0f, 1.0f);
  }
  vec3 refr = vec3(refraction.x, refraction.y, refraction.z);
  vec3 deep = refr * distScale + p.deepColor * (1.0f - distScale);
  vec3 water = p.waterColor * facing + deep * (1.0f - facing);
  vec3 c = vec3(reflection.x, reflection.y, reflection.z) * fresnel + water;
  return vec4(c.x, c.y, c.z, 1.0f);
}

SNELL_FN vec4 snellWater(SNELL_TEX2D sceneColor, SNELL_TEX2D reflectionMap, vec2 uv, vec3 bumpNormal, vec3 eye,
                         float viewDistance, SnellWaterParams p) {
  vec3 n = snellSafeNormalize(bumpNormal);
  if (dot(n, n) == 0.0f) {
    n = vec3(0.0f, 0.0f, 1.0f);
  }
  vec3 refrBump = n * p.refractionBumpScale;
  vec3 reflBump = n * p.reflectionBumpScale;
  vec2 one = vec2(1.0f, 1.0f);
  vec2 zero = vec2(0.0f, 0.0f);
  vec2 uvRefl = clamp(snellPerturbUv(uv, vec2(reflBump.x, reflBump.y), 1.0f), zero, one);
  vec2 uvRefr = clamp(snellPerturbUv(uv, vec2(refrBump.x, refrBump.y), 1.0f), zero, one);
  vec2 uvProj = clamp(snellPerturbUv(uv, zero, 0.0f), zero, one);
  vec4 reflection = SNELL_SAMPLE_LOD(reflectionMap, uvRefl, 0.0f);
  vec4 refrA = SNELL_SAMPLE_LOD(sceneColor, uvRefr, 0.0f);
  vec4 refrB = SNELL_SAMPLE_LOD(sceneColor, uvProj, 0.0f);
  return snellWaterCompose(reflection, snellRefractionMaskBlend(refrA, refrB), bumpNormal, eye, viewDistance, p);
}

#endif
/*
description: Sousa's stained glass: environment bump mapping with a 2D
  reflection map, the masked screen-space refraction of S modulated by the
  diffuse (stain) colour, blended by a bias/power Fresnel term.
use: vec4 c = snellGlass(sceneColor, reflectionMap, uv, bumpTexel, diffuse, eyeTs);
  sceneColor     texture S: the scene without the glass, refraction mask in
                 alpha (glass written as 0, the rest 1; see refraction_mask.glsl)
  reflectionMap  2D environment map indexed by the reflection vector's xy
  uv             projected viewport uv of the fragment (ScreenPos.xy / ScreenPos.w)
  bumpTexel      the bump map's texel at the base uv (rgb in [0,1], unpacked here)
  diffuse        the diffuse (stain) texture's texel at the base uv
  eye            fragment-to-eye vector in the bump map's tangent space (z up);
                 need not be unit
options:
  SNELL_GLASS_BUMP_SCALE     xy scale of the unpacked bump before normalizing (0.2f)
  SNELL_GLASS_FRESNEL_BIAS   snellFresnelBiasPower bias (0.4f)
  SNELL_GLASS_FRESNEL_POWER  snellFresnelBiasPower power (5.0f)
contract (Example 19-5, s = SNELL_GLASS_BUMP_SCALE):
  - b = normalize((2 bumpTexel - 1) * (s, s, 1)), (0,0,1) when that vanishes or
    is not finite; e = normalize(eye), (0,0,0) when eye is zero, NaN or infinite;
  - LdotN = dot(b, e) (0 when NaN); r = 2 LdotN b - e;
    env = reflectionMap((r.xy + 1) * 0.5);
  - refraction = snellRefractionMaskBlend(S(uv + b.xy), S(uv));
  - F = snellFresnelBiasPower(LdotN, bias, power) (LdotN saturated there);
  - tint = (saturate(0.1 + 0.9 diffuse.rgb), diffuse.a), a NaN diffuse.rgb
    channel counting as 1 (clear);
  - result = tint * refraction * (1 - F) + env * F (all four channels).
  Reads use snellPerturbUv (NaN uv -> screen centre) clamped to [0,1]^2, lod 0;
  an invalid eye gives F = 1 and the reflection map's centre. Other colours
  (texels, diffuse.a) are used as given.
source: T. Sousa, "Generic Refraction Simulation", GPU Gems 2, ch. 19 (2005),
  sec. 19.3.2, Example 19-5 (Fresnel(LdotN, 0.4, 5.0) of Example 19-3).
*/
#ifndef SNELL_SHADE_GLASS_GLSL
#define SNELL_SHADE_GLASS_GLSL






#ifndef SNELL_GLASS_BUMP_SCALE
#  define SNELL_GLASS_BUMP_SCALE 0.2f
#endif
#ifndef SNELL_GLASS_FRESNEL_BIAS
#  define SNELL_GLASS_FRESNEL_BIAS 0.4f
#endif
#ifndef SNELL_GLASS_FRESNEL_POWER
#  define SNELL_GLASS_FRESNEL_POWER 5.0f
#endif

SNELL_FN vec4 snellGlass(SNELL_TEX2D sceneColor, SNELL_TEX2D reflectionMap, vec2 uv, vec3 bumpTexel, vec4 diffuse,
                         vec3 eye) {
  vec3 b = snellSafeNormalize(snellUnpackBump(bumpTexel) *
                              vec3(SNELL_GLASS_BUMP_SCALE, SNELL_GLASS_BUMP_SCALE, 1.0f));
  if (dot(b, b) == 0.0f) {
    b = vec3(0.0f, 0.0f, 1.0f);
  }
  vec3 e = snellSafeNormalize(eye);
  float lDotN = dot(b, e);
  lDotN = isnan(lDotN) ? 0.0f : lDotN;
  vec3 r = b * (2.0f * lDotN) - e;
  vec2 one = vec2(1.0f, 1.0f);
  vec2 zero = vec2(0.0f, 0.0f);
  vec2 uvEnv = clamp((vec2(r.x, r.y) + 1.0f) * 0.5f, zero, one);
  vec4 env = SNELL_SAMPLE_LOD(reflectionMap, uvEnv, 0.0f);
  vec2 uvRefr = clamp(snellPerturbUv(uv, vec2(b.x, b.y), 1.0f), zero, one);
  vec2 uvProj = clamp(snellPerturbUv(uv, zero, 0.0f), zero, one);
  vec4 refraction =
      snellRefractionMaskBlend(SNELL_SAMPLE_LOD(sceneColor, uvRefr, 0.0f), SNELL_SAMPLE_LOD(sceneColor, uvProj, 0.0f));
  float f = snellFresnelBiasPower(lDotN, SNELL_GLASS_FRESNEL_BIAS, SNELL_GLASS_FRESNEL_POWER);
  // isnan first: clamp of a NaN differs between GPUs and GLM.
  vec3 d = vec3(isnan(diffuse.x) ? 1.0f : diffuse.x, isnan(diffuse.y) ? 1.0f : diffuse.y,
                isnan(diffuse.z) ? 1.0f : diffuse.z);
  vec3 t = clamp(d * 0.9f + 0.1f, vec3(0.0f, 0.0f, 0.0f), vec3(1.0f, 1.0f, 1.0f));
  vec4 tint = vec4(t.x, t.y, t.z, diffuse.w);
  return tint * refraction * (1.0f - f) + env * f;
}

#endif
/*
description: the ice shader's reflection and two-sided refraction: refract the
  eye vector once about the blend of the front normal and the negated
  back-face normal (eqs. 1-2), reflect it about the front normal (eq. 3), and
  mix the two environment colours with the cubic Fresnel term (eq. 4).
use: SnellIce s = snellIce(eyeWs, frontNormalWs, backNormalWs, 0.33f, SNELL_ICE_ETA);
     SnellIce s = snellIce(eyeWs, frontNormalWs, backNormalWs);  // a, eta defaults
     vec4 refl = texture(envCube, s.reflected), refr = texture(envCube, s.refracted);
     vec4 c = snellIceCompose(refl, refr, s.fresnel);
  eye          the paper's e: from the viewer to the surface point (need not be
               unit)
  frontNormal  outward normal of the front face (need not be unit)
  backNormal   outward normal of the back face from the back-face normal buffer
               (points away from the viewer; eq. 1 negates it)
  a            share of the back-face normal in [0, 1] (snellIceNormalBlend)
  eta          n_air / n_ice
options:
  SNELL_ICE_ETA         default eta, 1.0003f / 1.3091f (about 0.7641: the paper's
                        air/ice ratio)
  SNELL_ICE_TIR_POLICY  snellRefract's TIR policy (SNELL_TIR_REFLECT); with
                        eta < 1 TIR cannot occur
  (SNELL_ICE_NORMAL_BLEND, the default a, comes from optics/ice_normal_blend.glsl)
contract:
  - blended = snellIceNormalBlend(frontNormal, backNormal, a);
    refracted = snellRefract(eye, blended, eta, SNELL_ICE_TIR_POLICY).direction;
    reflected = e - 2 (nf . e) nf with e, nf the normalized eye and front normal;
    fresnel = snellFresnelCubic(eye, frontNormal) = (1 - |e . nf|)^3.
  - eta NaN, <= 0, denormal or infinite: 1 (no bending, refracted = e).
  - valid is false when eye or frontNormal is zero, denormal-small, NaN or
    infinite: refracted = reflected = (0,0,0), fresnel = 1. An invalid
    backNormal gives one-sided refraction about nf (snellIceNormalBlend).
  - with SNELL_TIR_ZERO as the policy a TIR gives refracted = (0,0,0) and
    fresnel 1 (everything reflected); valid stays true.
  - snellIceCompose = refraction (1 - f) + reflection f with f = fresnel clamped
    to [0, 1]; a NaN fresnel counts as 1.
source: "Real-Time Ice Rendering" (ice shader report), sec. 3.2: eq. 1 (normal
  blend, a = 0.33), eq. 2 (refraction with eta = 1.0003/1.3091), eq. 3
  (r_refl = e - 2 (e.n_f) n_f), eq. 4 (f = (1 - e.n)^3) and the mix of the two
  environment samples by f.
*/
#ifndef SNELL_SHADE_ICE_GLSL
#define SNELL_SHADE_ICE_GLSL







#ifndef SNELL_ICE_ETA
#  define SNELL_ICE_ETA (1.0003f / 1.3091f)
#endif
#ifndef SNELL_ICE_TIR_POLICY
#  define SNELL_ICE_TIR_POLICY SNELL_TIR_REFLECT
#endif

struct SnellIce {
  vec3 refracted;
  vec3 reflected;
  float fresnel;
  bool valid;
};

SNELL_FN SnellIce snellIce(vec3 eye, vec3 frontNormal, vec3 backNormal, float a, float eta) {
  SnellIce s;
  s.refracted = vec3(0.0f, 0.0f, 0.0f);
  s.reflected = vec3(0.0f, 0.0f, 0.0f);
  s.fresnel = 1.0f;
  s.valid = false;
  vec3 e = snellSafeNormalize(eye);
  vec3 nf = snellSafeNormalize(frontNormal);
  if (dot(e, e) == 0.0f || dot(nf, nf) == 0.0f) {
    return s;
  }
  s.valid = true;
  float k = (!isnan(eta) && eta >= SNELL_FLT_MIN && eta < SNELL_FLT_MAX) ? eta : 1.0f;
  vec3 nr = snellIceNormalBlend(nf, backNormal, a);
  SnellRefraction r = snellRefract(e, nr, k, SNELL_ICE_TIR_POLICY);
  s.refracted = r.direction;
  s.reflected = e - nf * (2.0f * dot(nf, e));
  s.fresnel = dot(r.direction, r.direction) == 0.0f ? 1.0f : snellFresnelCubic(e, nf);
  return s;
}

SNELL_FN SnellIce snellIce(vec3 eye, vec3 frontNormal, vec3 backNormal) {
  return snellIce(eye, frontNormal, backNormal, SNELL_ICE_NORMAL_BLEND, SNELL_ICE_ETA);
}

SNELL_FN vec4 snellIceCompose(vec4 reflection, vec4 refraction, float fresnel) {
  // isnan first: clamp of a NaN differs between GPUs and GLM.
  float f = isnan(fresnel) ? 1.0f : clamp(fresnel, 0.0f, 1.0f);
  return refraction * (1.0f - f) + reflection * f;
}

#endif
/*
description: the ice shader's crack clipping, a screen-space Boolean
  intersection: a fragment of a generic crack surface is kept only when its
  depth lies inside the [front, back] depth interval of the (convex) ice
  object at that pixel, read from the object's front- and back-face depth
  textures.
use: if (!snellIceCrackKeep(gl_FragCoord.z, frontDepth, backDepth, SNELL_DEPTH_GL)) discard;
  crackDepth  depth-buffer value of the crack fragment
  frontDepth  the ice object's front-face depth at the pixel (nearest surface)
  backDepth   the ice object's back-face depth at the pixel (farthest surface)
  convention  depth convention of all three (camera/conventions.glsl): GL,
              ZERO_ONE, INFINITE_GL store near -> 0, REVERSED and
              INFINITE_REVERSED near -> 1
options: -
contract:
  - near -> 0 conventions: keep iff frontDepth <= crackDepth <= backDepth;
    reversed conventions: keep iff frontDepth >= crackDepth >= backDepth; the
    interval includes both ends.
  - false (the fragment is clipped) when any depth is NaN or outside [0, 1]
    (not a depth-buffer value), the convention is unknown, or the interval is
    empty (front behind back: no ice at the pixel when the front texture is
    cleared to the far value and the back texture to the near value).
source: "Real-Time Ice Rendering" (ice shader report), sec. 3.3 ("If the
  value is not contained within the interval of the two sampled values
  nothing is drawn"), Figure 5.
*/
#ifndef SNELL_SHADE_ICE_CRACK_CLIP_GLSL
#define SNELL_SHADE_ICE_CRACK_CLIP_GLSL



SNELL_FN bool snellIceCrackKeep(float crackDepth, float frontDepth, float backDepth, int convention) {
  if (isnan(crackDepth) || isnan(frontDepth) || isnan(backDepth)) {
    return false;
  }
  bool inRange = (crackDepth >= 0.0f && crackDepth <= 1.0f) && (frontDepth >= 0.0f && frontDepth <= 1.0f) &&
                 (backDepth >= 0.0f && backDepth <= 1.0f);
  if (!inRange) {
    return false;
  }
  if (convention == SNELL_DEPTH_GL || convention == SNELL_DEPTH_ZERO_ONE || convention == SNELL_DEPTH_INFINITE_GL) {
    return frontDepth <= crackDepth && crackDepth <= backDepth;
  }
  if (convention == SNELL_DEPTH_REVERSED || convention == SNELL_DEPTH_INFINITE_REVERSED) {
    return frontDepth >= crackDepth && crackDepth >= backDepth;
  }
  return false;
}

#endif
/*
description: G. Oliveira's refractive texture mapping, per vertex of a
  perturbed water mesh: the approximate refracted eye ray (incident direction
  plus the inverted normal times a refraction factor) is followed down to a
  planar map lying a given depth below the mesh's rest plane, and the hit's x
  and z are mapped linearly over the mesh extent to the map's uv.
use: SnellRefractiveTextureMapParams p =
         snellRefractiveTextureMapParams(vec2(x0, z0), vec2(x1, z1), restY, depth, factor);
     p.policy = SNELL_RTM_SHRINK; p.uvMin = 0.1f; p.uvMax = 0.9f;   // optional
     SnellRefractiveTextureMapHit h = snellRefractiveTextureMap(vertexPos, vertexNormal, eyePos, p);
     uv = h.uv;
     float u = snellRefractiveTextureMapAxis(x, x_i, x_e);   // eq. 12 alone
  Space: the paper's, y up; the mesh rests in the plane y = restY spanning
  [x_i, x_e] x [z_i, z_e] and the map lies in the plane y = restY - depth.
  vertex, normal  the (perturbed) vertex position and its normal (need not be
                  unit)
  eyePosition     camera position in the same space
  params fields:
    extentMin, extentMax  (x_i, z_i) and (x_e, z_e); the constructor's
    restY                 y_i, the unperturbed mesh's height
    depth                 p_i, the map's depth below restY
    refractionFactor      snellApproxRefract's factor (>= 0)
    policy                SNELL_RTM_CLAMP (constructor default) or SNELL_RTM_SHRINK
    uvMin, uvMax          the policy's interval (constructor: 0, 1)
options:
  SNELL_RTM_CLAMP   uv = clamp(uv_eq, uvMin, uvMax): the paper's first fix
                    (Listing 4 clamps to refraction_uv_min / _max)
  SNELL_RTM_SHRINK  uv = uvMin + (uvMax - uvMin) uv_eq, then clamped to [0, 1]:
                    the paper's second fix, the mesh extent mapped to a shrunk
                    interval such as [0.1, 0.9]. For rays reaching at most m
                    beyond an edge of an extent of length L, uvMin = m / (L + 2m)
                    and uvMax = 1 - uvMin keep every hit in [0, 1]
contract:
  - dir = snellApproxRefract(vertex - eyePosition, normal, refractionFactor)
    (eq. 8, Listing 4); the hit is vertex + t dir on y = restY - depth, i.e.
    t = (depth + (vertex.y - restY)) / (-dir.y) (eqs. 9-11: the final depth p
    is the initial depth plus the vertex's displacement above the rest plane,
    as Listing 4 computes it; the text's eq. 11 prints the displacement with
    the opposite sign, and Listing 4 divides by the signed dir.y, which is
    negative for a ray going down), found with snellRayPlane.
  - uv_eq = ((x - x_i) / (x_e - x_i), (z - z_i) / (z_e - z_i)) (eqs. 12-13), each
    component limited to [-1e6, 1e6]. A reversed extent (x_e < x_i) flips
    that axis: Listing 4's v, flipped for DirectX 7, is extentMin.y = z_e,
    extentMax.y = z_i. An extent with |length| below the smallest normal float
    or a non-finite bound gives 0.5 for that axis.
  - valid is false when there is no hit: the ray does not go down towards the
    map (the vertex is below it, the ray is horizontal or goes up), or vertex,
    normal or eyePosition is zero-length where it matters, NaN or infinite.
    Then position = (vertex.x, restY - depth, vertex.z) (straight down, each
    non-finite component replaced by 0: always finite) and uv is computed from
    it the same way, except that an axis whose vertex coordinate is not finite
    gives 0.5.
  - inRange is true when valid and uv_eq lies in [0, 1]^2 (before the policy).
  - uvMin, uvMax: NaN counts as 0 and 1; both are clamped to [0, 1] and
    ordered (swapped values are swapped back); an unknown policy is CLAMP.
    The returned uv is always finite and in [0, 1]^2.
source: G. Oliveira, "Refractive Texture Mapping, Part Two", Gamasutra 2000,
  Equations 8-13 and Listing 4 (water_compute_refraction), and the two
  out-of-range fixes described after Equation 13.
*/
#ifndef SNELL_SHADE_REFRACTIVE_TEXTURE_MAP_GLSL
#define SNELL_SHADE_REFRACTIVE_TEXTURE_MAP_GLSL





#define SNELL_RTM_CLAMP 0
#define SNELL_RTM_SHRINK 1

struct SnellRefractiveTextureMapParams {
  vec2 extentMin;
  vec2 extentMax;
  float restY;
  float depth;
  float refractionFactor;
  int policy;
  float uvMin;
  float uvMax;
};

struct SnellRefractiveTextureMapHit {
  vec2 uv;
  vec3 position;
  bool valid;
  bool inRange;
};

SNELL_FN SnellRefractiveTextureMapParams snellRefractiveTextureMapParams(vec2 extentMin, vec2 extentMax, float restY,
                                                                         float depth, float refractionFactor) {
  SnellRefractiveTextureMapParams p;
  p.extentMin = extentMin;
  p.extentMax = extentMax;
  p.restY = restY;
  p.depth = depth;
  p.refractionFactor = refractionFactor;
  p.policy = SNELL_RTM_CLAMP;
  p.uvMin = 0.0f;
  p.uvMax = 1.0f;
  return p;
}

/* Eqs. 12-13 for one axis: (x - lo) / (hi - lo) limited to [-1e6, 1e6]; 0.5
   when x, lo, hi or hi - lo is not finite or |hi - lo| is below the smallest
   normal float. */
SNELL_FN float snellRefractiveTextureMapAxis(float x, float lo, float hi) {
  float len = hi - lo;
  if (!SNELL_FINITE(x) || !SNELL_FINITE(lo) || !SNELL_FINITE(hi) || !SNELL_FINITE(len) ||
      !(abs(len) >= SNELL_FLT_MIN)) {
    return 0.5f;
  }
  // (x - lo) may overflow to +-inf, never NaN; clamp keeps it finite.
  return clamp((x - lo) / len, -1e6f, 1e6f);
}

SNELL_FN SnellRefractiveTextureMapHit snellRefractiveTextureMap(vec3 vertex, vec3 normal, vec3 eyePosition,
                                                                SnellRefractiveTextureMapParams p) {
  SnellRefractiveTextureMapHit h;
  float planeY = p.restY - p.depth;
  vec3 dir = snellApproxRefract(vertex - eyePosition, normal, p.refractionFactor);
  SnellRayPlaneHit hit = snellRayPlane(vertex, dir, vec3(0.0f, planeY, 0.0f), vec3(0.0f, 1.0f, 0.0f));
  // A hit must come from a ray going down: a ray going up from below the map
  // also meets its plane.
  h.valid = hit.valid && dir.y < 0.0f;
  if (h.valid) {
    h.position = hit.position;
  } else {
    h.position = vec3(SNELL_FINITE(vertex.x) ? vertex.x : 0.0f, SNELL_FINITE(planeY) ? planeY : 0.0f,
                      SNELL_FINITE(vertex.z) ? vertex.z : 0.0f);
  }
  float px = h.valid || SNELL_FINITE(vertex.x) ? h.position.x : vertex.x;
  float pz = h.valid || SNELL_FINITE(vertex.z) ? h.position.z : vertex.z;
  vec2 e = vec2(snellRefractiveTextureMapAxis(px, p.extentMin.x, p.extentMax.x),
                snellRefractiveTextureMapAxis(pz, p.extentMin.y, p.extentMax.y));
  h.inRange = h.valid && e.x >= 0.0f && e.x <= 1.0f && e.y >= 0.0f && e.y <= 1.0f;
  float a = isnan(p.uvMin) ? 0.0f : clamp(p.uvMin, 0.0f, 1.0f);
  float b = isnan(p.uvMax) ? 1.0f : clamp(p.uvMax, 0.0f, 1.0f);
  float lo = min(a, b);
  float hi = max(a, b);
  if (p.policy == SNELL_RTM_SHRINK) {
    h.uv = clamp(vec2(lo, lo) + e * (hi - lo), vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
  } else {
    h.uv = clamp(e, vec2(lo, lo), vec2(hi, hi));
  }
  return h;
}

#endif
/*
description: chromatic dispersion: per-channel indices of refraction from a
  base IOR and an Abbe number (or given explicitly), and the refraction of one
  ray per colour channel. Sample the scene once per channel with the three
  directions (or their screen-space offsets) for chromatic aberration.
use: vec3 iors = snellDispersionIors(1.5168f, 64.17f);   // BK7: n_d, V_d
     SnellDispersion d = snellDispersionRefract(viewDir, n, 1.0f, iors, SNELL_TIR_CRITICAL);
     SnellDispersion d = snellDispersionRefract(viewDir, n, 1.0f, vec3(1.51f, 1.52f, 1.53f), SNELL_TIR_ZERO);
  iorD        IOR at the helium d line (587.56 nm), the usual catalogue value
  abbe        Abbe number V_d = (n_d - 1) / (n_F - n_C) (crown glass ~ 60, flint
              ~ 30, water ~ 55); larger means less dispersion
  iorOutside  IOR of the medium the ray comes from (1 for air)
  iors        IOR per channel (r, g, b) of the medium it enters
options:
  SNELL_DISPERSION_LAMBDA_R  wavelength of the red channel in nm (656.27f, the
                             hydrogen C line)
  SNELL_DISPERSION_LAMBDA_G  green (587.56f, the helium d line)
  SNELL_DISPERSION_LAMBDA_B  blue (486.13f, the hydrogen F line)
contract:
  - snellDispersionIors uses Cauchy's two-term equation n(l) = A + B / l^2
    fitted to n(587.56 nm) = iorD and n(486.13) - n(656.27) = (iorD - 1) / V:
    n(l) = iorD + (iorD - 1) / V * (1/l^2 - 1/l_d^2) / (1/l_F^2 - 1/l_C^2).
    With the default wavelengths r = n_C, g = n_d = iorD, b = n_F, so
    b - r = (iorD - 1) / V and b > g > r for iorD > 1 (blue bends most).
  - iorD NaN, below the smallest normal float or infinite: (1, 1, 1). abbe NaN,
    <= 0 or +inf: no dispersion, (iorD, iorD, iorD). abbe below 1 counts as 1.
    Each channel is clamped to [1e-6, 1e6].
  - snellDispersionRefract refracts incident about normal once per channel with
    eta_c = snellIorToEta(iorOutside, iors.c) and snellRefract(.., policy);
    red/green/blue are the directions; tir is true when any channel totally
    reflects, valid when every channel is valid (false only for a zero, NaN
    or infinite incident or normal: then all three are (0,0,0)). Invalid IORs
    give eta 1 for that channel (snellIorToEta).
source: E. Abbe's number V_d = (n_d - 1) / (n_F - n_C) (Schott optical glass
  data sheets; ISO 7944 reference wavelengths) and Cauchy's dispersion formula
  n = A + B / lambda^2 (two-term form); per-channel refraction for chromatic
  aberration, cf. Kilgard 2001 "Chromatic Aberration" (NVIDIA), which Sousa
  (GPU Gems 2 ch. 19, sec. 19.3.2) cites as the wavelength-dependent extension.
*/
#ifndef SNELL_SHADE_DISPERSION_GLSL
#define SNELL_SHADE_DISPERSION_GLSL





#ifndef SNELL_DISPERSION_LAMBDA_R
#  define SNELL_DISPERSION_LAMBDA_R 656.27f
#endif
#ifndef SNELL_DISPERSION_LAMBDA_G
#  define SNELL_DISPERSION_LAMBDA_G 587.56f
#endif
#ifndef SNELL_DISPERSION_LAMBDA_B
#  define SNELL_DISPERSION_LAMBDA_B 486.13f
#endif

struct SnellDispersion {
  vec3 red;
  vec3 green;
  vec3 blue;
  bool tir;
  bool valid;
};

SNELL_FN vec3 snellDispersionIors(float iorD, float abbe) {
  if (isnan(iorD) || !(iorD >= SNELL_FLT_MIN) || isinf(iorD)) {
    return vec3(1.0f, 1.0f, 1.0f);
  }
  if (isnan(abbe) || !(abbe > 0.0f) || isinf(abbe)) {
    return vec3(iorD, iorD, iorD);
  }
  float v = max(abbe, 1.0f);
  // 1 / lambda^2 in 1 / um^2 (lambda in nm).
  float wC = 1e6f / (656.27f * 656.27f);
  float wD = 1e6f / (587.56f * 587.56f);
  float wF = 1e6f / (486.13f * 486.13f);
  float wR = 1e6f / (SNELL_DISPERSION_LAMBDA_R * SNELL_DISPERSION_LAMBDA_R);
  float wG = 1e6f / (SNELL_DISPERSION_LAMBDA_G * SNELL_DISPERSION_LAMBDA_G);
  float wB = 1e6f / (SNELL_DISPERSION_LAMBDA_B * SNELL_DISPERSION_LAMBDA_B);
  float k = (iorD - 1.0f) / (v * (wF - wC));
  vec3 n = vec3(iorD + k * (wR - wD), iorD + k * (wG - wD), iorD + k * (wB - wD));
  return clamp(n, vec3(1e-6f, 1e-6f, 1e-6f), vec3(1e6f, 1e6f, 1e6f));
}

SNELL_FN SnellDispersion snellDispersionRefract(vec3 incident, vec3 normal, float iorOutside, vec3 iors,
                                                int policy) {
  SnellRefraction r = snellRefract(incident, normal, snellIorToEta(iorOutside, iors.x), policy);
  SnellRefraction g = snellRefract(incident, normal, snellIorToEta(iorOutside, iors.y), policy);
  SnellRefraction b = snellRefract(incident, normal, snellIorToEta(iorOutside, iors.z), policy);
  SnellDispersion d;
  d.red = r.direction;
  d.green = g.direction;
  d.blue = b.direction;
  d.tir = r.tir || g.tir || b.tir;
  d.valid = r.valid && g.valid && b.valid;
  return d;
}

#endif
/*
description: surface roughness -> mip level of the scene-colour texture, for
  blurred (frosted) refraction: read S with SNELL_SAMPLE_LOD at this level of
  a mipmapped (ideally pre-blurred) chain. A fixed share of the chain per
  roughness, whatever the distances and the resolution: the composed
  technique blurs by the cone of light instead (shade/rough_cone.glsl: the
  same width in the world at every resolution, measured closer to a rough
  ray trace); this mapping suits a host without the path's lengths.
use: float lod = snellRoughnessToLod(perceptualRoughness, levelCount);
     vec4 c = SNELL_SAMPLE_LOD(sceneColor, uvRefracted, lod);
  roughness  perceptual roughness in [0, 1] (0 smooth, 1 fully rough)
  levels     number of mip levels of the texture (base level included), e.g.
             floor(log2(max(width, height))) + 1 for a full chain
options: -
contract:
  - lod = (levels - 1) r (2 - r) = (levels - 1) (1 - (1 - r)^2) with r = roughness clamped to [0, 1]: 0 at
    r = 0, levels - 1 at r = 1, monotone non-decreasing in r, always in
    [0, levels - 1] (finite);
  - a NaN roughness counts as 0 (sharp); levels <= 1 gives 0.
source: the quadratic fit of log2(roughness) + level used for prefiltered
  environment maps in Google Filament (perceptualRoughnessToLod: lod =
  iblRoughnessOneLevel * r * (2 - r), with the roughness-one level being the
  last mip level), applied here to the scene-colour mip chain.
*/
#ifndef SNELL_SHADE_ROUGHNESS_GLSL
#define SNELL_SHADE_ROUGHNESS_GLSL


SNELL_FN float snellRoughnessToLod(float roughness, int levels) {
  if (levels <= 1) {
    return 0.0f;
  }
  // isnan first: clamp of a NaN differs between GPUs and GLM.
  float r = isnan(roughness) ? 0.0f : clamp(roughness, 0.0f, 1.0f);
  float top = float(levels - 1);
  // r (2 - r) written as 1 - (1 - r)^2: the same value, but every step is
  // monotone, so the rounded result is too (r * (2 - r) is not near r = 1).
  float m = 1.0f - r;
  return min(top * (1.0f - m * m), top);
}

#endif
/*
description: the scene colour's mip chain for rough reads, each level a
  tent-filtered (separable [1 3 3 1] / 8) half of the one below instead of
  glGenerateMipmap's 2x2 box. A box chain is not shift-invariant: what a
  texel of level L holds depends on where the image falls on its 2^L grid,
  so a blurred read changes as the camera moves by a fraction of a pixel,
  and a third of its spread is texels moved to their block's centre. The
  tent's response has a triple zero at the level's Nyquist frequency (the
  box's a single one), so far less of the finer level aliases into the
  coarser one, and a read at level L is close to a Gaussian of width
  proportional to 2^L at every offset: the bell the rough cone's two taps
  assume (rough_cone.glsl).
use: level L+1 from level L, one fragment (or compute) invocation per texel
     px of level L+1 (fragment: px = ivec2(gl_FragCoord.xy)):
       out = snellColorPyramidReduce(colorTex, L, px);
     a full GL pass is glsl/passes/color_pyramid.frag (driven level by level
     by snell::gpu::ColorPyramidPass); C++: snell::snellBuildColorPyramid(base)
     (include/snell/color_pyramid.hpp). Sample the result with trilinear
     filtering (GL_LINEAR_MIPMAP_LINEAR), as snellRoughConeSample does.
contract:
  - level L has size (W, H) = SNELL_TEXTURE_SIZE(tex, L) (at least 1 each);
    level L+1 has (max(1, W/2), max(1, H/2)) (GL's floor sizes); px is
    clamped into it. lod must name a level of tex.
  - per axis, the output texel's centre in level L's texel units (centres at
    integers) is c = (px + 0.5) W / max(1, W/2) - 0.5 (2 px + 0.5 for even
    W), and the four texels floor(c) - 1 .. floor(c) + 2, clamped to the
    level's edge as GL's clamp-to-edge does, weigh (1 - f, 2 - f, 1 + f, f) / 4,
    f = c - floor(c): the tent max(0, 1 - |x - c| / 2) at each, halved (the
    four tent values sum to 2), so the weights sum to 1 (for even W, f = 1/2:
    1/8, 3/8, 3/8, 1/8). The 2D weights are the product of the two axes'
    (16 fetches).
  - a constant level gives the same constant, and a level affine in x and y
    the affine function at the centres away from the edge taps, both to
    float rounding.
  - a texel with a non-finite channel counts as 0 in every channel, so one
    NaN or infinity does not spread through the chain; the result is finite
    whenever the finite texels' sums do not overflow.
  - the sums run in a fixed order (rows, then columns within a row), with c
    and f computed from integers, so the GPU pass and the C++ build agree to
    float rounding of the products.
  - the standard deviation of a level-L trilinear read is about 0.65 x 2^L
    texels of level 0 (the box chain's: 0.5 x 2^L): the chain's levels
    variance 0.75 (4^L - 1) / 3, the bilinear read's 4^L / 6.
source: the REDUCE of P. J. Burt, E. H. Adelson, "The Laplacian Pyramid as
  a Compact Image Code" (IEEE Trans. Comm. 1983), eq. 1 (each level a
  weighted sum of the one below, a separable, symmetric, normalised,
  Gaussian-like kernel), here with the even-length kernel [1 3 3 1] / 8 that
  centres each texel of level L+1 between its parents (GL's floor sizes).
*/
#ifndef SNELL_SHADE_COLOR_PYRAMID_GLSL
#define SNELL_SHADE_COLOR_PYRAMID_GLSL


/* A texel as the reduce reads it: a non-finite channel makes it 0. */
SNELL_FN vec4 snellColorPyramidTexel(vec4 t) {
  bool finite = SNELL_FINITE(t.x) && SNELL_FINITE(t.y) && SNELL_FINITE(t.z) && SNELL_FINITE(t.w);
  return finite ? t : vec4(0.0f);
}

/* One axis of a reduce: the first of the four texels it reads and their weights. */
struct SnellColorPyramidAxis {
  int first;
  vec4 weights;
};

SNELL_FN SnellColorPyramidAxis snellColorPyramidAxis(int px, int size) {
  int w = max(size, 1);
  int outSize = max(w / 2, 1);
  int p = clamp(px, 0, outSize - 1);
  // c = ((2 p + 1) w - outSize) / (2 outSize): its floor and fraction from integers (the numerator is >= 0).
  int num = (2 * p + 1) * w - outSize;
  int den = 2 * outSize;
  int b = num / den;
  float f = float(num - b * den) / float(den);
  SnellColorPyramidAxis a;
  a.first = b - 1;
  a.weights = vec4(1.0f - f, 2.0f - f, 1.0f + f, f) * 0.25f;
  return a;
}

SNELL_FN vec4 snellColorPyramidReduce(SNELL_TEX2D colorTex, int lod, ivec2 px) {
  ivec2 size = max(SNELL_TEXTURE_SIZE(colorTex, lod), ivec2(1, 1));
  SnellColorPyramidAxis ax = snellColorPyramidAxis(px.x, size.x);
  SnellColorPyramidAxis ay = snellColorPyramidAxis(px.y, size.y);
  vec4 sum = vec4(0.0f);
  for (int j = 0; j < 4; ++j) {
    int y = clamp(ay.first + j, 0, size.y - 1);
    vec4 row = vec4(0.0f);
    for (int i = 0; i < 4; ++i) {
      int x = clamp(ax.first + i, 0, size.x - 1);
      row += ax.weights[i] * snellColorPyramidTexel(SNELL_TEXEL_FETCH(colorTex, ivec2(x, y), lod));
    }
    sum += ay.weights[j] * row;
  }
  return sum;
}

#endif
/*
description: how wide rough (frosted) glass blurs what it shows, as a cone of
  light around the ray: from the roughness, the relative IOR and the path's
  lengths inside and behind the glass, its radius where the ray meets the
  scene, and the mip level of the scene colour (or the environment) whose
  texels are that wide, read twice (the lobe's narrow peak and its wide
  tail). The same glass blurs the same amount of the world at every
  resolution and distance, and the blur grows with what lies behind.
use: SnellRoughCone c = snellRoughConeTransmit(m.roughness, eta, insideLength, bounces);
     float lod = snellRoughConeSceneLod(c, distanceBehind, hitPosition, scene.clipFromView,
                                        SNELL_TEXTURE_SIZE(sceneColor, 0), v.sceneColorLevels);
     float envLod = snellRoughConeEnvironmentLod(c, v.environmentLevels);
     SnellRoughCone r = snellRoughConeReflect(m.roughness);   // the first surface's reflection
     SnellRoughTaps t = snellRoughConeTaps(lod, v.sceneColorLevels);  // the lobe as two reads
     vec4 color = snellRoughConeSample(sceneColor, uv, t);   // snellRoughConeFetches(t) fetches
     vec4 sky = snellRoughConeSampleEnvironment(environment, dirWorld,
                                                snellRoughConeTaps(envLod, v.environmentLevels));
  the scene colour's and the environment's chains built by the colour
  pyramid (color_pyramid.glsl: snell::gpu::ColorPyramidPass after each draw
  of the scene colour, snellBuildColorPyramid for an image), whose levels
  blur as the bells the levels below assume. glGenerateMipmap's box chain
  also works: the same level then blurs 0.77x as wide (part of it the
  texels' misplacement, a third of its variance; define SNELL_ROUGH_CONE_LOD_SCALE 3.0 for the same
  blur), and the read changes as the camera moves by a fraction of a pixel.
  roughness     perceptual roughness in [0, 1]; the GGX width is alpha = roughness^2
  eta           n_outside / n_inside at the entry (snellIorToEta(iorOutside, ior))
  insideLength  the path's length inside the glass (view units)
  bounces       total internal reflections inside (each off the rough surface)
  distance      from where the ray leaves the glass to where it meets the scene
  p             that point, in view space; clipFromView: the projection of the
                scene colour buffer, whose size (texels) is `size`
  levels        the texture's mip levels (base included); the environment's
                base level is taken to span 2 pi radians over 2^(levels - 1)
                texels (an equirectangular map with a full chain)
options: SNELL_ROUGH_CONE_LOD_SCALE (default 2.32): texels of the chosen level
  per unit of the cone's radius: 3, fitted against the rough ray trace with
  a box chain (below), times 0.5 / 0.645, the two chains' widths at a level
  (color_pyramid.glsl), so the colour pyramid blurs as wide as the fit.
  SNELL_ROUGH_CONE_TAIL_WEIGHT (default 0.34): the wide read's share of a rough
  read; 0 reads once, at the cone's level (one fetch instead of two).
  SNELL_ROUGH_CONE_CORE_OFFSET (default -0.52) and SNELL_ROUGH_CONE_TAIL_OFFSET
  (default 1.14): the two reads' levels from the cone's (below).
contract:
  - a cone is a radius at the surface it leaves and two angles (radians):
    radius(d) = sqrt((radius + angle d)^2 + (exitAngle d)^2) at distance d.
    The two lobes are independent, so they add in quadrature; the entry
    lobe's spread is carried along the inside path, so its radius and angle
    add linearly.
  - snellRoughConeTransmit: s = alpha = clamp(roughness, 0, 1)^2 (NaN: 0).
    Small-slope Snell's law: a microfacet tilted by s turns a ray refracted
    with relative index e by |1 - e| s. Inside, the entry lobe's angle is
    a = s sqrt((1 - eta)^2 + 4 bounces): |1 - eta| s, widened by each
    bounce's reflection (2 s) in quadrature.
    The cone leaves with radius = a insideLength, angle = a / eta (the exit
    refraction magnifies it by 1 / eta) and exitAngle = |1 / eta - 1| s (the
    exit lobe). A NaN, infinite or negative insideLength counts as 0; eta
    NaN or outside [1e-6, 1e6] counts as 1 (no bending: no blur); bounces
    clamped to [0, SNELL_MAX_BOUNCES].
  - snellRoughConeReflect: radius 0, angle 2 s (reflection doubles the
    facet's tilt), exitAngle 0.
  - snellRoughConeRadius(c, d): as above; d and the cone's fields NaN or
    negative count as 0, +inf as the largest float, and the result is
    finite (snellRoughConeHypot: max sqrt(1 + (min / max)^2), capped at the
    largest float). snellRoughConeMeasure(x): that reading of one value.
  - snellRoughConeLevel(radius, texelsPerUnit, levels): log2(scale radius
    texelsPerUnit) clamped to [0, levels - 1]; 0 when either is not
    positive or levels <= 1.
  - snellRoughConeSceneLod: the cone's radius at d in texels of the base
    level (texels per view unit at p: (size.x |P00| + size.y |P11|) / (4 w),
    w = (clipFromView p).w), times SNELL_ROUGH_CONE_LOD_SCALE, as a level:
    log2 of it clamped to [0, levels - 1]. 0 when the radius is 0, levels
    <= 1, or p does not project (a coordinate not finite, or w not positive
    and finite).
  - snellRoughConeEnvironmentLod: the same for the directions, sqrt(angle^2 +
    exitAngle^2) radians at 2^(levels - 1) / (2 pi) texels per radian.
  - every result is finite; a cone of a smooth surface (roughness 0) gives
    level 0 exactly.
  - snellRoughConeTaps(lod, levels): GGX's lobe is heavy-tailed (its slopes
    are Student's t with 2 degrees of freedom: a narrow peak, and a fifth of
    the light beyond twice its median), which one read, a bell, cannot be.
    Two reads mixed stand for it: l = lod clamped to [0, levels - 1] (NaN: 0);
    for l > 0 and a positive tail weight w, coreLod = clamp(l + CORE_OFFSET),
    tailLod = clamp(l + TAIL_OFFSET) (both to [0, levels - 1]), tailWeight = w;
    else (smooth glass, level 0, no chain) one read: coreLod = tailLod = l,
    tailWeight 0. At the top level the tail is clamped to it and the core
    still reads below (the mix stays the lobe's shape as far as the chain
    allows).
  - snellRoughConeSample(tex, uv, t): SNELL_SAMPLE_LOD at coreLod, mixed with
    SNELL_SAMPLE_LOD at tailLod by tailWeight when it is positive;
    snellRoughConeSampleEnvironment the same through SNELL_SAMPLE_ENVIRONMENT.
    snellRoughConeFetches(t): 2 with a tail, else 1.
  - the constants: with a read at level L taken as a Gaussian of standard
    deviation proportional to 2^L, the mixture of two Gaussians nearest
    to the t lobe (squared difference of their spectra, weighted as the
    1 / f^2 power spectrum of natural images weighs it) against the single
    Gaussian nearest to it: the core 0.70x its width (-0.52 levels) with
    weight 0.66, the tail 2.2x (+1.14 levels) with 0.34. The single read's
    level (SNELL_ROUGH_CONE_LOD_SCALE) stays the one fitted against the ray
    trace; the two reads take their levels from it.
source: the rough BTDF of B. Walter, S. Marschner, H. Li, K. Torrance,
  "Microfacet Models for Refraction through Rough Surfaces" (EGSR 2007): GGX
  (eq. 33) with width alpha, refraction about the microfacet normal (eq. 40);
  its small-slope linearisation here. The cone traced through the scene
  colour's mip chain, its radius growing with the distance behind the
  object and both interfaces' lobes combined: C. de Rousiers, A. Bousseau,
  K. Subr, N. Holzschuch, R. Ramamoorthi, "Real-Time Rendering of Rough
  Refraction" (TVCG 2012), cone tracing at the exit interface. GGX's slopes
  as Student's t with 2 degrees of freedom: E. Heitz, "Understanding the
  Masking-Shadowing Function in Microfacet-Based BRDFs" (JCGT 2014), its GGX
  slope distribution P22; natural images' 1 / f^2 power spectrum: D. J.
  Field, "Relations between the statistics of natural images and the
  response properties of cortical cells" (JOSA A 1987). The scale was
  fitted on the rough sphere_painting scenes against the lab's GGX ray trace
  through a box chain, checked on the rough bunny, and carried over to the
  colour pyramid at equal width (docs/lab/rough/README.md).
*/
#ifndef SNELL_SHADE_ROUGH_CONE_GLSL
#define SNELL_SHADE_ROUGH_CONE_GLSL

/*
description: what a two-interface refraction technique is made of, split by
  what each part describes and how long it lives:
  - SnellSlot: one place a ray is resolved (where it reads from, the
    intersection strategy and its parameters, what it shows when the buffers
    give nothing). A technique has four: back (where T1 leaves the object),
    exit (what T2 sees), reflect (what the first surface's reflected ray R
    sees, and a ray that leaves through the front faces after bouncing
    inside), inside (where a ray reflected inside the object leaves it). The
    exit and the reflection are the same call with their own slot.
  - bounces: how many total internal reflections inside the object a ray
    follows (0: none, the two-interface model); insideScene: whether the
    opaque scene has surfaces inside the object.
  - SnellTechnique: the technique's choices, the set of slots (the presets,
    technique_presets.glsl, return one).
  - SnellMaterial: the object's optics (IORs, dispersion, absorption, TIR
    policy, reflection on/off, roughness).
  - SnellView: the frame's constants (the environment's basis, the mip
    counts of the colour lookups).
  Each constructor fills every field with the documented default.
use: SnellTechnique t = snellTechnique();   // or a preset: snellPresetDir()
     t.back = snellSlot(SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_CBS);
     t.back.intersect.cbsSteps = 8;
     t.exit = snellSlot(SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_PLANE_NORMAL);
     SnellMaterial m = snellMaterial();
     m.ior = 1.33f;
     SnellView v = snellView();
options:
  sources (SnellSlot.source): SNELL_SOURCE_ENVIRONMENT 0 (the distant
  environment along the ray; the intersector is not run), SNELL_SOURCE_BUFFERS
  1 (the slot's intersector against the buffers of its layer: the back-face
  buffers for the back slot, the opaque scene's for exit and reflect),
  SNELL_SOURCE_WYMAN 2 (back slot only: Wyman 2005 distance interpolation
  between d_V and the per-vertex d_N; the intersector is not run; in the exit
  or reflect slot it reads as SNELL_SOURCE_BUFFERS)
  fallbacks when a BUFFERS slot finds nothing (exit and reflect slots):
  SNELL_FALLBACK_ENVIRONMENT 0 (the environment along the ray),
  SNELL_FALLBACK_EDGE_FADE 1 (scene colour at the clamped projection of origin
  + fallbackDistance dir, faded to the environment over edgeFadeWidth of uv
  near and beyond the screen edge)
contract (defaults):
  snellSlot(source, strategy): intersect = snellIntersectOptions(strategy),
    fallback = ENVIRONMENT, fallbackDistance = 1, edgeFadeWidth = 0.1.
  snellTechnique(): back = snellSlot(BUFFERS, CBS), exit =
    snellSlot(ENVIRONMENT, PLANE_NORMAL), reflect = snellSlot(ENVIRONMENT,
    LINEAR_MARCH) (the strategies are read only when the source becomes
    BUFFERS), inside = snellSlot(BUFFERS, LINEAR_MARCH) (the march between
    the front and back layers, intersect/inside_march.glsl, with the linear
    march's marchSteps, marchBisections and marchMaxDistance; PLANE_NORMAL:
    that march's bracket, then the normal plane on the layer it crossed,
    planeIterations times, intersect/inside_plane.glsl. Only these two
    work from inside: a ray inside starts on a layer, so a strategy that
    reads the surface at the ray origin's pixel (single sample, the plane
    methods' first plane, the far start) reads the face it leaves from, and
    one that tests the ray against one layer (CBS, the binary searches, DDA)
    cannot tell when it leaves: inside, it is behind the front layer and in
    front of the back one at once. CBS's binary search, run on the two-layer
    test, is the march's bisection (a march of few steps is its
    bracket). Any other
    strategy or source
    ends the path at the reflection, as a fallback), bounces = 0 (clamped to
    [0, SNELL_MAX_BOUNCES], default 4, a compile-time bound), insideScene =
    false (true: the opaque scene may have surfaces inside the object, a
    candle in a hurricane glass, a card in a paperweight: the refracted ray
    is also run against the scene buffers with the exit slot's strategy, and
    the nearer of that hit and the back faces ends the first segment,
    two_interface_shade.glsl; the scene buffers are read whatever the exit
    slot's source; one more scene search per trace, so set it only where
    something opaque is inside).
  snellMaterial(): ior = 1.5, iorOutside = 1, dispersion = 1 (one trace; 3 =
    one per channel with iors, e.g. snellDispersionIors(1.5168f, 64.17f) from
    shade/dispersion.glsl), iors = (1.5, 1.5, 1.5), absorption = 0
    (Beer-Lambert sigma per channel, per view unit), tirPolicy =
    SNELL_TIR_CRITICAL (both interfaces; Wyman 2005, O&B 2007 sec. 5),
    reflection = true (Fresnel-weighted reflection at the first interface),
    roughness = 0.
  snellView(): envX/envY/envZ = the columns of the world-from-view rotation
    used for environment lookups (identity), sceneColorLevels =
    environmentLevels = 1 (mip levels the rough cone reads,
    shade/rough_cone.glsl).
source: the composition of DESIGN.md sec. 2 (a technique = optics, an
  intersector against the back faces, optics, an intersector against the scene
  or an environment lookup); Oliveira & Brauwers 2007 sec. 3; Wyman 2005;
  Mayer & Assarsson, "Constant-Time Light Refraction Simulation".
*/
#ifndef SNELL_SHADE_TECHNIQUE_OPTIONS_GLSL
#define SNELL_SHADE_TECHNIQUE_OPTIONS_GLSL




#define SNELL_SOURCE_ENVIRONMENT 0
#define SNELL_SOURCE_BUFFERS 1
#define SNELL_SOURCE_WYMAN 2

#define SNELL_FALLBACK_ENVIRONMENT 0
#define SNELL_FALLBACK_EDGE_FADE 1

struct SnellSlot {
  int source;
  SnellIntersectOptions intersect;
  int fallback;
  float fallbackDistance;
  float edgeFadeWidth;
};

#ifndef SNELL_MAX_BOUNCES
#  define SNELL_MAX_BOUNCES 4
#endif

struct SnellTechnique {
  SnellSlot back;
  SnellSlot exit;
  SnellSlot reflect;
  SnellSlot inside;
  int bounces;
  bool insideScene;
};

struct SnellMaterial {
  float ior;
  float iorOutside;
  int dispersion;
  vec3 iors;
  vec3 absorption;
  int tirPolicy;
  bool reflection;
  float roughness;
};

struct SnellView {
  vec3 envX;
  vec3 envY;
  vec3 envZ;
  int sceneColorLevels;
  int environmentLevels;
};

SNELL_FN SnellSlot snellSlot(int source, int strategy) {
  SnellSlot s;
  s.source = source;
  s.intersect = snellIntersectOptions(strategy);
  s.fallback = SNELL_FALLBACK_ENVIRONMENT;
  s.fallbackDistance = 1.0f;
  s.edgeFadeWidth = 0.1f;
  return s;
}

SNELL_FN SnellTechnique snellTechnique() {
  SnellTechnique t;
  t.back = snellSlot(SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_CBS);
  t.exit = snellSlot(SNELL_SOURCE_ENVIRONMENT, SNELL_STRATEGY_PLANE_NORMAL);
  t.reflect = snellSlot(SNELL_SOURCE_ENVIRONMENT, SNELL_STRATEGY_LINEAR_MARCH);
  t.inside = snellSlot(SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_LINEAR_MARCH);
  t.bounces = 0;
  t.insideScene = false;
  return t;
}

SNELL_FN SnellMaterial snellMaterial() {
  SnellMaterial m;
  m.ior = 1.5f;
  m.iorOutside = 1.0f;
  m.dispersion = 1;
  m.iors = vec3(1.5f, 1.5f, 1.5f);
  m.absorption = vec3(0.0f, 0.0f, 0.0f);
  m.tirPolicy = SNELL_TIR_CRITICAL;
  m.reflection = true;
  m.roughness = 0.0f;
  return m;
}

SNELL_FN SnellView snellView() {
  SnellView v;
  v.envX = vec3(1.0f, 0.0f, 0.0f);
  v.envY = vec3(0.0f, 1.0f, 0.0f);
  v.envZ = vec3(0.0f, 0.0f, 1.0f);
  v.sceneColorLevels = 1;
  v.environmentLevels = 1;
  return v;
}

#endif
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


/*
description: cube-map face selection: which face of a cube map a direction
  reads, and the face coordinates (s, t) there, as the GL specification defines
  it. The C++ snell::TextureCube (include/snell/texture_cube.hpp) samples
  through this function, so its face choice and the GPU's cannot drift apart.
use: SnellCubeFace f = snellCubeFaceUv(dir);  // f.face 0..5 = +X -X +Y -Y +Z -Z
                                             // (GL_TEXTURE_CUBE_MAP_POSITIVE_X + f.face)
  dir  direction (any length)
options: -
contract:
  - the major axis is the component of largest magnitude; ties go to x over y
    over z (|x| >= |y| and |x| >= |z| selects x; else |y| >= |z| selects y);
    GL leaves ties to the implementation, so a texel exactly on a cube edge may
    read the neighbouring face on a GPU;
  - (sc, tc, ma) per face as the table below; s = 0.5 (sc / |ma| + 1),
    t = 0.5 (tc / |ma| + 1), in [0, 1];
      +X: (-z, -y, x)  -X: (+z, -y, x)  +Y: (+x, +z, y)
      -Y: (+x, -z, y)  +Z: (+x, -y, z)  -Z: (-x, -y, z)
  - valid = false, face 0, uv (0.5, 0.5) when dir is zero, denormal-small (every
    component below the smallest normal float) or has a NaN/Inf component.
source: OpenGL 4.5 core specification, sec. 8.13 "Cube Map Texture
  Selection", table 8.19, equations 8.6-8.7.
*/
#ifndef SNELL_SHADE_ENVIRONMENT_CUBE_FACE_GLSL
#define SNELL_SHADE_ENVIRONMENT_CUBE_FACE_GLSL



struct SnellCubeFace {
  int face;
  vec2 uv;
  bool valid;
};

/* GL 4.5 core, sec. 8.13, table 8.19 */
SNELL_FN SnellCubeFace snellCubeFaceUv(vec3 dir) {
  SnellCubeFace r;
  r.face = 0;
  r.uv = vec2(0.5f, 0.5f);
  r.valid = false;
  if (!SNELL_FINITE(dir.x) || !SNELL_FINITE(dir.y) || !SNELL_FINITE(dir.z)) {
    return r;
  }
  float ax = abs(dir.x);
  float ay = abs(dir.y);
  float az = abs(dir.z);
  float sc = 0.0f;
  float tc = 0.0f;
  float ma = 0.0f;
  if (ax >= ay && ax >= az) {
    ma = ax;
    r.face = dir.x >= 0.0f ? 0 : 1;
    sc = dir.x >= 0.0f ? -dir.z : dir.z;
    tc = -dir.y;
  } else if (ay >= az) {
    ma = ay;
    r.face = dir.y >= 0.0f ? 2 : 3;
    sc = dir.x;
    tc = dir.y >= 0.0f ? dir.z : -dir.z;
  } else {
    ma = az;
    r.face = dir.z >= 0.0f ? 4 : 5;
    sc = dir.z >= 0.0f ? dir.x : -dir.x;
    tc = -dir.y;
  }
  if (!(ma >= SNELL_FLT_MIN)) {
    r.face = 0;
    return r;
  }
  r.uv = vec2(0.5f * (sc / ma + 1.0f), 0.5f * (tc / ma + 1.0f));
  r.valid = true;
  return r;
}

#endif

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

#ifndef SNELL_ROUGH_CONE_LOD_SCALE
#  define SNELL_ROUGH_CONE_LOD_SCALE 2.32f
#endif
#ifndef SNELL_ROUGH_CONE_TAIL_WEIGHT
#  define SNELL_ROUGH_CONE_TAIL_WEIGHT 0.34f
#endif
#ifndef SNELL_ROUGH_CONE_CORE_OFFSET
#  define SNELL_ROUGH_CONE_CORE_OFFSET (-0.52f)
#endif
#ifndef SNELL_ROUGH_CONE_TAIL_OFFSET
#  define SNELL_ROUGH_CONE_TAIL_OFFSET 1.14f
#endif

struct SnellRoughCone {
  float radius;     // at the surface the ray leaves (view units)
  float angle;      // grows the radius linearly (the entry lobe, carried through the glass)
  float exitAngle;  // the lobe of the surface it leaves, independent of the first
};

SNELL_FN float snellRoughConeSlope(float roughness) {
  float r = isnan(roughness) ? 0.0f : clamp(roughness, 0.0f, 1.0f);
  return r * r;
}

SNELL_FN SnellRoughCone snellRoughConeTransmit(float roughness, float eta, float insideLength, int bounces) {
  float s = snellRoughConeSlope(roughness);
  float e = (eta >= 1e-6f && eta <= 1e6f) ? eta : 1.0f;
  float len = (insideLength > 0.0f && insideLength < SNELL_FLT_MAX) ? insideLength : 0.0f;
  int b = clamp(bounces, 0, SNELL_MAX_BOUNCES);
  float a = s * sqrt((1.0f - e) * (1.0f - e) + 4.0f * float(b));
  SnellRoughCone c;
  c.radius = min(a * len, SNELL_FLT_MAX);
  c.angle = min(a / e, SNELL_FLT_MAX);
  c.exitAngle = min(s * abs(1.0f / e - 1.0f), SNELL_FLT_MAX);
  return c;
}

SNELL_FN SnellRoughCone snellRoughConeReflect(float roughness) {
  SnellRoughCone c;
  c.radius = 0.0f;
  c.angle = 2.0f * snellRoughConeSlope(roughness);
  c.exitAngle = 0.0f;
  return c;
}

/* A length or angle as the cone reads it: NaN or not positive counts as 0, +inf as the largest float (so
   no product of two of them is NaN, and min / max never see a NaN, whose result differs between GPUs). */
SNELL_FN float snellRoughConeMeasure(float x) {
  return x > 0.0f ? min(x, SNELL_FLT_MAX) : 0.0f;
}

/* sqrt(x^2 + y^2) without overflow: max sqrt(1 + (min / max)^2); x, y as snellRoughConeMeasure reads them. */
SNELL_FN float snellRoughConeHypot(float x, float y) {
  float a = snellRoughConeMeasure(x);
  float b = snellRoughConeMeasure(y);
  float hi = max(a, b);
  if (!(hi > 0.0f)) {
    return 0.0f;
  }
  float q = min(a, b) / hi;
  return min(hi * sqrt(1.0f + q * q), SNELL_FLT_MAX);
}

SNELL_FN float snellRoughConeRadius(SNELL_IN(SnellRoughCone) c, float distance) {
  float d = snellRoughConeMeasure(distance);
  float carried = min(snellRoughConeMeasure(c.radius) + min(snellRoughConeMeasure(c.angle) * d, SNELL_FLT_MAX),
                      SNELL_FLT_MAX);
  return snellRoughConeHypot(carried, snellRoughConeMeasure(c.exitAngle) * d);
}

/* log2(scale radius texelsPerUnit) clamped to [0, levels - 1], as a sum of logs so no product overflows. */
SNELL_FN float snellRoughConeLevel(float radius, float texelsPerUnit, int levels) {
  if (levels <= 1 || !(radius > 0.0f) || !(texelsPerUnit > 0.0f)) {
    return 0.0f;
  }
  float lod = log2(SNELL_ROUGH_CONE_LOD_SCALE) + log2(clamp(radius, SNELL_FLT_MIN, SNELL_FLT_MAX)) +
              log2(clamp(texelsPerUnit, SNELL_FLT_MIN, SNELL_FLT_MAX));
  return clamp(lod, 0.0f, float(levels - 1));
}

SNELL_FN float snellRoughConeSceneLod(SNELL_IN(SnellRoughCone) c, float distance, vec3 p, mat4 clipFromView,
                                      ivec2 size, int levels) {
  // Smooth glass and chains without mips return before the projection: the smooth technique pays two tests.
  float radius = levels > 1 ? snellRoughConeRadius(c, distance) : 0.0f;
  if (!(radius > 0.0f)) {
    return 0.0f;
  }
  // A point with a NaN or infinite coordinate does not project (a matrix product may or may not carry
  // it into w, differently on each runtime).
  if (!SNELL_FINITE(p.x) || !SNELL_FINITE(p.y) || !SNELL_FINITE(p.z)) {
    return 0.0f;
  }
  vec4 clip = SNELL_MUL(clipFromView, vec4(p, 1.0f));
  if (!(clip.w > 0.0f) || !(clip.w < SNELL_FLT_MAX)) {
    return 0.0f;
  }
  float span = float(size.x) * abs(clipFromView[0][0]) + float(size.y) * abs(clipFromView[1][1]);
  float texelsPerUnit = min(span / (4.0f * clip.w), SNELL_FLT_MAX);
  return snellRoughConeLevel(radius, texelsPerUnit, levels);
}

SNELL_FN float snellRoughConeEnvironmentLod(SNELL_IN(SnellRoughCone) c, int levels) {
  if (levels <= 1) {
    return 0.0f;
  }
  // 2^(levels - 1) texels over 2 pi, with levels - 1 capped so the power stays finite.
  float texelsPerRadian = exp2(float(min(levels - 1, 100))) / (2.0f * SNELL_PI);
  return snellRoughConeLevel(snellRoughConeHypot(c.angle, c.exitAngle), texelsPerRadian, levels);
}

/* The two reads a rough read takes at a cone's level (lod from snellRoughConeSceneLod or
   snellRoughConeEnvironmentLod, levels: that texture's): the lobe's peak and its tail. */
struct SnellRoughTaps {
  float coreLod;
  float tailLod;
  float tailWeight;  // the tail read's share; 0: one read, at coreLod
};

SNELL_FN SnellRoughTaps snellRoughConeTaps(float lod, int levels) {
  float top = float(max(levels - 1, 0));
  float l = lod > 0.0f ? min(lod, top) : 0.0f;
  SnellRoughTaps t;
  t.coreLod = l;
  t.tailLod = l;
  t.tailWeight = 0.0f;
  if (l > 0.0f && SNELL_ROUGH_CONE_TAIL_WEIGHT > 0.0f) {
    t.coreLod = clamp(l + SNELL_ROUGH_CONE_CORE_OFFSET, 0.0f, top);
    t.tailLod = clamp(l + SNELL_ROUGH_CONE_TAIL_OFFSET, 0.0f, top);
    t.tailWeight = SNELL_ROUGH_CONE_TAIL_WEIGHT;
  }
  return t;
}

SNELL_FN int snellRoughConeFetches(SNELL_IN(SnellRoughTaps) t) {
  return t.tailWeight > 0.0f ? 2 : 1;
}

SNELL_FN vec4 snellRoughConeSample(SNELL_TEX2D tex, vec2 uv, SNELL_IN(SnellRoughTaps) t) {
  vec4 c = SNELL_SAMPLE_LOD(tex, uv, t.coreLod);
  if (t.tailWeight > 0.0f) {
    c = mix(c, SNELL_SAMPLE_LOD(tex, uv, t.tailLod), t.tailWeight);
  }
  return c;
}

SNELL_FN vec4 snellRoughConeSampleEnvironment(SNELL_ENVIRONMENT_TEX env, vec3 dir, SNELL_IN(SnellRoughTaps) t) {
  vec4 c = SNELL_SAMPLE_ENVIRONMENT(env, dir, t.coreLod);
  if (t.tailWeight > 0.0f) {
    c = mix(c, SNELL_SAMPLE_ENVIRONMENT(env, dir, t.tailLod), t.tailWeight);
  }
  return c;
}

#endif



/*
description: the buffers a two-interface technique reads, as the parameter
  lists every technique function declares and the argument lists every call
  inside snell passes on. A layer of buffers is a depth texture, its
  view-space normals, its depth min/max pyramid where a strategy needs one,
  and the SnellDepthSurface that says how to read them; the object's layers
  (its back faces and its front faces) and the opaque scene's (its layer,
  its colour and the environment) each travel as one list, so a new layer
  (a second back-face layer) is one edit here, not one per function and
  call site inside snell.
use: in a function that takes or forwards the buffers:
     SNELL_FN SnellTwoInterfacePath f(vec3 p, SNELL_OBJECT_BUFFERS, SNELL_SCENE_BUFFERS) {
       return g(p, SNELL_OBJECT_BUFFER_ARGS, SNELL_SCENE_BUFFER_ARGS);
     }
     A caller outside snell passes its own textures in the order below.
options:
  SNELL_OBJECT_BUFFERS  SNELL_TEX2D backDepth, SNELL_TEX2D backNormal,
                        SNELL_TEX2D backPyramid, SnellDepthSurface back
                        (the back-face pass: depth cleared to the near value
                        and drawn with GL_GREATER, view-space normals, the
                        pyramid of that depth, how to read the depth),
                        SNELL_TEX2D frontLayerDepth, SNELL_TEX2D
                        frontLayerNormal, SnellDepthSurface frontLayer (the
                        front-face pass: depth
                        cleared to the far value and drawn with GL_LESS,
                        view-space normals, how to read the depth; read only
                        by rays that bounce inside, SnellTechnique.bounces >
                        0: any texture of the right kind may be bound when
                        bounces is 0)
  SNELL_SCENE_BUFFERS   SNELL_TEX2D sceneDepth, SNELL_TEX2D sceneNormal,
                        SNELL_TEX2D scenePyramid, SNELL_TEX2D sceneColor,
                        SnellDepthSurface scene, SNELL_ENVIRONMENT_TEX
                        environment (the opaque scene without the object,
                        its colour, mipmapped for roughness > 0, and the
                        distant environment)
  SNELL_OBJECT_BUFFER_ARGS, SNELL_SCENE_BUFFER_ARGS  the same names as
                        arguments, for the call sites inside snell.
contract: macros only, each on one line (GLSL 330 has no line continuation). Why parameter lists and not a struct of samplers:
  GLSL allows a struct holding samplers only as a uniform (no constructor, so
  a shader could not group textures it declared apart), Vulkan GLSL cannot
  give such a struct's members explicit bindings, WGSL has no structs of
  textures, and GLSL ES has no token pasting for a per-layer name prefix.
  A fixed list of names compiles in every language snell runs, and the code
  after the preprocessor is the code written out by hand (no cost on any
  runtime).
*/
#ifndef SNELL_SHADE_TECHNIQUE_BUFFERS_GLSL
#define SNELL_SHADE_TECHNIQUE_BUFFERS_GLSL




#define SNELL_OBJECT_BUFFERS SNELL_TEX2D backDepth, SNELL_TEX2D backNormal, SNELL_TEX2D backPyramid, SNELL_IN(SnellDepthSurface) back, SNELL_TEX2D frontLayerDepth, SNELL_TEX2D frontLayerNormal, SNELL_IN(SnellDepthSurface) frontLayer
#define SNELL_OBJECT_BUFFER_ARGS backDepth, backNormal, backPyramid, back, frontLayerDepth, frontLayerNormal, frontLayer

#define SNELL_SCENE_BUFFERS SNELL_TEX2D sceneDepth, SNELL_TEX2D sceneNormal, SNELL_TEX2D scenePyramid, SNELL_TEX2D sceneColor, SNELL_IN(SnellDepthSurface) scene, SNELL_ENVIRONMENT_TEX environment
#define SNELL_SCENE_BUFFER_ARGS sceneDepth, sceneNormal, scenePyramid, sceneColor, scene, environment

#endif
/*
description: named presets for the published two-interface refraction methods
  and the baselines, all through the same technique (snellTwoInterfaceTrace /
  snellTwoInterfaceRefraction), so the lab compares them fairly. Each returns
  snellTechnique() with the back and exit slots' strategies set (the exit
  slot's source stays the default, ENVIRONMENT: point it at the scene with
  t.exit.source = SNELL_SOURCE_BUFFERS).
use: SnellTechnique t = snellPresetDir();           // then adjust fields
     SnellTechnique t = snellPresetPlaneNormal(2);
presets (back slot / exit slot):
  snellPresetDir()                 Oliveira & Brauwers 2007 (DIR): CBS, 5 steps,
                                   range from the min/max pyramid's top level /
                                   the same
  snellPresetDirBounds(zNearest, zFarthest)  DIR with the bounding-box range
                                   (their suggested speed-up: no reduction
                                   pass); the numbers from snellDepthRangeFromBox;
                                   back slot only, the exit slot keeps the pyramid
  snellPresetIsr()                 Wyman 2005 (ISR): back.source
                                   SNELL_SOURCE_WYMAN, distance interpolation
                                   between d_V and the per-vertex d_N /
                                   single sample
  snellPresetPlaneNormal(n)        Mayer & Assarsson, normal-based plane, n
                                   refinement iterations / the same
  snellPresetPlaneDepth(n)         Mayer & Assarsson, depth-based plane (depth
                                   mips = the pyramid), n iterations / the same
                                   (both plane presets keep planeFarStart's
                                   default, true: the far start of
                                   intersect/plane_far_start.glsl on the closed
                                   back faces; set it false in both slots for
                                   the poster's method)
  snellPresetSingleSample()        the single-sample (GPU Gems) baseline / the same
  snellPresetLinearMarch()         screen-space ray march, view-space steps +
                                   bisection / the same
  snellPresetDdaMarch()            perspective-correct pixel DDA march / the same
  snellPresetPlaneNormalBounces(n) snellPresetPlaneNormal(n) that follows
                                   TIR inside the object: bounces =
                                   SNELL_PRESET_BOUNCES (4), the inside slot's
                                   march SNELL_PRESET_INSIDE_STEPS (16) steps +
                                   SNELL_PRESET_INSIDE_BISECTIONS (5)
                                   bisections (set inside.intersect.
                                   marchMaxDistance to the object's extent);
                                   reads the front-face layer
  snellPresetLinearMarchBounces()  snellPresetLinearMarch() with the same bounces
  snellPresetImageSpaceBoundBounces()  the image-space bound below with the
                                   same bounces, its inside march at the
                                   linear march's compile-time limits too:
                                   what the bounce techniques are measured
                                   against
  snellPresetImageSpaceBound()     not a real-time method: the best any
                                   image-space technique can do with the same
                                   buffers, for measuring the others against:
                                   the linear march at its compile-time limits
                                   (SNELL_LINEAR_MARCH_MAX_STEPS steps of at
                                   most ~1 px, SNELL_LINEAR_MARCH_MAX_REFINE_STEPS
                                   bisections) on bilinear depth reads
                                   (SNELL_DEPTH_FILTER_BILINEAR: exact on
                                   planes between texel centres) / the same;
                                   set back.intersect.marchMaxDistance and
                                   exit.intersect.marchMaxDistance to the depths the
                                   object and the scene span
the technique table (the one list of named techniques: snell-lab's
  --technique names, the benchmarks and the tests all draw on it; names and
  labels for C++ in include/snell/technique_table.hpp):
  id                              name            preset
  SNELL_TECHNIQUE_SINGLE          single          snellPresetSingleSample()
  SNELL_TECHNIQUE_PLANE_NORMAL_0  plane-normal-0  snellPresetPlaneNormal(0)
  SNELL_TECHNIQUE_PLANE_NORMAL_1  plane-normal-1  snellPresetPlaneNormal(1)
  SNELL_TECHNIQUE_PLANE_NORMAL_2  plane-normal-2  snellPresetPlaneNormal(2)
  SNELL_TECHNIQUE_PLANE_DEPTH     plane-depth     snellPresetPlaneDepth(1)
  SNELL_TECHNIQUE_DIR             dir             snellPresetDir()
  SNELL_TECHNIQUE_ISR             isr             snellPresetIsr()
  SNELL_TECHNIQUE_LINEAR_MARCH    linear-march    snellPresetLinearMarch()
  SNELL_TECHNIQUE_DDA             dda             snellPresetDdaMarch()
  SNELL_TECHNIQUE_IMAGE_SPACE_BOUND  image-space-bound  snellPresetImageSpaceBound()
  SNELL_TECHNIQUE_PLANE_NORMAL_2_BOUNCES  plane-normal-2-bounces  snellPresetPlaneNormalBounces(2)
  SNELL_TECHNIQUE_LINEAR_MARCH_BOUNCES    linear-march-bounces    snellPresetLinearMarchBounces()
  SNELL_TECHNIQUE_IMAGE_SPACE_BOUND_BOUNCES  image-space-bound-bounces  snellPresetImageSpaceBoundBounces()
  SNELL_TECHNIQUE_COUNT           the number of ids (ids are 0 .. COUNT - 1)
  SnellTechnique t = snellTechniquePreset(SNELL_TECHNIQUE_PLANE_NORMAL_1);
  Adding a technique: a preset function here, an id, a branch in
  snellTechniquePreset and a row in include/snell/technique_table.hpp (a
  compile-time check there keeps the two the same length).
options: the defaults of technique_options.glsl and of each strategy's file.
contract: pure constructors, no texture access; iteration counts are stored as
  given (each strategy clamps them). snellTechniquePreset of an id outside
  0 .. SNELL_TECHNIQUE_COUNT - 1: snellTechniquePresetSlots(-1, -1), whose
  slots answer every ray with a miss (snellIntersectWith).
source: Oliveira & Brauwers 2007 (sec. 3.3, 5 steps; sec. 6, bounding box);
  Wyman 2005 via O&B 2007 sec. 2.1, eqs. 1-2; Mayer & Assarsson,
  "Constant-Time Light Refraction Simulation" (methods 1 and 2, step 5);
  McGuire & Mara 2014 (DDA); Davis & Wyman 2007 (bounces inside between
  front and back depth maps).
*/
#ifndef SNELL_SHADE_TECHNIQUE_PRESETS_GLSL
#define SNELL_SHADE_TECHNIQUE_PRESETS_GLSL



SNELL_FN SnellTechnique snellTechniquePresetSlots(int backStrategy, int exitStrategy) {
  SnellTechnique t = snellTechnique();
  t.back.intersect = snellIntersectOptions(backStrategy);
  t.exit.intersect = snellIntersectOptions(exitStrategy);
  return t;
}

/* Oliveira & Brauwers 2007, sec. 3.3: CBS with c = 5 (SNELL_CBS_STEPS' default) */
SNELL_FN SnellTechnique snellPresetDir() {
  return snellTechniquePresetSlots(SNELL_STRATEGY_CBS, SNELL_STRATEGY_CBS);
}

/* Oliveira & Brauwers 2007, sec. 6: bounding-box range instead of the reduction */
SNELL_FN SnellTechnique snellPresetDirBounds(float zNearest, float zFarthest) {
  SnellTechnique t = snellPresetDir();
  t.back.intersect.rangeSource = SNELL_RANGE_EXPLICIT;
  t.back.intersect.range.zNearest = zNearest;
  t.back.intersect.range.zFarthest = zFarthest;
  t.back.intersect.range.valid = true;
  return t;
}

/* Wyman 2005 (O&B 2007 eqs. 1-2): the trace's Wyman variant; the exit slot samples once */
SNELL_FN SnellTechnique snellPresetIsr() {
  SnellTechnique t = snellTechniquePresetSlots(SNELL_STRATEGY_SINGLE, SNELL_STRATEGY_SINGLE);
  t.back.source = SNELL_SOURCE_WYMAN;
  return t;
}

/* Mayer & Assarsson, method 1 + step 5 */
SNELL_FN SnellTechnique snellPresetPlaneNormal(int iterations) {
  SnellTechnique t = snellTechniquePresetSlots(SNELL_STRATEGY_PLANE_NORMAL, SNELL_STRATEGY_PLANE_NORMAL);
  t.back.intersect.planeIterations = iterations;
  t.exit.intersect.planeIterations = iterations;
  return t;
}

/* Mayer & Assarsson, method 2 + step 5 */
SNELL_FN SnellTechnique snellPresetPlaneDepth(int iterations) {
  SnellTechnique t = snellTechniquePresetSlots(SNELL_STRATEGY_PLANE_DEPTH, SNELL_STRATEGY_PLANE_DEPTH);
  t.back.intersect.planeIterations = iterations;
  t.exit.intersect.planeIterations = iterations;
  return t;
}

SNELL_FN SnellTechnique snellPresetSingleSample() {
  return snellTechniquePresetSlots(SNELL_STRATEGY_SINGLE, SNELL_STRATEGY_SINGLE);
}

SNELL_FN SnellTechnique snellPresetLinearMarch() {
  return snellTechniquePresetSlots(SNELL_STRATEGY_LINEAR_MARCH, SNELL_STRATEGY_LINEAR_MARCH);
}

SNELL_FN SnellTechnique snellPresetDdaMarch() {
  return snellTechniquePresetSlots(SNELL_STRATEGY_DDA, SNELL_STRATEGY_DDA);
}

/* The image-space bound: the linear march at its limits, both slots. */
SNELL_FN SnellTechnique snellPresetImageSpaceBound() {
  SnellTechnique t = snellTechniquePresetSlots(SNELL_STRATEGY_LINEAR_MARCH, SNELL_STRATEGY_LINEAR_MARCH);
  t.back.intersect.marchSteps = SNELL_LINEAR_MARCH_MAX_STEPS;
  t.back.intersect.marchBisections = SNELL_LINEAR_MARCH_MAX_REFINE_STEPS;
  t.exit.intersect.marchSteps = SNELL_LINEAR_MARCH_MAX_STEPS;
  t.exit.intersect.marchBisections = SNELL_LINEAR_MARCH_MAX_REFINE_STEPS;
  t.back.intersect.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
  t.exit.intersect.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
  return t;
}

#ifndef SNELL_PRESET_BOUNCES
#  define SNELL_PRESET_BOUNCES 4
#endif
#ifndef SNELL_PRESET_INSIDE_STEPS
#  define SNELL_PRESET_INSIDE_STEPS 16
#endif
#ifndef SNELL_PRESET_INSIDE_BISECTIONS
#  define SNELL_PRESET_INSIDE_BISECTIONS 5
#endif

/* Davis & Wyman 2007 on the normal plane: TIR at the back face followed inside (the inside march between
   the front and back layers) up to SNELL_PRESET_BOUNCES times */
SNELL_FN SnellTechnique snellPresetPlaneNormalBounces(int iterations) {
  SnellTechnique t = snellPresetPlaneNormal(iterations);
  t.bounces = SNELL_PRESET_BOUNCES;
  t.inside.intersect.marchSteps = SNELL_PRESET_INSIDE_STEPS;
  t.inside.intersect.marchBisections = SNELL_PRESET_INSIDE_BISECTIONS;
  return t;
}

/* The linear march in the back and exit slots, with bounces as snellPresetPlaneNormalBounces */
SNELL_FN SnellTechnique snellPresetLinearMarchBounces() {
  SnellTechnique t = snellPresetLinearMarch();
  t.bounces = SNELL_PRESET_BOUNCES;
  t.inside.intersect.marchSteps = SNELL_PRESET_INSIDE_STEPS;
  t.inside.intersect.marchBisections = SNELL_PRESET_INSIDE_BISECTIONS;
  return t;
}

/* The image-space bound that follows TIR inside: the inside march exhaustive as well, so a bounce technique's
   "x bound" compares it with the best any image-space method does on the same buffers and bounce count */
SNELL_FN SnellTechnique snellPresetImageSpaceBoundBounces() {
  SnellTechnique t = snellPresetImageSpaceBound();
  t.bounces = SNELL_PRESET_BOUNCES;
  t.inside.intersect.marchSteps = SNELL_LINEAR_MARCH_MAX_STEPS;
  t.inside.intersect.marchBisections = SNELL_LINEAR_MARCH_MAX_REFINE_STEPS;
  return t;
}

#define SNELL_TECHNIQUE_SINGLE 0
#define SNELL_TECHNIQUE_PLANE_NORMAL_0 1
#define SNELL_TECHNIQUE_PLANE_NORMAL_1 2
#define SNELL_TECHNIQUE_PLANE_NORMAL_2 3
#define SNELL_TECHNIQUE_PLANE_DEPTH 4
#define SNELL_TECHNIQUE_DIR 5
#define SNELL_TECHNIQUE_ISR 6
#define SNELL_TECHNIQUE_LINEAR_MARCH 7
#define SNELL_TECHNIQUE_DDA 8
#define SNELL_TECHNIQUE_IMAGE_SPACE_BOUND 9
#define SNELL_TECHNIQUE_PLANE_NORMAL_2_BOUNCES 10
#define SNELL_TECHNIQUE_LINEAR_MARCH_BOUNCES 11
#define SNELL_TECHNIQUE_IMAGE_SPACE_BOUND_BOUNCES 12
#define SNELL_TECHNIQUE_COUNT 13

/* the technique table's constructor: id -> preset */
SNELL_FN SnellTechnique snellTechniquePreset(int technique) {
  if (technique == SNELL_TECHNIQUE_SINGLE) {
    return snellPresetSingleSample();
  }
  if (technique == SNELL_TECHNIQUE_PLANE_NORMAL_0) {
    return snellPresetPlaneNormal(0);
  }
  if (technique == SNELL_TECHNIQUE_PLANE_NORMAL_1) {
    return snellPresetPlaneNormal(1);
  }
  if (technique == SNELL_TECHNIQUE_PLANE_NORMAL_2) {
    return snellPresetPlaneNormal(2);
  }
  if (technique == SNELL_TECHNIQUE_PLANE_DEPTH) {
    return snellPresetPlaneDepth(1);
  }
  if (technique == SNELL_TECHNIQUE_DIR) {
    return snellPresetDir();
  }
  if (technique == SNELL_TECHNIQUE_ISR) {
    return snellPresetIsr();
  }
  if (technique == SNELL_TECHNIQUE_LINEAR_MARCH) {
    return snellPresetLinearMarch();
  }
  if (technique == SNELL_TECHNIQUE_DDA) {
    return snellPresetDdaMarch();
  }
  if (technique == SNELL_TECHNIQUE_IMAGE_SPACE_BOUND) {
    return snellPresetImageSpaceBound();
  }
  if (technique == SNELL_TECHNIQUE_PLANE_NORMAL_2_BOUNCES) {
    return snellPresetPlaneNormalBounces(2);
  }
  if (technique == SNELL_TECHNIQUE_LINEAR_MARCH_BOUNCES) {
    return snellPresetLinearMarchBounces();
  }
  if (technique == SNELL_TECHNIQUE_IMAGE_SPACE_BOUND_BOUNCES) {
    return snellPresetImageSpaceBoundBounces();
  }
  return snellTechniquePresetSlots(-1, -1);
}

#endif
/*
description: the geometry of two-interface refraction: refract the view ray at
  the front face, find where the refracted ray T1 leaves the object in the
  back-face depth buffer (with the back slot's intersection strategy, or, in
  Wyman's variant, by his distance interpolation), refract again with the
  back-face normal found there; with t.bounces > 0, a total internal
  reflection there (and at each later exit) is followed inside the object
  instead of clamped. The exit ray (P2, T2) is then resolved by
  two_interface_shade.glsl against the opaque scene or the environment.
use: SnellTwoInterfacePath p = snellTwoInterfaceTrace(frontPosition, frontNormal, eta, dN,
         backDepth, backNormal, backPyramid, back, frontLayerDepth, frontLayerNormal, frontLayer,
         t, m.tirPolicy);
  frontPosition  P1: view-space position of the front-face fragment (camera at
                 the origin, so the view ray V is frontPosition itself)
  frontNormal    N1: its normal (either orientation, any length)
  eta            n_outside / n_object (snellIorToEta(1.0f, 1.5f) for glass in air)
  dN             Wyman's d_N: thickness along -N1, interpolated from the per-vertex
                 values the host precomputes (include/snell/wyman_dn.hpp); read
                 only by Wyman's variant (slot.source SNELL_SOURCE_WYMAN)
  backDepth, backNormal, backPyramid, back
                 SNELL_OBJECT_BUFFERS (technique_buffers.glsl): the back-face
                 pass: depth (GL_GREATER after clearing to the near value),
                 view-space normals, the depth min/max pyramid of that depth
                 (snellBuildDepthPyramid / glsl/passes/depth_pyramid.frag), and
                 how to read the depth (emptyDepth = the clear value); then
                 the front-face pass (depth drawn with GL_LESS after clearing
                 to the far value, view-space normals, how to read it), read
                 only when t.bounces > 0
  t              the technique (technique_options.glsl): its back slot (source
                 and intersector), its inside slot and bounce count
  tirPolicy      SNELL_TIR_ZERO / _CRITICAL / _REFLECT, at the first interface
                 and the last one the path meets
options: technique_options.glsl, and
  SNELL_TWO_INTERFACE_NORMAL_SAMPLE  how N2 is read from backNormal at the hit
                 uv: 1 (default) SNELL_SAMPLE_LOD at level 0 with the texture's
                 own filter (bilinear for a LINEAR texture: the normal at the hit
                 point, not at the centre of its texel; NEAREST gives the texel
                 containing the uv, as 0 does); 0 SNELL_TEXEL_FETCH of the texel
                 containing the uv (level 0)
contract:
  - T1 = snellRefract(frontPosition, frontNormal, eta, tirPolicy). If it is
    invalid or zero (NaN/zero inputs, eta not finite positive; TIR under ZERO
    when eta > 1), the path is invalid: valid = false, every vector 0, fetches 0.
  - slot.source SNELL_SOURCE_WYMAN: one sample of the back depth at the projection of P1
    gives d_V = |P1| (zBack / P1.z - 1) (front-to-back distance along the view
    ray); d = snellWymanDistanceVec(P1, N1, T1, d_V, dN); P2 = P1 + d T1,
    accepted when snellHitOnSurface(P2) is valid (the back buffer has a
    surface there; 2 fetches). SNELL_SOURCE_BUFFERS (and any value but the
    two named here): snellIntersectWith(P1, T1, back..., slot.intersect).
    SNELL_SOURCE_ENVIRONMENT: no back-face read (0 fetches), the fallback
    below (the ray leaves at P1 along T1: a thin surface).
  - on a hit: N2 = xyz of the back normal read at the hit uv, level 0
    (SNELL_TWO_INTERFACE_NORMAL_SAMPLE: filtered sample or texel fetch; 1
    fetch), normalized and flipped to face T1 (dot(N2, T1) <= 0); T2 =
    snellRefract(T1, N2, 1 / eta, tirPolicy). hit = true, exitPoint = P2,
    exitUv = the hit uv, exitNormal = N2, pathLength = entryLength = |P2 -
    P1| (entryLength keeps the first segment's when bounces add more), tir = TIR at
    the second interface (T2 follows the policy: critical-angle tangent or
    mirror; the reflected ray is not traced further), exitIncident = T1 (the
    ray T2 was refracted from, so that a caller can refract it again, as
    two_interface_shade.glsl does for rough glass); exitIncident = 0 wherever
    T2 is not snellRefract's result at the last interface (a fallback, an
    invalid path).
  - fallback (fellBack = true, the path still valid): no back hit (invalid or
    off-screen texel, empty range; a hit so far that |P2 - P1| overflows a
    float, beyond ~1.8e19 view units, counts as none), a zero or NaN stored
    normal, or TIR under SNELL_TIR_ZERO: the ray leaves as if the second
    interface did not bend it: exitPoint = P2 when found, else P1,
    exitDirection = T1, pathLength = |P2 - P1| when P2 was found, else 0.
  - bounces (t.bounces = B > 0, clamped to [0, SNELL_MAX_BOUNCES]): at the
    back hit and at each later exit but the (B + 1)-th, TIR reflects (R =
    reflect(T, N)) instead of following tirPolicy: the inside slot
    (SNELL_SOURCE_BUFFERS with SNELL_STRATEGY_LINEAR_MARCH: snellInsideMarch
    from the exit point along R between the back layer and the front layer,
    with inside.intersect's marchMaxDistance, marchSteps, marchBisections;
    with SNELL_STRATEGY_PLANE_NORMAL: snellInsidePlane with marchMaxDistance,
    marchSteps, planeIterations) finds where R leaves; N there is read from that layer's normals (as N2,
    1 fetch), flipped to face R, and the ray refracts out, or reflects again,
    the last allowed interface under tirPolicy. bounces = the reflections
    taken (one that ends as a fallback counts); exitPoint, exitUv, exitNormal are the last interface's,
    exitIncident the ray inside that met it;
    exitFront = the last interface is a front face (T2 heads towards the
    camera's side: two_interface_shade.glsl resolves it with the reflect
    slot); pathLength adds every segment inside; tir = TIR at the last
    interface. A reflection the inside march cannot follow (no exit in the
    buffers, a zero normal there, a path length that overflows, an inside slot
    of another source or strategy) ends the path as a fallback (fellBack =
    true): it leaves from the last interface point along R. bounces = 0 is
    the two-interface path above, bit for bit.
  - fetches: the strategy's count plus the normal fetch, plus each bounce's
    march and normal fetch.
source: C. Wyman, "An Approximate Image-Space Approach for Interactive
  Refraction", SIGGRAPH 2005 (two interfaces, back-face normal and depth
  buffers); M. M. Oliveira & M. Brauwers, "Real-Time Refraction Through
  Deformable Objects", I3D 2007, sec. 2.1 (eqs. 1-2), sec. 3 (intersecting T1
  with the back-face depth map, N2 from the normal map at the hit), sec. 5
  (critical-angle TIR policy); C. Davis & C. Wyman, "Interactive Refractions
  with Total Internal Reflection", Graphics Interface 2007 (bounces inside
  between front and back depth maps).
*/
#ifndef SNELL_SHADE_TWO_INTERFACE_GLSL
#define SNELL_SHADE_TWO_INTERFACE_GLSL















#ifndef SNELL_TWO_INTERFACE_NORMAL_SAMPLE
#  define SNELL_TWO_INTERFACE_NORMAL_SAMPLE 1
#endif

struct SnellTwoInterfacePath {
  vec3 entryDirection;  // T1
  vec3 exitPoint;       // P2 (P1 when no back hit)
  vec3 exitNormal;      // N2, facing T1
  vec3 exitDirection;   // T2 (T1 on fallback)
  vec2 exitUv;          // uv of P2 in the back buffers (in the front buffers when exitFront)
  float pathLength;     // |P2 - P1|, plus every segment after a bounce
  float entryLength;    // |P2 - P1| of the first segment alone (0 without a back hit)
  int fetches;
  int bounces;          // total internal reflections followed inside
  bool hit;
  bool tir;
  bool fellBack;
  bool valid;
  bool exitFront;       // the last interface is a front face (after a bounce): T2 heads to the camera's side
  vec3 exitIncident;    // the ray inside that met the last interface, when T2 is its refraction (else 0)
};

/* Wyman 2005 / Oliveira & Brauwers 2007 sec. 3: P1, T1 -> P2 (back-face buffer), N2 -> T2 */
SNELL_FN SnellTwoInterfacePath snellTwoInterfaceTrace(vec3 frontPosition, vec3 frontNormal, float eta, float dN,
                                                      SNELL_OBJECT_BUFFERS, SNELL_IN(SnellTechnique) t, int tirPolicy) {
  SnellTwoInterfacePath p;
  p.entryDirection = vec3(0.0f, 0.0f, 0.0f);
  p.exitPoint = vec3(0.0f, 0.0f, 0.0f);
  p.exitNormal = vec3(0.0f, 0.0f, 0.0f);
  p.exitDirection = vec3(0.0f, 0.0f, 0.0f);
  p.exitUv = vec2(0.0f, 0.0f);
  p.pathLength = 0.0f;
  p.entryLength = 0.0f;
  p.fetches = 0;
  p.bounces = 0;
  p.hit = false;
  p.tir = false;
  p.fellBack = true;
  p.valid = false;
  p.exitFront = false;
  p.exitIncident = vec3(0.0f, 0.0f, 0.0f);
  SnellRefraction r1 = snellRefract(frontPosition, frontNormal, eta, tirPolicy);
  if (!r1.valid || dot(r1.direction, r1.direction) == 0.0f || !SNELL_FINITE(frontPosition.x) ||
      !SNELL_FINITE(frontPosition.y) || !SNELL_FINITE(frontPosition.z)) {
    return p;
  }
  vec3 t1 = r1.direction;
  p.entryDirection = t1;
  p.exitPoint = frontPosition;
  p.exitDirection = t1;
  p.valid = true;
  SnellHit h = snellHitMiss(0);
  if (t.back.source == SNELL_SOURCE_WYMAN) {
    SnellScreenPoint sp = snellViewToUv(back.clipFromView, frontPosition);
    if (sp.valid && frontPosition.z < 0.0f) {
      SnellSurfaceSample b = snellSampleSurface(backDepth, sp.uv, back);
      h = snellHitMiss(1);
      if (b.valid) {
        float dV = length(frontPosition) * (b.viewZ / frontPosition.z - 1.0f);
        float d = snellWymanDistanceVec(frontPosition, frontNormal, t1, dV, dN);
        h = snellHitOnSurface(frontPosition + d * t1, backDepth, back, 1);
      }
    }
  } else if (t.back.source != SNELL_SOURCE_ENVIRONMENT) {
    h = snellIntersectWith(frontPosition, t1, backDepth, backNormal, backPyramid, back, t.back.intersect);
  }
  p.fetches = h.fetches;
  // length() squares first: it overflows beyond ~1.8e19 (Wyman's estimate with a huge dN).
  float pathLength = length(h.position - frontPosition);
  if (!h.valid || !SNELL_FINITE(pathLength)) {
    return p;
  }
  p.hit = true;
  p.exitPoint = h.position;
  p.exitUv = h.uv;
  p.pathLength = pathLength;
  p.entryLength = pathLength;
  int bounces = clamp(t.bounces, 0, SNELL_MAX_BOUNCES);
  vec3 d = t1;
  // One interface per pass: the back hit, then each exit the inside slot finds after a bounce. Every
  // interface but the last allowed one reflects on TIR and goes on; the last takes the material's policy.
  for (int k = 0; k <= SNELL_MAX_BOUNCES; ++k) {
    // Only a bounce reaches a front face. Testing bounces first makes the test a constant false for a
    // technique without bounces, so the front layer's read drops out: GPUs without uniform branches
    // (llvmpipe) read both sides of a ?:.
    bool front = bounces > 0 && p.exitFront;
#if SNELL_TWO_INTERFACE_NORMAL_SAMPLE
    vec4 nk = front ? SNELL_SAMPLE_LOD(frontLayerNormal, p.exitUv, 0.0f)
                    : SNELL_SAMPLE_LOD(backNormal, p.exitUv, 0.0f);
#else
    vec4 nk = front
                  ? SNELL_TEXEL_FETCH(frontLayerNormal,
                                      snellUvToPixel(p.exitUv, SNELL_TEXTURE_SIZE(frontLayerNormal, 0)), 0)
                  : SNELL_TEXEL_FETCH(backNormal, snellUvToPixel(p.exitUv, SNELL_TEXTURE_SIZE(backNormal, 0)), 0);
#endif
    p.fetches = p.fetches + 1;
    vec3 n = snellSafeNormalize(vec3(nk.x, nk.y, nk.z));
    if (dot(n, n) == 0.0f) {
      return p;
    }
    if (dot(n, d) > 0.0f) {
      n = -n;
    }
    p.exitNormal = n;
    // bounces == 0 first: a constant for a technique without bounces, so all that follows the first
    // interface drops out (a compiler does not see that k >= 0 here).
    bool last = bounces == 0 || k >= bounces;
    SnellRefraction r2 = snellRefract(d, n, 1.0f / eta, last ? tirPolicy : SNELL_TIR_REFLECT);
    if (last || !r2.tir) {
      p.tir = r2.tir;
      if (!r2.valid || dot(r2.direction, r2.direction) == 0.0f) {
        return p;
      }
      p.exitDirection = r2.direction;
      p.exitIncident = d;
      p.fellBack = false;
      return p;
    }
    // From here a path that cannot be followed leaves along the reflection from the last point (a fallback).
    d = r2.direction;
    p.exitDirection = d;
    p.tir = true;
    p.bounces = k + 1;
    bool insidePlane = t.inside.intersect.strategy == SNELL_STRATEGY_PLANE_NORMAL;
    if (t.inside.source != SNELL_SOURCE_BUFFERS ||
        (!insidePlane && t.inside.intersect.strategy != SNELL_STRATEGY_LINEAR_MARCH)) {
      return p;
    }
    SnellInsideHit ih;
    if (insidePlane) {
      ih = snellInsidePlane(p.exitPoint, d, backDepth, backNormal, back, frontLayerDepth, frontLayerNormal, frontLayer,
                            t.inside.intersect.marchMaxDistance, t.inside.intersect.marchSteps,
                            t.inside.intersect.planeIterations);
    } else {
      ih = snellInsideMarch(p.exitPoint, d, backDepth, back, frontLayerDepth, frontLayer,
                            t.inside.intersect.marchMaxDistance, t.inside.intersect.marchSteps,
                            t.inside.intersect.marchBisections);
    }
    p.fetches = p.fetches + ih.hit.fetches;
    float segment = length(ih.hit.position - p.exitPoint);
    if (!ih.hit.valid || !SNELL_FINITE(p.pathLength + segment)) {
      return p;
    }
    p.exitPoint = ih.hit.position;
    p.exitUv = ih.hit.uv;
    p.exitFront = ih.front;
    p.pathLength = p.pathLength + segment;
  }
  return p;
}

#endif
/*
description: two-interface refraction, shaded: the full technique a fragment
  shader calls for a front-face fragment of a refractive object. Trace the
  path through the object (two_interface.glsl), resolve the exit ray with the
  exit slot against the opaque scene behind the object (its depth, normal,
  pyramid and colour buffers, with any strategy: Mayer & Assarsson's painting
  behind a glass sphere) or against a distant environment, with a documented
  fallback when the scene hit is not found; absorb along the path inside
  (Beer-Lambert), add the Fresnel-weighted reflection at the first interface,
  resolved by the same call with the reflect slot; optionally once per colour
  channel (chromatic dispersion) and with blurred (roughness) lookups.
use: SnellTechnique t = snellPresetDir();   // or any preset, then adjust
     t.exit.source = SNELL_SOURCE_BUFFERS;
     SnellMaterial m = snellMaterial();
     SnellView v = snellView();
     SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(frontPosition, frontNormal, dN,
         backDepth, backNormal, backPyramid, back, frontLayerDepth, frontLayerNormal, frontLayer,
         sceneDepth, sceneNormal, scenePyramid, sceneColor, scene, environment, t, m, v);
     fragColor = vec4(r.color, 1.0f);
     SnellTwoInterfaceExit e = snellTwoInterfaceExitRough(origin, dir, cone, sceneDepth, sceneNormal,
         scenePyramid, sceneColor, scene, environment, t.exit, v);   // one slot alone
     SnellTwoInterfaceExit e = snellTwoInterfaceExit(origin, dir, sceneDepth, sceneNormal,
         scenePyramid, sceneColor, scene, environment, t.exit, m, v);   // ... through a thin sheet of m
  frontPosition, frontNormal, dN, back*: as snellTwoInterfaceTrace
                 (SNELL_OBJECT_BUFFERS, technique_buffers.glsl)
  sceneDepth, sceneNormal, scenePyramid, scene: the opaque scene without the
                 object, read by a BUFFERS slot (normals for PLANE_NORMAL, the
                 pyramid for the search range and PLANE_DEPTH); any textures
                 when no slot reads them (never read)
  sceneColor     the opaque scene's colour (mipmapped for roughness > 0)
  environment    SNELL_ENVIRONMENT_TEX: an equirectangular 2D texture by
                 default, a cube map through the hook (environment.glsl); looked
                 up with world directions: v.envX, v.envY, v.envZ = the columns
                 of the world-from-view rotation
  t, m, v        SnellTechnique (its back, exit and reflect slots),
                 SnellMaterial, SnellView (technique_options.glsl)
options: technique_options.glsl; technique_buffers.glsl; environment.glsl hooks.
contract (snellTwoInterfaceExitRough(origin, dir, cone, ..., slot, v)):
  - lods (shade/rough_cone.glsl): every environment read at
    envLod = snellRoughConeEnvironmentLod(cone, v.environmentLevels); a read
    of the scene colour at a point q (the hit, or the edge fade's point) at
    snellRoughConeSceneLod(cone, |q - origin|, q, scene.clipFromView, its
    base size, v.sceneColorLevels): the cone's width where the ray meets
    the scene, in that buffer's texels. A cone of radius and angles 0 (smooth
    glass) reads level 0. Each read is snellRoughConeSample (or
    snellRoughConeSampleEnvironment) at snellRoughConeTaps(that level, the
    texture's levels): at level 0 one SNELL_SAMPLE_LOD, above it two (the
    lobe's peak and tail), each counted.
  - dir zero or not finite, or origin not finite: color 0, fellBack, 0 fetches.
  - slot.source ENVIRONMENT: color = the environment read along
    world(dir / |dir|) at envLod, hit = snellHitMiss(0), fellBack false.
  - any other source (BUFFERS; WYMAN reads as BUFFERS here): hit =
    snellIntersectWith(origin, dir, scene..., slot.intersect), then the
    foreground rule, snellRejectForeground(hit, origin, sceneDepth, scene,
    SNELL_FOREGROUND_TOLERANCE) (it reads the texel containing the hit)
    (intersect/foreground.glsl: 1 fetch when the strategy hit; a hit on a
    surface nearer the camera than the whole ray is refused, so a foreground
    never shows through the object); valid: color = the scene colour read
    at hit.uv and sceneLod. Invalid (ray
    leaves the screen, points towards the camera where a search cannot
    follow, lands on an empty texel): fellBack = true and slot.fallback
    ENVIRONMENT: the environment along dir; EDGE_FADE: q = origin +
    slot.fallbackDistance dir/|dir|, w = snellScreenEdgeFade(projection of q,
    slot.edgeFadeWidth) (0 when q does not project), color = mix(environment,
    sceneColor at the projection clamped to [0,1]^2, w) (the scene read only
    when w > 0). Never black unless the environment is.
  - fetches: the strategy's, the foreground rule's read, and the colour and
    environment reads' (snellRoughConeFetches: 1 on smooth glass, 2 on rough).
contract (snellTwoInterfaceExit(origin, dir, ..., slot, m, v)): the above
  with the cone of a ray through a thin sheet of the material:
  snellRoughConeTransmit(m.roughness, snellIorToEta(m.iorOutside, m.ior), 0, 0).
contract (snellTwoInterfaceRefraction):
  - one trace with eta = snellIorToEta(m.iorOutside, m.ior) (m.dispersion != 3),
    or three (m.dispersion == 3), with m.iors.x/.y/.z for red/green/blue, each
    channel taken from its own trace; the back slot t.back finds P2 (with
    t.bounces > 0 the trace follows TIR inside, two_interface.glsl), the exit
    slot t.exit resolves (P2, T2), or the reflect slot t.reflect when the
    path left through a front face (after a bounce: T2 heads towards the
    camera's side); the reported geometry (exit point, direction, hit, path
    length, tir, bounces, backHit) is the single / green trace's; fetches and
    fellBack (any) cover all traces. fellBack: the path fell back
    (two_interface.glsl) or the exit slot did; a reflect slot that resolves a
    path leaving through a front face and finds no scene shows the
    environment, as the first surface's reflection does, and is no fallback.
  - t.insideScene (the opaque scene has surfaces inside the object): after
    a trace that found a back hit, the refracted ray T1 from P1 is also run
    against the scene buffers with the exit slot's strategy
    (snellIntersectWith with t.exit.intersect, then snellRejectForeground
    with the hit itself as the segment's origin: the surface at its texel
    may not be nearer than the hit by more than the tolerance, so a search
    that passed behind a surface's silhouette is not taken for a hit on it;
    its fetches added). A hit nearer than the back hit
    (|hit - P1| < the path's entryLength) ends the path on that surface:
    colour = sceneColor at the hit (read as above, at the level of the
    entry lobe's width there: the cone below with its angles set to 0, at
    distance 0), exitPoint = the hit,
    exitDirection = T1, exitHit = the hit, pathLength = |hit - P1|, no tir,
    no bounces, no fallback, insideHit = true (the single / green trace's).
    The surface is shaded as the opaque surface it is: its colour, absorbed
    over the path inside, no second refraction.
  - rough exit (snellRoughConeSlope(m.roughness) = alpha > 0): where the
    path left by refraction (its exitIncident is not 0; not inside), T2 =
    snellRefractRough(exitIncident, exitNormal, 1 / eta of that trace, alpha,
    m.tirPolicy).direction (optics/refract_rough.glsl: Snell's law with cos_t^2
    averaged over the exit interface's microfacet slopes, smooth through the
    critical angle), which the exit slot resolves and exitDirection reports;
    tir stays the mean normal's. Smooth glass keeps the trace's T2, bit for bit.
  - blur: each trace's exit slot reads through the cone
    snellRoughConeTransmit(m.roughness, that trace's eta, pathLength,
    bounces) (both interfaces' lobes: the entry lobe carried over the path
    inside and the distance behind, the exit lobe over the distance behind,
    added in quadrature); the reflect slot of the first surface's reflection
    through snellRoughConeReflect(m.roughness).
  - transmitted = exit color * snellBeerLambert(m.absorption, pathLength) per
    channel, pathLength = |P2 - P1| of that channel's trace (0 on fallback
    without a back hit; finite: a back hit whose |P2 - P1| overflows a float
    counts as none, two_interface.glsl).
  - reflection (m.reflection): F = snellFresnelDielectric(cos(V, N1), eta of
    the green/single trace); R = reflect(V, N1); bg(R) =
    snellTwoInterfaceExit(P1, R, scene..., t.reflect, m, v) (the environment
    along R, or the scene colour where the reflect slot's intersector finds
    the scene, else its fallback; snellTwoInterfaceExitRough with the
    reflection's cone); its fetches added, its hit in
    reflectionHit; color = F bg(R) + (1 - F) transmitted. Else F = 0, color =
    transmitted. The Fresnel loss at the later interfaces, and the light they
    reflect back inside where Snell allows refraction, are not modelled.
  - an invalid path (NaN / zero inputs): color 0, fellBack true, the
    reflection still added when R is defined.
source: Wyman 2005 and Oliveira & Brauwers 2007 (two interfaces, distant
  environment); C. Mayer & U. Assarsson, "Constant-Time Light Refraction
  Simulation" (nearby geometry: the exit ray against the scene buffers, "a
  transparent sphere refracts a painting"); Fresnel: optics/fresnel_dielectric.glsl;
  edge fade: shade/perturb_edge_fade.glsl;
  absorption: optics/beer_lambert.glsl (Beer-Lambert over the found chord);
  blur: shade/rough_cone.glsl (Walter et al. 2007; de Rousiers et al. 2012).
*/
#ifndef SNELL_SHADE_TWO_INTERFACE_SHADE_GLSL
#define SNELL_SHADE_TWO_INTERFACE_SHADE_GLSL


















struct SnellTwoInterfaceExit {
  vec3 color;
  SnellHit hit;
  bool fellBack;
  int fetches;
};

struct SnellTwoInterfaceResult {
  vec3 color;
  vec3 exitPoint;      // P2 (P1 when the back hit failed)
  vec3 exitDirection;  // T2 (T1 on fallback)
  SnellHit exitHit;    // the exit slot's hit in the scene buffers (SNELL_SOURCE_BUFFERS)
  SnellHit reflectionHit;  // the reflect slot's hit in the scene buffers (SNELL_SOURCE_BUFFERS)
  float pathLength;    // |P2 - P1| inside the object
  float fresnel;       // F at the first interface (0 without reflection)
  int fetches;
  bool backHit;        // P2 found in the back-face buffers
  bool fellBack;       // any fallback: back hit, TIR under ZERO, a bounce not followed, exit slot
  bool tir;            // TIR at the last interface
  int bounces;         // total internal reflections followed inside (SnellTechnique.bounces at most)
  bool insideHit;      // the refracted ray met the opaque scene inside the object (t.insideScene)
};

/* Mayer & Assarsson: a ray from the object resolved by one slot against the scene buffers or the environment,
   its colour blurred over the rough glass's cone (de Rousiers et al.; shade/rough_cone.glsl) */
SNELL_FN SnellTwoInterfaceExit snellTwoInterfaceExitRough(vec3 origin, vec3 dir, SNELL_IN(SnellRoughCone) cone,
                                                          SNELL_SCENE_BUFFERS, SNELL_IN(SnellSlot) slot,
                                                          SNELL_IN(SnellView) v) {
  SnellTwoInterfaceExit e;
  e.color = vec3(0.0f, 0.0f, 0.0f);
  e.hit = snellHitMiss(0);
  e.fellBack = true;
  e.fetches = 0;
  vec3 d = snellSafeNormalize(dir);
  if (dot(d, d) == 0.0f || !SNELL_FINITE(origin.x) || !SNELL_FINITE(origin.y) ||
      !SNELL_FINITE(origin.z)) {
    return e;
  }
  SnellRoughTaps envTaps = snellRoughConeTaps(snellRoughConeEnvironmentLod(cone, v.environmentLevels),
                                              v.environmentLevels);
  ivec2 colorSize = SNELL_TEXTURE_SIZE(sceneColor, 0);
  vec3 world = d.x * v.envX + d.y * v.envY + d.z * v.envZ;
  if (slot.source != SNELL_SOURCE_ENVIRONMENT) {
    e.hit = snellIntersectWith(origin, dir, sceneDepth, sceneNormal, scenePyramid, scene, slot.intersect);
    e.hit = snellRejectForeground(e.hit, origin, sceneDepth, scene, SNELL_FOREGROUND_TOLERANCE);
    e.fetches = e.hit.fetches;
    if (e.hit.valid) {
      float lod = snellRoughConeSceneLod(cone, length(e.hit.position - origin), e.hit.position, scene.clipFromView,
                                         colorSize, v.sceneColorLevels);
      SnellRoughTaps taps = snellRoughConeTaps(lod, v.sceneColorLevels);
      vec4 c = snellRoughConeSample(sceneColor, e.hit.uv, taps);
      e.color = vec3(c.x, c.y, c.z);
      e.fetches = e.fetches + snellRoughConeFetches(taps);
      e.fellBack = false;
      return e;
    }
    vec4 env = snellRoughConeSampleEnvironment(environment, world, envTaps);
    e.fetches = e.fetches + snellRoughConeFetches(envTaps);
    e.color = vec3(env.x, env.y, env.z);
    if (slot.fallback == SNELL_FALLBACK_EDGE_FADE) {
      vec3 q = origin + slot.fallbackDistance * d;
      SnellScreenPoint sp = snellViewToUv(scene.clipFromView, q);
      float w = sp.valid ? snellScreenEdgeFade(sp.uv, slot.edgeFadeWidth) : 0.0f;
      if (w > 0.0f) {
        vec2 uv = clamp(sp.uv, vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
        float lod = snellRoughConeSceneLod(cone, slot.fallbackDistance, q, scene.clipFromView, colorSize,
                                           v.sceneColorLevels);
        SnellRoughTaps taps = snellRoughConeTaps(lod, v.sceneColorLevels);
        vec4 c = snellRoughConeSample(sceneColor, uv, taps);
        e.fetches = e.fetches + snellRoughConeFetches(taps);
        e.color = mix(e.color, vec3(c.x, c.y, c.z), w);
      }
    }
    return e;
  }
  vec4 env = snellRoughConeSampleEnvironment(environment, world, envTaps);
  e.color = vec3(env.x, env.y, env.z);
  e.fetches = snellRoughConeFetches(envTaps);
  e.fellBack = false;
  return e;
}

/* The same for a ray that left through a thin sheet of the material: both rough interfaces, no path inside */
SNELL_FN SnellTwoInterfaceExit snellTwoInterfaceExit(vec3 origin, vec3 dir, SNELL_SCENE_BUFFERS,
                                                     SNELL_IN(SnellSlot) slot, SNELL_IN(SnellMaterial) m,
                                                     SNELL_IN(SnellView) v) {
  SnellRoughCone cone = snellRoughConeTransmit(m.roughness, snellIorToEta(m.iorOutside, m.ior), 0.0f, 0);
  return snellTwoInterfaceExitRough(origin, dir, cone, SNELL_SCENE_BUFFER_ARGS, slot, v);
}

/* Wyman 2005; Oliveira & Brauwers 2007; Mayer & Assarsson: the composed technique */
SNELL_FN SnellTwoInterfaceResult snellTwoInterfaceRefraction(vec3 frontPosition, vec3 frontNormal, float dN,
                                                             SNELL_OBJECT_BUFFERS, SNELL_SCENE_BUFFERS,
                                                             SNELL_IN(SnellTechnique) t, SNELL_IN(SnellMaterial) m,
                                                             SNELL_IN(SnellView) v) {
  bool three = m.dispersion == 3;
  float eta = snellIorToEta(m.iorOutside, three ? m.iors.y : m.ior);
  SnellTwoInterfaceResult r;
  r.reflectionHit = snellHitMiss(0);
  r.fresnel = 0.0f;
  vec3 transmitted = vec3(0.0f, 0.0f, 0.0f);
  // The green (or only) channel's path gives every field; with dispersion, red and blue follow their own
  // paths for their colour. One loop, not three copies of the trace: WebGL 2 on SwiftShader runs out of
  // shader stack with three, and every browser compiles a third of the code.
  int channels = three ? 3 : 1;
  for (int k = 0; k < 3; ++k) {
    float etaK = eta;
    if (k == 1) {
      etaK = snellIorToEta(m.iorOutside, m.iors.x);
    } else if (k == 2) {
      etaK = snellIorToEta(m.iorOutside, m.iors.z);
    }
    SnellTwoInterfacePath p =
        snellTwoInterfaceTrace(frontPosition, frontNormal, etaK, dN, SNELL_OBJECT_BUFFER_ARGS, t, m.tirPolicy);
    // An opaque surface inside the object: the refracted ray against the scene too (the exit slot's strategy);
    // nearer than the back faces, it ends the path there, unrefracted.
    bool inside = false;
    SnellHit ih = snellHitMiss(0);
    if (t.insideScene && p.hit) {
      ih = snellIntersectWith(frontPosition, p.entryDirection, sceneDepth, sceneNormal, scenePyramid, scene,
                              t.exit.intersect);
      // The hit must lie on the surface at its texel: the rule with the hit as the whole segment refuses a
      // surface nearer than the hit, i.e. a march that passed behind the card's silhouette (it did not hit it).
      ih = snellRejectForeground(ih, ih.position, sceneDepth, scene, SNELL_FOREGROUND_TOLERANCE);
      float d = length(ih.position - frontPosition);
      inside = ih.valid && d < p.entryLength;
      if (inside) {
        p.exitPoint = ih.position;
        p.exitDirection = p.entryDirection;
        p.exitUv = ih.uv;
        p.pathLength = d;
        p.tir = false;
        p.fellBack = false;
        p.exitFront = false;
        p.bounces = 0;
        p.exitIncident = vec3(0.0f, 0.0f, 0.0f);
      }
      p.fetches = p.fetches + ih.fetches;
    }
    // A path that left through a front face is resolved by the reflect slot (an if: WebGL rejects ?: on
    // structs). Only a bounce reaches a front face: testing t.bounces first makes the test a constant
    // false for a technique without bounces, so the exit slot stays the constant t.exit and its options fold.
    SnellSlot leave = t.exit;
    if (t.bounces > 0 && p.exitFront) {
      leave = t.reflect;
    }
    // Rough glass: the last interface's microfacets turn the exit ray smoothly through the critical angle,
    // where the smooth ray swings across the scene behind with every fraction of a pixel the picture moves.
    float alpha = snellRoughConeSlope(m.roughness);
    if (alpha > 0.0f && dot(p.exitIncident, p.exitIncident) > 0.0f) {
      p.exitDirection = snellRefractRough(p.exitIncident, p.exitNormal, 1.0f / etaK, alpha, m.tirPolicy).direction;
    }
    // The blur: the entry lobe carried over the path inside and both lobes over the distance behind; an
    // opaque surface inside the glass sees the entry lobe alone.
    SnellRoughCone cone = snellRoughConeTransmit(m.roughness, etaK, p.pathLength, p.bounces);
    SnellTwoInterfaceExit e;
    if (inside) {
      SnellRoughCone entry = cone;
      entry.angle = 0.0f;
      entry.exitAngle = 0.0f;
      float lod = snellRoughConeSceneLod(entry, 0.0f, ih.position, scene.clipFromView,
                                         SNELL_TEXTURE_SIZE(sceneColor, 0), v.sceneColorLevels);
      SnellRoughTaps taps = snellRoughConeTaps(lod, v.sceneColorLevels);
      vec4 c = snellRoughConeSample(sceneColor, ih.uv, taps);
      e.color = vec3(c.x, c.y, c.z);
      e.hit = ih;
      e.fellBack = false;
      e.fetches = snellRoughConeFetches(taps);
    } else {
      e = snellTwoInterfaceExitRough(p.exitPoint, p.exitDirection, cone, SNELL_SCENE_BUFFER_ARGS, leave, v);
    }
    vec3 c = e.color * snellBeerLambert(m.absorption, p.pathLength);
    // Where the reflect slot finds no scene after a front-face exit, the environment is what is there,
    // as for the first surface's reflection: not a fallback.
    bool fellBack = p.fellBack || (e.fellBack && !p.exitFront);
    if (k == 0) {
      transmitted = c;
      r.exitPoint = p.exitPoint;
      r.exitDirection = p.exitDirection;
      r.exitHit = e.hit;
      r.pathLength = p.pathLength;
      r.fetches = p.fetches + e.fetches;
      r.backHit = p.hit;
      r.fellBack = fellBack || !p.valid;
      r.tir = p.tir;
      r.bounces = p.bounces;
      r.insideHit = inside;
    } else {
      if (k == 1) {
        transmitted.x = c.x;
      } else {
        transmitted.z = c.z;
      }
      r.fetches = r.fetches + p.fetches + e.fetches;
      r.fellBack = r.fellBack || fellBack;
    }
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (k + 1 >= channels) {
      break;
    }
  }
  r.color = transmitted;
  vec3 vv = snellSafeNormalize(frontPosition);
  vec3 n1 = snellSafeNormalize(frontNormal);
  if (m.reflection && dot(vv, vv) > 0.0f && dot(n1, n1) > 0.0f) {
    float f = snellFresnelDielectric(dot(vv, n1), eta);
    // The reflect slot: the exit's call with its own slot, from P1 along R.
    SnellTwoInterfaceExit re = snellTwoInterfaceExitRough(frontPosition, reflect(vv, n1),
                                                          snellRoughConeReflect(m.roughness),
                                                          SNELL_SCENE_BUFFER_ARGS, t.reflect, v);
    r.reflectionHit = re.hit;
    r.fetches = r.fetches + re.fetches;
    r.fresnel = f;
    r.color = f * re.color + (1.0f - f) * transmitted;
  }
  return r;
}

#endif
/*
description: the engines' screen-space refraction models by number, so a host
  can run any of them through one call (the lab's engine rows); the names and
  labels for C++ are in include/snell/engine_model_table.hpp.
use: SnellEngineRefraction e = snellEngineRefraction(SNELL_ENGINE_THREEJS, p, n, eta, parameter,
                                                     proxyFromView, sceneDepth, scene);
     int blur = snellEngineBlurOf(SNELL_ENGINE_THREEJS);  // how that engine reads rough glass (engine_rough.glsl)
  model       SNELL_ENGINE_* below
  parameter   the model's one free value: thickness (three.js / Bevy,
              Filament solid, HDRP sphere and box), microThickness (Filament
              thin), the uv scale (Godot)
  the rest    as the models' own functions (proxyFromView is read by the HDRP
              models only, sceneDepth by HDRP and Godot; every model projects
              with scene.clipFromView)
ids:
  SNELL_ENGINE_THREEJS          snellEngineThreeJs (threejs.glsl; Bevy's too)
  SNELL_ENGINE_FILAMENT_SOLID   snellEngineFilamentSolid (filament.glsl)
  SNELL_ENGINE_FILAMENT_THIN    snellEngineFilamentThin (filament.glsl)
  SNELL_ENGINE_HDRP_SPHERE      snellEngineHdrpSphere (hdrp.glsl)
  SNELL_ENGINE_HDRP_BOX         snellEngineHdrpBox (hdrp.glsl)
  SNELL_ENGINE_GODOT            snellEngineGodot (godot.glsl)
  SNELL_ENGINE_MODEL_COUNT      the number of ids (0 .. COUNT - 1)
contract: the chosen model's function with these arguments; a model outside
  0 .. SNELL_ENGINE_MODEL_COUNT - 1: snellEngineInvalid().
  snellEngineBlurOf(model): the engine's blur of engine_rough.glsl
  (SNELL_ENGINE_BLUR_THREEJS for three.js, _FILAMENT for both Filament
  models, _HDRP for both HDRP models, _GODOT for Godot); -1 for any other id
  (snellEngineBlurRead then reads the smooth texel). Bevy shares three.js's
  point (SNELL_ENGINE_THREEJS) but has a blur of its own,
  SNELL_ENGINE_BLUR_BEVY, which no model id names: a host that shows Bevy
  pairs the two (the lab's engine-bevy row).
source: the models' own files.
*/
#ifndef SNELL_SHADE_ENGINE_MODELS_ENGINE_MODELS_GLSL
#define SNELL_SHADE_ENGINE_MODELS_ENGINE_MODELS_GLSL
/*
description: what the engines' screen-space refraction models return, and
  the step they all share: refract the view ray at the front face, then read
  the opaque scene's colour where a point projects. The models themselves
  (threejs.glsl, filament.glsl, hdrp.glsl, godot.glsl) re-derive, from each
  engine's documented source, where that engine reads its scene colour, so a
  host can score them against snell's techniques on the same buffers (the lab
  does). They need no back-face pass: they are snell's cheapest tier.
use: SnellEngineEntry t = snellEngineEntry(p, n, eta);   // the entry refraction every refracting model starts from
     SnellEngineRefraction e = snellEngineSeePoint(x, direction, distance, clipFromView);
     SnellEngineRefraction e = snellEngineInvalid();   // what every model returns for invalid input
     vec4 s = SNELL_SAMPLE_LOD(sceneColor, clamp(e.uv, vec2(0.0f, 0.0f), vec2(1.0f, 1.0f)), 0.0f);
     vec3 c = mix(environmentAlong(e.direction), vec3(s.x, s.y, s.z), e.sceneWeight);
  p, n      the front-face fragment's view-space position and normal (the
            normal may face either way; it is turned towards the eye)
  eta       n_outside / n_inside (1 / ior: every engine refracts from air)
  x         the view-space point whose projection is read
contract:
  - SnellEngineRefraction.uv: where the model reads the scene colour, in the
    uv of clipFromView's buffers; it may lie outside [0,1]^2: every engine
    reads it clamped to the edge (its sampler), the caller clamps.
  - sceneWeight in [0,1]: the scene colour's share; the rest is the
    environment along `direction` (HDRP's probe fallback; 0 also where the
    point does not project: at or behind the camera).
  - direction: unit, the direction an environment read follows.
  - distance in [0, SNELL_FLT_MAX]: the length the engine absorbs over.
  - valid false (uv 0, weight 0, direction 0, distance 0): p or n zero, NaN or
    infinite, or (every model but Godot's, which has no eta) eta not a finite
    positive normal number (snellRefract's rules); the caller shows what it
    shows for an invalid fragment.
  - snellEngineEntry(p, n, eta): direction, tir and valid of snellRefract(p,
    n, eta, SNELL_TIR_ZERO); normal = n / |n| turned towards the eye exactly as
    snellRefract turns it (0 when n is zero or not finite); cosine =
    dot(normal, direction) (0 on TIR or invalid input).
  - every model that refracts starts with snellEngineEntry: where it is not valid,
    snellEngineInvalid(); on TIR at the entry (eta > 1, direction 0),
    snellEngineSeePoint(p, p, 0, clipFromView): the fragment's own texel, no
    displacement. A length parameter that is negative or NaN counts as 0, as
    the engines clamp theirs.
  - snellEngineSeePoint(x, direction, distance, clipFromView): uv =
    snellViewToUv(clipFromView, x).uv and weight 1 where x projects, else uv 0
    and weight 0; direction normalized (0 stays 0), distance clamped to
    [0, SNELL_FLT_MAX] (NaN: 0).
source: the engines' shared first step: T = refract(-V, N, 1/ior) at the front
  face (three.js transmission_pars_fragment, Filament surface_light_indirect.fs,
  HDRP Refraction.hlsl, Bevy transmission.wesl).
*/
#ifndef SNELL_SHADE_ENGINE_MODELS_ENGINE_REFRACTION_GLSL
#define SNELL_SHADE_ENGINE_MODELS_ENGINE_REFRACTION_GLSL





struct SnellEngineEntry {
  vec3 direction;  // T (0 on TIR)
  vec3 normal;     // the unit normal turned as snellRefract turns it (towards the eye)
  float cosine;    // dot(normal, T), <= 0
  bool tir;
  bool valid;
};

struct SnellEngineRefraction {
  vec2 uv;
  float sceneWeight;
  vec3 direction;
  float distance;
  bool valid;
};

SNELL_FN SnellEngineRefraction snellEngineInvalid() {
  SnellEngineRefraction e;
  e.uv = vec2(0.0f, 0.0f);
  e.sceneWeight = 0.0f;
  e.direction = vec3(0.0f, 0.0f, 0.0f);
  e.distance = 0.0f;
  e.valid = false;
  return e;
}

/* The entry refraction every refracting model starts from: T = refract(-V, N, 1/ior) */
SNELL_FN SnellEngineEntry snellEngineEntry(vec3 p, vec3 n, float eta) {
  SnellRefraction t = snellRefract(p, n, eta, SNELL_TIR_ZERO);
  SnellEngineEntry e;
  e.direction = t.direction;
  e.normal = snellSafeNormalize(n);
  e.normal = -dot(e.normal, snellSafeNormalize(p)) < 0.0f ? -e.normal : e.normal;
  e.cosine = dot(e.normal, t.direction);
  e.tir = t.tir;
  e.valid = t.valid;
  return e;
}

SNELL_FN SnellEngineRefraction snellEngineSeePoint(vec3 x, vec3 direction, float distance, mat4 clipFromView) {
  SnellEngineRefraction e = snellEngineInvalid();
  SnellScreenPoint sp = snellViewToUv(clipFromView, x);
  if (sp.valid) {
    e.uv = sp.uv;
    e.sceneWeight = 1.0f;
  }
  e.direction = snellSafeNormalize(direction);
  float d = distance > 0.0f ? distance : 0.0f;
  e.distance = d < SNELL_FLT_MAX ? d : SNELL_FLT_MAX;
  e.valid = true;
  return e;
}

#endif
/*
description: three.js's transmission (MeshPhysicalMaterial, r187), as a
  screen-space refraction model: refract at the front face only, walk the
  material's thickness along the refracted ray, and read the opaque pass's
  colour where that point projects. Bevy's specular transmission (0.20,
  transmission.wesl) places its point the same way (X = P + t T), so on a
  uniformly scaled object both engines read the same texel.
use: SnellEngineRefraction e = snellEngineThreeJs(p, n, eta, thickness, clipFromView);
  p, n, eta       as in engine_refraction.glsl
  thickness       the material's thickness times the model's scale (three.js
                  "thickness", default 0: no displacement; Bevy "thickness"),
                  view-space units; it is a constant, not the object's chord
  clipFromView    the projection of the opaque pass's colour buffer
contract:
  - T = snellEngineEntry(p, n, eta).direction, t = thickness (0 when negative or NaN);
    X = p + t T; the result is snellEngineSeePoint(X, T, t, clipFromView);
    TIR at the entry and invalid input as engine_refraction.glsl says.
  - What the engines do around it is not modelled here: three.js's roughness
    lod (log2(width) roughness clamp(2 ior - 2, 0, 1), bicubic mips), Bevy's
    blur taps, the Fresnel weights and Beer-Lambert over t (the caller's).
source: three.js r187 (npm three@0.187.0, MIT),
  src/renderers/shaders/ShaderChunk/transmission_pars_fragment.glsl.js
  (getVolumeTransmissionRay: refract(-v, n, 1 / ior), normalized, times
  thickness and the model matrix's scale; getTransmissionSample at the
  projected point); Bevy 0.20-dev (MIT OR Apache-2.0),
  crates/bevy_pbr/src/transmission.wesl (specular_transmissive_light: the exit
  point P + thickness T). Re-derived from their documented behaviour, not
  copied.
*/
#ifndef SNELL_SHADE_ENGINE_MODELS_THREEJS_GLSL
#define SNELL_SHADE_ENGINE_MODELS_THREEJS_GLSL


SNELL_FN SnellEngineRefraction snellEngineThreeJs(vec3 p, vec3 n, float eta, float thickness, mat4 clipFromView) {
  SnellEngineEntry t = snellEngineEntry(p, n, eta);
  if (!t.valid) {
    return snellEngineInvalid();
  }
  if (t.tir) {
    return snellEngineSeePoint(p, p, 0.0f, clipFromView);
  }
  float d = (thickness > 0.0f ? thickness : 0.0f);
  return snellEngineSeePoint(p + d * t.direction, t.direction, d, clipFromView);
}

#endif
/*
description: Filament's screen-space refraction (refractionMode screenspace),
  its two refractionType models: "solid", which takes the object for a sphere
  of diameter `thickness` tangent to the surface at the fragment and reads the
  scene where the refracted ray leaves that sphere; and "thin", a slab of
  thickness `microThickness` crossed along the refracted ray (no offset at all
  when microThickness is 0).
use: SnellEngineRefraction e = snellEngineFilamentSolid(p, n, eta, thickness, clipFromView);
     SnellEngineRefraction e = snellEngineFilamentThin(p, n, eta, microThickness, clipFromView);
  p, n, eta       as in engine_refraction.glsl
  thickness       the sphere's diameter (Filament's material "thickness"), view-space units
  microThickness  the slab's thickness (Filament's "microThickness")
  clipFromView    the projection of the opaque pass's colour buffer
contract:
  - T = snellEngineEntry(p, n, eta).direction, N the unit normal turned
    towards the eye, c = dot(N, T) (<= 0), t = thickness or microThickness (0 when
    negative or NaN).
  - solid: d = -c t (the sphere's chord along T), X = p + d T.
  - thin: d = t / max(-c, 0.001), X = p + d T.
  - the result is snellEngineSeePoint(X, T, d, clipFromView) (solid) or
    snellEngineSeePoint(X, p, d, clipFromView) (thin: a slab's exit restores
    the view direction); TIR at the entry and invalid input as
    engine_refraction.glsl says. Screen-space mode
    reads only X's projection, so the sphere's exit refraction (Filament's
    cubemap mode) is not computed.
source: Filament (Apache-2.0), shaders/src/surface_light_indirect.fs at
  3681fe96573edd94dde8a98369a7e8aec588cfd0: refractionSolidSphere (d =
  thickness * -NoR, position = P + d r), refractionThinSphere (d = uThickness
  / max(-NoR, 0.001)), evaluateRefraction (screen space: the position's
  projection). Re-derived from the engine's documented behaviour, not copied.
*/
#ifndef SNELL_SHADE_ENGINE_MODELS_FILAMENT_GLSL
#define SNELL_SHADE_ENGINE_MODELS_FILAMENT_GLSL


/* Filament refractionSolidSphere, screen space: the exit of the tangent sphere of diameter thickness */
SNELL_FN SnellEngineRefraction snellEngineFilamentSolid(vec3 p, vec3 n, float eta, float thickness,
                                                        mat4 clipFromView) {
  SnellEngineEntry t = snellEngineEntry(p, n, eta);
  if (!t.valid) {
    return snellEngineInvalid();
  }
  if (t.tir) {
    return snellEngineSeePoint(p, p, 0.0f, clipFromView);
  }
  float c = t.cosine;
  float d = -c * (thickness > 0.0f ? thickness : 0.0f);
  return snellEngineSeePoint(p + d * t.direction, t.direction, d, clipFromView);
}

/* Filament refractionThinSphere, screen space: a slab of thickness microThickness */
SNELL_FN SnellEngineRefraction snellEngineFilamentThin(vec3 p, vec3 n, float eta, float microThickness,
                                                       mat4 clipFromView) {
  SnellEngineEntry t = snellEngineEntry(p, n, eta);
  if (!t.valid) {
    return snellEngineInvalid();
  }
  if (t.tir) {
    return snellEngineSeePoint(p, p, 0.0f, clipFromView);
  }
  float c = t.cosine;
  float d = (microThickness > 0.0f ? microThickness : 0.0f) / max(-c, 0.001f);
  return snellEngineSeePoint(p + d * t.direction, p, d, clipFromView);
}

#endif
/*
description: Unity HDRP's screen-space refraction (Lit, transparent), its
  refraction models "Sphere" and "Box" (the UI's "Thin" is the box model at a
  fixed thickness, 5 cm in Unity's documentation): the model gives an exit point and
  direction, the exit ray is cast against the reflection probe's proxy volume,
  and the scene colour is read where that hit projects, faded out towards the
  screen's edges (the probe fills the rest) and replaced by the fragment's
  own texel where the opaque scene there lies in front of the surface.
use: SnellEngineRefraction e = snellEngineHdrpSphere(p, n, eta, thickness, proxyFromView, sceneDepth, scene);
     SnellEngineRefraction e = snellEngineHdrpBox(p, n, eta, thickness, proxyFromView, sceneDepth, scene);
     float s = snellEngineProxyExit(origin, dir, proxyFromView);
     SnellEngineRefraction e = snellEngineHdrpProxyLookup(p, origin, dir, dist, proxyFromView, sceneDepth, scene);
     float w = snellEngineHdrpEdgeFade(uv);
  p, n, eta       as in engine_refraction.glsl
  thickness       the sphere's diameter / the box's (slab's) thickness
                  (HDRP's material "thickness"), view-space units
  proxyFromView   the probe's proxy box: the affine map from view space to the
                  box's own space, where the box is [-1,1]^3 (a box of half
                  extents h centred at c with axes A: scale(1/h) A^T translate(-c))
  sceneDepth, scene  the opaque scene's depth buffer and its SnellDepthSurface
                  (its clipFromView is the colour buffer's projection)
options:
  SNELL_HDRP_SCREEN_FADE_DISTANCE  the edge fade's width (HDRP's volume
                  setting screenFadeDistance, default 0.1f)
contract:
  - T = snellEngineEntry(p, n, eta).direction, N the unit normal turned
    towards the eye, c = dot(N, T), t = thickness (0 when negative or NaN).
  - sphere: d = -c t, P1 = p + d T, N1 = (c T - 0.5 N) / |c T - 0.5 N| (towards
    the sphere's centre p - N t / 2), R2 = snellRefract(T, N1, 1 / eta,
    SNELL_TIR_ZERO) (T on TIR); snellEngineHdrpProxyLookup(p, P1, R2, d, ...).
  - box: d = t / max(-c, 1e-5), snellEngineHdrpProxyLookup(p, p + d T, p / |p|,
    d, ...): a slab's exit restores the view direction.
  - snellEngineProxyExit(o, dir, M): with o', d' = o and dir in the box's space,
    s = min over the axes with |d'_i| >= SNELL_FLT_MIN of (sign(d'_i) - o'_i) / d'_i, then
    max(s, 0): the distance to the box's far side, in units of |dir|;
    SNELL_FLT_MAX when no axis is crossed (a degenerate proxy); 0 when o' or
    d' is not finite.
  - snellEngineHdrpProxyLookup(p, o, dir, d, ...): H = o + s dir/|dir|; where H
    does not project, weight 0 (the probe); else uv = H's projection, weight =
    snellEngineHdrpEdgeFade(uv), and when the scene depth at uv is valid and no
    farther from the eye than p, uv becomes p's own projection (HDRP's halo
    test; weight kept). direction dir/|dir|, distance d.
  - snellEngineHdrpEdgeFade(uv) = S(x) S(y) with x = clamp((1 - |2 u - 1|) /
    SNELL_HDRP_SCREEN_FADE_DISTANCE, 0, 1) (y from v), S(x) = x^2 (3 - 2x);
    non-finite uv: 0.
  - TIR at the entry and invalid input as engine_refraction.glsl says. Not modelled:
    the mip level from roughness (alpha^1.3 (levels - 1), its halo shrink), the
    probe's content (the caller's environment), Fresnel and absorption weights.
source: Unity Graphics (Unity Companion License), Packages/
  com.unity.render-pipelines.core/ShaderLibrary/Refraction.hlsl at
  d220553d7b20798d48be08af60db4048cbd39f7d (RefractionModelSphere,
  RefractionModelBox); com.unity.render-pipelines.high-definition/Runtime/
  Material/Lit/Lit.hlsl at 1390609ca74ecc860907a6e87759644f944fbada
  (EvaluateBSDF_ScreenspaceRefraction: proxy raycast, EdgeOfScreenFade, the
  depth test against the refracting pixel). Re-derived from the engine's
  documented behaviour, not copied.
*/
#ifndef SNELL_SHADE_ENGINE_MODELS_HDRP_GLSL
#define SNELL_SHADE_ENGINE_MODELS_HDRP_GLSL



#ifndef SNELL_HDRP_SCREEN_FADE_DISTANCE
#  define SNELL_HDRP_SCREEN_FADE_DISTANCE 0.1f
#endif

/* HDRP EdgeOfScreenFade */
SNELL_FN float snellEngineHdrpEdgeFade(vec2 uv) {
  if (!SNELL_FINITE(uv.x) || !SNELL_FINITE(uv.y)) {
    return 0.0f;
  }
  float x = clamp((1.0f - abs(2.0f * uv.x - 1.0f)) / SNELL_HDRP_SCREEN_FADE_DISTANCE, 0.0f, 1.0f);
  float y = clamp((1.0f - abs(2.0f * uv.y - 1.0f)) / SNELL_HDRP_SCREEN_FADE_DISTANCE, 0.0f, 1.0f);
  return (x * x * (3.0f - 2.0f * x)) * (y * y * (3.0f - 2.0f * y));
}

/* HDRP IntersectBoxProxy: the far side of the proxy box along the ray */
SNELL_FN float snellEngineProxyExit(vec3 origin, vec3 dir, mat4 proxyFromView) {
  vec4 o4 = SNELL_MUL(proxyFromView, vec4(origin.x, origin.y, origin.z, 1.0f));
  vec4 d4 = SNELL_MUL(proxyFromView, vec4(dir.x, dir.y, dir.z, 0.0f));
  if (!SNELL_FINITE(o4.x) || !SNELL_FINITE(o4.y) || !SNELL_FINITE(o4.z) || !SNELL_FINITE(d4.x) ||
      !SNELL_FINITE(d4.y) || !SNELL_FINITE(d4.z)) {
    return 0.0f;
  }
  // Comparisons, not min(): min() of a NaN differs between languages.
  float s = SNELL_FLT_MAX;
  // An axis the ray does not cross: zero or denormal (the prelude's rule: a GPU may flush it to 0).
  if (abs(d4.x) >= SNELL_FLT_MIN) {
    float c = ((d4.x > 0.0f ? 1.0f : -1.0f) - o4.x) / d4.x;
    s = c < s ? c : s;
  }
  if (abs(d4.y) >= SNELL_FLT_MIN) {
    float c = ((d4.y > 0.0f ? 1.0f : -1.0f) - o4.y) / d4.y;
    s = c < s ? c : s;
  }
  if (abs(d4.z) >= SNELL_FLT_MIN) {
    float c = ((d4.z > 0.0f ? 1.0f : -1.0f) - o4.z) / d4.z;
    s = c < s ? c : s;
  }
  return s > 0.0f ? s : 0.0f;
}

/* HDRP EvaluateBSDF_ScreenspaceRefraction: proxy hit, edge fade, halo test */
SNELL_FN SnellEngineRefraction snellEngineHdrpProxyLookup(vec3 p, vec3 origin, vec3 dir, float dist,
                                                          mat4 proxyFromView, SNELL_TEX2D sceneDepth,
                                                          SNELL_IN(SnellDepthSurface) scene) {
  vec3 d = snellSafeNormalize(dir);
  float s = snellEngineProxyExit(origin, d, proxyFromView);
  SnellEngineRefraction e = snellEngineSeePoint(origin + s * d, d, dist, scene.clipFromView);
  if (e.sceneWeight > 0.0f) {
    e.sceneWeight = snellEngineHdrpEdgeFade(e.uv);
    SnellSurfaceSample b = snellSampleSurface(sceneDepth, e.uv, scene);
    if (b.valid && b.viewZ >= p.z) {
      SnellScreenPoint own = snellViewToUv(scene.clipFromView, p);
      e.uv = own.uv;
    }
  }
  return e;
}

/* HDRP RefractionModelSphere, then the proxy lookup */
SNELL_FN SnellEngineRefraction snellEngineHdrpSphere(vec3 p, vec3 n, float eta, float thickness, mat4 proxyFromView,
                                                     SNELL_TEX2D sceneDepth, SNELL_IN(SnellDepthSurface) scene) {
  SnellEngineEntry t = snellEngineEntry(p, n, eta);
  if (!t.valid) {
    return snellEngineInvalid();
  }
  if (t.tir) {
    return snellEngineSeePoint(p, p, 0.0f, scene.clipFromView);
  }
  vec3 nf = t.normal;
  float c = t.cosine;
  float d = -c * (thickness > 0.0f ? thickness : 0.0f);
  vec3 p1 = p + d * t.direction;
  vec3 n1 = snellSafeNormalize(c * t.direction - 0.5f * nf);
  SnellRefraction out2 = snellRefract(t.direction, n1, 1.0f / eta, SNELL_TIR_ZERO);
  vec3 r2 = t.direction;
  if (out2.valid && !out2.tir) {
    r2 = out2.direction;
  }
  return snellEngineHdrpProxyLookup(p, p1, r2, d, proxyFromView, sceneDepth, scene);
}

/* HDRP RefractionModelBox (its "Thin" model at a fixed thickness), then the proxy lookup */
SNELL_FN SnellEngineRefraction snellEngineHdrpBox(vec3 p, vec3 n, float eta, float thickness, mat4 proxyFromView,
                                                  SNELL_TEX2D sceneDepth, SNELL_IN(SnellDepthSurface) scene) {
  SnellEngineEntry t = snellEngineEntry(p, n, eta);
  if (!t.valid) {
    return snellEngineInvalid();
  }
  if (t.tir) {
    return snellEngineSeePoint(p, p, 0.0f, scene.clipFromView);
  }
  float d = (thickness > 0.0f ? thickness : 0.0f) / max(-t.cosine, 1e-5f);
  return snellEngineHdrpProxyLookup(p, p + d * t.direction, p, d, proxyFromView, sceneDepth, scene);
}

#endif
/*
description: Godot 4's refraction (BaseMaterial3D "Refraction"): no ray at
  all, the screen uv shifted against the view-space normal's xy by a constant
  scale, the shift faded out where the opaque scene at the shifted uv lies
  less than one unit behind the surface.
use: SnellEngineRefraction e = snellEngineGodot(p, n, scale, sceneDepth, scene);
  p, n            the front-face fragment's view-space position and normal (the
                  normal is turned towards the eye)
  scale           Godot's "refraction" (uv units per unit of normal, default
                  0.05; the editor offers -1 .. 1)
  sceneDepth, scene  the opaque scene's depth buffer and its SnellDepthSurface
                  (its clipFromView is the colour buffer's projection)
contract:
  - u0 = snellViewToUv(scene.clipFromView, p).uv, N the unit normal turned
    towards the eye, k = scale clamped to [-1, 1] (the editor's range; NaN:
    0), u1 = u0 - k N.xy.
  - g = S(clamp(p.z - z, 0, 1)), S(x) = x^2 (3 - 2x), with z the scene's view z
    at u1 clamped to [0,1]^2 (snellSampleSurface), g = 1 where that read is not
    valid (no surface: the far plane); uv = u0 + g (u1 - u0).
  - weight 1 (0 where p does not project), direction p / |p|, distance 0 (no
    absorption). p or n zero, NaN or infinite: snellEngineInvalid().
  - The uv is in the buffer's own convention (origin bottom-left here); on
    Godot's Vulkan renderers SCREEN_UV runs downwards while the normal's y
    runs upwards, so there the vertical shift has the other sign: this function
    keeps both axes consistent. Not modelled: the blur lod 8 roughness, the
    emission blend.
source: Godot (MIT), scene/resources/material.cpp at
  0059d788b03b559846087c2a1b86a0e19cbdc4ce (BaseMaterial3D::_update_shader,
  the refraction block: ref_ofs = SCREEN_UV - ref_normal.xy * refraction, the
  depth-guarded mix). Re-derived from the generated shader's behaviour, not
  copied.
*/
#ifndef SNELL_SHADE_ENGINE_MODELS_GODOT_GLSL
#define SNELL_SHADE_ENGINE_MODELS_GODOT_GLSL



SNELL_FN SnellEngineRefraction snellEngineGodot(vec3 p, vec3 n, float scale, SNELL_TEX2D sceneDepth,
                                                SNELL_IN(SnellDepthSurface) scene) {
  vec3 v = snellSafeNormalize(p);
  vec3 nf = snellSafeNormalize(n);
  if (dot(v, v) == 0.0f || dot(nf, nf) == 0.0f) {
    return snellEngineInvalid();
  }
  nf = -dot(nf, v) < 0.0f ? -nf : nf;
  SnellEngineRefraction e = snellEngineSeePoint(p, p, 0.0f, scene.clipFromView);
  if (e.sceneWeight > 0.0f) {
    float k = isnan(scale) ? 0.0f : clamp(scale, -1.0f, 1.0f);
    vec2 u0 = e.uv;
    vec2 u1 = u0 - k * vec2(nf.x, nf.y);
    SnellSurfaceSample b = snellSampleSurface(sceneDepth, clamp(u1, vec2(0.0f, 0.0f), vec2(1.0f, 1.0f)), scene);
    float g = 1.0f;
    if (b.valid) {
      g = clamp(p.z - b.viewZ, 0.0f, 1.0f);
      g = g * g * (3.0f - 2.0f * g);
    }
    e.uv = u0 + g * (u1 - u0);
  }
  return e;
}

#endif
/*
description: the engines' rough (frosted) transmission: how each engine
  blurs the scene colour it reads for a rough material, re-derived from its
  source, so the engine rows read rough glass as the engines do. three.js
  reads a mip level from the roughness through a bicubic B-spline filter over
  two levels; Bevy averages taps on a spiral around the point at level 0;
  Filament, HDRP and Godot read one trilinear sample of their mip chain at a
  level from the roughness. The point read is the geometric models' uv
  (engine_models.glsl); this file only says how it is read.
use: SnellEngineBlurRead c = snellEngineBlurRead(blur, sceneColor, e.uv, roughness, ior, p, clipFromView, levels);
     float lod = snellEngineBlurLod(blur, roughness, ior, levels, size, clipFromView);
     SnellEngineBlurRead c = snellEngineBicubicMips(sceneColor, uv, lod, levels);         // three.js's textureBicubic
     SnellEngineBlurRead c = snellEngineBevyBlur(sceneColor, uv, roughness, ior, viewZ, pixel, taps);
     SnellEngineBlurRead c = snellEngineSmoothRead(sceneColor, uv);   // the smooth read
  blur        SNELL_ENGINE_BLUR_* below
  sceneColor  the opaque scene's colour, mipmapped (levels levels, a full or
              partial chain; filtered linearly within and between levels)
  uv          where the engine reads (SnellEngineRefraction.uv; clamped to
              [0,1]^2 here, as the engines' clamp-to-edge samplers read it;
              a NaN component counts as 0)
  roughness   the material's perceptual roughness (0 smooth, 1 fully rough)
  ior         the material's index of refraction (the engines refract from air)
  p           the front-face fragment's view-space position (Bevy's blur
              width and noise; the caller's fragment)
  clipFromView  the colour buffer's projection (Filament's lod offset, Bevy's pixel)
  levels      sceneColor's mip levels (1: no mips)
  size        the colour buffer's size in texels (level 0)
  viewZ, pixel, taps  Bevy's: the fragment's view z (< 0 in front of the
              camera), its pixel centre counted from the image's top row (as
              WebGPU's frag_coord), its tap count (4, 8, 16, 32: quality Low
              .. Ultra; SNELL_BEVY_TRANSMISSION_TAPS by default)
options:
  SNELL_BEVY_TRANSMISSION_TAPS  the taps snellEngineBlurRead's Bevy blur
              takes (8: Bevy's default quality, Medium)
ids:
  SNELL_ENGINE_BLUR_THREEJS   three.js: bicubic over two mip levels
  SNELL_ENGINE_BLUR_BEVY      Bevy: spiral taps at level 0
  SNELL_ENGINE_BLUR_FILAMENT  Filament: one trilinear read
  SNELL_ENGINE_BLUR_HDRP      HDRP: one trilinear read
  SNELL_ENGINE_BLUR_GODOT     Godot: one trilinear read
  SNELL_ENGINE_BLUR_COUNT     the number of ids
contract:
  - smooth: where roughness is not > 0 (0, negative, NaN) or ior is not a
    finite positive number, every blur reads what the smooth models read:
    SNELL_SAMPLE_LOD(sceneColor, clamp(uv, 0, 1), 0), 1 fetch (every function
    clamps uv so, a NaN component to 0). (three.js
    reads its bicubic filter, and floors roughness at 0.045, even on smooth
    glass; not modelled, so a smooth material's read is one texel read.)
  - r = min(roughness, 1). levels < 1 counts as 1; L = levels - 1, the last level.
  - snellEngineBlurLod: three.js log2(size.x) max(r, 0.045) clamp(2 ior - 2,
    0, 1); Filament: with q = r (1 - clamp(3 / ior - 2, 0, 1)) and
    o = -log2(sqrt(2) (22 / 6) t / size.y), t = tan(2 atan(1 / |P11|)) (P11
    = clipFromView[1][1]), lod = max(0, (2 log2(q) + o) 0.8614) clamped to
    K - 1 with K = max(min(4, levels), levels - 4); 0 where q is 0 or t is not
    finite and positive (a vertical field of view of 90 degrees or more);
    HDRP: r^1.3 L; Godot: min(8 r, L); Bevy and ids outside the range: 0.
  - snellEngineBicubicMips(sceneColor, uv, lod, levels): lod < 0 or NaN counts
    as 0; a = floor(lod), b = ceil(lod), both clamped to L; level a filtered
    by the cubic B-spline with level a's texel size, level b with the texel
    size of level min(a + 1, L) (three.js's int(lod + 1)); mixed by lod - a.
    The B-spline is 4 bilinear reads per level (weights g, offsets h of its
    two halves), 8 fetches. Exact for the B-spline of the clamped texels at
    both levels.
  - snellEngineBevyBlur: s = r clamp(2 ior - 2, 0, 1), b = s^2 / viewZ (viewZ
    zero or not finite: the smooth read); n = clamp(taps, 1, 32) taps of
    level 0, averaged; tap i on spiral k = i / 8 of m = ceil(n / 8), offset
    SPIRAL[i & 7] (the even offsets first, then the odd) scaled by
    1 - 0.5 (k + 1) / m, rotated by -(g + k / m) 2 pi, its y scaled by the
    aspect size.x / size.y, times b (1 - 0.1 c); in snell's uv (y up) the
    offset's y is negated. g = fract(52.9829189 fract(0.06711056 x + 0.00583715
    y)) and c = (int(x) + int(y)) & 1 at the pixel (x, y) (each clamped to
    [0, 2^24]; not finite: 0). n fetches.
  - snellEngineBlurRead: uv clamped to [0,1]^2; three.js
    snellEngineBicubicMips at its lod; Bevy snellEngineBevyBlur with
    SNELL_BEVY_TRANSMISSION_TAPS taps, viewZ = p.z and the pixel under p's
    projection (x = floor(u W) + 0.5, y = H - floor(v H) - 0.5, with W, H
    the size of level 0); Filament, HDRP, Godot one SNELL_SAMPLE_LOD at
    their lod, 1 fetch; the smooth read where the contract's first rule says,
    and for ids outside the range.
  - snellEngineSmoothRead(sceneColor, uv): the smooth read above.
  - an engine model's blur: snellEngineBlurOf (engine_models.glsl).
  - Not modelled: three.js's geometryRoughness (from screen derivatives);
    Bevy's frame-varying noise (TEMPORAL_JITTER: the frame count in the noise
    and the checkerboard; frame 0 is modelled), TAA, its depth-prepass test
    that zeroes taps in front of the fragment (off without a DepthPrepass),
    its firefly limit min(rgb, normalize(rgb) / saturate(b / 2)), which never
    acts (b < 0 in front of the camera makes saturate 0); the chains' own
    kernels (Filament's 21-tap Gaussian per level, HDRP's and Godot's
    Gaussian pyramids, three.js's box chain: the host's mip chain is what
    is read; the lab's is snell's colour pyramid); HDRP's halo
    shrink at the blurred level and its clear-coat roughness.
source: three.js r187 (npm three@0.187.0, MIT),
  src/renderers/shaders/ShaderChunk/transmission_pars_fragment.glsl.js
  (applyIorToRoughness, getTransmissionSample, textureBicubic and bicubic
  with w0..w3, g0, g1, h0, h1: the 4-tap B-spline over levels floor and ceil
  of lod mixed by fract(lod)), lights_physical_fragment.glsl.js (roughness
  floor 0.045); Bevy 0.20.0-dev (MIT OR Apache-2.0) at
  4805ca792c3e94eef07afd6fa9a2712f388c9a67, crates/bevy_pbr/src/
  transmission.wesl (ior_corrected_roughness, specular_transmissive_light,
  fetch_transmissive_background), render/utils.wesl
  (interleaved_gradient_noise, SPIRAL_OFFSET_0_..7_), render/mesh.rs (taps
  4/8/16/32 by ScreenSpaceTransmissionQuality, default Medium: 8),
  render/pbr_functions.wesl (view_z); Filament (Apache-2.0)
  shaders/src/surface_light_indirect.fs at
  3681fe96573edd94dde8a98369a7e8aec588cfd0 (evaluateRefraction: the
  roughness remap by etaIR and the lod with invLog2sqrt5 = 0.8614),
  filament/src/PostProcessManager.cpp (prepareMipmapSSR: sigma0 = 22 / 6,
  texelSizeAtOneMeter = tan(verticalFieldOfView) / height, refractionLodOffset
  = -log2(sqrt(2) sigma0 texelSizeAtOneMeter), roughnessLodCount) with
  FCamera::getFieldOfView (2 atan(1 / p[1][1])); Unity HDRP Lit.hlsl
  (GetPreLightData: transparentSSMipLevel = PositivePow(perceptual
  roughness, 1.3) (_ColorPyramidLodCount - 1)); Godot scene/resources/
  material.cpp at 0059d788b03b559846087c2a1b86a0e19cbdc4ce (the refraction
  read textureLod(screen_texture, ref_ofs, ROUGHNESS * 8.0)). Re-derived
  from the engines' sources, not copied.
*/
#ifndef SNELL_SHADE_ENGINE_MODELS_ENGINE_ROUGH_GLSL
#define SNELL_SHADE_ENGINE_MODELS_ENGINE_ROUGH_GLSL



#ifndef SNELL_BEVY_TRANSMISSION_TAPS
#  define SNELL_BEVY_TRANSMISSION_TAPS 8
#endif

#define SNELL_ENGINE_BLUR_THREEJS 0
#define SNELL_ENGINE_BLUR_BEVY 1
#define SNELL_ENGINE_BLUR_FILAMENT 2
#define SNELL_ENGINE_BLUR_HDRP 3
#define SNELL_ENGINE_BLUR_GODOT 4
#define SNELL_ENGINE_BLUR_COUNT 5

/* uv clamped to [0,1]^2, a NaN component 0: clamp of a NaN differs between GPUs and GLM. */
#define SNELL_ENGINE_BLUR_UV(uv) vec2(isnan((uv).x) ? 0.0f : clamp((uv).x, 0.0f, 1.0f), isnan((uv).y) ? 0.0f : clamp((uv).y, 0.0f, 1.0f))

struct SnellEngineBlurRead {
  vec3 color;
  int fetches;
};

/* The engines' mip level for a rough material (0 where the read is smooth) */
SNELL_FN float snellEngineBlurLod(int blur, float roughness, float ior, int levels, vec2 size, mat4 clipFromView) {
  // isnan first: clamp and max of a NaN differ between GPUs and GLM.
  if (isnan(roughness) || !(roughness > 0.0f) || isnan(ior) || !SNELL_FINITE(ior) || !(ior > 0.0f)) {
    return 0.0f;
  }
  float r = min(roughness, 1.0f);
  float last = float(max(levels, 1) - 1);
  if (blur == SNELL_ENGINE_BLUR_THREEJS) {
    float w = isnan(size.x) ? 1.0f : max(size.x, 1.0f);
    return log2(w) * max(r, 0.045f) * clamp(2.0f * ior - 2.0f, 0.0f, 1.0f);
  }
  if (blur == SNELL_ENGINE_BLUR_FILAMENT) {
    float q = r * (1.0f - clamp(3.0f / ior - 2.0f, 0.0f, 1.0f));
    // tan(2 atan(x)) = 2 x / (1 - x^2), x = 1 / |P11|: positive and finite below 90 degrees.
    float x = 1.0f / abs(clipFromView[1][1]);
    float t = 2.0f * x / (1.0f - x * x);
    float h = isnan(size.y) ? 1.0f : max(size.y, 1.0f);
    if (!(q > 0.0f) || isnan(t) || !SNELL_FINITE(t) || !(t > 0.0f)) {
      return 0.0f;
    }
    float offset = -log2(1.41421356f * (22.0f / 6.0f) * t / h);
    float lod = max((2.0f * log2(q) + offset) * 0.8614f, 0.0f);
    int count = max(min(4, max(levels, 1)), max(levels, 1) - 4);
    return min(lod, float(count - 1));
  }
  if (blur == SNELL_ENGINE_BLUR_HDRP) {
    return pow(r, 1.3f) * last;
  }
  if (blur == SNELL_ENGINE_BLUR_GODOT) {
    return min(8.0f * r, last);
  }
  return 0.0f;
}

/* three.js textureBicubic: the cubic B-spline of two mip levels, 4 bilinear reads each, mixed by fract(lod) */
SNELL_FN SnellEngineBlurRead snellEngineBicubicMips(SNELL_TEX2D sceneColor, vec2 uv, float lod, int levels) {
  vec2 c0 = SNELL_ENGINE_BLUR_UV(uv);
  int last = max(levels, 1) - 1;
  float l = isnan(lod) ? 0.0f : clamp(lod, 0.0f, float(last));
  int a = int(floor(l));
  int b = min(int(ceil(l)), last);
  int sizeB = min(a + 1, last);
  float mixB = l - floor(l);
  vec3 sum = vec3(0.0f, 0.0f, 0.0f);
  for (int k = 0; k < 2; ++k) {
    int level = k == 0 ? a : b;
    ivec2 si = SNELL_TEXTURE_SIZE(sceneColor, k == 0 ? a : sizeB);
    vec2 s = vec2(float(si.x), float(si.y));
    vec2 inv = vec2(1.0f / s.x, 1.0f / s.y);
    vec2 x = c0 * s + vec2(0.5f, 0.5f);
    vec2 i = floor(x);
    vec2 f = x - i;
    // The B-spline's four weights per axis, then its two halves' weights g and offsets h.
    vec2 w0 = (1.0f / 6.0f) * (f * (f * (-f + 3.0f) - 3.0f) + 1.0f);
    vec2 w1 = (1.0f / 6.0f) * (f * f * (3.0f * f - 6.0f) + 4.0f);
    vec2 w2 = (1.0f / 6.0f) * (f * (f * (-3.0f * f + 3.0f) + 3.0f) + 1.0f);
    vec2 w3 = (1.0f / 6.0f) * (f * f * f);
    vec2 g0 = w0 + w1;
    vec2 g1 = w2 + w3;
    vec2 h0 = w1 / (w0 + w1) - 1.0f;
    vec2 h1 = w3 / (w2 + w3) + 1.0f;
    vec2 p0 = (vec2(i.x + h0.x, i.y + h0.y) - 0.5f) * inv;
    vec2 p1 = (vec2(i.x + h1.x, i.y + h0.y) - 0.5f) * inv;
    vec2 p2 = (vec2(i.x + h0.x, i.y + h1.y) - 0.5f) * inv;
    vec2 p3 = (vec2(i.x + h1.x, i.y + h1.y) - 0.5f) * inv;
    float lf = float(level);
    vec4 c = g0.y * (g0.x * SNELL_SAMPLE_LOD(sceneColor, p0, lf) + g1.x * SNELL_SAMPLE_LOD(sceneColor, p1, lf)) +
             g1.y * (g0.x * SNELL_SAMPLE_LOD(sceneColor, p2, lf) + g1.x * SNELL_SAMPLE_LOD(sceneColor, p3, lf));
    float weight = k == 0 ? 1.0f - mixB : mixB;
    sum = sum + weight * vec3(c.x, c.y, c.z);
  }
  SnellEngineBlurRead r;
  r.color = sum;
  r.fetches = 8;
  return r;
}

/* The read every blur makes on smooth glass: one texel read at level 0 */
SNELL_FN SnellEngineBlurRead snellEngineSmoothRead(SNELL_TEX2D sceneColor, vec2 uv) {
  vec4 c = SNELL_SAMPLE_LOD(sceneColor, SNELL_ENGINE_BLUR_UV(uv), 0.0f);
  SnellEngineBlurRead r;
  r.color = vec3(c.x, c.y, c.z);
  r.fetches = 1;
  return r;
}

/* Bevy fetch_transmissive_background: spiral taps at level 0 (frame 0 of its noise) */
SNELL_FN SnellEngineBlurRead snellEngineBevyBlur(SNELL_TEX2D sceneColor, vec2 uv, float roughness, float ior,
                                                 float viewZ, vec2 pixel, int taps) {
  vec2 c0 = SNELL_ENGINE_BLUR_UV(uv);
  bool rough = !isnan(roughness) && roughness > 0.0f && !isnan(ior) && SNELL_FINITE(ior) && ior > 0.0f;
  float s = rough ? min(roughness, 1.0f) * clamp(2.0f * ior - 2.0f, 0.0f, 1.0f) : 0.0f;
  if (!(s > 0.0f) || isnan(viewZ) || !SNELL_FINITE(viewZ) || viewZ == 0.0f) {
    return snellEngineSmoothRead(sceneColor, c0);
  }
  float b = s * s / viewZ;
  ivec2 si = SNELL_TEXTURE_SIZE(sceneColor, 0);
  float aspect = float(si.x) / float(si.y);
  int n = clamp(taps, 1, 32);
  int spirals = (n + 7) / 8;
  float px = (isnan(pixel.x) || !SNELL_FINITE(pixel.x)) ? 0.0f : clamp(pixel.x, 0.0f, 16777216.0f);
  float py = (isnan(pixel.y) || !SNELL_FINITE(pixel.y)) ? 0.0f : clamp(pixel.y, 0.0f, 16777216.0f);
  float t = 0.06711056f * px + 0.00583715f * py;
  t = 52.9829189f * (t - floor(t));
  float noise = t - floor(t);
  float checker = float((int(px) + int(py)) & 1);
  float scale = b * (1.0f - 0.1f * checker);
  vec3 sum = vec3(0.0f, 0.0f, 0.0f);
  // Every pass runs and the taps past n add nothing, not the end-of-pass break of docs/DESIGN.md's common
  // subset: with that break Vulkan's llvmpipe summed other taps than GL and C++ (7625 of 12000 parity cases
  // off, 0 this way). The idle passes cost llvmpipe time, which an engine's model in the lab can afford.
  for (int i = 0; i < 32; ++i) {
    if (i >= n) {
      continue;
    }
    int k = i >> 3;
    int j = i & 7;
    // Bevy's order: the even offsets of the spiral first, then the odd (4 taps still go round once).
    vec2 o = vec2(-0.7071f, 0.7071f);
    if (j == 1) {
      o = vec2(0.5303f, 0.5303f);
    } else if (j == 2) {
      o = vec2(0.3536f, -0.3536f);
    } else if (j == 3) {
      o = vec2(-0.1768f, -0.1768f);
    } else if (j == 4) {
      o = vec2(0.0f, -0.875f);
    } else if (j == 5) {
      o = vec2(-0.625f, 0.0f);
    } else if (j == 6) {
      o = vec2(0.0f, 0.375f);
    } else if (j == 7) {
      o = vec2(0.125f, 0.0f);
    }
    o = o * (1.0f - 0.5f * float(k + 1) / float(spirals));
    float angle = (noise + float(k) / float(spirals)) * (2.0f * SNELL_PI);
    float sa = sin(angle);
    float ca = cos(angle);
    vec2 d = vec2(ca * o.x + sa * o.y, (ca * o.y - sa * o.x) * aspect) * scale;
    // Bevy's uv runs down the image, snell's up: the offset's y turns over.
    vec2 tap = clamp(c0 + vec2(d.x, -d.y), vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
    vec4 c = SNELL_SAMPLE_LOD(sceneColor, tap, 0.0f);
    sum = sum + vec3(c.x, c.y, c.z);
  }
  SnellEngineBlurRead r;
  r.color = sum / float(n);
  r.fetches = n;
  return r;
}

/* The scene colour an engine reads at uv for a material of that roughness and ior */
SNELL_FN SnellEngineBlurRead snellEngineBlurRead(int blur, SNELL_TEX2D sceneColor, vec2 uv, float roughness, float ior,
                                                 vec3 p, mat4 clipFromView, int levels) {
  vec2 c0 = SNELL_ENGINE_BLUR_UV(uv);
  ivec2 si = SNELL_TEXTURE_SIZE(sceneColor, 0);
  vec2 size = vec2(float(si.x), float(si.y));
  if (blur == SNELL_ENGINE_BLUR_BEVY) {
    vec2 f = snellViewToUv(clipFromView, p).uv;
    vec2 pixel = vec2(floor(f.x * size.x) + 0.5f, size.y - floor(f.y * size.y) - 0.5f);
    return snellEngineBevyBlur(sceneColor, c0, roughness, ior, p.z, pixel, SNELL_BEVY_TRANSMISSION_TAPS);
  }
  bool rough = !isnan(roughness) && roughness > 0.0f && !isnan(ior) && SNELL_FINITE(ior) && ior > 0.0f;
  if (!rough || blur < 0 || blur >= SNELL_ENGINE_BLUR_COUNT) {
    return snellEngineSmoothRead(sceneColor, c0);
  }
  float lod = snellEngineBlurLod(blur, roughness, ior, levels, size, clipFromView);
  if (blur == SNELL_ENGINE_BLUR_THREEJS) {
    return snellEngineBicubicMips(sceneColor, c0, lod, levels);
  }
  vec4 c = SNELL_SAMPLE_LOD(sceneColor, c0, lod);
  SnellEngineBlurRead r;
  r.color = vec3(c.x, c.y, c.z);
  r.fetches = 1;
  return r;
}

#endif

#define SNELL_ENGINE_THREEJS 0
#define SNELL_ENGINE_FILAMENT_SOLID 1
#define SNELL_ENGINE_FILAMENT_THIN 2
#define SNELL_ENGINE_HDRP_SPHERE 3
#define SNELL_ENGINE_HDRP_BOX 4
#define SNELL_ENGINE_GODOT 5
#define SNELL_ENGINE_MODEL_COUNT 6

SNELL_FN SnellEngineRefraction snellEngineRefraction(int model, vec3 p, vec3 n, float eta, float parameter,
                                                     mat4 proxyFromView, SNELL_TEX2D sceneDepth,
                                                     SNELL_IN(SnellDepthSurface) scene) {
  if (model == SNELL_ENGINE_THREEJS) {
    return snellEngineThreeJs(p, n, eta, parameter, scene.clipFromView);
  }
  if (model == SNELL_ENGINE_FILAMENT_SOLID) {
    return snellEngineFilamentSolid(p, n, eta, parameter, scene.clipFromView);
  }
  if (model == SNELL_ENGINE_FILAMENT_THIN) {
    return snellEngineFilamentThin(p, n, eta, parameter, scene.clipFromView);
  }
  if (model == SNELL_ENGINE_HDRP_SPHERE) {
    return snellEngineHdrpSphere(p, n, eta, parameter, proxyFromView, sceneDepth, scene);
  }
  if (model == SNELL_ENGINE_HDRP_BOX) {
    return snellEngineHdrpBox(p, n, eta, parameter, proxyFromView, sceneDepth, scene);
  }
  if (model == SNELL_ENGINE_GODOT) {
    return snellEngineGodot(p, n, parameter, sceneDepth, scene);
  }
  return snellEngineInvalid();
}

SNELL_FN int snellEngineBlurOf(int model) {
  if (model == SNELL_ENGINE_THREEJS) {
    return SNELL_ENGINE_BLUR_THREEJS;
  }
  if (model == SNELL_ENGINE_FILAMENT_SOLID || model == SNELL_ENGINE_FILAMENT_THIN) {
    return SNELL_ENGINE_BLUR_FILAMENT;
  }
  if (model == SNELL_ENGINE_HDRP_SPHERE || model == SNELL_ENGINE_HDRP_BOX) {
    return SNELL_ENGINE_BLUR_HDRP;
  }
  if (model == SNELL_ENGINE_GODOT) {
    return SNELL_ENGINE_BLUR_GODOT;
  }
  return -1;
}

#endif
#endif
#endif
