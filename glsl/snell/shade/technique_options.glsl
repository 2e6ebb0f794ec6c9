/*
description: what a two-interface refraction technique is made of, split by
  what each part describes and how long it lives:
  - SnellSlot: one place a ray is resolved (where it reads from, the
    intersection strategy and its parameters, what it shows when the buffers
    give nothing). A technique has four: back (where T1 leaves the object),
    exit (what T2 sees), reflect (what the first surface's reflected ray R
    sees, and a ray that leaves through the front faces after bouncing
    inside), inside (where a ray reflected inside the object leaves it). The
    exit and the reflection are the same call with their own slot.
  - bounces: how many total internal reflections inside the object a ray
    follows (0: none, the two-interface model); insideScene: whether the
    opaque scene has surfaces inside the object.
  - SnellTechnique: the technique's choices, the set of slots (the presets,
    technique_presets.glsl, return one).
  - SnellMaterial: the object's optics (IORs, dispersion, absorption, TIR
    policy, reflection on/off, roughness).
  - SnellView: the frame's constants (the environment's basis, the mip
    counts of the colour lookups).
  Each constructor fills every field with the documented default.
use: SnellTechnique t = snellTechnique();   // or a preset: snellPresetDir()
     t.back = snellSlot(SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_CBS);
     t.back.intersect.cbsSteps = 8;
     t.exit = snellSlot(SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_PLANE_NORMAL);
     SnellMaterial m = snellMaterial();
     m.ior = 1.33f;
     SnellView v = snellView();
options:
  sources (SnellSlot.source): SNELL_SOURCE_ENVIRONMENT 0 (the distant
  environment along the ray; the intersector is not run), SNELL_SOURCE_BUFFERS
  1 (the slot's intersector against the buffers of its layer: the back-face
  buffers for the back slot, the opaque scene's for exit and reflect),
  SNELL_SOURCE_WYMAN 2 (back slot only: Wyman 2005 distance interpolation
  between d_V and the per-vertex d_N; the intersector is not run; in the exit
  or reflect slot it reads as SNELL_SOURCE_BUFFERS)
  fallbacks when a BUFFERS slot finds nothing (exit and reflect slots):
  SNELL_FALLBACK_ENVIRONMENT 0 (the environment along the ray),
  SNELL_FALLBACK_EDGE_FADE 1 (scene colour at the clamped projection of origin
  + fallbackDistance dir, faded to the environment over edgeFadeWidth of uv
  near and beyond the screen edge)
contract (defaults):
  snellSlot(source, strategy): intersect = snellIntersectOptions(strategy),
    fallback = ENVIRONMENT, fallbackDistance = 1, edgeFadeWidth = 0.1.
  snellTechnique(): back = snellSlot(BUFFERS, CBS), exit =
    snellSlot(ENVIRONMENT, PLANE_NORMAL), reflect = snellSlot(ENVIRONMENT,
    LINEAR_MARCH) (the strategies are read only when the source becomes
    BUFFERS), inside = snellSlot(BUFFERS, LINEAR_MARCH) (the march between
    the front and back layers, intersect/inside_march.glsl, with the linear
    march's marchSteps, marchBisections and marchMaxDistance; PLANE_NORMAL:
    that march's bracket, then the normal plane on the layer it crossed,
    planeIterations times, intersect/inside_plane.glsl. Only these two
    work from inside: a ray inside starts on a layer, so a strategy that
    reads the surface at the ray origin's pixel (single sample, the plane
    methods' first plane, the far start) reads the face it leaves from, and
    one that tests the ray against one layer (CBS, the binary searches, DDA)
    cannot tell when it leaves: inside, it is behind the front layer and in
    front of the back one at once. CBS's binary search, run on the two-layer
    test, is the march's bisection (a march of few steps is its
    bracket). Any other
    strategy or source
    ends the path at the reflection, as a fallback), bounces = 0 (clamped to
    [0, SNELL_MAX_BOUNCES], default 4, a compile-time bound), insideScene =
    false (true: the opaque scene may have surfaces inside the object, a
    candle in a hurricane glass, a card in a paperweight: the refracted ray
    is also run against the scene buffers with the exit slot's strategy, and
    the nearer of that hit and the back faces ends the first segment,
    two_interface_shade.glsl; the scene buffers are read whatever the exit
    slot's source; one more scene search per trace, so set it only where
    something opaque is inside).
  snellMaterial(): ior = 1.5, iorOutside = 1, dispersion = 1 (one trace; 3 =
    one per channel with iors, e.g. snellDispersionIors(1.5168f, 64.17f) from
    shade/dispersion.glsl), iors = (1.5, 1.5, 1.5), absorption = 0
    (Beer-Lambert sigma per channel, per view unit), tirPolicy =
    SNELL_TIR_CRITICAL (both interfaces; Wyman 2005, O&B 2007 sec. 5),
    reflection = true (Fresnel-weighted reflection at the first interface),
    roughness = 0.
  snellView(): envX/envY/envZ = the columns of the world-from-view rotation
    used for environment lookups (identity), sceneColorLevels =
    environmentLevels = 1 (mip levels the rough cone reads,
    shade/rough_cone.glsl).
source: the composition of DESIGN.md sec. 2 (a technique = optics, an
  intersector against the back faces, optics, an intersector against the scene
  or an environment lookup); Oliveira & Brauwers 2007 sec. 3; Wyman 2005;
  Mayer & Assarsson, "Constant-Time Light Refraction Simulation".
*/
#ifndef SNELL_SHADE_TECHNIQUE_OPTIONS_GLSL
#define SNELL_SHADE_TECHNIQUE_OPTIONS_GLSL
#include "../prelude.glsl"
#include "../optics/refract.glsl"
#include "../intersect/intersect_with.glsl"

