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
   - textures are not here: WGSL separates textures from samplers, so the host
     that writes the shader defines SNELL_TEX2D and the sampling hooks for its
     own bindings (the parity runtime: one texture and one sampler per
     texture the case reads). */
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

#endif
