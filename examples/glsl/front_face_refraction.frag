#version 450 core
#extension GL_GOOGLE_include_directive : require  // or resolve includes your own way
#include "snell/optics.glsl"

layout(location = 0) in vec3 vsPosition;  // view-space position of the front face
layout(location = 1) in vec3 vsNormal;
layout(location = 0) out vec4 color;

void main() {
  vec3 viewDir = normalize(vsPosition);  // the camera sits at the origin
  SnellRefraction t1 = snellRefract(viewDir, vsNormal, 1.0f / 1.5f, SNELL_TIR_CRITICAL);
  color = vec4(t1.direction * 0.5f + 0.5f, 1.0f);
}
