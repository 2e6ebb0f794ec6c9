#version 450 core
// snell-gallery: a triangle soup pulled from one storage buffer by gl_VertexID
// (three vec4 per vertex: position + material, normal + u, colour + v), in
// world space, with one world clip plane (the planar reflection's).
layout(std430, binding = 0) readonly buffer GalleryVertices { vec4 vertices[]; };
uniform mat4 clipFromWorld;
uniform vec4 clipPlane;  // kept where dot(clipPlane.xyz, p) + clipPlane.w >= 0
layout(location = 0) out vec3 world;
layout(location = 1) out vec3 normal;
layout(location = 2) out vec3 albedo;
layout(location = 3) out vec2 uv;
layout(location = 4) flat out float material;  // flat: compared for equality

void main() {
  vec4 a = vertices[3 * gl_VertexID];
  vec4 b = vertices[3 * gl_VertexID + 1];
  vec4 c = vertices[3 * gl_VertexID + 2];
  world = a.xyz;
  normal = b.xyz;
  albedo = c.xyz;
  material = a.w;
  uv = vec2(b.w, c.w);
  gl_ClipDistance[0] = dot(clipPlane.xyz, a.xyz) + clipPlane.w;
  gl_Position = clipFromWorld * vec4(a.xyz, 1.0f);
}
