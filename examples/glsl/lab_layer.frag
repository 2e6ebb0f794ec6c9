#version 450 core
// snell-lab pass 1b: an object already drawn (the objects are drawn back to
// front), as part of the scene layer a nearer object reads: its front faces
// with the colour the frame holds there so far (`composite`: the objects drawn,
// over the opaque scene; the guard band holds the opaque scene only), their
// depth and view-space normal. With `peel`, as lab_scene.frag.
layout(location = 0) in vec3 vsPosition;
layout(location = 1) in vec3 vsNormal;
layout(location = 2) in float vsDn;
layout(binding = 0) uniform sampler2D composite;
layout(binding = 1) uniform sampler2D backDepth;
layout(location = 7) uniform int peel;
// Which surface this is, for the lab's leak count only (no technique reads it): -(o + 1) for object o.
layout(location = 8) uniform float surfaceId;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 normal;
layout(location = 2) out vec4 surface;

void main() {
  if (peel != 0) {
    float back = texelFetch(backDepth, ivec2(gl_FragCoord.xy), 0).x;
    if (back > 0.0f && gl_FragCoord.z <= back) discard;
  }
  color = vec4(texelFetch(composite, ivec2(gl_FragCoord.xy), 0).xyz, 1.0f);
  normal = vec4(normalize(vsNormal), 1.0f);
  surface = vec4(surfaceId, 0.0f, 0.0f, 0.0f);
}
