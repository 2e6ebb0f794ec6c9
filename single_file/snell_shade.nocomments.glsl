// snell 0.2.0, single-file GLSL: glsl/snell/shade.glsl with every #include spliced in
// (snell-flatten --no-line --strip-comments). Generated: do not edit; regenerate with
// `cmake --build build --target single_file`. No #version line: put it, and on
// ES the precision statements, before this text.
#ifndef SNELL_SHADE_GLSL
#define SNELL_SHADE_GLSL

#ifndef SNELL_SHADE_PERTURB_GLSL
#define SNELL_SHADE_PERTURB_GLSL

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

#ifndef SNELL_CAMERA_CONVENTIONS_GLSL
#define SNELL_CAMERA_CONVENTIONS_GLSL

#define SNELL_DEPTH_GL 0
#define SNELL_DEPTH_ZERO_ONE 1
#define SNELL_DEPTH_REVERSED 2
#define SNELL_DEPTH_INFINITE_GL 3
#define SNELL_DEPTH_INFINITE_REVERSED 4
#define SNELL_DEPTH_CONVENTION_COUNT 5

#if defined(SNELL_LANG_HLSL)
#  define SNELL_CAMERA_MAT4_COLUMNS(c0, c1, c2, c3) transpose(float4x4(c0, c1, c2, c3))
#else
#  define SNELL_CAMERA_MAT4_COLUMNS(c0, c1, c2, c3) mat4(c0, c1, c2, c3)
#endif

#if defined(SNELL_LANG_HLSL)
#  define SNELL_CAMERA_MAT_COLUMN(m, i) (transpose(m)[i])
#else
#  define SNELL_CAMERA_MAT_COLUMN(m, i) ((m)[i])
#endif

#endif

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

#ifndef SNELL_SHADE_REFRACTION_MASK_GLSL
#define SNELL_SHADE_REFRACTION_MASK_GLSL

SNELL_FN vec4 snellRefractionMaskBlend(vec4 refrA, vec4 refrB) {
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

#ifndef SNELL_SHADE_WATER_GLSL
#define SNELL_SHADE_WATER_GLSL

#ifndef SNELL_OPTICS_SAFE_NORMALIZE_GLSL
#define SNELL_OPTICS_SAFE_NORMALIZE_GLSL

SNELL_FN vec3 snellSafeNormalize(vec3 v) {
  float len2 = dot(v, v);
  if (!(len2 > 1e-30f) || !(len2 < SNELL_FLT_MAX)) {
    return vec3(0.0f, 0.0f, 0.0f);
  }
  return v * inversesqrt(len2);
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
  vec3 d = vec3(isnan(diffuse.x) ? 1.0f : diffuse.x, isnan(diffuse.y) ? 1.0f : diffuse.y,
                isnan(diffuse.z) ? 1.0f : diffuse.z);
  vec3 t = clamp(d * 0.9f + 0.1f, vec3(0.0f, 0.0f, 0.0f), vec3(1.0f, 1.0f, 1.0f));
  vec4 tint = vec4(t.x, t.y, t.z, diffuse.w);
  return tint * refraction * (1.0f - f) + env * f;
}

#endif

#ifndef SNELL_SHADE_ICE_GLSL
#define SNELL_SHADE_ICE_GLSL

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
  float f = isnan(fresnel) ? 1.0f : clamp(fresnel, 0.0f, 1.0f);
  return refraction * (1.0f - f) + reflection * f;
}

#endif

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

#ifndef SNELL_SHADE_REFRACTIVE_TEXTURE_MAP_GLSL
#define SNELL_SHADE_REFRACTIVE_TEXTURE_MAP_GLSL

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

SNELL_FN float snellRefractiveTextureMapAxis(float x, float lo, float hi) {
  float len = hi - lo;
  if (!SNELL_FINITE(x) || !SNELL_FINITE(lo) || !SNELL_FINITE(hi) || !SNELL_FINITE(len) ||
      !(abs(len) >= SNELL_FLT_MIN)) {
    return 0.5f;
  }
  return clamp((x - lo) / len, -1e6f, 1e6f);
}

