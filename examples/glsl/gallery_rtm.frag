#version 450 core
// snell-gallery: the refracted pool floor: one bilinear read at the
// interpolated uv, which output 1 keeps for the C++ side with the surface
// point and normal (for the exact per-pixel refraction there).
layout(location = 0) in vec2 floorUv;
layout(location = 1) in vec3 world;
layout(location = 2) in vec3 normal;
layout(binding = 0) uniform sampler2D floorMap;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 uvOut;
layout(location = 2) out vec4 worldOut;
layout(location = 3) out vec4 normalOut;

void main() {
  color = vec4(textureLod(floorMap, floorUv, 0.0f).xyz, 1.0f);
  uvOut = vec4(floorUv, 0.0f, 1.0f);
  worldOut = vec4(world, 1.0f);
  normalOut = vec4(normal, 1.0f);
}
