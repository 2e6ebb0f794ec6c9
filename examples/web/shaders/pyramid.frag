// One level of the depth min/max pyramid into its own target (glsl/passes/depth_pyramid.frag's body): level
// 0 from the depth texture, level L + 1 from level L's target. WebGL 2 cannot render one level of a texture
// while sampling another level of it (a feedback loop, or an attachment outside [base level, max level]),
// so every level is drawn into a target of its own and then copied into the pyramid's mip chain.
precision highp float;
precision highp int;
precision highp sampler2D;
#include <snell>

uniform sampler2D source;
uniform int fromDepth;  // 1: source is the depth texture
uniform float zNear;
uniform float zFar;
uniform float emptyDepth;
out vec4 texel;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  if (fromDepth != 0) {
    SnellDepthSurface s = snellDepthSurface(mat4(1.0), zNear, zFar, SNELL_DEPTH_GL, emptyDepth);
    texel = snellDepthPyramidBase(texelFetch(source, px, 0).x, s);
  } else {
    texel = snellDepthMinMaxReduce(source, 0, px, emptyDepth);
  }
}
