#version 450 core
#extension GL_GOOGLE_include_directive : require  // or resolve includes your own way
// snell-lab pass 1: the environment behind everything, one full-screen
// triangle (depth untouched): the colour along each pixel's view ray.
#include "snell/shade/environment.glsl"

layout(binding = 0) uniform sampler2D environment;
layout(location = 0) uniform mat4 viewFromClip;
layout(location = 1) uniform vec3 envX;
layout(location = 2) uniform vec3 envY;
layout(location = 3) uniform vec3 envZ;
layout(location = 4) uniform vec2 viewport;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 normal;
layout(location = 2) out vec4 surface;  // 0: the environment (the lab's leak count)

void main() {
  vec2 ndc = 2.0f * gl_FragCoord.xy / viewport - 1.0f;
  vec4 v = viewFromClip * vec4(ndc, 1.0f, 1.0f);
  vec3 d = v.xyz / v.w;
  vec3 w = d.x * envX + d.y * envY + d.z * envZ;
  color = vec4(snellSampleEquirect(environment, w, 0.0f).xyz, 1.0f);
  normal = vec4(0.0f);
  surface = vec4(0.0f);
}
