// snell 0.2.0, single-file GLSL: glsl/snell/camera.glsl with every #include spliced in
// (snell-flatten --no-line --strip-comments). Generated: do not edit; regenerate with
// `cmake --build build --target single_file`. No #version line: put it, and on
// ES the precision statements, before this text.
#ifndef SNELL_CAMERA_GLSL
#define SNELL_CAMERA_GLSL

#ifndef SNELL_CAMERA_CONVENTIONS_GLSL
#define SNELL_CAMERA_CONVENTIONS_GLSL

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
  float halfFovy = fovy / 2.0f;
  bool upper = halfFovy > 0.78539818525f;
  float r = halfFovy;
  if (upper) {
    r = (1.57079637050628662f - halfFovy) - 4.37113900018624283e-8f;
  }
  float r2 = r * r;
  float tanR = ((((((9.38540185543e-3f * r2 + 3.11992232697e-3f) * r2 + 2.44301354525e-2f) * r2 +
                   5.34112807005e-2f) * r2 + 1.33387994085e-1f) * r2 + 3.33331568548e-1f) * r2) * r + r;
  float tanHalfFovy = upper ? 1.0f / tanR : tanR;
  if (!SNELL_FINITE(tanHalfFovy) || !(tanHalfFovy >= SNELL_FLT_MIN) || !(aspect * tanHalfFovy >= SNELL_FLT_MIN)) {
    return zero;
  }
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
  if (!SNELL_FINITE(ia) || !SNELL_FINITE(ib) || !SNELL_FINITE(id) || !SNELL_FINITE(cd) ||
      !(ia >= SNELL_FLT_MIN) || !(ib >= SNELL_FLT_MIN) || !(abs(id) >= SNELL_FLT_MIN) ||
      (cd != 0.0f && !(abs(cd) >= SNELL_FLT_MIN))) {
    return SNELL_CAMERA_MAT4_COLUMNS(zero4, zero4, zero4, zero4);
  }
  return SNELL_CAMERA_MAT4_COLUMNS(vec4(ia, 0.0f, 0.0f, 0.0f), vec4(0.0f, ib, 0.0f, 0.0f),
                                   vec4(0.0f, 0.0f, 0.0f, id), vec4(0.0f, 0.0f, -1.0f, cd));
}

#endif

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
#endif