SNELL_FN SnellRefractiveTextureMapHit snellRefractiveTextureMap(vec3 vertex, vec3 normal, vec3 eyePosition,
                                                                SnellRefractiveTextureMapParams p) {
  SnellRefractiveTextureMapHit h;
  float planeY = p.restY - p.depth;
  vec3 dir = snellApproxRefract(vertex - eyePosition, normal, p.refractionFactor);
  SnellRayPlaneHit hit = snellRayPlane(vertex, dir, vec3(0.0f, planeY, 0.0f), vec3(0.0f, 1.0f, 0.0f));
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

#ifndef SNELL_SHADE_DISPERSION_GLSL
#define SNELL_SHADE_DISPERSION_GLSL

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

#ifndef SNELL_SHADE_ROUGHNESS_GLSL
#define SNELL_SHADE_ROUGHNESS_GLSL

SNELL_FN float snellRoughnessToLod(float roughness, int levels) {
  if (levels <= 1) {
    return 0.0f;
  }
  float r = isnan(roughness) ? 0.0f : clamp(roughness, 0.0f, 1.0f);
  float top = float(levels - 1);
  float m = 1.0f - r;
  return min(top * (1.0f - m * m), top);
}

#endif

#ifndef SNELL_SHADE_COLOR_PYRAMID_GLSL
#define SNELL_SHADE_COLOR_PYRAMID_GLSL

SNELL_FN vec4 snellColorPyramidTexel(vec4 t) {
  bool finite = SNELL_FINITE(t.x) && SNELL_FINITE(t.y) && SNELL_FINITE(t.z) && SNELL_FINITE(t.w);
  return finite ? t : vec4(0.0f);
}

struct SnellColorPyramidAxis {
  int first;
  vec4 weights;
};

SNELL_FN SnellColorPyramidAxis snellColorPyramidAxis(int px, int size) {
  int w = max(size, 1);
  int outSize = max(w / 2, 1);
  int p = clamp(px, 0, outSize - 1);
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

#ifndef SNELL_SHADE_ROUGH_CONE_GLSL
#define SNELL_SHADE_ROUGH_CONE_GLSL

#ifndef SNELL_SHADE_TECHNIQUE_OPTIONS_GLSL
#define SNELL_SHADE_TECHNIQUE_OPTIONS_GLSL

#ifndef SNELL_INTERSECT_INTERSECT_WITH_GLSL
#define SNELL_INTERSECT_INTERSECT_WITH_GLSL

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

#ifndef SNELL_INTERSECT_DEPTH_SURFACE_GLSL
#define SNELL_INTERSECT_DEPTH_SURFACE_GLSL

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
    v = d >= SNELL_FLT_MIN ? zNear / d : SNELL_FLT_MAX;
  } else {
    return 0.0f;
  }
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
    return reversed ? 1.0f : 0.0f;
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

#ifndef SNELL_CAMERA_PIXEL_TO_UV_GLSL
#define SNELL_CAMERA_PIXEL_TO_UV_GLSL

SNELL_FN vec2 snellPixelToUv(ivec2 px, ivec2 size) {
  float u = size.x > 0 ? (float(px.x) + 0.5f) / float(size.x) : 0.0f;
  float v = size.y > 0 ? (float(px.y) + 0.5f) / float(size.y) : 0.0f;
  return vec2(u, v);
}

#define SNELL_PIXEL_ON_SCREEN(uv, size) ivec2(min(int((uv).x * float((size).x)), (size).x - 1), min(int((uv).y * float((size).y)), (size).y - 1))

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
  bool interpolated;
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
  float den = a + b * s.nearOverFar;
  float v = den > 0.0f ? s.zNear / den : SNELL_FLT_MAX;
  if (!(v > 0.0f)) {
    return 0.0f;
  }
  v = v < s.zNear ? s.zNear : v;
  v = v > s.depthFarLimit ? s.depthFarLimit : v;
  return v > 0.0f && v <= SNELL_FLT_MAX ? v : 0.0f;
}

