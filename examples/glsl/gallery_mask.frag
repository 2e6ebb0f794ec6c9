#version 450 core
// snell-gallery: Sousa's refraction mask: the refractive meshes write 0 into
// the alpha of S (and of the leak probe) where they are visible; colour
// writes are masked off by the caller (glColorMaski).
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 probe;

void main() {
  color = vec4(0.0f);
  probe = vec4(0.0f);
}
