/*
description: two-interface refraction, shaded: the full technique a fragment
  shader calls for a front-face fragment of a refractive object. Trace the
  path through the object (two_interface.glsl), resolve the exit ray against
  the opaque scene behind the object (its depth, normal, pyramid and colour
  buffers, with any strategy: Mayer & Assarsson's painting behind a glass
  sphere) or against a distant environment, with a documented fallback when
  the scene hit is not found; absorb along the path inside (Beer-Lambert), add
  the Fresnel-weighted environment reflection at the first interface;
  optionally once per colour channel (chromatic dispersion) and with blurred
  (roughness) lookups.
use: SnellTechniqueOptions o = snellPresetDir();   // or any preset, then adjust
     o.exitMode = SNELL_EXIT_SCENE;
     SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(frontPosition, frontNormal, dN,
         backDepth, backNormal, backPyramid, backSurface,
         sceneDepth, sceneNormal, scenePyramid, sceneColor, sceneSurface, environment, o);
     fragColor = vec4(r.color, 1.0f);
     SnellTwoInterfaceExit e = snellTwoInterfaceExit(origin, dir, sceneDepth, sceneNormal,
         scenePyramid, sceneColor, sceneSurface, environment, o);   // the exit slot alone
  frontPosition, frontNormal, dN, back*: as snellTwoInterfaceTrace
  sceneDepth, sceneNormal, scenePyramid, sceneSurface: the opaque scene without the
                 object, read by o.exit (normals for PLANE_NORMAL, the pyramid
                 for the search range and PLANE_DEPTH); any textures in
                 environment mode (never read)
  sceneColor     the opaque scene's colour (mipmapped for roughness > 0)
  environment    SNELL_ENVIRONMENT_TEX: an equirectangular 2D texture by
                 default, a cube map through the hook (environment.glsl); looked
                 up with world directions: envX, envY, envZ = the columns of
                 the world-from-view rotation
  o              SnellTechniqueOptions (technique_options.glsl)
options: technique_options.glsl; environment.glsl hooks.
contract (snellTwoInterfaceExit(origin, dir, ...)):
  - lods: envLod = snellRoughnessToLod(o.roughness, o.environmentLevels),
    sceneLod = snellRoughnessToLod(o.roughness, o.sceneColorLevels)
    (shade/roughness.glsl); every colour read uses them.
  - dir zero or not finite, or origin not finite: color 0, fellBack, 0 fetches.
  - ENVIRONMENT mode: color = SNELL_SAMPLE_ENVIRONMENT(env, world(dir), envLod).xyz,
    1 fetch, hit = snellHitMiss(0), fellBack false.
  - SCENE mode: hit = snellIntersectWith(origin, dir, scene..., o.exit); valid: color = SNELL_SAMPLE_LOD(sceneColor, hit.uv, sceneLod).xyz
    (+1 fetch). Invalid (ray leaves the screen, points towards the camera where a
    search cannot follow, lands on an empty texel): fellBack = true and
    FALLBACK_ENVIRONMENT: the environment along dir; FALLBACK_EDGE_FADE: q =
    origin + fallbackDistance dir/|dir|, w = snellScreenEdgeFade(projection of q,
    edgeFadeWidth) (0 when q does not project), color = mix(environment,
    sceneColor at the projection clamped to [0,1]^2, w) (the scene read only
    when w > 0). Never black unless the environment is.
  - fetches: the strategy's plus one per colour or environment read.
contract (snellTwoInterfaceRefraction):
  - one trace with eta = snellIorToEta(o.iorOutside, o.ior) (o.dispersion != 3),
    or three (o.dispersion == 3), with o.iors.x/.y/.z for red/green/blue, each
    channel taken from its own trace; the reported geometry (exit point,
    direction, hit, path length, tir, backHit) is the single / green trace's;
    fetches and fellBack (any) cover all traces.
  - transmitted = exit color * snellBeerLambert(o.absorption, pathLength) per
    channel, pathLength = |P2 - P1| of that channel's trace (0 on fallback
    without a back hit; finite: a back hit whose |P2 - P1| overflows a float
    counts as none, two_interface.glsl).
  - reflection (o.reflection): F = snellFresnelDielectric(cos(V, N1), eta of
    the green/single trace); R = reflect(V, N1); color = F bg(R) + (1 - F)
    transmitted; bg(R) = env(R), +1 fetch (SNELL_REFLECT_ENVIRONMENT), or
    (SNELL_REFLECT_SCENE) snellTwoInterfaceExit(P1, R, scene..., o with exit =
    o.reflect, SCENE mode, FALLBACK_ENVIRONMENT): the scene colour where the
    reflect slot finds the scene, else env(R), its fetches added and its hit
    in reflectionHit (snellHitMiss(0) otherwise); else F = 0, color =
    transmitted. The second
    interface's Fresnel loss and internally reflected light are not modelled.
  - an invalid path (NaN / zero inputs): color 0, fellBack true, the
    reflection still added when R is defined.
source: Wyman 2005 and Oliveira & Brauwers 2007 (two interfaces, distant
  environment); C. Mayer & U. Assarsson, "Constant-Time Light Refraction
  Simulation" (nearby geometry: the exit ray against the scene buffers, "a
  transparent sphere refracts a painting"); Fresnel: optics/fresnel_dielectric.glsl;
  edge fade: shade/perturb_edge_fade.glsl;
  absorption: optics/beer_lambert.glsl (Beer-Lambert over the found chord).
*/
#ifndef SNELL_SHADE_TWO_INTERFACE_SHADE_GLSL
#define SNELL_SHADE_TWO_INTERFACE_SHADE_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"
#include "../camera/view_to_uv.glsl"
#include "../optics/safe_normalize.glsl"
#include "../optics/ior_to_eta.glsl"
#include "../optics/fresnel_dielectric.glsl"
#include "../optics/beer_lambert.glsl"
#include "../intersect/hit.glsl"
#include "roughness.glsl"
#include "environment.glsl"
#include "perturb_edge_fade.glsl"
#include "../intersect/intersect_with.glsl"
#include "technique_options.glsl"
#include "two_interface.glsl"

