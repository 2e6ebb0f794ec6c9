/* The hand-written kernels of benchmarks/kernels/kernels.hpp in GLSL: single
   sample, the normal-based plane, CBS and the linear march for
   exactly the kernel study's setup, under the same assumptions A1-A6 listed
   there (finite inputs, a glm::perspective matrix, GL depth, level 0, nearest
   reads at texel centres, RGBA32F textures); and the whole two-interface
   technique (kTwoInterface, below) for the study's shading setup.
   gpu_kernel_study.cpp runs them beside snell's own functions on the same
   rays and buffers on Mesa and reports how far snell's shader is from them,
   and how far the plane is from single sample when both are written by hand. */
layout(binding = 0) uniform sampler2D kDepth;   // .x GL window depth, 0 = empty
layout(binding = 1) uniform sampler2D kNormal;  // .xyz view-space normal
layout(binding = 2) uniform sampler2D kPyramid; // the depth min/max pyramid of kDepth
uniform vec4 kCam;          // m00, m11, m00 m11, zNear
uniform float kNearOverFar; // zNear / zFar, as snellLinearizeDepth computes it

struct KHit {
  vec3 position;
  vec2 uv;
  bool valid;
  int fetches;
  float depth;  // kPlaneNormalOn: the depth texel its last lookup read at uv (the foreground rule reuses it)
};

KHit kMiss(int fetches) {
  KHit h;
  h.position = vec3(0.0);
  h.uv = vec2(0.0);
  h.valid = false;
  h.fetches = fetches;
  h.depth = 0.0;
  return h;
}

bool kProject(vec3 p, out vec2 uv) {
  float w = -p.z;
  uv = vec2(0.0);
  if (!(w >= 1.175494351e-38)) return false;
  uv = vec2(kCam.x * p.x / w * 0.5 + 0.5, kCam.y * p.y / w * 0.5 + 0.5);
  return true;
}

bool kOnScreen(vec2 uv) {
  return uv.x >= 0.0 && uv.x <= 1.0 && uv.y >= 0.0 && uv.y <= 1.0;
}

ivec2 kTexel(vec2 uv, int size) {
  return min(ivec2(uv * float(size)), ivec2(size - 1));
}

float kViewZ(float d) {
  return -(kCam.w / ((1.0 - d) + d * kNearOverFar));
}

// snellUvZToView at the centre of texel px (A3, A5).
vec3 kCentrePoint(ivec2 px, int size, float vz, out vec2 centre) {
  centre = (vec2(px) + 0.5) / float(size);
  vec2 n = 2.0 * centre - 1.0;
  return vec3(-(vz * n.x) * kCam.y / kCam.z, kCam.x * -(vz * n.y) / kCam.z, vz);
}

bool kRayPlane(vec3 o, vec3 d, float eps, vec3 b, vec3 nRaw, out vec3 p, out float t) {
  vec3 n = nRaw * (1.0 / sqrt(dot(nRaw, nRaw)));
  float denom = dot(d, n);
  p = vec3(0.0);
  t = 0.0;
  if (!(abs(denom) > eps)) return false;
  t = dot(b - o, n) / denom;
  if (!(t >= 0.0)) return false;
  p = o + t * d;
  return true;
}

KHit kSingleSample(vec3 o, vec3 d) {
  int size = textureSize(kDepth, 0).x;
  vec2 uv;
  if (!kProject(o, uv)) return kMiss(0);
  if (!kOnScreen(uv)) return kMiss(1);
  ivec2 px = kTexel(uv, size);
  float dv = texelFetch(kDepth, px, 0).x;
  if (dv == 0.0) return kMiss(1);
  vec2 centre;
  vec3 b = kCentrePoint(px, size, kViewZ(dv), centre);
  vec3 p = o + (length(b - o) / length(d)) * d;
  if (!kProject(p, uv) || !kOnScreen(uv)) return kMiss(1);
  KHit h;
  h.position = p;
  h.uv = uv;
  h.valid = true;
  h.fetches = 1;
  return h;
}

/* snellPlaneFarStart on kPyramid (the back buffer's, a closed surface): the
   plane facing the camera at the farthest distance of the pyramid texel
   halfway along the way from W to where the ray meets the whole buffer's
   farthest plane, its level the first whose texels cover that way. */
uniform int kPyramidTop;  // the pyramid's top level (its 1x1 texel)

