#version 450 core
#extension GL_GOOGLE_include_directive : require
// snell-gallery: G. Oliveira's refractive texture mapping: the water mesh's
// vertices (pulled from a storage buffer: position, normal) get the pool
// floor's uv per vertex, by the approximate ray or by Snell's law
// (galleryRtmUv, also run in C++: the uvs are stored by gl_VertexID for the
// comparison), and the rasterizer interpolates it.
#include "gallery_effects.glsl"
layout(std430, binding = 0) readonly buffer RtmVertices { vec4 vertices[]; };  // position, normal per vertex
layout(std430, binding = 1) writeonly buffer RtmUvs { vec4 uvs[]; };  // the uv of each drawn vertex, for C++
uniform mat4 clipFromWorld;
uniform vec3 eye;
uniform int exact;
uniform int storeUvs;  // 1: write uvs (the comparison pass), 0: the timed passes
uniform float eta;
uniform vec4 extent;  // x_i, z_i, x_e, z_e
uniform vec3 planeParams;  // restY, depth, refraction factor
layout(location = 0) out vec2 floorUv;
layout(location = 1) out vec3 world;
layout(location = 2) out vec3 normal;

void main() {
  vec3 p = vertices[2 * gl_VertexID].xyz;
  vec3 n = vertices[2 * gl_VertexID + 1].xyz;
  SnellRefractiveTextureMapParams rp = snellRefractiveTextureMapParams(vec2(extent.x, extent.y), vec2(extent.z, extent.w),
                                                                       planeParams.x, planeParams.y, planeParams.z);
  floorUv = galleryRtmUv(p, n, eye, exact != 0, eta, rp);
  if (storeUvs != 0) {
    uvs[gl_VertexID] = vec4(floorUv, 0.0f, 0.0f);
  }
  world = p;
  normal = n;
  gl_Position = clipFromWorld * vec4(p, 1.0f);
}
