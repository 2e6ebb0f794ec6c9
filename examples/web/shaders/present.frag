// The canvas: the frame's viewport part (inside the guard band, margin texels per side), encoded for the
// 8-bit sRGB canvas. Every buffer before this holds linear colour.
precision highp float;
precision highp int;
precision highp sampler2D;
#include <srgb_encode>

uniform sampler2D frame;
uniform int margin;
out vec4 color;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy) + ivec2(margin, margin);
  color = vec4(pageEncodeSrgb(texelFetch(frame, px, 0).xyz), 1.0);
}
