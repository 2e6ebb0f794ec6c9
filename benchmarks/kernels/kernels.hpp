// Minimal hand-written kernels: per intersection
// strategy, the same per-ray floating-point work as snell's C++ mirror of the
// GLSL, written for exactly the benchmark's setup, so that every output bit
// (hit.position xyz, hit.uv, hit.valid, hit.fetches) equals snell's ray by ray
// (kernel_study.cpp -DCHECK proves it on the 20000 rays). Plain C++, no GLM.
//
// What every kernel assumes (the benchmark guarantees it; snell checks it):
//  A1 finite inputs and no overflow anywhere: every SNELL_FINITE / isnan test and
//     every clamp to +-SNELL_FLT_MAX is a no-op and is left out;
//  A2 non-degenerate inputs: |dir|^2 >= 1e-30, normal texels behind a surface
//     texel are non-zero (snellSafeNormalize's len2 tests, dot(n, n) == 0 left out);
//  A3 clipFromView is a glm::perspective (GL convention): only m00 = a, m11 = b,
//     m22 = c, m32 = d and m23 = -1 are non-zero, so clip = (a x, b y, c z + d, -z).
//     GLM's (m0 x + m1 y) + (m2 z + m3 w) equals that for finite values up to the
//     sign of an exactly-zero component, which every use below washes out
//     (u = 0.5 ndc + 0.5) or which cannot occur (w = -z is tested >= FLT_MIN);
//     clip z is never used;
//  A4 depth: SNELL_DEPTH_GL, emptyDepth 0, level 0, NEAREST reads, stored depths
//     (and pyramid means) inside (0, 1): snellLinearizeDepth's clamps are no-ops
//     and its result is > 0, so a texel is valid exactly when it is != 0;
//  A5 the textures are RGBA32F float arrays, level 0 of size kW x kW (a power of
//     two: (i + 0.5) / kW == (i + 0.5) * (1 / kW) exactly, and 2 u - 1 is never 0
//     at a texel centre, so the zero terms of snellUvZToView drop out exactly);
//  A6 a zero-weight term of a sum (0 * y) is dropped where its value is +-0 and
//     the other term is non-zero (exact), as in A3.
// The remaining tests are the geometric ones, which go either way on real rays.
#ifndef KERNELS_HPP
#define KERNELS_HPP
#include <cmath>

