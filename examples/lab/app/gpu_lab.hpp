// The lab's GL pipeline on one context (OSMesa or EGL, Mesa llvmpipe by
// default): (1) the whole opaque scene (environment background, paintings:
// colour, depth, view-space normal), (2) each refractive object's back faces
// (depth GL_GREATER after clearing to 0, front faces culled, normals) and front
// faces (depth GL_LESS after clearing to 1, normals), (3) the depth min/max
// pyramids (glsl/passes/depth_pyramid.frag), then per object, back to front:
// (1b) the scene layer the object reads (SceneLayer): the opaque scene behind
// its nearest point and the objects already drawn, with the colours the frame
// holds for them so far (examples/glsl/lab_layer.frag), and its pyramid,
// (4) the object's front faces with one technique
// (examples/glsl/lab_refract.frag), depth-tested against the whole opaque
// scene (its depth copied in first, as an engine draws its glass after its
// opaque pass): colour, per-pixel stats and the fragment inputs, in RGBA32F
// attachments.
#pragma once
#include "lab/scene.hpp"

#include <snell/bridge.hpp>
#include <snell/shade.hpp>

#include "technique.hpp"  // LabParams (lab_technique.glsl)

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace snell::lab {

// Where the shaders live: `labGlsl` holds lab_*.frag/vert, `snellGlsl` is the
// library's glsl/ directory (with passes/: the pyramid pass and the full-screen
// vertex stage).
struct ShaderDirs {
  std::filesystem::path labGlsl;
  std::filesystem::path snellGlsl;
};

// Read back after passes 1-3 and 1b for one object: the viewport plus the guard band on every side
// (ShadeConstants::margin texels), rendered with ShadeConstants::params.clipFromView.
struct StaticBuffers {
  // The layer of the scene that snell's rows read for the object (SceneLayer; the objects drawn before it
  // included): depth in .x (window depth, GL convention, 1 = empty).
  Image sceneColor, sceneDepth, sceneNormal;
  // The whole opaque scene: what the picture shows around the object, what the object is depth-tested
  // against, and what the engine rows read (their opaque colour copy).
  Image fullColor, fullDepth, fullNormal;
  // Which surface each texel of the scene layer and of the whole opaque scene shows, in .x: 0 the environment,
  // k + 1 painting k, -(o + 1) object o (drawn before). The lab's leak count names what leaked with it; no
  // technique reads it, and the memory report leaves it out.
  Image sceneSurface, fullSurface;
  // With a rough object: the scene layer's colour mip levels 1, 2, ... as the GPU built them (its colour
  // pyramid pass, shade/color_pyramid.glsl), which the C++ side samples as they are.
  std::vector<Image> sceneColorMips;
  std::vector<Image> fullColorMips;  // ... and of the whole scene's colour (the engine rows'), the same pass
  Image backDepth, backNormal;                // depth in .x (0 = empty)
  Image frontDepth, frontNormal;              // the object's front faces: depth in .x (1 = empty)
};

// Read back after pass 4.
struct TechniqueBuffers {
  Image color;     // rgb linear, a = 1 on the object
  Image stats;     // x fell back, y fetches, z back hit, w exit hit
  Image position;  // xyz view-space front position, w d_N
  Image normal;    // xyz interpolated front normal, w coverage (1 on the object)
};

// Which layer of the opaque scene snell's rows read (their exit and reflect slots). Behind: only what lies
// beyond the object's nearest point (the scene drawn with a clip plane there), so an opaque object between
// the camera and the glass is not in the buffers the refraction reads and what it hides is; Full: the
// whole opaque scene, as an engine's colour copy holds it (the foreground rule then refuses the hits on
// it, intersect/foreground.glsl, and the slot falls back); Peeled: only what lies behind the object's
// back faces at each texel (the scene drawn after the back faces, discarding what is nearer): all that an
// exit ray leaving a convex object can meet, without what stands in front of the object or inside it. The
// engine rows always read the whole scene.
enum class SceneLayer { Behind, Full, Peeled };

// How both sides read the normal buffers (back faces and opaque scene): GL_LINEAR
// (the default: empty texels hold a zero normal, so a filtered read renormalized
// blends only the surface's own normals, also at the silhouette) or GL_NEAREST.
enum class NormalFilter { Linear, Nearest };

// The frame's constants: what labShade takes on both sides (params: the GPU
// gets these bytes as the uniform block LabUniforms), and what only the host
// passes need.
struct ShadeConstants {
  // params.clipFromView is the buffers' projection (the guard band, below); depthFilter and reflectSource
  // keep their defaults (SNELL_DEPTH_FILTER_NEAREST, SNELL_SOURCE_BUFFERS) until the caller sets them.
  LabParams params = defaultLabParams();
  mat4 viewFromWorld{1.0f};
  mat4 clipFromView{1.0f};        // the viewport's projection (the front-face pass, the pictures)
  // The guard band: the scene and back-face buffers cover `margin` more texels on every side, at the same
  // texel density, through params.clipFromView (clipFromView with x and y scaled by W / (W + 2 margin),
  // H / (H + 2 margin)); the techniques read the buffers through it, so exits just off the viewport are found.
  int margin = 0;
  NormalFilter normalFilter = NormalFilter::Linear;   // how both sides read the normal buffers
  SceneLayer sceneLayer = SceneLayer::Behind;         // what snell's rows read
  // The object's nearest view distance (its vertices'): where the Behind layer's clip plane lies, and
  // the key of the back-to-front order (drawOrder).
  float objectNearDistance = 0.0f;
  // The object that contains this one (nested media, -1: none). params.ior stays the object's own index
  // (shadeConstants says why).
  int enclosing = -1;

  static LabParams defaultLabParams() {
    LabParams p{};
    p.clipFromView = mat4(1.0f);
    p.zNear = 0.1f;
    p.zFar = 100.0f;
    p.ior = 1.5f;
    p.iors = vec3(1.5f);
    p.dispersion = 0;
    p.absorption = vec3(0.0f);
    p.envX = vec3(1, 0, 0);
    p.envY = vec3(0, 1, 0);
    p.envZ = vec3(0, 0, 1);
    p.backRange = 10.0f;  // object bounding-box diagonal
    p.exitRange = 10.0f;  // diagonal of the box around object and opaque scene
    p.depthFilter = SNELL_DEPTH_FILTER_NEAREST;
    p.reflectSource = SNELL_SOURCE_BUFFERS;
    p.insideScene = 0;  // shadeConstants: 1 when a painting reaches inside the object
    p.proxyFromView = mat4(1.0f);  // shadeConstants: the world-axis box around the object and the paintings
    p.roughness = 0.0f;
    p.sceneColorLevels = 1;  // shadeConstants: the full chains when an object is rough
    p.environmentLevels = 1;
    p.pad0 = 0;
    return p;
  }
};
// The frame's constants for frame.objects[object] with a guard band of `margin` texels per side; the read
// modes keep their defaults (set the fields). An object inside another (all its vertices inside that
// object's mesh; the innermost such object) is `enclosing` it; insideScene is on when a painting or another
// object reaches inside it.
ShadeConstants shadeConstants(const SceneFrame& frame, std::size_t object, int margin = 0);

// The order the lab draws the objects in: back to front by their nearest point (ShadeConstants::
// objectNearDistance), so an object inside another (its nearest point farther) comes before it; ties
// keep the file's order. Each object's exit and reflect slots read the ones drawn before it.
std::vector<std::size_t> drawOrder(const std::vector<ShadeConstants>& objects);

// The environment's picture, its intensity applied (what environmentTexture samples, without a chain).
Image environmentImage(const SceneFrame& frame);
// The environment as every row samples it: intensity applied, GL_LINEAR, clamp to edge; with a rough
// object, its colour pyramid too (snellBuildColorPyramid, trilinear): the chain snell's rough reads expect,
// and, like the engines' prefiltered environments, a smooth one.
Texture2D environmentTexture(const SceneFrame& frame);
// Whether an object of the frame is rough (then the scene colour and the environment carry mip chains).
bool roughObjects(const SceneFrame& frame);
// The levels of a full mip chain of a width x height texture (floor(log2(max)) + 1).
int mipLevels(int width, int height);

// One pass-4 program: a technique of the table (SNELL_TECHNIQUE_*, `reference` for the table's Reference rows)
// or, when engineModel >= 0, that engine model (SNELL_ENGINE_*).
struct LabShader {
  int technique = -1;
  bool reference = false;
  int engineModel = -1;
  bool readsFullScene() const { return engineModel >= 0; }  // an engine row reads its colour copy
};

class GpuLab {
 public:
  // backend: "auto", "osmesa" or "egl". `shaders`: one program each. dN[i]: Wyman's d_N per vertex of
  // frame.objects[i] (zeros when absent or empty). k[i]: shadeConstants(frame, i, margin) with the read
  // modes the C++ side uses too (margin and read modes the same for every object).
  GpuLab(const std::string& backend, const SceneFrame& frame, const std::vector<std::vector<float>>& dN,
         const std::vector<LabShader>& shaders, const ShaderDirs& dirs, const std::vector<ShadeConstants>& k);
  ~GpuLab();
  GpuLab(const GpuLab&) = delete;
  GpuLab& operator=(const GpuLab&) = delete;

  std::string description() const;  // backend, GL renderer and version
  // Binds this lab's context to the thread again after another GpuLab used it (an animated run draws each
  // further frame with its own), so that what follows, its destructor included, reaches its own objects.
  void makeCurrent() const;

  // Passes 1-3; returns their wall time in ms (glFinish on both sides).
  double renderStatic();
  // Pass 1b for `object`: its scene layer, with the objects in `drawn` (drawn before it) coloured as
  // `composite` holds them (the frame so far, buffer-sized: viewport plus guard band; nullptr when `drawn`
  // is empty). Returns its wall time in ms (the composite's upload not included).
  double renderLayer(std::size_t object, const std::vector<std::size_t>& drawn, const Image* composite);
  // The buffers `object` is shaded from: its own and the scene layer pass 1b drew last.
  StaticBuffers readStatic(std::size_t object) const;
  // GPU memory of one object's own buffers (mesh, back and front faces, back-face pyramid), bytes.
  std::size_t objectBytes(std::size_t object) const;
  // GPU memory shared by all objects (the scene layers and their pyramids, the refraction pass's targets).
  std::size_t sharedBytes() const;

  // Pass 4 of `object` with shaders[index]: glFinish, steady clock, draw, glFinish.
  // Returns the pass's wall time in ms. `backSide`: the object's back faces instead, their normal turned to
  // the camera (an engine model only: three.js's WebGPU order shades them).
  double renderTechnique(std::size_t index, std::size_t object, bool backSide = false);
  // The free value of shaders[index]'s engine model (0 until set).
  void setEngineParameter(std::size_t index, float value);
  // The colour copy the engine rows read (buffer-sized; Bevy's steps copy the frame so far before each group
  // of objects); nullptr: the whole opaque scene's colour, as the one copy of every engine row.
  void setColorCopy(const Image* frame);
  TechniqueBuffers readTechnique() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace snell::lab