struct SnellTwoInterfaceExit {
  vec3 color;
  SnellHit hit;
  bool fellBack;
  int fetches;
};

struct SnellTwoInterfaceResult {
  vec3 color;
  vec3 exitPoint;      // P2 (P1 when the back hit failed)
  vec3 exitDirection;  // T2 (T1 on fallback)
  SnellHit exitHit;    // the exit slot's hit in the scene buffers (SCENE mode)
  SnellHit reflectionHit;  // the reflection slot's hit in the scene buffers (SNELL_REFLECT_SCENE)
  float pathLength;    // |P2 - P1| inside the object
  float fresnel;       // F at the first interface (0 without reflection)
  int fetches;
  bool backHit;        // P2 found in the back-face buffers
  bool fellBack;       // any fallback: back hit, TIR under ZERO, exit slot
  bool tir;            // TIR at the second interface
};

SNELL_FN SnellTwoInterfaceExit snellTwoInterfaceExit(vec3 origin, vec3 dir, SNELL_TEX2D sceneDepth,
                                                     SNELL_TEX2D sceneNormal, SNELL_TEX2D scenePyramid,
                                                     SNELL_TEX2D sceneColor, SNELL_IN(SnellDepthSurface) scene,
                                                     SNELL_ENVIRONMENT_TEX environment, SnellTechniqueOptions o) {
  SnellTwoInterfaceExit e;
  e.color = vec3(0.0f, 0.0f, 0.0f);
  e.hit = snellHitMiss(0);
  e.fellBack = true;
  e.fetches = 0;
  vec3 d = snellSafeNormalize(dir);
  if (dot(d, d) == 0.0f || !SNELL_FINITE(origin.x) || !SNELL_FINITE(origin.y) ||
      !SNELL_FINITE(origin.z)) {
    return e;
  }
  float envLod = snellRoughnessToLod(o.roughness, o.environmentLevels);
  float sceneLod = snellRoughnessToLod(o.roughness, o.sceneColorLevels);
  vec3 world = d.x * o.envX + d.y * o.envY + d.z * o.envZ;
  if (o.exitMode == SNELL_EXIT_SCENE) {
    e.hit = snellIntersectWith(origin, dir, sceneDepth, sceneNormal, scenePyramid, scene, o.exit);
    e.fetches = e.hit.fetches;
    if (e.hit.valid) {
      vec4 c = SNELL_SAMPLE_LOD(sceneColor, e.hit.uv, sceneLod);
      e.color = vec3(c.x, c.y, c.z);
      e.fetches = e.fetches + 1;
      e.fellBack = false;
      return e;
    }
    vec4 env = SNELL_SAMPLE_ENVIRONMENT(environment, world, envLod);
    e.fetches = e.fetches + 1;
    e.color = vec3(env.x, env.y, env.z);
    if (o.fallback == SNELL_FALLBACK_EDGE_FADE) {
      SnellScreenPoint sp = snellViewToUv(scene.clipFromView, origin + o.fallbackDistance * d);
      float w = sp.valid ? snellScreenEdgeFade(sp.uv, o.edgeFadeWidth) : 0.0f;
      if (w > 0.0f) {
        vec2 uv = clamp(sp.uv, vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
        vec4 c = SNELL_SAMPLE_LOD(sceneColor, uv, sceneLod);
        e.fetches = e.fetches + 1;
        e.color = mix(e.color, vec3(c.x, c.y, c.z), w);
      }
    }
    return e;
  }
  vec4 env = SNELL_SAMPLE_ENVIRONMENT(environment, world, envLod);
  e.color = vec3(env.x, env.y, env.z);
  e.fetches = 1;
  e.fellBack = false;
  return e;
}

/* Wyman 2005; Oliveira & Brauwers 2007; Mayer & Assarsson: the composed technique */
SNELL_FN SnellTwoInterfaceResult snellTwoInterfaceRefraction(vec3 frontPosition, vec3 frontNormal, float dN,
                                                             SNELL_TEX2D backDepth, SNELL_TEX2D backNormal,
                                                             SNELL_TEX2D backPyramid, SNELL_IN(SnellDepthSurface) back,
                                                             SNELL_TEX2D sceneDepth, SNELL_TEX2D sceneNormal,
                                                             SNELL_TEX2D scenePyramid, SNELL_TEX2D sceneColor,
                                                             SNELL_IN(SnellDepthSurface) scene, SNELL_ENVIRONMENT_TEX environment,
                                                             SnellTechniqueOptions o) {
  bool three = o.dispersion == 3;
  float eta = snellIorToEta(o.iorOutside, three ? o.iors.y : o.ior);
  SnellTwoInterfacePath p =
      snellTwoInterfaceTrace(frontPosition, frontNormal, eta, dN, backDepth, backNormal, backPyramid, back, o);
  SnellTwoInterfaceExit e = snellTwoInterfaceExit(p.exitPoint, p.exitDirection, sceneDepth, sceneNormal,
                                                  scenePyramid, sceneColor, scene, environment, o);
  vec3 transmitted = e.color * snellBeerLambert(o.absorption, p.pathLength);
  SnellTwoInterfaceResult r;
  r.exitPoint = p.exitPoint;
  r.exitDirection = p.exitDirection;
  r.exitHit = e.hit;
  r.reflectionHit = snellHitMiss(0);
  r.pathLength = p.pathLength;
  r.fresnel = 0.0f;
  r.fetches = p.fetches + e.fetches;
  r.backHit = p.hit;
  r.fellBack = p.fellBack || e.fellBack || !p.valid;
  r.tir = p.tir;
  if (three) {
    SnellTwoInterfacePath pr = snellTwoInterfaceTrace(frontPosition, frontNormal,
                                                      snellIorToEta(o.iorOutside, o.iors.x), dN, backDepth,
                                                      backNormal, backPyramid, back, o);
    SnellTwoInterfaceExit er = snellTwoInterfaceExit(pr.exitPoint, pr.exitDirection, sceneDepth, sceneNormal,
                                                     scenePyramid, sceneColor, scene, environment, o);
    SnellTwoInterfacePath pb = snellTwoInterfaceTrace(frontPosition, frontNormal,
                                                      snellIorToEta(o.iorOutside, o.iors.z), dN, backDepth,
                                                      backNormal, backPyramid, back, o);
    SnellTwoInterfaceExit eb = snellTwoInterfaceExit(pb.exitPoint, pb.exitDirection, sceneDepth, sceneNormal,
                                                     scenePyramid, sceneColor, scene, environment, o);
    transmitted.x = er.color.x * snellBeerLambert(o.absorption, pr.pathLength).x;
    transmitted.z = eb.color.z * snellBeerLambert(o.absorption, pb.pathLength).z;
    r.fetches = r.fetches + pr.fetches + er.fetches + pb.fetches + eb.fetches;
    r.fellBack = r.fellBack || pr.fellBack || er.fellBack || pb.fellBack || eb.fellBack;
  }
  r.color = transmitted;
  vec3 v = snellSafeNormalize(frontPosition);
  vec3 n1 = snellSafeNormalize(frontNormal);
  if (o.reflection && dot(v, v) > 0.0f && dot(n1, n1) > 0.0f) {
    float f = snellFresnelDielectric(dot(v, n1), eta);
    vec3 rv = reflect(v, n1);
    vec3 reflected = vec3(0.0f, 0.0f, 0.0f);
    if (o.reflectionMode == SNELL_REFLECT_SCENE) {
      // The reflection slot: the exit machinery with the reflect slot's strategy, from P1 along R.
      SnellTechniqueOptions ro = o;
      ro.exit = o.reflect;
      ro.exitMode = SNELL_EXIT_SCENE;
      ro.fallback = SNELL_FALLBACK_ENVIRONMENT;
      SnellTwoInterfaceExit re = snellTwoInterfaceExit(frontPosition, rv, sceneDepth, sceneNormal, scenePyramid,
                                                       sceneColor, scene, environment, ro);
      reflected = re.color;
      r.reflectionHit = re.hit;
      r.fetches = r.fetches + re.fetches;
    } else {
      vec3 world = rv.x * o.envX + rv.y * o.envY + rv.z * o.envZ;
      vec4 env = SNELL_SAMPLE_ENVIRONMENT(environment, world, snellRoughnessToLod(o.roughness, o.environmentLevels));
      reflected = vec3(env.x, env.y, env.z);
      r.fetches = r.fetches + 1;
    }
    r.fresnel = f;
    r.color = f * reflected + (1.0f - f) * transmitted;
  }
  return r;
}

#endif
