// A painting's colour (its texture, linear filter, no mips) and its view-space normal.
precision highp float;
precision highp sampler2D;
uniform sampler2D painting;
in vec2 vUv;
in vec3 vsNormal;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 normal;

void main() {
  color = vec4(textureLod(painting, vUv, 0.0).xyz, 1.0);
  normal = vec4(normalize(vsNormal), 1.0);
}
