/*
description: the HLSL side of the language bridge (see glsl/snell/prelude.glsl).
  It maps the GLSL names the shared bodies use to HLSL ones, so glsl/snell/**
  compiles as HLSL unchanged. The entry files next to this one
  (optics.hlsl, camera.hlsl, intersect.hlsl, shade.hlsl, snell.hlsl) include
  this file and then the GLSL bodies; include one of them, not this file alone.
use:
  #include "snell/snell.hlsl"      // or snell/optics.hlsl, ... one family
  Include paths: the entry files reach the bodies with
  `#include "../../glsl/snell/<family>.glsl"`, which resolves both in the source
  tree (hlsl_like/snell next to glsl/snell) and in an install tree
  (share/snell/hlsl_like/snell next to share/snell/glsl/snell). Keep that layout
  when you copy the folders into an engine.
  Compilers: tested with glslang's HLSL front end (glslangValidator -D, shader
  model 5 style entry points) to SPIR-V, and executed (SPIR-V -> spirv-cross ->
  GLSL 450 on Mesa llvmpipe, compared with the C++ build). The bodies use plain
  SM 5 HLSL and spell every vector constructor out (no GLSL-style scalar splats
  such as float4(0.0f), which glslang accepts but DXC/FXC may reject).
options (define before including an entry file):
  SNELL_HLSL_SAMPLER     the SamplerState used by SNELL_SAMPLE_LOD (default: the
                         bridge declares `SamplerState snellLinearClampSampler;`
                         and your engine binds a linear, clamp-to-edge sampler
                         to it). In D3D the filter lives in the sampler, not in
                         the texture: snell's contract "filtered by the texture's
                         own filter state" means "by this sampler" here. The
                         intersectors read depth with SNELL_TEXEL_FETCH (no
                         sampler); SNELL_SAMPLE_LOD reads colour, normal and
                         environment images, plus the scene depth in
                         snellRefractionMaskDepth (bind a point sampler there,
                         or redefine SNELL_SAMPLE_LOD, to match a NEAREST GL
                         texture). Mipmapped reads need a sampler with a mip
                         filter (the GL texture's min filter in the GL build).
  SNELL_HLSL_FLIP_V      define when the textures snell reads are D3D render
                         targets (row 0 at the top). snell's uv has its origin
                         bottom-left (uv = 0.5 NDC.xy + 0.5, as in GL); with this
                         option the hooks flip v (SampleLevel) and the texel row
                         (Load) so the same uv math addresses D3D-oriented data.
                         Leave it undefined for Vulkan-style engines that already
                         flip the viewport, or when uploading GL-oriented data.
  SNELL_TEX2D, SNELL_TEXEL_FETCH, SNELL_SAMPLE_LOD, SNELL_TEXTURE_SIZE
                         the hooks themselves (see prelude.glsl); define any of
                         them first to redirect reads (Hi-Z chain, texture arrays,
                         linear depth, reversed Z, a per-texture sampler).
conventions that differ from GL (also in hlsl_like/README.md):
  - uv origin: snell's uv is bottom-left; D3D texture space is top-left. Either
    define SNELL_HLSL_FLIP_V or flip uv.y / the texel row in your own hooks.
  - depth: pass SNELL_DEPTH_ZERO_ONE (D3D / Vulkan 0..1) or SNELL_DEPTH_REVERSED
    (reversed Z, near -> 1) as the `convention` argument of the camera and
    intersect functions; SNELL_DEPTH_GL is for glDepthRange(0,1) buffers only.
  - matrices: snell's matrices are column-vector matrices as in GL
    (clip = clipFromView * v). Bodies multiply with SNELL_MUL(m, v) = mul(m, v).
    A GL-style float[16] (column-major) uploaded into a cbuffer float4x4 with
    HLSL's default column_major packing is the same matrix, so mul(m, v) works
    unchanged. If your engine packs row_major, or stores row-vector matrices
    (v * M, D3DX style), pass transpose(M). Matrices built in shader code from
    four columns must use SNELL_CAMERA_MAT4_COLUMNS(c0, c1, c2, c3)
    (glsl/snell/camera/conventions.glsl): HLSL's float4x4(a, b, c, d) takes rows,
    and m[i] is a row in HLSL but a column in GLSL.
  - handedness: snell's view space is right-handed, camera looking down -Z
    (points in front have z < 0). A left-handed engine (+Z forward) negates z on
    the way in and out (pView.z = -pEngine.z, same for directions and normals),
    or folds a scale(1, 1, -1) into clipFromView / viewFromClip.
contract: macros and one helper (snellHlslTextureSize); no snell function is
  defined here. Global `const` is a uniform in HLSL, hence #defines for constants.
*/
#ifndef SNELL_HLSL_BRIDGE
#define SNELL_HLSL_BRIDGE
#define SNELL_HLSL 1

