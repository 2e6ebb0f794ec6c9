#version 450 core
// snell-lab pass 1: one painting (a textured quad), two triangles from gl_VertexID.
// With GL_CLIP_DISTANCE0 enabled, only what lies beyond `clipNearerThan` (a view
// distance) is drawn: the layer of the scene behind the refractive object.
layout(location = 0) uniform mat4 viewFromWorld;
layout(location = 1) uniform mat4 clipFromView;
layout(location = 2) uniform vec3 corners[4];  // world space, uv order (0,0) (1,0) (1,1) (0,1)
layout(location = 0) out vec2 uv;
layout(location = 1) out vec3 vsNormal;
layout(location = 6) uniform float clipNearerThan;
out float gl_ClipDistance[1];

void main() {
  int k[6] = int[6](0, 1, 2, 0, 2, 3);
  vec2 uvs[4] = vec2[4](vec2(0.0f, 0.0f), vec2(1.0f, 0.0f), vec2(1.0f, 1.0f), vec2(0.0f, 1.0f));
  int c = k[gl_VertexID];
  uv = uvs[c];
  vec3 n = cross(corners[1] - corners[0], corners[3] - corners[0]);
  vsNormal = normalize(mat3(viewFromWorld) * n);
  vec4 view = viewFromWorld * vec4(corners[c], 1.0f);
  gl_ClipDistance[0] = -view.z - clipNearerThan;
  gl_Position = clipFromView * view;
}
