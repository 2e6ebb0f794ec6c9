// snell 0.2.0, single-file GLSL: glsl/snell/optics.glsl with every #include spliced in
// (snell-flatten --no-line). Generated: do not edit; regenerate with
// `cmake --build build --target single_file`. No #version line: put it, and on
// ES the precision statements, before this text.
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
