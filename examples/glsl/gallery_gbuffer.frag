#version 450 core
// snell-gallery: a refracting surface's G-buffer: world normal (w 1 where
// covered), world position and window depth, pane uv and material. The
// opaque scene's depth hides what lies behind it (tested here, so the pass
// keeps its own depth buffer).
layout(location = 0) in vec3 world;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 albedo;
layout(location = 3) in vec2 uv;
layout(location = 4) flat in float material;
layout(binding = 0) uniform sampler2D occluderDepth;
layout(location = 0) out vec4 gNormal;
layout(location = 1) out vec4 gWorld;
layout(location = 2) out vec4 gSurface;

void main() {
  if (gl_FragCoord.z >= texelFetch(occluderDepth, ivec2(gl_FragCoord.xy), 0).x) discard;
  gNormal = vec4(normalize(normal), 1.0f);
  gWorld = vec4(world, gl_FragCoord.z);
  gSurface = vec4(uv, material, 1.0f);
}
