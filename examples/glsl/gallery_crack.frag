#version 450 core
// snell-gallery: one crack surface's window depth, into the attachment the
// caller leaves writable (glColorMaski): the ice pass clips it per pixel.
layout(location = 0) out vec4 crack0;
layout(location = 1) out vec4 crack1;
layout(location = 2) out vec4 crack2;
layout(location = 3) out vec4 crack3;

void main() {
  vec4 d = vec4(gl_FragCoord.z, 0.0f, 0.0f, 1.0f);
  crack0 = d;
  crack1 = d;
  crack2 = d;
  crack3 = d;
}
