// A painting's colour (its texture, linear filter, no mips) and its view-space normal. Only what lies beyond
// `clipNearerThan` (a view distance; 0: all) is drawn: the scene layer behind a refractive object's nearest
// point, as snell-lab's clip plane (lab_scene.vert). WebGL 2 has no gl_ClipDistance without an extension;
// the interpolated distance is linear in view space, so discarding where it is negative keeps the same
// pixels as clipping the quad.
precision highp float;
precision highp sampler2D;
uniform sampler2D painting;
uniform float clipNearerThan;
in vec2 vUv;
in vec3 vsNormal;
in float vsDistance;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 normal;

void main() {
  if (clipNearerThan > 0.0 && vsDistance - clipNearerThan < 0.0) discard;
  color = vec4(textureLod(painting, vUv, 0.0).xyz, 1.0);
  normal = vec4(normalize(vsNormal), 1.0);
}
