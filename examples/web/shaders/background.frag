// The opaque scene's first layer: the environment along each texel's view ray (depth untouched), normal 0:
// snell-lab's lab_background.frag.
precision highp float;
precision highp int;
precision highp sampler2D;
#include <snell>

uniform sampler2D environment;
uniform mat4 viewFromClip;  // the buffers' projection, inverted
uniform vec3 envX;
uniform vec3 envY;
uniform vec3 envZ;
uniform vec2 viewport;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 normal;

void main() {
  vec2 ndc = 2.0 * gl_FragCoord.xy / viewport - 1.0;
  vec4 v = viewFromClip * vec4(ndc, 1.0, 1.0);
  vec3 d = v.xyz / v.w;
  vec3 w = d.x * envX + d.y * envY + d.z * envZ;
  color = vec4(snellSampleEquirect(environment, w, 0.0).xyz, 1.0);
  normal = vec4(0.0);
}
