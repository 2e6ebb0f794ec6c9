/* The shared part of the texture hooks' parity cases (described in
   tests/parity/hooks_cases.cpp): the C++ snell::Texture2D must address and
   filter exactly as GL does (texel centres, clamp-to-edge, nearest, bilinear,
   explicit-LOD mip selection). One texture per filter state. */
#include "snell/prelude.glsl"

#if defined(SNELL_LANG_GLSL)
uniform sampler2D parityTexNearest;      /* NEAREST, no mips */
uniform sampler2D parityTexLinear;       /* LINEAR, no mips */
uniform sampler2D parityTexTrilinear;    /* LINEAR, LINEAR_MIPMAP_LINEAR */
uniform sampler2D parityTexMipNearest;   /* NEAREST, NEAREST_MIPMAP_NEAREST */
uniform sampler2D parityTexMagLinear;    /* mag LINEAR, min NEAREST_MIPMAP_NEAREST (c = 0.5) */
#endif
#if defined(SNELL_LANG_HLSL)
Texture2D<float4> parityTexNearest;
Texture2D<float4> parityTexLinear;
Texture2D<float4> parityTexTrilinear;
Texture2D<float4> parityTexMipNearest;
Texture2D<float4> parityTexMagLinear;
#endif