SNELL_FN_INLINE SnellSurfaceSample snellSampleSurface(SNELL_TEX2D depthTex, vec2 uv, SNELL_IN(SnellDepthSurface) s) {
  SnellSurfaceSample r;
  r.viewZ = 0.0f;
  r.valid = false;
  r.interpolated = false;
  if (!(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f)) {
    return r;
  }
  ivec2 size = SNELL_TEXTURE_SIZE(depthTex, s.lod);
  if (size.x <= 0 || size.y <= 0) {
    return r;
  }
  float d = SNELL_TEXEL_FETCH_IN_LEVEL(depthTex, SNELL_PIXEL_ON_SCREEN(uv, size), s.lod).x;
  if (d == s.emptyDepth) {
    return r;
  }
  if (s.depthFilter == SNELL_DEPTH_FILTER_BILINEAR) {
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

#ifndef SNELL_INTERSECT_SINGLE_SAMPLE_GLSL
#define SNELL_INTERSECT_SINGLE_SAMPLE_GLSL

#ifndef SNELL_CAMERA_VIEW_TO_UV_GLSL
#define SNELL_CAMERA_VIEW_TO_UV_GLSL

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

#ifndef SNELL_INTERSECT_SURFACE_PROJECTION_GLSL
#define SNELL_INTERSECT_SURFACE_PROJECTION_GLSL

#ifndef SNELL_CAMERA_UV_Z_TO_VIEW_GLSL
#define SNELL_CAMERA_UV_Z_TO_VIEW_GLSL

#ifndef SNELL_CAMERA_UV_DEPTH_TO_VIEW_GLSL
#define SNELL_CAMERA_UV_DEPTH_TO_VIEW_GLSL

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
  float cx = c0.x * pView.x + c2.x * pView.z;
  float cy = c1.y * pView.y + c2.y * pView.z;
  float cz = c2.z * pView.z + c3.z;
  float cw = -pView.z;
  if (!SNELL_FINITE(cx) || !SNELL_FINITE(cy) || !(cw >= SNELL_FLT_MIN && cw <= SNELL_FLT_MAX)) {
    return r;
  }
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
  if (!SNELL_FINITE(viewZ) || !(viewZ <= -SNELL_FLT_MIN)) {
    return r;
  }
  vec4 c0 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 0);
  vec4 c1 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 1);
  vec4 c2 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 2);
  float nx = 2.0f * uv.x - 1.0f;
  float ny = 2.0f * uv.y - 1.0f;
  if (!SNELL_FINITE(nx) || !SNELL_FINITE(ny)) {
    return r;
  }
  float b0 = -(viewZ * (c2.x + nx) + 0.0f);
  float b1 = -(viewZ * (c2.y + ny) + 0.0f);
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

#ifndef SNELL_INTERSECT_SURFACE_POINT_GLSL
#define SNELL_INTERSECT_SURFACE_POINT_GLSL

struct SnellSurfacePoint {
  vec3 position;
  vec2 uv;
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

#ifndef SNELL_INTERSECT_PLANE_REFINE_GLSL
#define SNELL_INTERSECT_PLANE_REFINE_GLSL

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

#ifndef SNELL_PLANE_ITERATIONS
#  define SNELL_PLANE_ITERATIONS 1
#endif
#ifndef SNELL_PLANE_MAX_ITERATIONS
#  define SNELL_PLANE_MAX_ITERATIONS 8
#endif

#ifndef SNELL_PLANE_FACING_FALLBACK
#  define SNELL_PLANE_FACING_FALLBACK 1
#endif

#ifndef SNELL_PLANE_HOLD
#  define SNELL_PLANE_HOLD 1
#endif

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

#ifndef SNELL_INTERSECT_PLANE_NORMAL_GLSL
#define SNELL_INTERSECT_PLANE_NORMAL_GLSL

#ifndef SNELL_INTERSECT_PLANE_FAR_START_GLSL
#define SNELL_INTERSECT_PLANE_FAR_START_GLSL

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
      break;
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
    if (k >= n) {
      break;
    }
  }
  return snellPlaneHit(p, planeUv, depthTex, s, fetches);
}

#endif

#ifndef SNELL_INTERSECT_PLANE_DEPTH_GLSL
#define SNELL_INTERSECT_PLANE_DEPTH_GLSL

#ifndef SNELL_PLANE_DEPTH_MAX_SPAN_LOD
#  define SNELL_PLANE_DEPTH_MAX_SPAN_LOD 6
#endif

struct SnellDepthPlane {
  vec2 uv;
  vec3 position;
  vec3 normal;
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
  vec3 p = origin;
  vec2 planeUv = vec2(0.0f, 0.0f);
  int fetches = 0;
  for (int k = 0; k <= SNELL_PLANE_MAX_ITERATIONS; ++k) {
    SnellDepthPlane plk = snellDepthPlaneAt(p, dirN, depthMips, s, maxLod);
    fetches += plk.fetches;
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
      break;
    }
    p = hk.position;
    planeUv = plk.uv;
    if (k >= n) {
      break;
    }
  }
  return snellPlaneHit(p, planeUv, depthMips, s, fetches);
}

