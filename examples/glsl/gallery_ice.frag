#version 450 core
#extension GL_GOOGLE_include_directive : require
// snell-gallery: the ice block over its front and back G-buffers and the
// crack depths (one full-screen triangle): galleryIce (gallery_effects.glsl),
// also run in C++. Output 1 holds the kept cracks' bits.
#include "gallery_effects.glsl"
layout(binding = 0) uniform sampler2D frontNormal;  // w 1 on the block
layout(binding = 1) uniform sampler2D frontWorld;   // xyz world, w window depth
layout(binding = 2) uniform sampler2D backNormal;
layout(binding = 3) uniform sampler2D backWorld;    // w window depth
layout(binding = 4) uniform sampler2D crack0;
layout(binding = 5) uniform sampler2D crack1;
layout(binding = 6) uniform sampler2D crack2;
layout(binding = 7) uniform sampler2D crack3;
layout(binding = 8) uniform sampler2D environment;
layout(binding = 9) uniform sampler2D sceneColor;
uniform vec3 eye;
uniform int withCracks;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 cracks;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 nf = texelFetch(frontNormal, px, 0);
  cracks = vec4(0.0f);
  if (nf.w == 0.0f) {
    color = vec4(texelFetch(sceneColor, px, 0).xyz, 0.0f);
    return;
  }
  vec4 fw = texelFetch(frontWorld, px, 0);
  vec4 bw = texelFetch(backWorld, px, 0);
  vec4 cd = vec4(texelFetch(crack0, px, 0).x, texelFetch(crack1, px, 0).x, texelFetch(crack2, px, 0).x,
                 texelFetch(crack3, px, 0).x);
  GalleryIce r = galleryIce(nf.xyz, texelFetch(backNormal, px, 0).xyz, fw.xyz, eye, fw.w, bw.w, cd,
                            withCracks != 0, environment);
  color = r.color;
  cracks = vec4(float(r.cracks), 0.0f, 0.0f, 0.0f);
}
