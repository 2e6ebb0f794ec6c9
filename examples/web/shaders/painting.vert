// A painting: an opaque textured mesh (a scene file's quad, a glTF asset's mesh).
precision highp float;
in vec3 position;
in vec2 uv;
in vec3 normal;  // world space, as the lab's (not unit on a quad: its corners' cross product)
uniform mat4 viewFromWorld;
uniform mat4 clipFromView;
out vec2 vUv;
out vec3 vsNormal;
out float vsDistance;  // along the view axis: painting.frag's clip plane

void main() {
  vUv = uv;
  vsNormal = normalize(mat3(viewFromWorld) * normal);
  vec4 v = viewFromWorld * vec4(position, 1.0);
  vsDistance = -v.z;
  gl_Position = clipFromView * v;
}
