#version 450 core
#extension GL_GOOGLE_include_directive : require  // or resolve includes your own way
// Portable: compiles unchanged after any of #version 330 core, 450 core,
// 300 es, 310 es, or as Vulkan GLSL (tests/compile/check_glsl.sh).
#ifdef GL_ES
precision highp float;
precision highp int;
precision highp sampler2D;
#endif
#include "snell/optics.glsl"

// Vulkan needs locations on every in/out; GLSL 330 and ES 3.00 allow none on
// fragment inputs (GL matches them by name).
#ifdef VULKAN
#  define AT(n) layout(location = n)
#else
#  define AT(n)
#endif
AT(0) in vec3 vsPosition;  // view-space position of the front face
AT(1) in vec3 vsNormal;
AT(0) out vec4 color;

void main() {
  vec3 viewDir = normalize(vsPosition);  // the camera sits at the origin
  SnellRefraction t1 = snellRefract(viewDir, vsNormal, 1.0f / 1.5f, SNELL_TIR_CRITICAL);
  color = vec4(t1.direction * 0.5f + 0.5f, 1.0f);
}