bool kFarStart(vec3 o, vec3 d, float eps, vec2 wUv, int size, out vec3 q, out float t, inout int fetches) {
  vec4 whole = texelFetch(kPyramid, ivec2(0), kPyramidTop);
  fetches += 1;
  q = vec3(0.0);
  t = 0.0;
  if (!(whole.w > 0.0)) return false;
  vec3 g;
  float tg;
  vec2 gUv;
  if (!kRayPlane(o, d, eps, vec3(0.0, 0.0, -whole.z), vec3(0.0, 0.0, 1.0), g, tg) || !kProject(g, gUv)) return false;
  vec2 way = (gUv - wUv) * float(size);
  float dist = sqrt(dot(way, way));
  int level = 0;
  while (level < kPyramidTop && float(1 << level) < dist) level += 1;
  vec2 mid = clamp(0.5 * (gUv + wUv), vec2(0.0), vec2(1.0));
  int sizeL = size >> level;
  vec4 under = texelFetch(kPyramid, min(ivec2(mid * float(sizeL)), ivec2(sizeL - 1)), level);
  fetches += 1;
  if (!(under.w > 0.0)) return false;
  return kRayPlane(o, d, eps, vec3(0.0, 0.0, -under.z), vec3(0.0, 0.0, 1.0), q, t);
}

/* planeNormal<N> of kernels.hpp: the facing fallback and the hold of snell's
   defaults, the normal read as one texel at the texel centre (A6); on any
   depth and normal buffers of the same size and camera (emptyDepth: their
   clear value; closed: the hold applies, else a plane hit over an empty
   texel is a miss), the far start on kPyramid when asked. */
KHit kPlaneNormalOn(sampler2D depthTex, sampler2D normalTex, float emptyDepth, bool closed, bool farStart,
                    vec3 o, vec3 d, int iterations) {
  int size = textureSize(depthTex, 0).x;
  float eps = 1e-6 * length(d);
  vec2 uv;
  if (!kProject(o, uv)) return kMiss(0);
  int fetches = 0;
  vec2 planeUv = uv;
  vec3 p = o;
  bool projected = true;
  for (int k = 0; k <= iterations; ++k) {
    if (k > 0) {
      if (!kProject(p, uv)) return kMiss(fetches);
      projected = true;
    }
    fetches += 1;
    ivec2 px = ivec2(0);
    float dv = emptyDepth;
    if (kOnScreen(uv)) {
      px = kTexel(uv, size);
      dv = texelFetch(depthTex, px, 0).x;
    }
    if (dv == emptyDepth) {
      if (k == 0) return kMiss(fetches);
      break;
    }
    vec2 centre;
    vec3 b = kCentrePoint(px, size, kViewZ(dv), centre);
    vec3 n = texelFetch(normalTex, px, 0).xyz;
    fetches += 1;
    vec3 q;
    float t;
    bool hit = kRayPlane(o, d, eps, b, n, q, t);
    if (k == 0 && farStart) {
      vec3 fq;
      float ft;
      if (kFarStart(o, d, eps, uv, size, fq, ft, fetches) && (!hit || ft < t)) {
        q = fq;
        hit = true;
      }
    }
    if (!hit && !kRayPlane(o, d, eps, b, b, q, t)) {
      if (k == 0) return kMiss(fetches);
      break;
    }
    p = q;
    planeUv = centre;
    projected = false;
  }
  if (!projected && !kProject(p, uv)) return kMiss(fetches);
  fetches += 1;
  if (!kOnScreen(uv)) return kMiss(fetches);
  float last = texelFetch(depthTex, kTexel(uv, size), 0).x;
  bool onSurface = last != emptyDepth;
  if (!onSurface && !closed) return kMiss(fetches);
  KHit h;
  h.position = p;
  h.uv = onSurface ? uv : planeUv;
  h.valid = true;
  h.fetches = fetches;
  h.depth = last;
  return h;
}

KHit kPlaneNormal(vec3 o, vec3 d, int iterations) {
  return kPlaneNormalOn(kDepth, kNormal, 0.0, true, false, o, d, iterations);
}

// snellSampleSurface at any uv (A4): true and the view z when the texel holds a surface.
bool kSample(vec2 uv, out float vz) {
  vz = 0.0;
  if (!kOnScreen(uv)) return false;
  float dv = texelFetch(kDepth, kTexel(uv, textureSize(kDepth, 0).x), 0).x;
  if (dv == 0.0) return false;
  vz = kViewZ(dv);
  return true;
}

/* cbs<S> of kernels.hpp (snellConservativeBinarySearch): S steps, the segment
   from min(o.z, zNearest) to zFarthest, both projected by the perspective's
   two terms (A3). */
