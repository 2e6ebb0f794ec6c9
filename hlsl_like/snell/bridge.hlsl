// The HLSL side of the language bridge (see glsl/snell/prelude.glsl): GLSL names
// mapped to HLSL ones so the shared bodies compile unchanged. Include this, then
// the snell family files (hlsl_like/snell/*.hlsl do both).
#ifndef SNELL_HLSL_BRIDGE
#define SNELL_HLSL_BRIDGE
#define SNELL_HLSL 1

#define vec2 float2
#define vec3 float3
#define vec4 float4
#define ivec2 int2
#define ivec3 int3
#define ivec4 int4
#define bvec2 bool2
#define bvec3 bool3
#define bvec4 bool4
#define mat2 float2x2
#define mat3 float3x3
#define mat4 float4x4
#define mix lerp
#define fract frac
#define inversesqrt rsqrt
#define dFdx ddx
#define dFdy ddy

#ifndef SNELL_TEX2D
#  define SNELL_TEX2D Texture2D<float4>
#endif
// HLSL samples through a SamplerState; snell uses one linear, clamp-to-edge sampler
// the engine binds (define SNELL_HLSL_SAMPLER to use your own).
#ifndef SNELL_HLSL_SAMPLER
#  define SNELL_HLSL_SAMPLER snellLinearClampSampler
SamplerState snellLinearClampSampler;
#endif
#ifndef SNELL_TEXEL_FETCH
#  define SNELL_TEXEL_FETCH(tex, px, lod) ((tex).Load(int3(px, lod)))
#endif
#ifndef SNELL_SAMPLE_LOD
#  define SNELL_SAMPLE_LOD(tex, uv, lod) ((tex).SampleLevel(SNELL_HLSL_SAMPLER, uv, lod))
#endif
#ifndef SNELL_TEXTURE_SIZE
// GetDimensions has out parameters, so size queries go through a helper.
int2 snellHlslTextureSize(Texture2D<float4> tex, int lod) {
  uint w, h, levels;
  tex.GetDimensions(uint(lod), w, h, levels);
  return int2(int(w), int(h));
}
#  define SNELL_TEXTURE_SIZE(tex, lod) snellHlslTextureSize(tex, lod)
#endif
#endif
