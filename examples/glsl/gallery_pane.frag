#version 450 core
#extension GL_GOOGLE_include_directive : require
// snell-gallery: stained glass and heat haze over the panes' G-buffer (one
// full-screen triangle): galleryPane (gallery_effects.glsl), also run in C++.
#include "gallery_effects.glsl"
layout(binding = 0) uniform sampler2D gNormal;   // w 1 on a pane
layout(binding = 1) uniform sampler2D gWorld;    // xyz world
layout(binding = 2) uniform sampler2D gSurface;  // xy pane uv, z material
layout(binding = 3) uniform sampler2D bump;
layout(binding = 4) uniform sampler2D stain;
layout(binding = 5) uniform sampler2D sceneColor;
layout(binding = 6) uniform sampler2D environment;
uniform vec3 eye;
uniform float time;
uniform int mask;
uniform vec2 viewport;
layout(location = 0) out vec4 color;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec2 uv = (vec2(px) + 0.5f) / viewport;
  if (texelFetch(gNormal, px, 0).w == 0.0f) {
    color = vec4(textureLod(sceneColor, uv, 0.0f).xyz, 0.0f);
    return;
  }
  vec4 s = texelFetch(gSurface, px, 0);
  color = galleryPane(s.z, vec2(s.x, s.y), texelFetch(gWorld, px, 0).xyz, uv, eye, time, mask, bump, stain,
                      sceneColor, environment);
}
