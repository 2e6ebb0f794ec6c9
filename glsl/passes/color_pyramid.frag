#version 450 core
#extension GL_GOOGLE_include_directive : require  // or resolve includes your own way
// One level of the colour pyramid for rough reads (glsl/snell/shade/color_pyramid.glsl),
// drawn as a full-screen triangle into the level above the one it reads.
// snell::gpu::ColorPyramidPass runs it on GL with the texture's base and max
// level both set to the level read (with only the base level moved, a mipmap
// filter still selects the level being written: undefined) and sourceLod 0;
// the C++ twin is snell::snellBuildColorPyramid.
// Portable: compiles unchanged after any of #version 330 core, 450 core,
// 300 es, 310 es, or as Vulkan GLSL (tests/compile/check_glsl.sh).
#ifdef GL_ES
precision highp float;
precision highp int;
precision highp sampler2D;
#endif
#include "snell/shade/color_pyramid.glsl"

#ifdef VULKAN
// Vulkan has no free uniforms: the sampler at binding 0 of set 0, the level as a push constant.
layout(set = 0, binding = 0) uniform sampler2D source;
layout(push_constant) uniform PyramidParams {
  int sourceLod;
};
layout(location = 0) out vec4 texel;
#else
uniform sampler2D source;  // the colour texture, level sourceLod (relative to its base level) filled
uniform int sourceLod;
out vec4 texel;
#endif

void main() {
  texel = snellColorPyramidReduce(source, sourceLod, ivec2(gl_FragCoord.xy));
}