KHit kCbs(vec3 o, vec3 d, float zNearest, float zFarthest, int steps) {
  if (!(d.z <= -1.175494351e-38) || !(zNearest > zFarthest) || !(o.z > zFarthest)) return kMiss(0);
  float zS = o.z < zNearest ? o.z : zNearest;
  if (!(zS <= -1.175494351e-38) || !(zFarthest <= -1.175494351e-38)) return kMiss(0);
  float ls = (zS - o.z) / d.z;
  float le = (zFarthest - o.z) / d.z;
  vec2 s = vec2(o.x + ls * d.x, o.y + ls * d.y);
  vec2 e = vec2(o.x + le * d.x, o.y + le * d.y);
  vec2 ts = vec2(kCam.x * s.x / -zS * 0.5 + 0.5, kCam.y * s.y / -zS * 0.5 + 0.5);
  vec2 te = vec2(kCam.x * e.x / -zFarthest * 0.5 + 0.5, kCam.y * e.y / -zFarthest * 0.5 + 0.5);
  vec2 dt = te - ts;
  float kk = (1.0 / zS) * ((zS * zFarthest) / (zS - zFarthest));
  float dz = zFarthest - zS;
  float beta = 0.0, dBeta = 1.0, zHit = zS;
  vec2 uvHit = ts;
  bool advanced = false;
  for (int i = 0; i < steps; ++i) {
    dBeta = dBeta * 0.5;
    float b = beta + dBeta;
    float z = zS + b * dz;
    float alpha = ((zS - z) / z) * kk;
    vec2 uv = ts + alpha * dt;
    float vz;
    if (kSample(uv, vz) && z > vz) {
      beta = b;
      zHit = z;
      uvHit = uv;
      advanced = true;
    }
  }
  int fetches = steps;
  if (!advanced) {
    fetches += 1;
    float vz;
    if (!kSample(uvHit, vz)) return kMiss(fetches);
  }
  KHit h;
  h.position = vec3(s.x + beta * (e.x - s.x), s.y + beta * (e.y - s.y), zHit);
  h.uv = uvHit;
  h.valid = true;
  h.fetches = fetches;
  return h;
}

/* linearMarch<STEPS, REFINE> of kernels.hpp (snellLinearMarch): maxDistance > 0,
   the steps and refinements fixed by the caller. */
KHit kLinearMarch(vec3 o, vec3 d, float maxDistance, int steps, int refine) {
  float tMax = maxDistance / length(d);
  if (d.z > 0.0) tMax = min(tMax, (-kCam.w - o.z) / d.z);
  if (!(tMax > 0.0)) return kMiss(0);
  float dt = tMax / float(steps);
  int fetches = 0;
  float tHit = 0.0;
  vec2 uvHit = vec2(0.0);
  bool found = false;
  for (int i = 1; i <= steps; ++i) {
    float t = float(i) * dt;
    vec3 p = o + t * d;
    vec2 uv;
    if (!kProject(p, uv) || !kOnScreen(uv)) return kMiss(fetches);
    fetches += 1;
    float vz;
    if (kSample(uv, vz) && p.z <= vz) {
      found = true;
      tHit = t;
      uvHit = uv;
      break;
    }
  }
  if (!found) return kMiss(fetches);
  float lo = tHit - dt;
  for (int j = 0; j < refine; ++j) {
    float mid = 0.5 * (lo + tHit);
    vec3 q = o + mid * d;
    vec2 uv;
    bool crosses = false;
    if (kProject(q, uv) && kOnScreen(uv)) {
      fetches += 1;
      float vz;
      crosses = kSample(uv, vz) && q.z <= vz;
    }
    if (crosses) {
      tHit = mid;
      uvHit = uv;
    } else {
      lo = mid;
    }
  }
  KHit h;
  h.position = o + tHit * d;
  h.uv = uvHit;
  h.valid = true;
  h.fetches = fetches;
  return h;
}

/* The whole two-interface technique of the study's shading setup
   (snellTwoInterfaceRefraction with snellPresetPlaneNormal(2), the exit slot
   on the opaque scene's buffers, the environment as its fallback and as the
   reflect slot, Beer-Lambert absorption, Fresnel reflection; glass of
   ior 1.5 in air, one trace, roughness 0, the identity environment basis).
   Assumed beyond A1-A6: a front-face fragment with a finite non-zero normal
   (the entry cannot reflect totally: eta < 1), non-zero normals wherever
   the back hit reads them, a scene that is an open surface cleared to 1. */
layout(binding = 7) uniform sampler2D kSceneDepth;   // .x GL window depth, 1 = empty
layout(binding = 8) uniform sampler2D kSceneNormal;
layout(binding = 9) uniform sampler2D kSceneColor;
layout(binding = 10) uniform sampler2D kEnvironment;  // equirectangular
uniform vec3 kAbsorption;
// eta = 1 / 1.5: a uniform where the path refracts, the constant in the Fresnel
// term. That is how Mesa compiles snell's code (its per-channel loop keeps the
// trace's eta from folding; the Fresnel term's folds), and folding changes the
// last bits of near-grazing exits.
uniform float kEta;

