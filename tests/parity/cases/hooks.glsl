/* Parity cases for the prelude's texture hooks: the C++ snell::Texture2D must
   address and filter exactly as GL does (texel centres, clamp-to-edge, nearest,
   bilinear, explicit-LOD mip selection). One texture per filter state. */
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

/* a.xy uv, a.z lod; b.xy texel, b.z level. */
SNELL_FN SnellParityOut caseHookNearest(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  o.a = SNELL_SAMPLE_LOD(parityTexNearest, vec2(a.x, a.y), a.z);
  o.b = SNELL_TEXEL_FETCH(parityTexMipNearest, ivec2(int(b.x), int(b.y)), int(b.z));
  ivec2 s = SNELL_TEXTURE_SIZE(parityTexMipNearest, int(b.z));
  o.c = vec4(float(s.x), float(s.y), 0.0f, 0.0f);
  o.d = vec4(0.0f);
  return o;
}

SNELL_FN SnellParityOut caseHookLinear(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  o.a = SNELL_SAMPLE_LOD(parityTexLinear, vec2(a.x, a.y), a.z);
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

SNELL_FN SnellParityOut caseHookMipmaps(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  o.a = SNELL_SAMPLE_LOD(parityTexTrilinear, vec2(a.x, a.y), a.z);
  o.b = SNELL_SAMPLE_LOD(parityTexMipNearest, vec2(a.x, a.y), a.z);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

/* mag LINEAR with min NEAREST_MIPMAP_*: the spec switches to minification at
   lod c = 0.5, llvmpipe at 0; the inputs avoid lod in (0, 0.5] (see bridge.hpp). */
SNELL_FN SnellParityOut caseHookMagLinear(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  o.a = SNELL_SAMPLE_LOD(parityTexMagLinear, vec2(a.x, a.y), a.z);
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}
