#version 450 core
// snell-lab pass 1: a painting's colour (its texture, GL_LINEAR, no mips: what
// the reference tracer samples) and its view-space normal.
layout(location = 0) in vec2 uv;
layout(location = 1) in vec3 vsNormal;
layout(binding = 0) uniform sampler2D painting;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 normal;

void main() {
  color = vec4(textureLod(painting, uv, 0.0f).xyz, 1.0f);
  normal = vec4(normalize(vsNormal), 1.0f);
}
