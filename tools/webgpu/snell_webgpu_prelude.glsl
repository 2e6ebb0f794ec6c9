/* snell's language hooks for WebGPU: Vulkan GLSL that glslang compiles to
   SPIR-V and naga translates to WGSL. Include it after #version and before
   snell/prelude.glsl (the WebGPU parity runtime does,
   include/snell/gpu/parity_webgpu.hpp).
   - isnan / isinf: WGSL has neither and naga's WGSL writer rejects them, so
     both become bit tests on floatBitsToUint: exact for every float, and
     immune to a compiler that assumes no NaN. The function-like macros
     cover every direct call in snell's bodies (SNELL_FINITE is a bit test
     in prelude.glsl already).
   - SNELL_FLT_MAX by its bits (below), so the WGSL has no literal Tint
     rejects.
   - `precise` stays: glslang marks the operations NoContraction, which naga
     drops (WGSL cannot say it); on lavapipe the results equal the Vulkan
     runtime's bit for bit.
   - textures, when SNELL_WEBGPU_SAMPLER, defined before this file, names a
     `uniform sampler` the shader declares (examples/webgpu/refract.frag):
     WGSL has no combined image samplers and naga refuses a sampler2D passed
     to a function, so a snell texture is a texture2D (SNELL_TEX2D), bound as
     the shader declares it and passed to snell's functions as it is;
     SNELL_SAMPLE_LOD reads it through that one sampler (as the HLSL bridge's
     SNELL_HLSL_SAMPLER does: linear and clamp-to-edge for normals, colours
     and the environment), SNELL_TEXEL_FETCH and SNELL_TEXTURE_SIZE need none
     (WGSL's textureLoad and textureDimensions), so depth textures may be
     unfilterable. A host that needs a texture's own filters defines
     SNELL_TEX2D and the hooks itself instead (the parity runtime: each
     texture a slot number with its own sampler,
     include/snell/gpu/parity_webgpu.hpp). */
#ifndef SNELL_WEBGPU_PRELUDE_GLSL
#define SNELL_WEBGPU_PRELUDE_GLSL

bool snellWebgpuIsNan(float x) { return (floatBitsToUint(x) & 0x7fffffffu) > 0x7f800000u; }
bvec2 snellWebgpuIsNan(vec2 x) { return greaterThan(floatBitsToUint(x) & uvec2(0x7fffffffu), uvec2(0x7f800000u)); }
bvec3 snellWebgpuIsNan(vec3 x) { return greaterThan(floatBitsToUint(x) & uvec3(0x7fffffffu), uvec3(0x7f800000u)); }
bvec4 snellWebgpuIsNan(vec4 x) { return greaterThan(floatBitsToUint(x) & uvec4(0x7fffffffu), uvec4(0x7f800000u)); }
bool snellWebgpuIsInf(float x) { return (floatBitsToUint(x) & 0x7fffffffu) == 0x7f800000u; }
bvec2 snellWebgpuIsInf(vec2 x) { return equal(floatBitsToUint(x) & uvec2(0x7fffffffu), uvec2(0x7f800000u)); }
bvec3 snellWebgpuIsInf(vec3 x) { return equal(floatBitsToUint(x) & uvec3(0x7fffffffu), uvec3(0x7f800000u)); }
bvec4 snellWebgpuIsInf(vec4 x) { return equal(floatBitsToUint(x) & uvec4(0x7fffffffu), uvec4(0x7f800000u)); }
#define isnan(x) snellWebgpuIsNan(x)
#define isinf(x) snellWebgpuIsInf(x)
/* The largest finite float by its bits: naga writes the decimal literal with 39
   digits, which Tint (Dawn, Chrome) rejects as not representable in f32. */
#define SNELL_FLT_MAX uintBitsToFloat(0x7f7fffffu)

#ifdef SNELL_WEBGPU_SAMPLER
#  define SNELL_TEX2D texture2D
#  define SNELL_SAMPLE_LOD(tex, uv, lod) textureLod(sampler2D(tex, SNELL_WEBGPU_SAMPLER), uv, lod)
#  define SNELL_TEXEL_FETCH(tex, px, lod) texelFetch(sampler2D(tex, SNELL_WEBGPU_SAMPLER), px, lod)
#  define SNELL_TEXTURE_SIZE(tex, lod) max(textureSize(sampler2D(tex, SNELL_WEBGPU_SAMPLER), 0) >> (lod), ivec2(1, 1))
/* a cube-map environment (shade/environment.glsl: SNELL_ENVIRONMENT_TEX SNELL_TEXCUBE) is a textureCube */
#  define SNELL_TEXCUBE textureCube
#  define SNELL_SAMPLE_CUBE_LOD(tex, dir, lod) textureLod(samplerCube(tex, SNELL_WEBGPU_SAMPLER), dir, lod)
#endif

#endif
