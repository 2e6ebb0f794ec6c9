#version 450 core
#extension GL_GOOGLE_include_directive : require
// snell-gallery: the environment behind everything (one full-screen triangle,
// depth untouched): the equirectangular map along each pixel's world ray.
#include "snell/shade/environment.glsl"
layout(binding = 0) uniform sampler2D environment;
uniform mat4 worldFromClip;
uniform vec3 eye;
uniform vec2 viewport;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 probe;

void main() {
  vec2 ndc = 2.0f * gl_FragCoord.xy / viewport - 1.0f;
  vec4 w = worldFromClip * vec4(ndc, 1.0f, 1.0f);
  color = vec4(snellSampleEquirect(environment, w.xyz / w.w - eye, 0.0f).xyz, 1.0f);
  probe = vec4(0.0f, 0.0f, 0.0f, 1.0f);
}
