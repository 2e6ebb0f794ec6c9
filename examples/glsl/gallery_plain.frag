#version 450 core
// snell-gallery: the cost yardstick: one bilinear read of S per pixel.
layout(binding = 0) uniform sampler2D sceneColor;
uniform vec2 viewport;
layout(location = 0) out vec4 color;

void main() {
  color = textureLod(sceneColor, gl_FragCoord.xy / viewport, 0.0f);
}
