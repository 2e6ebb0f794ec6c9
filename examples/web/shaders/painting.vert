// A painting: a textured quad given by its four world-space corners.
precision highp float;
in vec3 position;
in vec2 uv;
uniform mat4 viewFromWorld;
uniform mat4 clipFromView;
uniform vec3 faceNormal;  // world space: cross(corner 1 - corner 0, corner 3 - corner 0)
out vec2 vUv;
out vec3 vsNormal;
out float vsDistance;  // along the view axis: painting.frag's clip plane

void main() {
  vUv = uv;
  vsNormal = normalize(mat3(viewFromWorld) * faceNormal);
  vec4 v = viewFromWorld * vec4(position, 1.0);
  vsDistance = -v.z;
  gl_Position = clipFromView * v;
}
