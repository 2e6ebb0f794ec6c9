#version 450 core
#extension GL_GOOGLE_include_directive : require  // or resolve includes your own way
// One pass of the depth min/max pyramid (Oliveira & Brauwers 2007, 2nd pass),
// drawn as a full-screen triangle into an RGBA32F target of the output level's
// size. baseLevel = 1: level 0 from the depth buffer; else level L+1 from level
// sourceLod = L of the pyramid. Texel layout: glsl/snell/intersect/depth_pyramid.glsl.
#include "snell/intersect/depth_pyramid.glsl"

layout(binding = 0) uniform sampler2D source;  // the depth buffer (baseLevel) or the pyramid so far
layout(location = 0) uniform int sourceLod;
layout(location = 1) uniform int baseLevel;
layout(location = 2) uniform float zNear;
layout(location = 3) uniform float zFar;
layout(location = 4) uniform int convention;
layout(location = 5) uniform float emptyDepth;
layout(location = 0) out vec4 texel;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  if (baseLevel != 0) {
    SnellDepthSurface s = snellDepthSurface(mat4(1.0f), zNear, zFar, convention, emptyDepth);
    texel = snellDepthPyramidBase(SNELL_TEXEL_FETCH(source, px, sourceLod).x, s);
  } else {
    texel = snellDepthMinMaxReduce(source, sourceLod, px, emptyDepth);
  }
}
