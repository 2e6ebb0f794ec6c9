/* The shade/ parity cases' shared part (the cases themselves are described in
   tests/parity/shade_cases.cpp): the family's include and the three textures
   the sampling cases read (built by buildTextures() there); the camera's
   perspective, which the rough cone's case projects with. */
#include "snell/shade.glsl"
#include "snell/camera/perspective.glsl"

#if defined(SNELL_LANG_GLSL)
uniform sampler2D parityShadeScene;       /* LINEAR, rgb colour, alpha = Sousa's mask (0 inside) */
uniform sampler2D parityShadeReflection;  /* LINEAR, reflection / environment map */
uniform sampler2D parityShadeDepth;       /* NEAREST, opaque scene depth in .x */
#endif
#if defined(SNELL_LANG_HLSL)
Texture2D<float4> parityShadeScene;
Texture2D<float4> parityShadeReflection;
Texture2D<float4> parityShadeDepth;
#endif
