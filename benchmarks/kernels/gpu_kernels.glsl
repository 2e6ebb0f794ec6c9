/* The hand-written kernels of benchmarks/kernels/kernels.hpp in GLSL: single
   sample, the normal-based plane, CBS and the linear march for
   exactly the kernel study's setup, under the same assumptions A1-A6 listed
   there (finite inputs, a glm::perspective matrix, GL depth, level 0, nearest
   reads at texel centres, RGBA32F textures). gpu_kernel_study.cpp runs them
   beside snell's own functions on the same rays and buffers on Mesa and
   reports how far snell's shader is from them, and how far the plane is from
   single sample when both are written by hand. */
layout(binding = 0) uniform sampler2D kDepth;   // .x GL window depth, 0 = empty
layout(binding = 1) uniform sampler2D kNormal;  // .xyz view-space normal
uniform vec4 kCam;          // m00, m11, m00 m11, zNear
uniform float kNearOverFar; // zNear / zFar, as snellLinearizeDepth computes it

struct KHit {
  vec3 position;
  vec2 uv;
  bool valid;
  int fetches;
};

KHit kMiss(int fetches) {
  KHit h;
  h.position = vec3(0.0);
  h.uv = vec2(0.0);
  h.valid = false;
  h.fetches = fetches;
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

bool kRayPlane(vec3 o, vec3 d, float eps, vec3 b, vec3 nRaw, out vec3 p) {
  vec3 n = nRaw * (1.0 / sqrt(dot(nRaw, nRaw)));
  float denom = dot(d, n);
  p = vec3(0.0);
  if (!(abs(denom) > eps)) return false;
  float t = dot(b - o, n) / denom;
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

/* planeNormal<N> of kernels.hpp: the facing fallback and the hold of snell's
   defaults, the normal read as one texel at the texel centre (A6). */
KHit kPlaneNormal(vec3 o, vec3 d, int iterations) {
  int size = textureSize(kDepth, 0).x;
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
    float dv = 0.0;
    if (kOnScreen(uv)) {
      px = kTexel(uv, size);
      dv = texelFetch(kDepth, px, 0).x;
    }
    if (dv == 0.0) {
      if (k == 0) return kMiss(fetches);
      break;
    }
    vec2 centre;
    vec3 b = kCentrePoint(px, size, kViewZ(dv), centre);
    vec3 n = texelFetch(kNormal, px, 0).xyz;
    fetches += 1;
    vec3 q;
    if (!kRayPlane(o, d, eps, b, n, q) && !kRayPlane(o, d, eps, b, b, q)) {
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
  KHit h;
  h.position = p;
  h.uv = texelFetch(kDepth, kTexel(uv, size), 0).x != 0.0 ? uv : planeUv;
  h.valid = true;
  h.fetches = fetches;
  return h;
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
