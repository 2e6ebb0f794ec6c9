#version 450 core
// snell-lab pass 2: the refractive object's back faces (front faces culled,
// depth test GL_GREATER after clearing depth to 0): depth in the depth
// attachment, the unit view-space normal in colour attachment 0 (w = 1).
layout(location = 0) in vec3 vsPosition;
layout(location = 1) in vec3 vsNormal;
layout(location = 2) in float vsDn;
layout(location = 0) out vec4 normal;

void main() {
  normal = vec4(normalize(vsNormal), 1.0f);
}
