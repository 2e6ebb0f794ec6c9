#version 450 core
#extension GL_GOOGLE_include_directive : require
// compile.wgsl_names (tests/compile/check_wgsl.sh): what snell-wgsl must get
// right beyond the example. Overloads that both survive (GLSL's and the
// prelude's isnan), names WGSL reserves (naga appends `_`, which must stay),
// a name ending in a digit (naga appends `_`, which may go), a global hidden
// by a nested local, an anonymous block, and parameters a function writes:
// `in` (a local copy), `inout` and `out` (pointers, as the caller reads them
// back). check_wgsl.sh greps the WGSL for each.
layout(local_size_x = 1) in;
layout(set = 0, binding = 1) uniform sampler linearClamp;
#define SNELL_WEBGPU_SAMPLER linearClamp
#include "snell_webgpu_prelude.glsl"
#include "snell/optics.glsl"

layout(set = 0, binding = 2) uniform texture2D depthMap;
layout(std430, set = 0, binding = 0) buffer Data { vec4 data[]; };
layout(std140, set = 0, binding = 3) uniform Params { vec4 scale; };

float twice(float x) { return 2.0f * x; }
vec3 twice(vec3 x) { return 2.0f * x; }
float halve2(float x) { return 0.5f * x; }

float clampedSteps(int steps) {
  steps = max(steps, 1);  // writes its `in` parameter
  return float(steps);
}
void bump(inout float x) { x += 1.0f; }
void split(float v, out float lo, out float hi) {
  lo = floor(v);
  hi = v - lo;
}

float readDepth(ivec2 px, int n) {
  float d = texelFetch(sampler2D(depthMap, linearClamp), px, 0).x;
  for (int i = 0; i < n; ++i) {
    float depthMap = d;  // hides the global in this block only
    for (int j = 0; j < i; ++j) depthMap *= 2.0f;
    d += depthMap;
  }
  return d;
}

void main() {
  vec4 a = data[0];
  // Locals WGSL reserves, each stored more than once so that spirv-opt keeps them.
  float loop = twice(a.x);
  vec3 self = twice(a.xyz);
  int match = int(a.w);
  for (int i = 0; i < match; ++i) {
    loop += 1.0f;
    self *= 0.5f;
    match -= 1;
  }
  float var = clampedSteps(match) + halve2(loop);
  bump(var);
  float lo, hi;
  split(a.y, lo, hi);
  bool n1 = isnan(a.x);
  bvec3 n3 = isnan(a.xyz);
  SnellRefraction r = snellRefract(self, vec3(0.0f, 0.0f, 1.0f), 1.0f / 1.5f, SNELL_TIR_CRITICAL);
  data[1] = vec4(r.direction * scale.xyz, var + lo + hi + readDepth(ivec2(a.zw), match) + (n1 || any(n3) ? 1.0f : 0.0f));
}
