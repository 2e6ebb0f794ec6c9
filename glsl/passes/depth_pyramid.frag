#version 450 core
#extension GL_GOOGLE_include_directive : require  // or resolve includes your own way
// One pass of the depth min/max pyramid (Oliveira & Brauwers 2007, 2nd pass),
// drawn as a full-screen triangle into an RGBA32F target of the output level's
// size. baseLevel = 1: level 0 from the depth buffer; else level L+1 from level
// sourceLod = L of the pyramid. Texel layout: glsl/snell/intersect/depth_pyramid.glsl.
// snell::gpu::DepthPyramidPass runs it on GL; the C++ twin is snell::snellBuildDepthPyramid.
// Portable: compiles unchanged after any of #version 330 core, 450 core,
// 300 es, 310 es, or as Vulkan GLSL (tests/compile/check_glsl.sh).
#ifdef GL_ES
precision highp float;
precision highp int;
precision highp sampler2D;
#endif
#include "snell/intersect/depth_pyramid.glsl"

#ifdef VULKAN
// Vulkan has no free uniforms: the sampler at binding 0 of set 0, the rest as push constants.
layout(set = 0, binding = 0) uniform sampler2D source;
layout(push_constant) uniform PyramidParams {
  int sourceLod;
  int baseLevel;
  float zNear;
  float zFar;
  int convention;
  float emptyDepth;
};
layout(location = 0) out vec4 texel;
#else
uniform sampler2D source;  // the depth buffer (baseLevel) or the pyramid so far
uniform int sourceLod;
uniform int baseLevel;
uniform float zNear;
uniform float zFar;
uniform int convention;
uniform float emptyDepth;
out vec4 texel;
#endif

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  if (baseLevel != 0) {
    SnellDepthSurface s = snellDepthSurface(mat4(1.0f), zNear, zFar, convention, emptyDepth);
    texel = snellDepthPyramidBase(SNELL_TEXEL_FETCH(source, px, sourceLod).x, s);
  } else {
    texel = snellDepthMinMaxReduce(source, sourceLod, px, emptyDepth);
  }
}
