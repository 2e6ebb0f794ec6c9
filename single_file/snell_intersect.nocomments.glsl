// snell 0.2.0, single-file GLSL: glsl/snell/intersect.glsl with every #include spliced in
// (snell-flatten --no-line --strip-comments). Generated: do not edit; regenerate with
// `cmake --build build --target single_file`. No #version line: put it, and on
// ES the precision statements, before this text.
#ifndef SNELL_INTERSECT_GLSL
#define SNELL_INTERSECT_GLSL

#ifndef SNELL_INTERSECT_HIT_GLSL
#define SNELL_INTERSECT_HIT_GLSL

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

#ifndef SNELL_INTERSECT_SURFACE_PROJECTION_GLSL
#define SNELL_INTERSECT_SURFACE_PROJECTION_GLSL

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

#ifndef SNELL_INTERSECT_PLANE_REFINE_GLSL
#define SNELL_INTERSECT_PLANE_REFINE_GLSL

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

#ifndef SNELL_INTERSECT_PLANE_FAR_START_GLSL
#define SNELL_INTERSECT_PLANE_FAR_START_GLSL

#ifndef SNELL_OPTICS_RAY_PLANE_GLSL
#define SNELL_OPTICS_RAY_PLANE_GLSL

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

#ifndef SNELL_INTERSECT_SEARCH_SEGMENT_GLSL
#define SNELL_INTERSECT_SEARCH_SEGMENT_GLSL

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

#ifndef SNELL_INTERSECT_CONSERVATIVE_BINARY_SEARCH_GLSL
#define SNELL_INTERSECT_CONSERVATIVE_BINARY_SEARCH_GLSL

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