#endif

#ifndef SNELL_INTERSECT_CONSERVATIVE_BINARY_SEARCH_GLSL
#define SNELL_INTERSECT_CONSERVATIVE_BINARY_SEARCH_GLSL

#ifndef SNELL_CAMERA_TEX_RAY_GLSL
#define SNELL_CAMERA_TEX_RAY_GLSL

struct SnellTexRay {
  vec3 s;
  vec3 e;
  float k1;
  float k2;
  vec2 ts;
  vec2 dt;
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
  vec4 c0 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 0);
  vec4 c1 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 1);
  vec4 c2 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 2);
  vec4 c3 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 3);
  vec3 cs = vec3((c0.x * s.x + c1.x * s.y) + (c2.x * s.z + c3.x), (c0.y * s.x + c1.y * s.y) + (c2.y * s.z + c3.y),
                 (c0.w * s.x + c1.w * s.y) + (c2.w * s.z + c3.w));
  vec3 ce = vec3((c0.x * e.x + c1.x * e.y) + (c2.x * e.z + c3.x), (c0.y * e.x + c1.y * e.y) + (c2.y * e.z + c3.y),
                 (c0.w * e.x + c1.w * e.y) + (c2.w * e.z + c3.w));
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
  return isnan(alpha) ? 0.0f : clamp(alpha, -SNELL_FLT_MAX, SNELL_FLT_MAX);
}

SNELL_FN vec2 snellTexRayUv(SnellTexRay r, float pz) {
  float alpha = snellTexRayAlpha(r, pz);
  vec2 uv = r.ts + alpha * r.dt;
  return clamp(uv, vec2(-SNELL_FLT_MAX, -SNELL_FLT_MAX), vec2(SNELL_FLT_MAX, SNELL_FLT_MAX));
}

#endif

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

#ifndef SNELL_CBS_STEPS
#  define SNELL_CBS_STEPS 5
#endif
#ifndef SNELL_CBS_MAX_STEPS
#  define SNELL_CBS_MAX_STEPS 24
#endif

SNELL_FN SnellHit snellConservativeBinarySearch(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) surface,
                                                float zNearest, float zFarthest, int steps) {
  SnellTexRay r = snellSearchSegment(origin, dir, zNearest, zFarthest, surface.clipFromView);
  if (!r.valid) {
    return snellHitMiss(0);
  }
  int n = clamp(steps, 0, SNELL_CBS_MAX_STEPS);
  float dz = r.e.z - r.s.z;
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

#ifndef SNELL_INTERSECT_BINARY_SEARCH_GLSL
#define SNELL_INTERSECT_BINARY_SEARCH_GLSL

#ifndef SNELL_BINARY_SEARCH_STEPS
#  define SNELL_BINARY_SEARCH_STEPS 5
#endif
#ifndef SNELL_BINARY_SEARCH_MAX_STEPS
#  define SNELL_BINARY_SEARCH_MAX_STEPS 24
#endif

SNELL_FN SnellHit snellBisectTexRay(SnellTexRay r, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) surface, float lo,
                                    float hi, int steps, SnellHit h) {
  if (isnan(lo) || isnan(hi)) {
    return h;
  }
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
    if (i + 1 >= n) {
      break;
    }
  }
  return h;
}

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

#ifndef SNELL_INTERSECT_LINEAR_BINARY_SEARCH_GLSL
#define SNELL_INTERSECT_LINEAR_BINARY_SEARCH_GLSL

#ifndef SNELL_LINEAR_SEARCH_STEPS
#  define SNELL_LINEAR_SEARCH_STEPS 10
#endif
#ifndef SNELL_LINEAR_SEARCH_MAX_STEPS
#  define SNELL_LINEAR_SEARCH_MAX_STEPS 256
#endif

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

#ifndef SNELL_SHADE_ENVIRONMENT_GLSL
#define SNELL_SHADE_ENVIRONMENT_GLSL

#ifndef SNELL_SHADE_ENVIRONMENT_CUBE_FACE_GLSL
#define SNELL_SHADE_ENVIRONMENT_CUBE_FACE_GLSL

struct SnellCubeFace {
  int face;
  vec2 uv;
  bool valid;
};

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
  float radius;
  float angle;
  float exitAngle;
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

