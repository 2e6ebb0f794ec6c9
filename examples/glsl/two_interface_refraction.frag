#version 450 core
#extension GL_GOOGLE_include_directive : require  // or resolve includes your own way
// snell's two-interface refraction (normal plane, 2 iterations, or any row of
// the technique table) in one fragment shader: the GLSL twin of examples/hlsl/plane_refraction.hlsl and
// examples/webgpu/refract.frag. Portable: compiles unchanged after any of
// #version 330 core, 450 core, 300 es, 310 es, or as Vulkan GLSL
// (tests/compile/check_glsl.sh). The buffers it reads, their formats and
// filters: examples/lab/README.md; the host side: docs/recipes.md.
#ifdef GL_ES
precision highp float;
precision highp int;
precision highp sampler2D;
#endif
// The technique: a row of the technique table (shade/technique_presets.glsl),
// and only the strategies its slots call (snellStrategiesUsed in C++): the
// others are not compiled, which is most of the compile time. A host that
// builds one program per technique defines both before this file
// (benchmarks/compile_times does, for every row).
#ifndef EXAMPLE_TECHNIQUE
#  define EXAMPLE_TECHNIQUE SNELL_TECHNIQUE_PLANE_NORMAL_2
#  define SNELL_INTERSECT_STRATEGIES (1 << SNELL_STRATEGY_PLANE_NORMAL)
#endif
#include "snell/snell.glsl"

// Vulkan needs locations on every in/out and bindings on every uniform; GLSL
// 330 and ES 3.00 allow neither here (the host sets sampler units by name).
#ifdef VULKAN
#  define AT(n) layout(location = n)
#  define BIND(n) layout(binding = n)
#  define FRAME layout(std140, binding = 10)
#else
#  define AT(n)
#  define BIND(n)
#  define FRAME layout(std140)
#endif

// The object's back faces (depth, normal, their min/max depth pyramid) and
// front layer, then the opaque scene (depth, normal, pyramid, colour) and the
// environment: the order of SNELL_OBJECT_BUFFERS and SNELL_SCENE_BUFFERS.
BIND(0) uniform sampler2D backDepth;
BIND(1) uniform sampler2D backNormal;
BIND(2) uniform sampler2D backPyramid;
BIND(3) uniform sampler2D frontLayerDepth;
BIND(4) uniform sampler2D frontLayerNormal;
BIND(5) uniform sampler2D sceneDepth;
BIND(6) uniform sampler2D sceneNormal;
BIND(7) uniform sampler2D scenePyramid;
BIND(8) uniform sampler2D sceneColor;
BIND(9) uniform sampler2D environment;

FRAME uniform Frame {
  mat4 clipFromView;  // the buffers' projection
  vec4 nearFar;       // zNear, zFar
  mat4 envFromView;   // columns: envX, envY, envZ (world directions of the view axes)
};

AT(0) in vec3 vsPosition;  // view-space position of the front face
AT(1) in vec3 vsNormal;
AT(0) out vec4 color;

void main() {
  // GL depth (glDepthRange 0..1 of a glm::perspective projection); the back faces rendered with
  // GL_GREATER after clearing depth to 0, so their "nothing there" value is 0.
  SnellDepthSurface back = snellDepthSurface(clipFromView, nearFar.x, nearFar.y, SNELL_DEPTH_GL, 0.0f);
  SnellDepthSurface frontLayer = snellDepthSurface(clipFromView, nearFar.x, nearFar.y, SNELL_DEPTH_GL, 1.0f);
  SnellDepthSurface scene = snellDepthSurface(clipFromView, nearFar.x, nearFar.y, SNELL_DEPTH_GL, 1.0f);
  scene.closed = false;
  SnellTechnique t = snellTechniquePreset(EXAMPLE_TECHNIQUE);
  t.exit.source = SNELL_SOURCE_BUFFERS;
  SnellView v = snellView();
  v.envX = vec3(envFromView[0].x, envFromView[0].y, envFromView[0].z);
  v.envY = vec3(envFromView[1].x, envFromView[1].y, envFromView[1].z);
  v.envZ = vec3(envFromView[2].x, envFromView[2].y, envFromView[2].z);
  SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(vsPosition, vsNormal, 0.0f, SNELL_OBJECT_BUFFER_ARGS,
                                                          SNELL_SCENE_BUFFER_ARGS, t, snellMaterial(), v);
  color = vec4(r.color, 1.0f);
}
