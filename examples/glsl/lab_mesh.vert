#version 450 core
// snell-lab: the refractive mesh, pulled from storage buffers by gl_VertexID
// (non-indexed draw of 3 * triangles vertices), so the lab needs no vertex
// attribute state. positions[i].w carries Wyman's d_N of the vertex. With
// GL_CLIP_DISTANCE0 enabled, only what lies beyond `clipNearerThan` (a view
// distance) is drawn: an object already drawn, in the scene layer behind a
// nearer one (lab_layer.frag).
layout(std430, binding = 0) readonly buffer LabPositions { vec4 positions[]; };
layout(std430, binding = 1) readonly buffer LabNormals { vec4 normals[]; };
layout(std430, binding = 2) readonly buffer LabIndices { uint indices[]; };
layout(location = 0) uniform mat4 viewFromWorld;
layout(location = 1) uniform mat4 clipFromView;
layout(location = 0) out vec3 vsPosition;
layout(location = 1) out vec3 vsNormal;
layout(location = 2) out float vsDn;
layout(location = 6) uniform float clipNearerThan;
out float gl_ClipDistance[1];

void main() {
  uint i = indices[gl_VertexID];
  vec4 p = positions[i];
  vec4 v = viewFromWorld * vec4(p.xyz, 1.0f);
  vsPosition = v.xyz;
  vsNormal = mat3(viewFromWorld) * normals[i].xyz;  // rigid view transform
  vsDn = p.w;
  gl_ClipDistance[0] = -v.z - clipNearerThan;
  gl_Position = clipFromView * v;
}
