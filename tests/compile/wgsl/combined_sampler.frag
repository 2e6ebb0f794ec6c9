#version 450 core
// compile.wgsl_error (tests/compile/check_wgsl.sh): a sampler2D uniform, which
// WGSL cannot have. snell-wgsl must name this file and the line that reads it.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
layout(binding = 0) uniform sampler2D scene;

void main() {
  color = textureLod(scene, uv, 0.0f);
}
