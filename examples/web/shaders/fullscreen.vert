// One triangle over the whole target (positions (-1,-1), (3,-1), (-1,3)).
precision highp float;
in vec3 position;

void main() {
  gl_Position = vec4(position.xy, 0.0, 1.0);
}
