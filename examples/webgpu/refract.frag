#version 450 core
#extension GL_GOOGLE_include_directive : require
// snell's two-interface refraction (normal plane, 2 iterations) in a WebGPU
// fragment shader: Vulkan GLSL that tools/webgpu/snell-wgsl turns into WGSL
// (tests: compile.wgsl_example). What WebGPU needs beyond the Vulkan recipe:
// the WebGPU prelude (isnan/isinf as bit tests), and textures as slots.
#include "snell_webgpu_prelude.glsl"

// WGSL has no combined image samplers and naga rejects a sampler2D passed to a
// function: a snell texture is a slot number, and the hooks pick slot k's
// texture2D and its own sampler (bindings 2k and 2k + 1 of group 1). Depth
// textures are r32float/rgba32float: unfilterable unless the device has
// float32-filterable, so give them non-filtering samplers (snell reads depth
// with texel fetches and NEAREST lookups); normals and colours may filter.
#define SLOT(k) \
  layout(set = 1, binding = 2 * k) uniform texture2D slotTexture##k; \
  layout(set = 1, binding = 2 * k + 1) uniform sampler slotSampler##k;
#define EACH_SLOT(M) M(0) M(1) M(2) M(3) M(4) M(5) M(6) M(7) M(8) M(9)
EACH_SLOT(SLOT)
#define SAMPLE(k) if (t == k) return textureLod(sampler2D(slotTexture##k, slotSampler##k), uv, lod);
#define FETCH(k) if (t == k) return texelFetch(sampler2D(slotTexture##k, slotSampler##k), px, lod);
#define SIZE(k) if (t == k) return textureSize(sampler2D(slotTexture##k, slotSampler##k), 0);
vec4 slotSampleLod(int t, vec2 uv, float lod) { EACH_SLOT(SAMPLE) return vec4(0.0f); }
vec4 slotTexelFetch(int t, ivec2 px, int lod) { EACH_SLOT(FETCH) return vec4(0.0f); }
ivec2 slotSize(int t) { EACH_SLOT(SIZE) return ivec2(0, 0); }
#define SNELL_TEX2D int
#define SNELL_SAMPLE_LOD(tex, uv, lod) slotSampleLod(tex, uv, lod)
#define SNELL_TEXEL_FETCH(tex, px, lod) slotTexelFetch(tex, px, lod)
#define SNELL_TEXTURE_SIZE(tex, lod) max(slotSize(tex) >> (lod), ivec2(1, 1))

// Only the strategy this technique's slots call (snellStrategiesUsed in C++): the dispatcher's other
// branches become constant-false (glslang and naga keep their code in the WGSL; the WebGPU compiler
// drops it).
#define SNELL_INTERSECT_STRATEGIES (1 << SNELL_STRATEGY_PLANE_NORMAL)
#include "snell/snell.glsl"

// The slots, in the order of SNELL_OBJECT_BUFFERS and SNELL_SCENE_BUFFERS.
const int backDepth = 0, backNormal = 1, backPyramid = 2, frontLayerDepth = 3, frontLayerNormal = 4;
const int sceneDepth = 5, sceneNormal = 6, scenePyramid = 7, sceneColor = 8, environment = 9;

layout(set = 0, binding = 0) uniform Frame {
  mat4 clipFromView;  // the buffers' projection
  vec4 nearFar;       // zNear, zFar
  mat4 envFromView;   // columns: envX, envY, envZ (world directions of the view axes)
};
layout(location = 0) in vec3 vsPosition;  // view-space position of the front face
layout(location = 1) in vec3 vsNormal;
layout(location = 0) out vec4 color;

void main() {
  // WebGPU's depth is zero-to-one; render the back faces with the compare function reversed (clear to 0).
  SnellDepthSurface back = snellDepthSurface(clipFromView, nearFar.x, nearFar.y, SNELL_DEPTH_ZERO_ONE, 0.0f);
  SnellDepthSurface frontLayer = snellDepthSurface(clipFromView, nearFar.x, nearFar.y, SNELL_DEPTH_ZERO_ONE, 1.0f);
  SnellDepthSurface scene = snellDepthSurface(clipFromView, nearFar.x, nearFar.y, SNELL_DEPTH_ZERO_ONE, 1.0f);
  scene.closed = false;
  SnellTechnique t = snellPresetPlaneNormal(2);
  t.exit.source = SNELL_SOURCE_BUFFERS;
  SnellView v = snellView();
  v.envX = envFromView[0].xyz;
  v.envY = envFromView[1].xyz;
  v.envZ = envFromView[2].xyz;
  SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(vsPosition, vsNormal, 0.0f, SNELL_OBJECT_BUFFER_ARGS,
                                                          SNELL_SCENE_BUFFER_ARGS, t, snellMaterial(), v);
  color = vec4(r.color, 1.0f);
}
