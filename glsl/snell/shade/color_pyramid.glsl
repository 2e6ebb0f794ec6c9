/*
description: the scene colour's mip chain for rough reads, each level a
  tent-filtered (separable [1 3 3 1] / 8) half of the one below instead of
  glGenerateMipmap's 2x2 box. A box chain is not shift-invariant: what a
  texel of level L holds depends on where the image falls on its 2^L grid,
  so a blurred read changes as the camera moves by a fraction of a pixel,
  and a third of its spread is texels moved to their block's centre. The
  tent's response has a triple zero at the level's Nyquist frequency (the
  box's a single one), so far less of the finer level aliases into the
  coarser one, and a read at level L is close to a Gaussian of width
  proportional to 2^L at every offset: the bell the rough cone's two taps
  assume (rough_cone.glsl).
use: level L+1 from level L, one fragment (or compute) invocation per texel
     px of level L+1 (fragment: px = ivec2(gl_FragCoord.xy)):
       out = snellColorPyramidReduce(colorTex, L, px);
     a full GL pass is glsl/passes/color_pyramid.frag (driven level by level
     by snell::gpu::ColorPyramidPass); C++: snell::snellBuildColorPyramid(base)
     (include/snell/color_pyramid.hpp). Sample the result with trilinear
     filtering (GL_LINEAR_MIPMAP_LINEAR), as snellRoughConeSample does.
contract:
  - level L has size (W, H) = SNELL_TEXTURE_SIZE(tex, L) (at least 1 each);
    level L+1 has (max(1, W/2), max(1, H/2)) (GL's floor sizes); px is
    clamped into it. lod must name a level of tex.
  - per axis, the output texel's centre in level L's texel units (centres at
    integers) is c = (px + 0.5) W / max(1, W/2) - 0.5 (2 px + 0.5 for even
    W), and the four texels floor(c) - 1 .. floor(c) + 2, clamped to the
    level's edge as GL's clamp-to-edge does, weigh (1 - f, 2 - f, 1 + f, f) / 4,
    f = c - floor(c): the tent max(0, 1 - |x - c| / 2) at each, halved (the
    four tent values sum to 2), so the weights sum to 1 (for even W, f = 1/2:
    1/8, 3/8, 3/8, 1/8). The 2D weights are the product of the two axes'
    (16 fetches).
  - a constant level gives the same constant, and a level affine in x and y
    the affine function at the centres away from the edge taps, both to
    float rounding.
  - a texel with a non-finite channel counts as 0 in every channel, so one
    NaN or infinity does not spread through the chain; the result is finite
    whenever the finite texels' sums do not overflow.
  - the sums run in a fixed order (rows, then columns within a row), with c
    and f computed from integers, so the GPU pass and the C++ build agree to
    float rounding of the products.
  - the standard deviation of a level-L trilinear read is about 0.65 x 2^L
    texels of level 0 (the box chain's: 0.5 x 2^L): the chain's levels
    variance 0.75 (4^L - 1) / 3, the bilinear read's 4^L / 6.
source: the REDUCE of P. J. Burt, E. H. Adelson, "The Laplacian Pyramid as
  a Compact Image Code" (IEEE Trans. Comm. 1983), eq. 1 (each level a
  weighted sum of the one below, a separable, symmetric, normalised,
  Gaussian-like kernel), here with the even-length kernel [1 3 3 1] / 8 that
  centres each texel of level L+1 between its parents (GL's floor sizes).
*/
#ifndef SNELL_SHADE_COLOR_PYRAMID_GLSL
#define SNELL_SHADE_COLOR_PYRAMID_GLSL
#include "../prelude.glsl"

/* A texel as the reduce reads it: a non-finite channel makes it 0. */
SNELL_FN vec4 snellColorPyramidTexel(vec4 t) {
  bool finite = SNELL_FINITE(t.x) && SNELL_FINITE(t.y) && SNELL_FINITE(t.z) && SNELL_FINITE(t.w);
  return finite ? t : vec4(0.0f);
}

/* One axis of a reduce: the first of the four texels it reads and their weights. */
struct SnellColorPyramidAxis {
  int first;
  vec4 weights;
};

SNELL_FN SnellColorPyramidAxis snellColorPyramidAxis(int px, int size) {
  int w = max(size, 1);
  int outSize = max(w / 2, 1);
  int p = clamp(px, 0, outSize - 1);
  // c = ((2 p + 1) w - outSize) / (2 outSize): its floor and fraction from integers (the numerator is >= 0).
  int num = (2 * p + 1) * w - outSize;
  int den = 2 * outSize;
  int b = num / den;
  float f = float(num - b * den) / float(den);
  SnellColorPyramidAxis a;
  a.first = b - 1;
  a.weights = vec4(1.0f - f, 2.0f - f, 1.0f + f, f) * 0.25f;
  return a;
}

SNELL_FN vec4 snellColorPyramidReduce(SNELL_TEX2D colorTex, int lod, ivec2 px) {
  ivec2 size = max(SNELL_TEXTURE_SIZE(colorTex, lod), ivec2(1, 1));
  SnellColorPyramidAxis ax = snellColorPyramidAxis(px.x, size.x);
  SnellColorPyramidAxis ay = snellColorPyramidAxis(px.y, size.y);
  vec4 sum = vec4(0.0f);
  for (int j = 0; j < 4; ++j) {
    int y = clamp(ay.first + j, 0, size.y - 1);
    vec4 row = vec4(0.0f);
    for (int i = 0; i < 4; ++i) {
      int x = clamp(ax.first + i, 0, size.x - 1);
      row += ax.weights[i] * snellColorPyramidTexel(SNELL_TEXEL_FETCH(colorTex, ivec2(x, y), lod));
    }
    sum += ay.weights[j] * row;
  }
  return sum;
}

#endif
