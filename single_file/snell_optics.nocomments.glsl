// snell 0.2.0, single-file GLSL: glsl/snell/optics.glsl with every #include spliced in
// (snell-flatten --no-line --strip-comments). Generated: do not edit; regenerate with
// `cmake --build build --target single_file`. No #version line: put it, and on
// ES the precision statements, before this text.
#ifndef SNELL_OPTICS_GLSL
#define SNELL_OPTICS_GLSL

#ifndef SNELL_OPTICS_SAFE_NORMALIZE_GLSL
#define SNELL_OPTICS_SAFE_NORMALIZE_GLSL

#ifndef SNELL_PRELUDE_GLSL
#define SNELL_PRELUDE_GLSL

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

#ifndef SNELL_FN_INLINE
#  if defined(SNELL_LANG_CXX)
#    define SNELL_FN_INLINE SNELL_FN SNELL_CXX_ALWAYS_INLINE
#  else
#    define SNELL_FN_INLINE SNELL_FN
#  endif
#endif

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

#    define SNELL_TEXTURE_SIZE(tex, lod) max(textureSize(tex, 0) >> (lod), ivec2(1, 1))
#  endif
#endif

#ifndef SNELL_TEXEL_FETCH_IN_LEVEL
#  define SNELL_TEXEL_FETCH_IN_LEVEL(tex, px, lod) SNELL_TEXEL_FETCH(tex, px, lod)
#endif

#ifndef SNELL_IN
#  if defined(SNELL_LANG_CXX)
#    define SNELL_IN(T) const T&
#  else
#    define SNELL_IN(T) T
#  endif
#endif

#if defined(SNELL_LANG_HLSL)
#  define SNELL_MUL(m, v) mul(m, v)
#else
#  define SNELL_MUL(m, v) ((m) * (v))
#endif

#define SNELL_PI 3.14159265358979f
#define SNELL_EPS 1e-6f

#ifndef SNELL_FLT_MAX
#  define SNELL_FLT_MAX 3.402823466e38f
#endif

#define SNELL_FLT_MIN 1.175494351e-38f

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
  if (!(len2 > 1e-30f) || !(len2 < SNELL_FLT_MAX)) {
    return vec3(0.0f, 0.0f, 0.0f);
  }
  return v * inversesqrt(len2);
}

#endif

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
      r.direction = snellSafeNormalize(tangent);
    }
    return r;
  }
  float cosT = sqrt(cos2T);
  r.direction = large ? snellSafeNormalize(eta * tangent - cosT * n) : snellSafeNormalize(eta * i + (eta * cosI - cosT) * n);
  return r;
}

#endif

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
  float k = factor > 0.0f ? factor : 0.0f;
  if (k > 1.0f) {
    return snellSafeNormalize(i * (1.0f / k) - n);
  }
  return snellSafeNormalize(i - k * n);
}

#endif

#ifndef SNELL_OPTICS_FRESNEL_DIELECTRIC_GLSL
#define SNELL_OPTICS_FRESNEL_DIELECTRIC_GLSL

SNELL_FN float snellFresnelDielectric(float cosI, float eta) {
  if (!(eta >= 1e-30f) || !(eta < SNELL_FLT_MAX)) {
    return 1.0f;
  }
  float e = min(max(eta, 1e-6f), 1e6f);
  float c = abs(cosI);
  if (!(c >= 0.0f)) {
    return 1.0f;
  }
  c = min(c, 1.0f);
  float e2 = e * e;
  float cos2T = (1.0f - e2) + e2 * (c * c);
  if (cos2T <= 0.0f) {
    return 1.0f;
  }
  float cosT = sqrt(cos2T);
  float rs = (e * c - cosT) / (e * c + cosT);
  float rp = (c - e * cosT) / (c + e * cosT);
  return 0.5f * (rs * rs + rp * rp);
}

#endif

#ifndef SNELL_OPTICS_FRESNEL_SCHLICK_GLSL
#define SNELL_OPTICS_FRESNEL_SCHLICK_GLSL

SNELL_FN float snellFresnelSchlick(float cosI, float f0) {
  float c = abs(cosI);
  if (!(c >= 0.0f)) {
    return 1.0f;
  }
  c = min(c, 1.0f);
  float f = f0 > 0.0f ? min(f0, 1.0f) : (f0 <= 0.0f ? 0.0f : 1.0f);
  float m = 1.0f - c;
  float m2 = m * m;
  return f + (1.0f - f) * (m2 * m2 * m);
}

#endif

#ifndef SNELL_OPTICS_FRESNEL_BIAS_POWER_GLSL
#define SNELL_OPTICS_FRESNEL_BIAS_POWER_GLSL

SNELL_FN float snellFresnelBiasPower(float nDotL, float bias, float power) {
  float c = nDotL > 0.0f ? min(nDotL, 1.0f) : 0.0f;
  float facing = 1.0f - c;
  float p = power >= 1e-30f ? min(power, 1e6f) : 0.0f;
  float b = bias >= -1e6f ? min(bias, 1e6f) : (bias < 0.0f ? -1e6f : 1.0f);
  float t = 1.0f;
  if (p > 0.0f) {
    t = facing > 0.0f ? pow(facing, p) : 0.0f;
  }
  return max(b + (1.0f - b) * t, 0.0f);
}

#endif

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

#ifndef SNELL_OPTICS_BEER_LAMBERT_GLSL
#define SNELL_OPTICS_BEER_LAMBERT_GLSL

SNELL_FN vec3 snellBeerLambert(vec3 absorption, float dist) {
  float d = dist > 0.0f ? min(dist, SNELL_FLT_MAX) : 0.0f;
  vec3 s = vec3(absorption.x > 0.0f ? min(absorption.x, SNELL_FLT_MAX) : 0.0f,
                absorption.y > 0.0f ? min(absorption.y, SNELL_FLT_MAX) : 0.0f,
                absorption.z > 0.0f ? min(absorption.z, SNELL_FLT_MAX) : 0.0f);
  return exp(-min(s * d, vec3(1e30f)));
}

#endif

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
  float x = min(0.5f * min(chordMinus, chordPlus), 1.0f);
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

#ifndef SNELL_OPTICS_WYMAN_DISTANCE_GLSL
#define SNELL_OPTICS_WYMAN_DISTANCE_GLSL

SNELL_FN float snellWymanDistance(float thetaT, float thetaI, float dV, float dN) {
  float ti = abs(thetaI);
  float tt = abs(thetaT);
  float r = 1.0f;
  if (ti >= 1e-30f) {
    float q = tt / ti;
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

#ifndef SNELL_OPTICS_RAY_PLANE_GLSL
#define SNELL_OPTICS_RAY_PLANE_GLSL

#ifndef SNELL_RAY_PLANE_PARALLEL_EPS
#  define SNELL_RAY_PLANE_PARALLEL_EPS 1e-6f
#endif

struct SnellRayPlaneHit {
  float t;
  vec3 position;
  bool valid;
};

SNELL_FN SnellRayPlaneHit snellRayPlane(vec3 origin, vec3 dir, vec3 planePoint, vec3 planeNormal) {
  SnellRayPlaneHit h;
  h.t = 0.0f;
  h.position = vec3(0.0f, 0.0f, 0.0f);
  h.valid = false;
  vec3 n = snellSafeNormalize(planeNormal);
  float dirLen2 = dot(dir, dir);
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
