#version 450 core
// snell-gallery: the opaque scene S, lit by one sun and a sky term. Material 0
// is plain colour, 1 the pool's tiles, 2 the room's striped wall. Output 1 is
// the leak probe: rgb 1 where the surface lies on the positive side of
// probePlane (in front of the refracting surface: what it must never
// refract), alpha the refraction mask like S's.
layout(location = 0) in vec3 world;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 albedo;
layout(location = 3) in vec2 uv;
layout(location = 4) flat in float material;
uniform vec4 probePlane;  // dot(xyz, world) + w > 0: in front
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 probe;

void main() {
  vec3 base = albedo;
  if (material == 1.0f) {
    vec2 t = floor(world.xz * 2.0f);
    bool odd = mod(t.x + t.y, 2.0f) > 0.5f;
    vec2 f = fract(world.xz * 2.0f);
    bool grout = min(min(f.x, 1.0f - f.x), min(f.y, 1.0f - f.y)) < 0.04f;
    base = grout ? vec3(0.55f) : (odd ? vec3(0.85f, 0.9f, 0.92f) : vec3(0.2f, 0.45f, 0.75f));
  } else if (material == 2.0f) {
    float s = fract(uv.x * 12.0f);
    float r = fract(uv.y * 6.0f + 0.5f * floor(uv.x * 12.0f));
    base = s < 0.5f ? vec3(0.85f, 0.75f, 0.45f) : vec3(0.35f, 0.2f, 0.15f);
    if (r < 0.08f) base = vec3(0.1f);
  }
  vec3 n = normalize(normal);
  float sun = max(dot(n, normalize(vec3(0.4f, 0.8f, 0.45f))), 0.0f);
  color = vec4(base * (0.35f + 0.65f * sun), 1.0f);
  probe = vec4(vec3(dot(probePlane.xyz, world) + probePlane.w > 0.0f ? 1.0f : 0.0f), 1.0f);
}
