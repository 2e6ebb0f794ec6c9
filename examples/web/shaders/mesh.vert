// The refractive object: view-space position and normal (a rigid view transform), Wyman's d_N.
precision highp float;
in vec3 position;
in vec3 normal;
in float dn;
uniform mat4 viewFromWorld;
uniform mat4 clipFromView;
out vec3 vsPosition;
out vec3 vsNormal;
out float vsDn;

void main() {
  vec4 v = viewFromWorld * vec4(position, 1.0);
  vsPosition = v.xyz;
  vsNormal = mat3(viewFromWorld) * normal;
  vsDn = dn;
  gl_Position = clipFromView * v;
}