SNELL_FN float snellRoughConeMeasure(float x) {
  return x > 0.0f ? min(x, SNELL_FLT_MAX) : 0.0f;
}

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
  float radius = levels > 1 ? snellRoughConeRadius(c, distance) : 0.0f;
  if (!(radius > 0.0f)) {
    return 0.0f;
  }
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
  float texelsPerRadian = exp2(float(min(levels - 1, 100))) / (2.0f * SNELL_PI);
  return snellRoughConeLevel(snellRoughConeHypot(c.angle, c.exitAngle), texelsPerRadian, levels);
}

struct SnellRoughTaps {
  float coreLod;
  float tailLod;
  float tailWeight;
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

#ifndef SNELL_SHADE_TECHNIQUE_BUFFERS_GLSL
#define SNELL_SHADE_TECHNIQUE_BUFFERS_GLSL

#define SNELL_OBJECT_BUFFERS SNELL_TEX2D backDepth, SNELL_TEX2D backNormal, SNELL_TEX2D backPyramid, SNELL_IN(SnellDepthSurface) back, SNELL_TEX2D frontLayerDepth, SNELL_TEX2D frontLayerNormal, SNELL_IN(SnellDepthSurface) frontLayer
#define SNELL_OBJECT_BUFFER_ARGS backDepth, backNormal, backPyramid, back, frontLayerDepth, frontLayerNormal, frontLayer

#define SNELL_SCENE_BUFFERS SNELL_TEX2D sceneDepth, SNELL_TEX2D sceneNormal, SNELL_TEX2D scenePyramid, SNELL_TEX2D sceneColor, SNELL_IN(SnellDepthSurface) scene, SNELL_ENVIRONMENT_TEX environment
#define SNELL_SCENE_BUFFER_ARGS sceneDepth, sceneNormal, scenePyramid, sceneColor, scene, environment

#endif

#ifndef SNELL_SHADE_TECHNIQUE_PRESETS_GLSL
#define SNELL_SHADE_TECHNIQUE_PRESETS_GLSL

SNELL_FN SnellTechnique snellTechniquePresetSlots(int backStrategy, int exitStrategy) {
  SnellTechnique t = snellTechnique();
  t.back.intersect = snellIntersectOptions(backStrategy);
  t.exit.intersect = snellIntersectOptions(exitStrategy);
  return t;
}

SNELL_FN SnellTechnique snellPresetDir() {
  return snellTechniquePresetSlots(SNELL_STRATEGY_CBS, SNELL_STRATEGY_CBS);
}

SNELL_FN SnellTechnique snellPresetDirBounds(float zNearest, float zFarthest) {
  SnellTechnique t = snellPresetDir();
  t.back.intersect.rangeSource = SNELL_RANGE_EXPLICIT;
  t.back.intersect.range.zNearest = zNearest;
  t.back.intersect.range.zFarthest = zFarthest;
  t.back.intersect.range.valid = true;
  return t;
}

SNELL_FN SnellTechnique snellPresetIsr() {
  SnellTechnique t = snellTechniquePresetSlots(SNELL_STRATEGY_SINGLE, SNELL_STRATEGY_SINGLE);
  t.back.source = SNELL_SOURCE_WYMAN;
  return t;
}

SNELL_FN SnellTechnique snellPresetPlaneNormal(int iterations) {
  SnellTechnique t = snellTechniquePresetSlots(SNELL_STRATEGY_PLANE_NORMAL, SNELL_STRATEGY_PLANE_NORMAL);
  t.back.intersect.planeIterations = iterations;
  t.exit.intersect.planeIterations = iterations;
  return t;
}

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

SNELL_FN SnellTechnique snellPresetPlaneNormalBounces(int iterations) {
  SnellTechnique t = snellPresetPlaneNormal(iterations);
  t.bounces = SNELL_PRESET_BOUNCES;
  t.inside.intersect.marchSteps = SNELL_PRESET_INSIDE_STEPS;
  t.inside.intersect.marchBisections = SNELL_PRESET_INSIDE_BISECTIONS;
  return t;
}

SNELL_FN SnellTechnique snellPresetLinearMarchBounces() {
  SnellTechnique t = snellPresetLinearMarch();
  t.bounces = SNELL_PRESET_BOUNCES;
  t.inside.intersect.marchSteps = SNELL_PRESET_INSIDE_STEPS;
  t.inside.intersect.marchBisections = SNELL_PRESET_INSIDE_BISECTIONS;
  return t;
}

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

#ifndef SNELL_SHADE_TWO_INTERFACE_GLSL
#define SNELL_SHADE_TWO_INTERFACE_GLSL

#ifndef SNELL_OPTICS_WYMAN_DISTANCE_GLSL
#define SNELL_OPTICS_WYMAN_DISTANCE_GLSL

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

#ifndef SNELL_INTERSECT_INSIDE_MARCH_GLSL
#define SNELL_INTERSECT_INSIDE_MARCH_GLSL

#ifndef SNELL_INSIDE_FIRST_STEP_HALVINGS
#  define SNELL_INSIDE_FIRST_STEP_HALVINGS 3
#endif

struct SnellInsideHit {
  SnellHit hit;
  bool front;
};

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

struct SnellInsideBracket {
  float lo;
  float hi;
  vec2 uv;
  vec2 loUv;
  int side;
  int fetches;
  bool valid;
};

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
    if (i >= n) {
      break;
    }
  }
  b.lo = 0.0f;
  b.loUv = vec2(0.0f, 0.0f);
  return b;
}

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

