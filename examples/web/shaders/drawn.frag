// An object already drawn (the objects are drawn back to front), as part of the scene layer a nearer object
// reads: its front faces with the colour the frame holds there so far (`frame`: the objects drawn, over the
// opaque scene), their depth and view-space normal; only beyond `clipNearerThan`, as painting.frag.
// snell-lab's lab_layer.frag.
precision highp float;
precision highp sampler2D;
uniform sampler2D frame;
uniform float clipNearerThan;
in vec3 vsPosition;
in vec3 vsNormal;
in float vsDn;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 normal;

void main() {
  if (clipNearerThan > 0.0 && -vsPosition.z - clipNearerThan < 0.0) discard;
  color = vec4(texelFetch(frame, ivec2(gl_FragCoord.xy), 0).xyz, 1.0);
  normal = vec4(normalize(vsNormal), 1.0);
}
