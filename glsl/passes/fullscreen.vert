#version 450 core
// One triangle that covers the viewport, its corners from gl_VertexID (draw 3
// vertices with any vertex array bound): the vertex stage of every full-screen
// pass (the depth pyramid, the lab's and the gallery's backgrounds and
// effects, the tests' frame passes). Portable: compiles unchanged after any of
// #version 330 core, 450 core, 300 es, 310 es, or as Vulkan GLSL.
#ifdef VULKAN
#  define SNELL_VERTEX_ID gl_VertexIndex
#else
#  define SNELL_VERTEX_ID gl_VertexID
#endif
void main() {
  vec2 p = vec2((SNELL_VERTEX_ID << 1) & 2, SNELL_VERTEX_ID & 2);
  gl_Position = vec4(p * 2.0f - 1.0f, 0.0f, 1.0f);
}
