#version 450 core
// snell-lab pass 1: one painting (an opaque textured mesh: a scene file's quad
// or a glTF asset's mesh), pulled from storage buffers by gl_VertexID as
// lab_mesh.vert pulls the objects. With GL_CLIP_DISTANCE0 enabled, only what
// lies beyond `clipNearerThan` (a view distance) is drawn: the layer of the
// scene behind the refractive object.
layout(std430, binding = 0) readonly buffer LabPositions { vec4 positions[]; };  // w: the uv's u
layout(std430, binding = 1) readonly buffer LabNormals { vec4 normals[]; };      // w: the uv's v
layout(std430, binding = 2) readonly buffer LabIndices { uint indices[]; };
layout(location = 0) uniform mat4 viewFromWorld;
layout(location = 1) uniform mat4 clipFromView;
layout(location = 0) out vec2 uv;
layout(location = 1) out vec3 vsNormal;
layout(location = 6) uniform float clipNearerThan;
out float gl_ClipDistance[1];

void main() {
  uint i = indices[gl_VertexID];
  vec4 p = positions[i];
  vec4 n = normals[i];
  uv = vec2(p.w, n.w);
  vsNormal = normalize(mat3(viewFromWorld) * n.xyz);
  vec4 view = viewFromWorld * vec4(p.xyz, 1.0f);
  gl_ClipDistance[0] = -view.z - clipNearerThan;
  gl_Position = clipFromView * view;
}
