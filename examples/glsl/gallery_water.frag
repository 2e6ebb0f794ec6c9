#version 450 core
#extension GL_GOOGLE_include_directive : require
// snell-gallery: Sousa's water over the water surface's G-buffer (one
// full-screen triangle): galleryWater (gallery_effects.glsl), the very function
// snell-gallery runs per pixel in C++ on the read-back buffers.
#include "gallery_effects.glsl"
layout(binding = 0) uniform sampler2D gNormal;  // w 1 on the water
layout(binding = 1) uniform sampler2D gWorld;   // xyz world, w window depth
layout(binding = 2) uniform sampler2D bump;
layout(binding = 3) uniform sampler2D sceneColor;
layout(binding = 4) uniform sampler2D sceneDepth;
layout(binding = 5) uniform sampler2D reflection;
uniform vec3 eye;
uniform float time;
uniform int mask;
uniform vec2 viewport;
uniform vec3 waterColor;  // the probe zeroes both colours
uniform vec3 deepColor;
uniform float deepDistance;
layout(location = 0) out vec4 color;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 g = texelFetch(gWorld, px, 0);
  if (texelFetch(gNormal, px, 0).w == 0.0f) {
    color = textureLod(sceneColor, (vec2(px) + 0.5f) / viewport, 0.0f);
    color.w = 0.0f;
    return;
  }
  SnellWaterParams p = snellWaterParams();
  p.waterColor = waterColor;
  p.deepColor = deepColor;
  p.deepDistance = deepDistance;
  color = galleryWater(g.xyz, g.w, (vec2(px) + 0.5f) / viewport, eye, time, mask, bump, sceneColor, sceneDepth,
                       reflection, p);
}