/* GLSL type names. */
#define vec2 float2
#define vec3 float3
#define vec4 float4
#define ivec2 int2
#define ivec3 int3
#define ivec4 int4
#define uvec2 uint2
#define uvec3 uint3
#define uvec4 uint4
#define bvec2 bool2
#define bvec3 bool3
#define bvec4 bool4
#define mat2 float2x2
#define mat3 float3x3
#define mat4 float4x4

/* GLSL builtins with another HLSL name and the same meaning. (mod, atan(y, x),
   fract on negative numbers and % are kept out of the shared bodies instead:
   DESIGN.md sec. 1.) */
#define mix lerp
#define fract frac
#define inversesqrt rsqrt
#define dFdx ddx
#define dFdy ddy
#define floatBitsToInt asint
#define floatBitsToUint asuint
#define intBitsToFloat asfloat
#define uintBitsToFloat asfloat

#ifndef SNELL_TEX2D
#  define SNELL_TEX2D Texture2D<float4>
#endif

/* One sampler for SNELL_SAMPLE_LOD (see options above). */
#ifndef SNELL_HLSL_SAMPLER
#  define SNELL_HLSL_SAMPLER snellLinearClampSampler
SamplerState snellLinearClampSampler;
#endif

/* Level size from the base size, exactly as the GLSL hook computes it
   (max(size0 >> lod, 1)): the same answer as GetDimensions(lod) for a full mip
   chain, and immune to a Mesa 22.3 llvmpipe bug that evaluates a size query
   with one invocation's lod for a whole SIMD batch. GetDimensions has out
   parameters, hence the helper. */
int2 snellHlslTextureSize(Texture2D<float4> tex, int lod) {
  uint w, h, levels;
  tex.GetDimensions(0u, w, h, levels);
  return max(int2(int(w), int(h)) >> lod, int2(1, 1));
}

#ifndef SNELL_TEXTURE_SIZE
#  define SNELL_TEXTURE_SIZE(tex, lod) snellHlslTextureSize(tex, lod)
#endif
#if defined(SNELL_HLSL_FLIP_V)
#  ifndef SNELL_TEXEL_FETCH
#    define SNELL_TEXEL_FETCH(tex, px, lod) \
       ((tex).Load(int3((px).x, snellHlslTextureSize(tex, lod).y - 1 - (px).y, lod)))
#  endif
#  ifndef SNELL_SAMPLE_LOD
#    define SNELL_SAMPLE_LOD(tex, uv, lod) \
       ((tex).SampleLevel(SNELL_HLSL_SAMPLER, float2((uv).x, 1.0f - (uv).y), lod))
#  endif
#else
#  ifndef SNELL_TEXEL_FETCH
#    define SNELL_TEXEL_FETCH(tex, px, lod) ((tex).Load(int3(px, lod)))
#  endif
#  ifndef SNELL_SAMPLE_LOD
#    define SNELL_SAMPLE_LOD(tex, uv, lod) ((tex).SampleLevel(SNELL_HLSL_SAMPLER, uv, lod))
#  endif
#endif

#endif