#ifndef SNELL_INTERSECT_INSIDE_PLANE_GLSL
#define SNELL_INTERSECT_INSIDE_PLANE_GLSL

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
  vec2 readUv = b.uv;
  bool readFront = onFront;
  int planes = 0;
  int misses = 0;
  for (int k = 1; n > 0 && k <= SNELL_PLANE_MAX_ITERATIONS + 2; ++k) {
    SnellSurfacePoint s;
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

#ifndef SNELL_TWO_INTERFACE_NORMAL_SAMPLE
#  define SNELL_TWO_INTERFACE_NORMAL_SAMPLE 1
#endif

struct SnellTwoInterfacePath {
  vec3 entryDirection;
  vec3 exitPoint;
  vec3 exitNormal;
  vec3 exitDirection;
  vec2 exitUv;
  float pathLength;
  float entryLength;
  int fetches;
  int bounces;
  bool hit;
  bool tir;
  bool fellBack;
  bool valid;
  bool exitFront;
  vec3 exitIncident;
};

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
  for (int k = 0; k <= SNELL_MAX_BOUNCES; ++k) {
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

#ifndef SNELL_SHADE_TWO_INTERFACE_SHADE_GLSL
#define SNELL_SHADE_TWO_INTERFACE_SHADE_GLSL

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

struct SnellTwoInterfaceExit {
  vec3 color;
  SnellHit hit;
  bool fellBack;
  int fetches;
};

struct SnellTwoInterfaceResult {
  vec3 color;
  vec3 exitPoint;
  vec3 exitDirection;
  SnellHit exitHit;
  SnellHit reflectionHit;
  float pathLength;
  float fresnel;
  int fetches;
  bool backHit;
  bool fellBack;
  bool tir;
  int bounces;
  bool insideHit;
};

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

SNELL_FN SnellTwoInterfaceExit snellTwoInterfaceExit(vec3 origin, vec3 dir, SNELL_SCENE_BUFFERS,
                                                     SNELL_IN(SnellSlot) slot, SNELL_IN(SnellMaterial) m,
                                                     SNELL_IN(SnellView) v) {
  SnellRoughCone cone = snellRoughConeTransmit(m.roughness, snellIorToEta(m.iorOutside, m.ior), 0.0f, 0);
  return snellTwoInterfaceExitRough(origin, dir, cone, SNELL_SCENE_BUFFER_ARGS, slot, v);
}

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
    bool inside = false;
    SnellHit ih = snellHitMiss(0);
    if (t.insideScene && p.hit) {
      ih = snellIntersectWith(frontPosition, p.entryDirection, sceneDepth, sceneNormal, scenePyramid, scene,
                              t.exit.intersect);
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
    SnellSlot leave = t.exit;
    if (t.bounces > 0 && p.exitFront) {
      leave = t.reflect;
    }
    float alpha = snellRoughConeSlope(m.roughness);
    if (alpha > 0.0f && dot(p.exitIncident, p.exitIncident) > 0.0f) {
      p.exitDirection = snellRefractRough(p.exitIncident, p.exitNormal, 1.0f / etaK, alpha, m.tirPolicy).direction;
    }
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
    if (k + 1 >= channels) {
      break;
    }
  }
  r.color = transmitted;
  vec3 vv = snellSafeNormalize(frontPosition);
  vec3 n1 = snellSafeNormalize(frontNormal);
  if (m.reflection && dot(vv, vv) > 0.0f && dot(n1, n1) > 0.0f) {
    float f = snellFresnelDielectric(dot(vv, n1), eta);
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

#ifndef SNELL_SHADE_ENGINE_MODELS_ENGINE_MODELS_GLSL
#define SNELL_SHADE_ENGINE_MODELS_ENGINE_MODELS_GLSL

#ifndef SNELL_SHADE_ENGINE_MODELS_ENGINE_REFRACTION_GLSL
#define SNELL_SHADE_ENGINE_MODELS_ENGINE_REFRACTION_GLSL

struct SnellEngineEntry {
  vec3 direction;
  vec3 normal;
  float cosine;
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

#ifndef SNELL_SHADE_ENGINE_MODELS_FILAMENT_GLSL
#define SNELL_SHADE_ENGINE_MODELS_FILAMENT_GLSL

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

#ifndef SNELL_SHADE_ENGINE_MODELS_HDRP_GLSL
#define SNELL_SHADE_ENGINE_MODELS_HDRP_GLSL

#ifndef SNELL_HDRP_SCREEN_FADE_DISTANCE
#  define SNELL_HDRP_SCREEN_FADE_DISTANCE 0.1f
#endif

SNELL_FN float snellEngineHdrpEdgeFade(vec2 uv) {
  if (!SNELL_FINITE(uv.x) || !SNELL_FINITE(uv.y)) {
    return 0.0f;
  }
  float x = clamp((1.0f - abs(2.0f * uv.x - 1.0f)) / SNELL_HDRP_SCREEN_FADE_DISTANCE, 0.0f, 1.0f);
  float y = clamp((1.0f - abs(2.0f * uv.y - 1.0f)) / SNELL_HDRP_SCREEN_FADE_DISTANCE, 0.0f, 1.0f);
  return (x * x * (3.0f - 2.0f * x)) * (y * y * (3.0f - 2.0f * y));
}

SNELL_FN float snellEngineProxyExit(vec3 origin, vec3 dir, mat4 proxyFromView) {
  vec4 o4 = SNELL_MUL(proxyFromView, vec4(origin.x, origin.y, origin.z, 1.0f));
  vec4 d4 = SNELL_MUL(proxyFromView, vec4(dir.x, dir.y, dir.z, 0.0f));
  if (!SNELL_FINITE(o4.x) || !SNELL_FINITE(o4.y) || !SNELL_FINITE(o4.z) || !SNELL_FINITE(d4.x) ||
      !SNELL_FINITE(d4.y) || !SNELL_FINITE(d4.z)) {
    return 0.0f;
  }
  float s = SNELL_FLT_MAX;
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

#define SNELL_ENGINE_BLUR_UV(uv) vec2(isnan((uv).x) ? 0.0f : clamp((uv).x, 0.0f, 1.0f), isnan((uv).y) ? 0.0f : clamp((uv).y, 0.0f, 1.0f))

struct SnellEngineBlurRead {
  vec3 color;
  int fetches;
};

SNELL_FN float snellEngineBlurLod(int blur, float roughness, float ior, int levels, vec2 size, mat4 clipFromView) {
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

SNELL_FN SnellEngineBlurRead snellEngineSmoothRead(SNELL_TEX2D sceneColor, vec2 uv) {
  vec4 c = SNELL_SAMPLE_LOD(sceneColor, SNELL_ENGINE_BLUR_UV(uv), 0.0f);
  SnellEngineBlurRead r;
  r.color = vec3(c.x, c.y, c.z);
  r.fetches = 1;
  return r;
}

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
  for (int i = 0; i < 32; ++i) {
    if (i >= n) {
      continue;
    }
    int k = i >> 3;
    int j = i & 7;
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
    vec2 tap = clamp(c0 + vec2(d.x, -d.y), vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
    vec4 c = SNELL_SAMPLE_LOD(sceneColor, tap, 0.0f);
    sum = sum + vec3(c.x, c.y, c.z);
  }
  SnellEngineBlurRead r;
  r.color = sum / float(n);
  r.fetches = n;
  return r;
}

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
