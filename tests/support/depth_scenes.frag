#version 450 core
// GPU twin of tests/support/depth_scenes.hpp: evaluates the same analytic
// surface per pixel (in float) and writes its window depth (gl_FragDepth) and
// view-space normal (colour 0, w = 1). Empty pixels are discarded, so they keep
// the depth buffer's clear value (the scene's emptyDepth). Drawn as one
// full-screen triangle with glDepthFunc(GL_ALWAYS).
uniform int sceneKind;       // snell_test::SceneKind
uniform vec4 sceneParams[4]; // DepthScene::params
uniform vec2 tanHalf;        // tan of the half field of view, x and y
uniform vec2 viewport;       // width, height
uniform float zNear;
uniform float zFar;
uniform int convention;      // SNELL_DEPTH_* (0 GL, 1 ZERO_ONE, 2 REVERSED, 3 INFINITE_GL, 4 INFINITE_REVERSED)
layout(location = 0) out vec4 outNormal;

struct Sample { float s; vec3 n; bool valid; };

Sample miss() { Sample r; r.s = 0.0; r.n = vec3(0.0); r.valid = false; return r; }

Sample rayPlane(vec3 q, vec3 p, vec3 n) {
  Sample r = miss();
  float den = dot(q, n);
  if (den == 0.0) return r;
  float s = dot(p, n) / den;
  if (!(s > 0.0)) return r;
  r.s = s; r.n = normalize(n); if (r.n.z < 0.0) r.n = -r.n; r.valid = true;
  return r;
}

Sample sphereBack(vec3 q, vec3 c, float radius) {
  Sample r = miss();
  float a = dot(q, q), b = -2.0 * dot(q, c), cc = dot(c, c) - radius * radius;
  float disc = b * b - 4.0 * a * cc;
  if (!(disc >= 0.0)) return r;
  float s = (-b + sqrt(disc)) / (2.0 * a);
  if (!(s > 0.0)) return r;
  r.s = s; r.n = (s * q - c) / radius; r.valid = true;
  return r;
}

Sample rayBox(vec3 q, vec3 lo, vec3 hi) {
  Sample r = miss();
  float tNear = 0.0, tFar = 3.4e38;
  int axis = -1; float sgn = 0.0;
  for (int k = 0; k < 3; ++k) {
    if (q[k] == 0.0) { if (0.0 < lo[k] || 0.0 > hi[k]) return r; continue; }
    float t0 = lo[k] / q[k], t1 = hi[k] / q[k], es = -1.0;
    if (t0 > t1) { float t = t0; t0 = t1; t1 = t; es = 1.0; }
    if (t0 > tNear) { tNear = t0; axis = k; sgn = es; }
    tFar = min(tFar, t1);
  }
  if (axis < 0 || tNear > tFar) return r;
  r.s = tNear; r.n = vec3(0.0); r.n[axis] = sgn; r.valid = true;
  return r;
}

Sample scene(vec3 q) {
  vec4 p0 = sceneParams[0], p1 = sceneParams[1], p2 = sceneParams[2], p3 = sceneParams[3];
  if (sceneKind == 0) return rayPlane(q, p0.xyz, p1.xyz);
  if (sceneKind == 1) return sphereBack(q, p0.xyz, p0.w);
  if (sceneKind == 2) {
    float s = -p2.x;
    if (s * q.x <= p2.y) { Sample a; a.s = s; a.n = vec3(0.0, 0.0, 1.0); a.valid = true; return a; }
    return rayPlane(q, p0.xyz, p1.xyz);
  }
  if (sceneKind == 3) {
    Sample a = rayPlane(q, p0.xyz, p1.xyz);
    if (a.valid) { float rr = length(a.s * q - p0.xyz); if (rr < p0.w || rr > p1.w) a.valid = false; }
    return a;
  }
  Sample bg = rayPlane(q, p0.xyz, p1.xyz);
  Sample box = rayBox(q, p2.xyz, p3.xyz);
  if (box.valid && (!bg.valid || box.s < bg.s)) return box;
  return bg;
}

float windowDepth(float v) {
  float n = zNear, f = zFar;
  if (convention == 0 || convention == 1) return f * (v - n) / (v * (f - n));
  if (convention == 2) return n * (f - v) / (v * (f - n));
  if (convention == 3) return 1.0 - n / v;
  return n / v;
}

void main() {
  vec2 uv = gl_FragCoord.xy / viewport;
  vec3 q = vec3((2.0 * uv.x - 1.0) * tanHalf.x, (2.0 * uv.y - 1.0) * tanHalf.y, -1.0);
  Sample a = scene(q);
  if (!a.valid || a.s < zNear || a.s > zFar) discard;
  gl_FragDepth = windowDepth(a.s);
  outNormal = vec4(a.n, 1.0);
}
