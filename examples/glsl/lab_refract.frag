#version 450 core
#extension GL_GOOGLE_include_directive : require  // or resolve includes your own way
// snell-lab pass 4: the refractive object's front faces, shaded with one
// technique (LAB_TECHNIQUE, a SNELL_TECHNIQUE_* id, and LAB_REFERENCE, whether its row of the
// technique table is a Reference; both set by the host before compiling) through
// labShadeRow (lab_technique.glsl; or LAB_ENGINE_MODEL, an engine model), the very function snell-lab runs per pixel in
// C++ on the read-back buffers. Outputs: colour, per-pixel stats, and the
// fragment's inputs (position, normal, d_N) so the CPU evaluates the same pixel.
#ifndef LAB_TECHNIQUE
#  define LAB_TECHNIQUE SNELL_TECHNIQUE_PLANE_NORMAL_1
#endif
#ifndef LAB_REFERENCE
#  define LAB_REFERENCE false
#endif
// An engine row: LAB_ENGINE_MODEL is a SNELL_ENGINE_* id (then LAB_TECHNIQUE is not run) and the
// uniform labEngineParameter its free value.
#ifndef LAB_ENGINE_MODEL
#  define LAB_ENGINE_MODEL -1
#endif
#include "lab_technique.glsl"

layout(location = 0) in vec3 vsPosition;
layout(location = 1) in vec3 vsNormal;
layout(location = 2) in float vsDn;

layout(binding = 0) uniform sampler2D backDepth;
layout(binding = 1) uniform sampler2D backNormal;
layout(binding = 2) uniform sampler2D backPyramid;
layout(binding = 3) uniform sampler2D sceneDepth;
layout(binding = 4) uniform sampler2D sceneNormal;
layout(binding = 5) uniform sampler2D scenePyramid;
layout(binding = 6) uniform sampler2D sceneColor;
layout(binding = 7) uniform sampler2D environment;
layout(binding = 8) uniform sampler2D frontLayerDepth;
layout(binding = 9) uniform sampler2D frontLayerNormal;
// The frame's constants, the host's LabParams bytes as they are (std140).
layout(std140, binding = 0) uniform LabUniforms { LabParams params; };
uniform float labEngineParameter;
// 1: the mesh's back faces are drawn (an engine order that shades them, three.js's WebGPU one): the normal is
// turned to the camera, as three.js does for a back side.
uniform int labBackSide;

layout(location = 0) out vec4 color;
layout(location = 1) out vec4 stats;     // x fell back, y texel fetches, z back hit, w exit hit
layout(location = 2) out vec4 position;  // xyz view-space front position, w d_N
layout(location = 3) out vec4 normal;    // xyz interpolated front normal, w 1 (coverage)

void main() {
  vec3 n = labBackSide != 0 ? -vsNormal : vsNormal;
  SnellTwoInterfaceResult r = labShadeRow(LAB_TECHNIQUE, LAB_ENGINE_MODEL, labEngineParameter, LAB_REFERENCE, vsPosition,
                                          n, vsDn, backDepth, backNormal, backPyramid, frontLayerDepth,
                                          frontLayerNormal, sceneDepth, sceneNormal, scenePyramid, sceneColor, environment,
                                          params);
  color = vec4(r.color, 1.0f);
  stats = vec4(r.fellBack ? 1.0f : 0.0f, float(r.fetches), r.backHit ? 1.0f : 0.0f, r.exitHit.valid ? 1.0f : 0.0f);
  position = vec4(vsPosition, vsDn);
  normal = vec4(n, 1.0f);
}
