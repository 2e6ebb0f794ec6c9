// One layer of the object (back faces or front faces): the unit view-space normal, w = 1; depth in the
// depth texture.
precision highp float;
in vec3 vsPosition;
in vec3 vsNormal;
in float vsDn;
layout(location = 0) out vec4 normal;

void main() {
  normal = vec4(normalize(vsNormal), 1.0);
}