namespace kern {

constexpr int kW = 256;                   // texture size (square, level 0)
constexpr float kInvW = 1.0f / static_cast<float>(kW);  // exact (a power of two)
constexpr float kFltMin = 1.175494351e-38f;
constexpr int kMaxLevels = 16;

struct Camera {
  float a, b, c, d;  // m00, m11, m22, m32 of clipFromView (A3)
  float det;         // a * b
  float zNear;
  float nearOverFar;  // zNear / zFar, as snellLinearizeDepth computes it
  const float* depth;   // RGBA32F kW x kW, depth in .x
  const float* normal;  // RGBA32F kW x kW, view-space normal in .xyz
  const float* pyramid[kMaxLevels];  // depth min/max pyramid levels (.x = depth), level l is (kW >> l)^2
  int levels;
};

struct Hit {
  float x, y, z;  // position
  float u, v;     // uv
  int valid;
  int fetches;
};

inline Hit miss(int fetches) { return Hit{0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0, fetches}; }

// snellViewToUv (A1, A3): clip w = -z; false when w < FLT_MIN.
inline bool project(const Camera& c, float x, float y, float z, float& u, float& v) {
  const float w = -z;
  if (!(w >= kFltMin)) return false;
  u = c.a * x / w * 0.5f + 0.5f;
  v = c.b * y / w * 0.5f + 0.5f;
  return true;
}

inline bool onScreen(float u, float v) { return u >= 0.0f && u <= 1.0f && v >= 0.0f && v <= 1.0f; }

// snellUvToPixel for uv in [0, 1] (floor == truncation there), level 0.
inline int texel(float u) {
  const int i = static_cast<int>(u * static_cast<float>(kW));
  return i < kW - 1 ? i : kW - 1;
}

inline float depthAt(const float* tex, int size, int x, int y) { return tex[4 * (y * size + x)]; }

// -snellLinearizeDepth(d, zNear, zFar, SNELL_DEPTH_GL) (A4).
inline float viewZ(const Camera& c, float d) { return -(c.zNear / ((1.0f - d) + d * c.nearOverFar)); }

// snellSampleSurface at an on-screen uv (level 0, A4): true and vz when the texel holds a surface.
inline bool sampleOnScreen(const Camera& c, float u, float v, float& vz) {
  const float d = depthAt(c.depth, kW, texel(u), texel(v));
  if (d == 0.0f) return false;
  vz = viewZ(c, d);
  return true;
}
// snellSampleSurface at any uv.
inline bool sample(const Camera& c, float u, float v, float& vz) { return onScreen(u, v) && sampleOnScreen(c, u, v, vz); }

// snellUvZToView at the centre (cu, cv) of texel (px, py) of a level of size
// `size` (A3, A5): x = (b0 a11) / det, y = (a00 b1) / det with b0 = -(z nx), b1 = -(z ny).
inline void centrePoint(const Camera& c, int px, int py, float invSize, float vz, float& cu, float& cv,
                        float p[3]) {
  cu = (static_cast<float>(px) + 0.5f) * invSize;
  cv = (static_cast<float>(py) + 0.5f) * invSize;
  const float nx = 2.0f * cu - 1.0f, ny = 2.0f * cv - 1.0f;
  p[0] = -(vz * nx) * c.b / c.det;
  p[1] = c.a * -(vz * ny) / c.det;
  p[2] = vz;
}

// snellRayPlane(o, d, B, nRaw) (A1, A2 for the normal's length); eps = 1e-6 |d|.
inline bool rayPlane(const float* o, const float* d, float eps, const float* B, const float* nRaw, float* p) {
  const float inv = 1.0f / std::sqrt(nRaw[0] * nRaw[0] + nRaw[1] * nRaw[1] + nRaw[2] * nRaw[2]);
  const float nx = nRaw[0] * inv, ny = nRaw[1] * inv, nz = nRaw[2] * inv;
  const float denom = d[0] * nx + d[1] * ny + d[2] * nz;
  if (!(std::fabs(denom) > eps)) return false;
  const float t = ((B[0] - o[0]) * nx + (B[1] - o[1]) * ny + (B[2] - o[2]) * nz) / denom;
  if (!(t >= 0.0f)) return false;
  p[0] = o[0] + t * d[0];
  p[1] = o[1] + t * d[1];
  p[2] = o[2] + t * d[2];
  return true;
}

// ---------------------------------------------------------------------------
// snellIntersectSingleSample(origin, dir, depthTex, surface)
// (single_sample.glsl, surface_point.glsl). Simplifications: A1-A5; the lookup
// uv is checked on screen once (snellSampleSurface), B is the texel centre point.
inline Hit singleSample(const Camera& c, const float* o, const float* d) {
  const float len2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  float u, v;
  if (!project(c, o[0], o[1], o[2], u, v)) return miss(0);
  if (!onScreen(u, v)) return miss(1);
  const int px = texel(u), py = texel(v);
  const float dv = depthAt(c.depth, kW, px, py);
  if (dv == 0.0f) return miss(1);
  float B[3], cu, cv;
  centrePoint(c, px, py, kInvW, viewZ(c, dv), cu, cv, B);
  const float tx = B[0] - o[0], ty = B[1] - o[1], tz = B[2] - o[2];
  const float s = std::sqrt(tx * tx + ty * ty + tz * tz) / std::sqrt(len2);
  const float x = o[0] + s * d[0], y = o[1] + s * d[1], z = o[2] + s * d[2];
  if (!project(c, x, y, z, u, v) || !onScreen(u, v)) return miss(1);
  return Hit{x, y, z, u, v, 1, 1};
}

// ---------------------------------------------------------------------------
// snellIntersectPlaneNormal(origin, dir, depthTex, normalTex, surface, 0.0f, N)
// (plane_normal.glsl, plane_refine.glsl snellPlaneHit, hit_on_surface.glsl,
// optics/ray_plane.glsl). Simplifications: A1-A6; the normal texture is sampled
// (Linear, level 0) at a texel centre, where the bilinear weights are exactly
// 1, 0, 0, 0: one texel read, 1 t00 + 0 t10 + 0 t01 + 0 t11 == t00 (A6; a
// normal component that is exactly 0 may differ in the sign of its zero, which
// reaches no output bit: it only meets dot products whose other terms are not
// all zero); SNELL_PLANE_FACING_FALLBACK 1,
// SNELL_PLANE_HOLD 1 on a closed surface; the last P's projection is computed
// once (snellPlaneHit projects it twice); a P that does not project ends the
// call as the miss snellPlaneHit would return.
template <int N>
inline Hit planeNormal(const Camera& c, const float* o, const float* d) {
  const float len2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const float eps = 1e-6f * std::sqrt(len2);
  float u, v;
  if (!project(c, o[0], o[1], o[2], u, v)) return miss(0);
  int fetches = 0;
  float pu = u, pv = v;  // planeUv
  float p[3] = {o[0], o[1], o[2]};
  bool projected = true;   // (u, v) is the projection of p
  for (int k = 0; k <= N; ++k) {
    if (k > 0) {
      if (!project(c, p[0], p[1], p[2], u, v)) return miss(fetches);
      projected = true;
    }
    fetches += 1;
    int px = 0, py = 0;
    float dv = 0.0f;
    if (onScreen(u, v)) px = texel(u), py = texel(v), dv = depthAt(c.depth, kW, px, py);
    if (dv == 0.0f) {  // empty, or off screen
      if (k == 0) return miss(fetches);
      break;
    }
    float B[3], cu, cv;
    centrePoint(c, px, py, kInvW, viewZ(c, dv), cu, cv, B);
    const float* n = c.normal + 4 * (py * kW + px);
    fetches += 1;
    float q[3];
    if (!rayPlane(o, d, eps, B, n, q) && !rayPlane(o, d, eps, B, B, q)) {
      if (k == 0) return miss(fetches);
      break;
    }
    p[0] = q[0], p[1] = q[1], p[2] = q[2];
    pu = cu, pv = cv;
    projected = false;
  }
  if (!projected && !project(c, p[0], p[1], p[2], u, v)) return miss(fetches);
  fetches += 1;
  if (!onScreen(u, v)) return miss(fetches);
  if (depthAt(c.depth, kW, texel(u), texel(v)) != 0.0f) return Hit{p[0], p[1], p[2], u, v, 1, fetches};
  return Hit{p[0], p[1], p[2], pu, pv, 1, fetches};  // SNELL_PLANE_HOLD: stays on the last plane
}

// ---------------------------------------------------------------------------
// snellConservativeBinarySearch(origin, dir, depthTex, surface, zNearest, zFarthest, S)
// (conservative_binary_search.glsl, search_segment.glsl, camera/tex_ray.glsl).
// Simplifications: A1, A3-A5; S fixed at compile time (dBeta = 0.5^i exact
// either way); S's and E's clip w are -zStart, -zFarthest, >= FLT_MIN by the
// segment tests, so their projections cannot fail; k2 != 0 since zStart > zFarthest.
template <int S>
inline Hit cbs(const Camera& c, const float* o, const float* d, float zNearest, float zFarthest) {
  if (!(d[2] <= -kFltMin) || !(zNearest > zFarthest) || !(o[2] > zFarthest)) return miss(0);
  const float zS = o[2] < zNearest ? o[2] : zNearest;
  if (!(zS <= -kFltMin) || !(zFarthest <= -kFltMin)) return miss(0);
  const float ls = (zS - o[2]) / d[2];
  const float le = (zFarthest - o[2]) / d[2];
  const float sx = o[0] + ls * d[0], sy = o[1] + ls * d[1];
  const float ex = o[0] + le * d[0], ey = o[1] + le * d[1];
  const float tsx = c.a * sx / -zS * 0.5f + 0.5f, tsy = c.b * sy / -zS * 0.5f + 0.5f;
  const float tex = c.a * ex / -zFarthest * 0.5f + 0.5f, tey = c.b * ey / -zFarthest * 0.5f + 0.5f;
  const float dtx = tex - tsx, dty = tey - tsy;
  const float k1 = 1.0f / zS;
  const float k2 = (zS * zFarthest) / (zS - zFarthest);
  const float kk = k1 * k2;
  const float dz = zFarthest - zS;
  float beta = 0.0f, dBeta = 1.0f, zHit = zS, uh = tsx, vh = tsy;
  bool advanced = false;
  for (int i = 0; i < S; ++i) {
    dBeta = dBeta * 0.5f;
    const float b = beta + dBeta;
    const float z = zS + b * dz;
    const float alpha = ((zS - z) / z) * kk;
    const float u = tsx + alpha * dtx, v = tsy + alpha * dty;
    float vz;
    if (sample(c, u, v, vz) && z > vz) {
      beta = b;
      zHit = z;
      uh = u;
      vh = v;
      advanced = true;
    }
  }
  int fetches = S;
  if (!advanced) {
    fetches += 1;
    float vz;
    if (!sample(c, uh, vh, vz)) return miss(fetches);
  }
  return Hit{sx + beta * (ex - sx), sy + beta * (ey - sy), zHit, uh, vh, 1, fetches};
}

// ---------------------------------------------------------------------------
// snellIntersectPlaneDepth(origin, dir, depthMips, surface, maxLod, N) on the depth
// min/max pyramid (plane_depth.glsl snellDepthPlaneAt, plane_refine.glsl,
// hit_on_surface.glsl, optics/ray_plane.glsl). Simplifications: A1-A6 (the
// pyramid's .x, level l of size kW >> l); the levels read are at most
// SNELL_PLANE_DEPTH_MAX_SPAN_LOD = 6, so every level is at least 4 texels wide
// and 2 u - 1 is never 0 at a texel centre (A5); a texel-centre uv
// (i + 0.5) / size is on screen exactly when 0 <= i < size and maps back to
// texel i; snellUvToPixel of a finite uv is the clamp of its truncation (equal
// to the clamp of its floor); the level is chosen with the same
// ceil(log2(span)) (std::log2f, std::ceil: a bit trick could round differently).
#define KERN_HAS_PLANE_DEPTH 1
constexpr int kPlaneDepthMaxSpanLod = 6;
static_assert((kW >> kPlaneDepthMaxSpanLod) >= 2, "levels read must be at least 2 texels wide (A5)");

// snellSurfacePoint(depthMips, snellPixelToUv((px, py), size), level)
inline bool levelPoint(const Camera& c, int level, int px, int py, float p[3]) {
  const int size = kW >> level;
  if (px < 0 || py < 0 || px >= size || py >= size) return false;
  const float dv = depthAt(c.pyramid[level], size, px, py);
  if (dv == 0.0f) return false;
  float cu, cv;
  centrePoint(c, px, py, 1.0f / static_cast<float>(size), viewZ(c, dv), cu, cv, p);
  return true;
}

struct DepthPlane {
  float u, v;  // where B0 was read (its texel centre)
  float b[3];  // B
  float n[3];  // cross(C - B, D - B)
  bool hasB, valid;
  int fetches;
};

inline int pixelOf(float u, int size) {  // snellUvToPixel, one component (A1)
  const int i = static_cast<int>(u * static_cast<float>(size));
  return i < 0 ? 0 : (i > size - 1 ? size - 1 : i);
}

inline DepthPlane depthPlaneAt(const Camera& c, const float* q, const float* dirN, int maxLod) {
  DepthPlane r;
  r.hasB = r.valid = false;
  r.fetches = 0;
  float su, sv;
  if (!project(c, q[0], q[1], q[2], su, sv)) return r;
  r.fetches = 1;
  if (!onScreen(su, sv)) return r;
  const int px0 = texel(su), py0 = texel(sv);
  const float d0 = depthAt(c.pyramid[0], kW, px0, py0);
  if (d0 == 0.0f) return r;
  float B0[3];
  centrePoint(c, px0, py0, kInvW, viewZ(c, d0), r.u, r.v, B0);
  const float tx = B0[0] - q[0], ty = B0[1] - q[1], tz = B0[2] - q[2];
  const float dist = std::sqrt(tx * tx + ty * ty + tz * tz);
  float q2[3];
  if (q[2] < B0[2]) {
    q2[0] = q[0] - dist * dirN[0], q2[1] = q[1] - dist * dirN[1], q2[2] = q[2] - dist * dirN[2];
  } else {
    q2[0] = q[0] + dist * dirN[0], q2[1] = q[1] + dist * dirN[1], q2[2] = q[2] + dist * dirN[2];
  }
  float u2, v2;
  if (!project(c, q2[0], q2[1], q2[2], u2, v2)) u2 = su, v2 = sv;
  const float sx = std::fabs(u2 - su) * static_cast<float>(kW), sy = std::fabs(v2 - sv) * static_cast<float>(kW);
  const float span = sx < sy ? sy : sx;
  const int top = maxLod < kPlaneDepthMaxSpanLod ? maxLod : kPlaneDepthMaxSpanLod;
  int level = 0;
  if (span > 1.0f) level = static_cast<int>(std::ceil(std::log2(span)));
  level = level < top ? level : top;
  level = level > 0 ? level : 0;
  const int size = kW >> level;
  const int pbx = pixelOf(su, size), pby = pixelOf(sv, size);
  int pcx = pixelOf(u2, size), pcy = pixelOf(v2, size);
  int ax = 1, ay = 0;
  const int dx = pcx - pbx, dy = pcy - pby;
  if ((dy < 0 ? -dy : dy) > (dx < 0 ? -dx : dx)) {
    ax = 0, ay = dy > 0 ? 1 : -1;
  } else if (dx != 0) {
    ax = dx > 0 ? 1 : -1;
  }
  if (dx == 0 && dy == 0) pcx = pbx + ax, pcy = pby + ay;
  const int bx = ax != 0 ? 0 : 1, by = ax != 0 ? 1 : 0;
  if (level != 0) {
    r.fetches += 1;
    if (!levelPoint(c, level, pbx, pby, r.b)) return r;
  } else {
    r.b[0] = B0[0], r.b[1] = B0[1], r.b[2] = B0[2];
  }
  r.hasB = true;
  float C[3], D[3];
  r.fetches += 1;
  if (!levelPoint(c, level, pcx, pcy, C)) {
    r.fetches += 1;
    if (!levelPoint(c, level, pbx - ax, pby - ay, C)) return r;
  }
  r.fetches += 1;
  if (!levelPoint(c, level, pbx + bx, pby + by, D)) {
    r.fetches += 1;
    if (!levelPoint(c, level, pbx - bx, pby - by, D)) return r;
  }
  const float x0 = C[0] - r.b[0], x1 = C[1] - r.b[1], x2 = C[2] - r.b[2];
  const float y0 = D[0] - r.b[0], y1 = D[1] - r.b[1], y2 = D[2] - r.b[2];
  r.n[0] = x1 * y2 - y1 * x2;  // glm::cross
  r.n[1] = x2 * y0 - y2 * x0;
  r.n[2] = x0 * y1 - y0 * x1;
  r.valid = true;
  return r;
}

template <int N>
inline Hit planeDepth(const Camera& c, const float* o, const float* d, int maxLod) {
  const float len2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  float u, v;
  if (!project(c, o[0], o[1], o[2], u, v)) return miss(0);
  const float len = std::sqrt(len2);
  const float dirN[3] = {d[0] / len, d[1] / len, d[2] / len};
  const float eps = 1e-6f * len;
  int fetches = 0;
  float p[3] = {o[0], o[1], o[2]};
  float pu = u, pv = v;
  for (int k = 0; k <= N; ++k) {
    const DepthPlane pl = depthPlaneAt(c, p, dirN, maxLod);
    fetches += pl.fetches;
    float q[3];
    // snellRayPlane's degenerate-normal test stays: three texels can give a tiny normal
    bool ok = pl.valid && pl.n[0] * pl.n[0] + pl.n[1] * pl.n[1] + pl.n[2] * pl.n[2] > 1e-30f &&
              rayPlane(o, d, eps, pl.b, pl.n, q);
    if (!ok && pl.hasB) ok = rayPlane(o, d, eps, pl.b, pl.b, q);
    if (!ok) {
      if (k == 0) return miss(fetches);
      break;
    }
    p[0] = q[0], p[1] = q[1], p[2] = q[2];
    pu = pl.u, pv = pl.v;
  }
  if (!project(c, p[0], p[1], p[2], u, v)) return miss(fetches);
  fetches += 1;
  if (!onScreen(u, v)) return miss(fetches);
  if (depthAt(c.pyramid[0], kW, texel(u), texel(v)) != 0.0f) return Hit{p[0], p[1], p[2], u, v, 1, fetches};
  return Hit{p[0], p[1], p[2], pu, pv, 1, fetches};  // SNELL_PLANE_HOLD
}

// ---------------------------------------------------------------------------
// snellLinearMarch(origin, dir, depthTex, surface, maxDistance, STEPS, REFINE)
// (linear_march.glsl). Simplifications: A1-A4; maxDistance > 0; step counts
// fixed at compile time.
template <int STEPS, int REFINE>
inline Hit linearMarch(const Camera& c, const float* o, const float* d, float maxDistance) {
  const float len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  float tMax = maxDistance / len;
  if (d[2] > 0.0f) {
    const float tNear = (-c.zNear - o[2]) / d[2];
    tMax = tNear < tMax ? tNear : tMax;
  }
  if (!(tMax > 0.0f)) return miss(0);
  const float dt = tMax / static_cast<float>(STEPS);
  int fetches = 0;
  float tHit = 0.0f, uh = 0.0f, vh = 0.0f;
  bool found = false;
  for (int i = 1; i <= STEPS; ++i) {
    const float t = static_cast<float>(i) * dt;
    const float z = o[2] + t * d[2];
    float u, v, vz;
    if (!project(c, o[0] + t * d[0], o[1] + t * d[1], z, u, v) || !onScreen(u, v)) return miss(fetches);
    fetches += 1;
    if (sampleOnScreen(c, u, v, vz) && z <= vz) {
      found = true;
      tHit = t;
      uh = u;
      vh = v;
      break;
    }
  }
  if (!found) return miss(fetches);
  float lo = tHit - dt;
  for (int j = 0; j < REFINE; ++j) {
    const float mid = 0.5f * (lo + tHit);
    const float z = o[2] + mid * d[2];
    float u, v, vz;
    bool crosses = false;
    if (project(c, o[0] + mid * d[0], o[1] + mid * d[1], z, u, v) && onScreen(u, v)) {
      fetches += 1;
      crosses = sampleOnScreen(c, u, v, vz) && z <= vz;
    }
    if (crosses) {
      tHit = mid;
      uh = u;
      vh = v;
    } else {
      lo = mid;
    }
  }
  return Hit{o[0] + tHit * d[0], o[1] + tHit * d[1], o[2] + tHit * d[2], uh, vh, 1, fetches};
}

// ---------------------------------------------------------------------------
// snellDdaMarch(origin, dir, depthTex, surface, maxDistance, SNELL_DDA_THICKNESS,
// stride, steps) (dda_march.glsl). Simplifications: A1-A4; thickness infinite
// (SNELL_DDA_THICKNESS = FLT_MAX: zNearRay >= viewZ - FLT_MAX always holds for
// finite values, the test is left out); 1 <= stride; 0 < maxDistance < 1e30;
// h0.w = -origin.z >= zNear by the origin test; h.w <= 1/FLT_MIN (A1).
inline Hit ddaMarch(const Camera& c, const float* o, const float* d, float maxDistance, float stride, int steps) {
  const float len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (!(o[2] <= -c.zNear)) return miss(0);
  float tMax = maxDistance / len;
  if (d[2] > 0.0f) {
    const float tNear = (-c.zNear - o[2]) / d[2];
    tMax = tNear < tMax ? tNear : tMax;
  }
  if (!(tMax > 0.0f)) return miss(0);
  const float e0 = o[0] + tMax * d[0], e1 = o[1] + tMax * d[1], e2 = o[2] + tMax * d[2];
  const float h0w = -o[2], h1w = -e2;
  if (!(h1w >= kFltMin)) return miss(0);
  const float k0 = 1.0f / h0w, k1 = 1.0f / h1w;
  const float q00 = o[0] * k0, q01 = o[1] * k0, q02 = o[2] * k0;
  const float q10 = e0 * k1, q11 = e1 * k1, q12 = e2 * k1;
  const float uv0x = c.a * o[0] * k0 * 0.5f + 0.5f, uv0y = c.b * o[1] * k0 * 0.5f + 0.5f;
  const float dux = c.a * e0 * k1 * 0.5f + 0.5f - uv0x, duy = c.b * e1 * k1 * 0.5f + 0.5f - uv0y;
  const float mx = std::fabs(dux * static_cast<float>(kW)), my = std::fabs(duy * static_cast<float>(kW));
  const float major = mx < my ? my : mx;
  const float ds = major > stride ? stride / major : 1.0f;
  int fetches = 0;
  float sA = 0.0f, zA = o[2];
  for (int i = 0; i < steps; ++i) {
    if (sA >= 1.0f) break;
    const float sc0 = static_cast<float>(i) * ds;
    const float sC = 1.0f < sc0 ? 1.0f : sc0;
    const float sb0 = (static_cast<float>(i) + 0.5f) * ds;
    const float sB = 1.0f < sb0 ? 1.0f : sb0;
    const float zB = (q02 * (1.0f - sB) + q12 * sB) / (k0 * (1.0f - sB) + k1 * sB);
    const float u = uv0x + sC * dux, v = uv0y + sC * duy;
    if (!onScreen(u, v)) return miss(fetches);
    fetches += 1;
    const float zNearRay = zA < zB ? zB : zA;
    const float zFarRay = zB < zA ? zB : zA;
    float vz;
    if (sampleOnScreen(c, u, v, vz) && zFarRay <= vz) {
      const float m = vz < zFarRay ? zFarRay : vz;
      const float zHit = zNearRay < m ? zNearRay : m;
      const float wA = k0 * (1.0f - sA) + k1 * sA, wB = k0 * (1.0f - sB) + k1 * sB;
      const float a0 = (q00 * (1.0f - sA) + q10 * sA) / wA, a1 = (q01 * (1.0f - sA) + q11 * sA) / wA,
                  a2 = (q02 * (1.0f - sA) + q12 * sA) / wA;
      const float b0 = (q00 * (1.0f - sB) + q10 * sB) / wB, b1 = (q01 * (1.0f - sB) + q11 * sB) / wB,
                  b2 = (q02 * (1.0f - sB) + q12 * sB) / wB;
      float f = 0.5f;
      if (b2 != a2) {
        const float f0 = (zHit - a2) / (b2 - a2);
        const float f1 = f0 < 0.0f ? 0.0f : f0;
        f = 1.0f < f1 ? 1.0f : f1;
      }
      return Hit{a0 + f * (b0 - a0), a1 + f * (b1 - a1), a2 + f * (b2 - a2), u, v, 1, fetches};
    }
    sA = sB;
    zA = zB;
  }
  return miss(fetches);
}

}  // namespace kern
#endif  // KERNELS_HPP