#define SNELL_SOURCE_ENVIRONMENT 0
#define SNELL_SOURCE_BUFFERS 1
#define SNELL_SOURCE_WYMAN 2

#define SNELL_FALLBACK_ENVIRONMENT 0
#define SNELL_FALLBACK_EDGE_FADE 1

struct SnellSlot {
  int source;
  SnellIntersectOptions intersect;
  int fallback;
  float fallbackDistance;
  float edgeFadeWidth;
};

#ifndef SNELL_MAX_BOUNCES
#  define SNELL_MAX_BOUNCES 4
#endif

struct SnellTechnique {
  SnellSlot back;
  SnellSlot exit;
  SnellSlot reflect;
  SnellSlot inside;
  int bounces;
  bool insideScene;
};

struct SnellMaterial {
  float ior;
  float iorOutside;
  int dispersion;
  vec3 iors;
  vec3 absorption;
  int tirPolicy;
  bool reflection;
  float roughness;
};

struct SnellView {
  vec3 envX;
  vec3 envY;
  vec3 envZ;
  int sceneColorLevels;
  int environmentLevels;
};

SNELL_FN SnellSlot snellSlot(int source, int strategy) {
  SnellSlot s;
  s.source = source;
  s.intersect = snellIntersectOptions(strategy);
  s.fallback = SNELL_FALLBACK_ENVIRONMENT;
  s.fallbackDistance = 1.0f;
  s.edgeFadeWidth = 0.1f;
  return s;
}

SNELL_FN SnellTechnique snellTechnique() {
  SnellTechnique t;
  t.back = snellSlot(SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_CBS);
  t.exit = snellSlot(SNELL_SOURCE_ENVIRONMENT, SNELL_STRATEGY_PLANE_NORMAL);
  t.reflect = snellSlot(SNELL_SOURCE_ENVIRONMENT, SNELL_STRATEGY_LINEAR_MARCH);
  t.inside = snellSlot(SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_LINEAR_MARCH);
  t.bounces = 0;
  t.insideScene = false;
  return t;
}

SNELL_FN SnellMaterial snellMaterial() {
  SnellMaterial m;
  m.ior = 1.5f;
  m.iorOutside = 1.0f;
  m.dispersion = 1;
  m.iors = vec3(1.5f, 1.5f, 1.5f);
  m.absorption = vec3(0.0f, 0.0f, 0.0f);
  m.tirPolicy = SNELL_TIR_CRITICAL;
  m.reflection = true;
  m.roughness = 0.0f;
  return m;
}

SNELL_FN SnellView snellView() {
  SnellView v;
  v.envX = vec3(1.0f, 0.0f, 0.0f);
  v.envY = vec3(0.0f, 1.0f, 0.0f);
  v.envZ = vec3(0.0f, 0.0f, 1.0f);
  v.sceneColorLevels = 1;
  v.environmentLevels = 1;
  return v;
}

#endif
