// A pyramid level's target into its level of the mip chain, texel for texel.
precision highp float;
precision highp sampler2D;
uniform sampler2D source;
out vec4 texel;

void main() {
  texel = texelFetch(source, ivec2(gl_FragCoord.xy), 0);
}
