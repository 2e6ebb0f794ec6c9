#version 450 core
// snell-lab: one full-screen triangle (background, pyramid passes).
void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  gl_Position = vec4(p * 2.0f - 1.0f, 0.0f, 1.0f);
}