struct KShade {
  vec3 color;
  float pathLength;
  float fresnel;
  int fetches;
  bool backHit;
  bool fellBack;
};

// snellRefract, the critical-angle policy.
vec3 kRefract(vec3 incident, vec3 normal, float eta) {
  vec3 i = incident * inversesqrt(dot(incident, incident));
  vec3 n = normal * inversesqrt(dot(normal, normal));
  float cosI = -dot(n, i);
  if (cosI < 0.0) {
    n = -n;
    cosI = -cosI;
  }
  cosI = min(cosI, 1.0);
  float eta2 = eta * eta;
  float cos2T = (1.0 - eta2) + eta2 * (cosI * cosI);
  vec3 r = cos2T < 0.0 ? i + cosI * n : eta * i + (eta * cosI - sqrt(cos2T)) * n;
  return r * inversesqrt(dot(r, r));
}

// snellAtan2 (Hastings) for finite, not both zero arguments.
float kAtan2(float y, float x) {
  float ax = abs(x), ay = abs(y);
  float a = min(ax, ay) / max(ax, ay);
  float s = a * a;
  float r = a * (0.9998660 + s * (-0.3302995 + s * (0.1801410 + s * (-0.0851330 + s * 0.0208351))));
  if (ay > ax) r = 1.57079632679 - r;
  if (x < 0.0) r = 3.14159265359 - r;
  if (y < 0.0) r = -r;
  return r;
}

// The environment along a non-zero direction (normalized first, as the exit does).
vec3 kEnvironmentAlong(vec3 dir) {
  vec3 w = dir * inversesqrt(dot(dir, dir));
  float horizontal = sqrt(w.x * w.x + w.z * w.z);
  vec2 uv = vec2(0.5 + kAtan2(w.x, -w.z) * (0.5 / 3.14159265358979), 0.5 + kAtan2(w.y, horizontal) * (1.0 / 3.14159265358979));
  return textureLod(kEnvironment, uv, 0.0).xyz;
}

KShade kTwoInterface(vec3 p1, vec3 n1) {
  KShade r;
  vec3 t1 = kRefract(p1, n1, kEta);
  KHit back = kPlaneNormalOn(kDepth, kNormal, 0.0, true, true, p1, t1, 2);
  r.fetches = back.fetches;
  r.backHit = back.valid;
  r.pathLength = 0.0;
  vec3 exitPoint = p1;
  vec3 exitDirection = t1;
  if (back.valid) {
    r.pathLength = length(back.position - p1);
    exitPoint = back.position;
    vec3 n2 = textureLod(kNormal, back.uv, 0.0).xyz;
    n2 = n2 * inversesqrt(dot(n2, n2));
    r.fetches += 1;
    exitDirection = kRefract(t1, dot(n2, t1) > 0.0 ? -n2 : n2, 1.0 / kEta);
  }
  KHit scene = kPlaneNormalOn(kSceneDepth, kSceneNormal, 1.0, false, false, exitPoint, exitDirection, 2);
  // The foreground rule (snellRejectForeground, tolerance 0.01) on the texel the hit's last lookup read: on
  // an open scene a hit is on a surface, so no second read (snell counts one; so does the kernel).
  if (scene.valid) {
    scene.fetches += 1;
    if (-kViewZ(scene.depth) < min(-exitPoint.z, -scene.position.z) * (1.0 - 0.01)) scene = kMiss(scene.fetches);
  }
  r.fetches += scene.fetches + 1;
  r.fellBack = !back.valid || !scene.valid;
  vec3 exitColor = scene.valid ? textureLod(kSceneColor, scene.uv, 0.0).xyz : kEnvironmentAlong(exitDirection);
  vec3 transmitted = exitColor * exp(-min(kAbsorption * r.pathLength, vec3(1e30)));
  vec3 v = p1 * inversesqrt(dot(p1, p1));
  vec3 n = n1 * inversesqrt(dot(n1, n1));
  float c = min(abs(dot(v, n)), 1.0);
  const float e = 1.0 / 1.5;  // kEta, folded (above)
  float e2 = e * e;
  float cosT = sqrt((1.0 - e2) + e2 * (c * c));
  float rs = (e * c - cosT) / (e * c + cosT);
  float rp = (c - e * cosT) / (c + e * cosT);
  r.fresnel = 0.5 * (rs * rs + rp * rp);
  r.fetches += 1;
  r.color = r.fresnel * kEnvironmentAlong(reflect(v, n)) + (1.0 - r.fresnel) * transmitted;
  return r;
}
