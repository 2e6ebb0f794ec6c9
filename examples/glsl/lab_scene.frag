#version 450 core
// snell-lab pass 1: a painting's colour (its texture, GL_LINEAR, no mips: what
// the reference tracer samples) and its view-space normal. With `peel`, only
// what lies behind the object's back faces at the fragment's texel (the
// back-face depth, cleared to 0 where there is none) is kept.
layout(location = 0) in vec2 uv;
layout(location = 1) in vec3 vsNormal;
layout(binding = 0) uniform sampler2D painting;
layout(binding = 1) uniform sampler2D backDepth;
layout(location = 7) uniform int peel;
// Which surface this is, for the lab's leak count only (no technique reads it): k + 1 for painting k.
layout(location = 8) uniform float surfaceId;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 normal;
layout(location = 2) out vec4 surface;

void main() {
  if (peel != 0) {
    float back = texelFetch(backDepth, ivec2(gl_FragCoord.xy), 0).x;
    if (back > 0.0f && gl_FragCoord.z <= back) discard;
  }
  color = vec4(textureLod(painting, uv, 0.0f).xyz, 1.0f);
  normal = vec4(normalize(vsNormal), 1.0f);
  surface = vec4(surfaceId, 0.0f, 0.0f, 0.0f);
}
