#version 450 core
#extension GL_GOOGLE_include_directive : require
// snell-gallery: galleryRtmUv for every vertex of the water mesh into a
// storage buffer (xy approximate, zw exact), compared vertex by vertex with C++.
#include "gallery_effects.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer RtmVertices { vec4 vertices[]; };
layout(std430, binding = 1) writeonly buffer RtmUvs { vec4 uvs[]; };
uniform vec3 eye;
uniform float eta;
uniform vec4 extent;
uniform vec3 planeParams;
uniform int count;

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= count) return;
  vec3 p = vertices[2 * i].xyz;
  vec3 n = vertices[2 * i + 1].xyz;
  SnellRefractiveTextureMapParams rp = snellRefractiveTextureMapParams(vec2(extent.x, extent.y), vec2(extent.z, extent.w),
                                                                       planeParams.x, planeParams.y, planeParams.z);
  uvs[i] = vec4(galleryRtmUv(p, n, eye, false, eta, rp), galleryRtmUv(p, n, eye, true, eta, rp));
}
