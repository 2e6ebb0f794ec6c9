#version 450 core
#extension GL_GOOGLE_include_directive : require
// snell's two-interface refraction (normal plane, 2 iterations) in a WebGPU
// fragment shader: Vulkan GLSL that tools/webgpu/snell-wgsl turns into WGSL
// (tests: compile.wgsl_example). What WebGPU needs beyond the Vulkan recipe:
// the WebGPU prelude (isnan/isinf as bit tests, snell's textures as texture2D)
// and one sampler.

// WGSL has no combined image samplers and naga refuses a sampler2D passed to a
// function: each texture is a texture2D, bound where it is declared below, and
// snell's functions take it as it is. With SNELL_WEBGPU_SAMPLER defined before
// the prelude, texel fetches and sizes (every depth read) use no sampler, and
// the filtered reads (normals, colour, environment) use this one: linear,
// clamp to edge. Depth textures (r32float, rgba32float) may therefore be
// unfilterable; filtered rgba32float needs the float32-filterable feature.
layout(set = 1, binding = 0) uniform sampler linearClamp;
#define SNELL_WEBGPU_SAMPLER linearClamp
#include "snell_webgpu_prelude.glsl"

// Only the strategy this technique's slots call (snellStrategiesUsed in C++): the dispatcher's other
// branches become constant-false, and snell-wgsl leaves them, and the searches only they call, out.
#define SNELL_INTERSECT_STRATEGIES (1 << SNELL_STRATEGY_PLANE_NORMAL)
#include "snell/snell.glsl"

// The textures, under the names and in the order of SNELL_OBJECT_BUFFERS and SNELL_SCENE_BUFFERS
// (shade/technique_buffers.glsl).
layout(set = 1, binding = 1) uniform texture2D backDepth;
layout(set = 1, binding = 2) uniform texture2D backNormal;
layout(set = 1, binding = 3) uniform texture2D backPyramid;
layout(set = 1, binding = 4) uniform texture2D frontLayerDepth;
layout(set = 1, binding = 5) uniform texture2D frontLayerNormal;
layout(set = 1, binding = 6) uniform texture2D sceneDepth;
layout(set = 1, binding = 7) uniform texture2D sceneNormal;
layout(set = 1, binding = 8) uniform texture2D scenePyramid;
layout(set = 1, binding = 9) uniform texture2D sceneColor;
layout(set = 1, binding = 10) uniform texture2D environment;

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
