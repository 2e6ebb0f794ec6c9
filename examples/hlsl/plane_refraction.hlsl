// Two-interface refraction with Mayer & Assarsson's normal-based plane
// technique, as an HLSL pixel shader (shader model 5 style; compiled by
// tests/hlsl/check_hlsl.sh with `glslangValidator -D -e main -S frag -V`).
//
// Draw the refractive object's front faces with this shader after three passes:
//   1. the opaque scene without the object: colour, depth, view-space normals,
//      and its depth min/max pyramid (snellDepthMinMaxReduce / depth_pyramid);
//   2. the object's back faces: depth (farthest surface kept: clear to the near
//      value, depth test "farther passes"), view-space normals, its pyramid.
// The ray refracts at the front face, meets the back faces (plane
// technique, 2 refinement iterations), refracts again, then meets the opaque
// scene (plane technique again) or, when that fails, the environment.
//
// Engine conventions (see hlsl_like/README.md):
//  - render targets are D3D-oriented (row 0 at the top): SNELL_HLSL_FLIP_V lets
//    snell keep its GL uv (origin bottom-left, uv = 0.5 ndc.xy + 0.5);
//  - depth buffers are reversed Z (near -> 1): convention SNELL_DEPTH_REVERSED;
//  - matrices arrive as GL-style column-major float[16] (cbuffer default
//    column_major packing): mul(m, v) is the GL m * v;
//  - view space is right-handed, looking down -Z (a left-handed engine negates
//    z of positions and normals before calling snell, see the vertex outputs).
#define SNELL_HLSL_FLIP_V 1
// SNELL_SAMPLE_LOD (colour, normals, environment) reads through this sampler:
// bind a linear, clamp-to-edge sampler at s0. Depth is read with Load.
SamplerState linearClamp : register(s0);
#define SNELL_HLSL_SAMPLER linearClamp
#include "snell/snell.hlsl"

cbuffer SnellRefractionParams : register(b0) {
  float4x4 clipFromView;  // the projection both depth passes used
  float4x4 worldFromView; // environment lookups use world directions
  float3 absorption;      // Beer-Lambert sigma per channel, per view-space unit
  float ior;              // of the object (outside: 1)
  float zNear;
  float zFar;
  float backEmptyDepth;   // back-face depth clear value (reversed Z: 1, the near value)
  float sceneEmptyDepth;  // scene depth clear value (reversed Z: 0, the far value)
};

Texture2D<float4> backDepth : register(t0);
Texture2D<float4> backNormal : register(t1);
Texture2D<float4> backPyramid : register(t2);
Texture2D<float4> sceneDepth : register(t3);
Texture2D<float4> sceneNormal : register(t4);
Texture2D<float4> scenePyramid : register(t5);
Texture2D<float4> sceneColor : register(t6);
Texture2D<float4> environment : register(t7);  // equirectangular
// The object's front faces (depth and view-space normals): read only by a technique that follows rays
// bouncing inside (t.bounces > 0); bind any texture otherwise.
Texture2D<float4> frontLayerDepth : register(t8);
Texture2D<float4> frontLayerNormal : register(t9);

struct PSInput {
  float4 position : SV_Position;
  float3 viewPosition : TEXCOORD0;  // right-handed view space (z < 0 in front)
  float3 viewNormal : TEXCOORD1;    // front-face normal, view space
};

float4 main(PSInput input) : SV_Target {
  SnellDepthSurface back = snellDepthSurface(clipFromView, zNear, zFar, SNELL_DEPTH_REVERSED, backEmptyDepth);
  SnellDepthSurface scene = snellDepthSurface(clipFromView, zNear, zFar, SNELL_DEPTH_REVERSED, sceneEmptyDepth);
  // Front faces clear to the far value, as the scene does.
  SnellDepthSurface frontLayer = snellDepthSurface(clipFromView, zNear, zFar, SNELL_DEPTH_REVERSED, sceneEmptyDepth);

  SnellTechnique t = snellPresetPlaneNormal(2);
  t.exit.source = SNELL_SOURCE_BUFFERS;         // refract the painting behind the object
  t.exit.fallback = SNELL_FALLBACK_EDGE_FADE;   // off-screen exit: fade to the environment
  SnellMaterial m = snellMaterial();
  m.ior = ior;
  m.absorption = absorption;
  SnellView v = snellView();
  v.envX = float3(worldFromView[0][0], worldFromView[1][0], worldFromView[2][0]);  // columns
  v.envY = float3(worldFromView[0][1], worldFromView[1][1], worldFromView[2][1]);
  v.envZ = float3(worldFromView[0][2], worldFromView[1][2], worldFromView[2][2]);

  SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(
      input.viewPosition, input.viewNormal, 0.0f /* dN: Wyman's ISR only */,
      backDepth, backNormal, backPyramid, back, frontLayerDepth, frontLayerNormal, frontLayer,
      sceneDepth, sceneNormal, scenePyramid, sceneColor, scene, environment, t, m, v);
  return float4(r.color, 1.0f);
}
