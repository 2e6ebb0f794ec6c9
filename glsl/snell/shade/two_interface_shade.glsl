/*
description: two-interface refraction, shaded: the full technique a fragment
  shader calls for a front-face fragment of a refractive object. Trace the
  path through the object (two_interface.glsl), resolve the exit ray with the
  exit slot against the opaque scene behind the object (its depth, normal,
  pyramid and colour buffers, with any strategy: Mayer & Assarsson's painting
  behind a glass sphere) or against a distant environment, with a documented
  fallback when the scene hit is not found; absorb along the path inside
  (Beer-Lambert), add the Fresnel-weighted reflection at the first interface,
  resolved by the same call with the reflect slot; optionally once per colour
  channel (chromatic dispersion) and with blurred (roughness) lookups.
use: SnellTechnique t = snellPresetDir();   // or any preset, then adjust
     t.exit.source = SNELL_SOURCE_BUFFERS;
     SnellMaterial m = snellMaterial();
     SnellView v = snellView();
     SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(frontPosition, frontNormal, dN,
         backDepth, backNormal, backPyramid, back, frontLayerDepth, frontLayerNormal, frontLayer,
         sceneDepth, sceneNormal, scenePyramid, sceneColor, scene, environment, t, m, v);
     fragColor = vec4(r.color, 1.0f);
     SnellTwoInterfaceExit e = snellTwoInterfaceExitRough(origin, dir, cone, sceneDepth, sceneNormal,
         scenePyramid, sceneColor, scene, environment, t.exit, v);   // one slot alone
     SnellTwoInterfaceExit e = snellTwoInterfaceExit(origin, dir, sceneDepth, sceneNormal,
         scenePyramid, sceneColor, scene, environment, t.exit, m, v);   // ... through a thin sheet of m
  frontPosition, frontNormal, dN, back*: as snellTwoInterfaceTrace
                 (SNELL_OBJECT_BUFFERS, technique_buffers.glsl)
  sceneDepth, sceneNormal, scenePyramid, scene: the opaque scene without the
                 object, read by a BUFFERS slot (normals for PLANE_NORMAL, the
                 pyramid for the search range and PLANE_DEPTH); any textures
                 when no slot reads them (never read)
  sceneColor     the opaque scene's colour (mipmapped for roughness > 0)
  environment    SNELL_ENVIRONMENT_TEX: an equirectangular 2D texture by
                 default, a cube map through the hook (environment.glsl); looked
                 up with world directions: v.envX, v.envY, v.envZ = the columns
                 of the world-from-view rotation
  t, m, v        SnellTechnique (its back, exit and reflect slots),
                 SnellMaterial, SnellView (technique_options.glsl)
options: technique_options.glsl; technique_buffers.glsl; environment.glsl hooks.
contract (snellTwoInterfaceExitRough(origin, dir, cone, ..., slot, v)):
  - lods (shade/rough_cone.glsl): every environment read at
    envLod = snellRoughConeEnvironmentLod(cone, v.environmentLevels); a read
    of the scene colour at a point q (the hit, or the edge fade's point) at
    snellRoughConeSceneLod(cone, |q - origin|, q, scene.clipFromView, its
    base size, v.sceneColorLevels): the cone's width where the ray meets
    the scene, in that buffer's texels. A cone of radius and angles 0 (smooth
    glass) reads level 0. Each read is snellRoughConeSample (or
    snellRoughConeSampleEnvironment) at snellRoughConeTaps(that level, the
    texture's levels): at level 0 one SNELL_SAMPLE_LOD, above it two (the
    lobe's peak and tail), each counted.
  - dir zero or not finite, or origin not finite: color 0, fellBack, 0 fetches.
  - slot.source ENVIRONMENT: color = the environment read along
    world(dir / |dir|) at envLod, hit = snellHitMiss(0), fellBack false.
  - any other source (BUFFERS; WYMAN reads as BUFFERS here): hit =
    snellIntersectWith(origin, dir, scene..., slot.intersect), then the
    foreground rule, snellRejectForeground(hit, origin, sceneDepth, scene,
    SNELL_FOREGROUND_TOLERANCE) (it reads the texel containing the hit)
    (intersect/foreground.glsl: 1 fetch when the strategy hit; a hit on a
    surface nearer the camera than the whole ray is refused, so a foreground
    never shows through the object); valid: color = the scene colour read
    at hit.uv and sceneLod. Invalid (ray
    leaves the screen, points towards the camera where a search cannot
    follow, lands on an empty texel): fellBack = true and slot.fallback
    ENVIRONMENT: the environment along dir; EDGE_FADE: q = origin +
    slot.fallbackDistance dir/|dir|, w = snellScreenEdgeFade(projection of q,
    slot.edgeFadeWidth) (0 when q does not project), color = mix(environment,
    sceneColor at the projection clamped to [0,1]^2, w) (the scene read only
    when w > 0). Never black unless the environment is.
  - fetches: the strategy's, the foreground rule's read, and the colour and
    environment reads' (snellRoughConeFetches: 1 on smooth glass, 2 on rough).
contract (snellTwoInterfaceExit(origin, dir, ..., slot, m, v)): the above
  with the cone of a ray through a thin sheet of the material:
  snellRoughConeTransmit(m.roughness, snellIorToEta(m.iorOutside, m.ior), 0, 0).
contract (snellTwoInterfaceRefraction):
  - one trace with eta = snellIorToEta(m.iorOutside, m.ior) (m.dispersion != 3),
    or three (m.dispersion == 3), with m.iors.x/.y/.z for red/green/blue, each
    channel taken from its own trace; the back slot t.back finds P2 (with
    t.bounces > 0 the trace follows TIR inside, two_interface.glsl), the exit
    slot t.exit resolves (P2, T2), or the reflect slot t.reflect when the
    path left through a front face (after a bounce: T2 heads towards the
    camera's side); the reported geometry (exit point, direction, hit, path
    length, tir, bounces, backHit) is the single / green trace's; fetches and
    fellBack (any) cover all traces. fellBack: the path fell back
    (two_interface.glsl) or the exit slot did; a reflect slot that resolves a
    path leaving through a front face and finds no scene shows the
    environment, as the first surface's reflection does, and is no fallback.
  - t.insideScene (the opaque scene has surfaces inside the object): after
    a trace that found a back hit, the refracted ray T1 from P1 is also run
    against the scene buffers with the exit slot's strategy
    (snellIntersectWith with t.exit.intersect, then snellRejectForeground
    with the hit itself as the segment's origin: the surface at its texel
    may not be nearer than the hit by more than the tolerance, so a search
    that passed behind a surface's silhouette is not taken for a hit on it;
    its fetches added). A hit nearer than the back hit
    (|hit - P1| < the path's entryLength) ends the path on that surface:
    colour = sceneColor at the hit (read as above, at the level of the
    entry lobe's width there: the cone below with its angles set to 0, at
    distance 0), exitPoint = the hit,
    exitDirection = T1, exitHit = the hit, pathLength = |hit - P1|, no tir,
    no bounces, no fallback, insideHit = true (the single / green trace's).
    The surface is shaded as the opaque surface it is: its colour, absorbed
    over the path inside, no second refraction.
  - rough exit (snellRoughConeSlope(m.roughness) = alpha > 0): where the
    path left by refraction (its exitIncident is not 0; not inside), T2 =
    snellRefractRough(exitIncident, exitNormal, 1 / eta of that trace, alpha,
    m.tirPolicy).direction (optics/refract_rough.glsl: Snell's law with cos_t^2
    averaged over the exit interface's microfacet slopes, smooth through the
    critical angle), which the exit slot resolves and exitDirection reports;
    tir stays the mean normal's. Smooth glass keeps the trace's T2, bit for bit.
  - blur: each trace's exit slot reads through the cone
    snellRoughConeTransmit(m.roughness, that trace's eta, pathLength,
    bounces) (both interfaces' lobes: the entry lobe carried over the path
    inside and the distance behind, the exit lobe over the distance behind,
    added in quadrature); the reflect slot of the first surface's reflection
    through snellRoughConeReflect(m.roughness).
  - transmitted = exit color * snellBeerLambert(m.absorption, pathLength) per
    channel, pathLength = |P2 - P1| of that channel's trace (0 on fallback
    without a back hit; finite: a back hit whose |P2 - P1| overflows a float
    counts as none, two_interface.glsl).
  - reflection (m.reflection): F = snellFresnelDielectric(cos(V, N1), eta of
    the green/single trace); R = reflect(V, N1); bg(R) =
    snellTwoInterfaceExit(P1, R, scene..., t.reflect, m, v) (the environment
    along R, or the scene colour where the reflect slot's intersector finds
    the scene, else its fallback; snellTwoInterfaceExitRough with the
    reflection's cone); its fetches added, its hit in
    reflectionHit; color = F bg(R) + (1 - F) transmitted. Else F = 0, color =
    transmitted. The Fresnel loss at the later interfaces, and the light they
    reflect back inside where Snell allows refraction, are not modelled.
  - an invalid path (NaN / zero inputs): color 0, fellBack true, the
    reflection still added when R is defined.
source: Wyman 2005 and Oliveira & Brauwers 2007 (two interfaces, distant
  environment); C. Mayer & U. Assarsson, "Constant-Time Light Refraction
  Simulation" (nearby geometry: the exit ray against the scene buffers, "a
  transparent sphere refracts a painting"); Fresnel: optics/fresnel_dielectric.glsl;
  edge fade: shade/perturb_edge_fade.glsl;
  absorption: optics/beer_lambert.glsl (Beer-Lambert over the found chord);
  blur: shade/rough_cone.glsl (Walter et al. 2007; de Rousiers et al. 2012).
*/
#ifndef SNELL_SHADE_TWO_INTERFACE_SHADE_GLSL
#define SNELL_SHADE_TWO_INTERFACE_SHADE_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"
#include "../camera/view_to_uv.glsl"
#include "../optics/safe_normalize.glsl"
#include "../optics/ior_to_eta.glsl"
#include "../optics/fresnel_dielectric.glsl"
#include "../optics/refract_rough.glsl"
#include "../optics/beer_lambert.glsl"
#include "../intersect/hit.glsl"
#include "rough_cone.glsl"
#include "environment.glsl"
#include "perturb_edge_fade.glsl"
#include "../intersect/intersect_with.glsl"
#include "../intersect/foreground.glsl"
#include "technique_options.glsl"
#include "technique_buffers.glsl"
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
  SnellHit exitHit;    // the exit slot's hit in the scene buffers (SNELL_SOURCE_BUFFERS)
  SnellHit reflectionHit;  // the reflect slot's hit in the scene buffers (SNELL_SOURCE_BUFFERS)
  float pathLength;    // |P2 - P1| inside the object
  float fresnel;       // F at the first interface (0 without reflection)
  int fetches;
  bool backHit;        // P2 found in the back-face buffers
  bool fellBack;       // any fallback: back hit, TIR under ZERO, a bounce not followed, exit slot
  bool tir;            // TIR at the last interface
  int bounces;         // total internal reflections followed inside (SnellTechnique.bounces at most)
  bool insideHit;      // the refracted ray met the opaque scene inside the object (t.insideScene)
};

/* Mayer & Assarsson: a ray from the object resolved by one slot against the scene buffers or the environment,
   its colour blurred over the rough glass's cone (de Rousiers et al.; shade/rough_cone.glsl) */
SNELL_FN SnellTwoInterfaceExit snellTwoInterfaceExitRough(vec3 origin, vec3 dir, SNELL_IN(SnellRoughCone) cone,
                                                          SNELL_SCENE_BUFFERS, SNELL_IN(SnellSlot) slot,
                                                          SNELL_IN(SnellView) v) {
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
  SnellRoughTaps envTaps = snellRoughConeTaps(snellRoughConeEnvironmentLod(cone, v.environmentLevels),
                                              v.environmentLevels);
  ivec2 colorSize = SNELL_TEXTURE_SIZE(sceneColor, 0);
  vec3 world = d.x * v.envX + d.y * v.envY + d.z * v.envZ;
  if (slot.source != SNELL_SOURCE_ENVIRONMENT) {
    e.hit = snellIntersectWith(origin, dir, sceneDepth, sceneNormal, scenePyramid, scene, slot.intersect);
    e.hit = snellRejectForeground(e.hit, origin, sceneDepth, scene, SNELL_FOREGROUND_TOLERANCE);
    e.fetches = e.hit.fetches;
    if (e.hit.valid) {
      float lod = snellRoughConeSceneLod(cone, length(e.hit.position - origin), e.hit.position, scene.clipFromView,
                                         colorSize, v.sceneColorLevels);
      SnellRoughTaps taps = snellRoughConeTaps(lod, v.sceneColorLevels);
      vec4 c = snellRoughConeSample(sceneColor, e.hit.uv, taps);
      e.color = vec3(c.x, c.y, c.z);
      e.fetches = e.fetches + snellRoughConeFetches(taps);
      e.fellBack = false;
      return e;
    }
    vec4 env = snellRoughConeSampleEnvironment(environment, world, envTaps);
    e.fetches = e.fetches + snellRoughConeFetches(envTaps);
    e.color = vec3(env.x, env.y, env.z);
    if (slot.fallback == SNELL_FALLBACK_EDGE_FADE) {
      vec3 q = origin + slot.fallbackDistance * d;
      SnellScreenPoint sp = snellViewToUv(scene.clipFromView, q);
      float w = sp.valid ? snellScreenEdgeFade(sp.uv, slot.edgeFadeWidth) : 0.0f;
      if (w > 0.0f) {
        vec2 uv = clamp(sp.uv, vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
        float lod = snellRoughConeSceneLod(cone, slot.fallbackDistance, q, scene.clipFromView, colorSize,
                                           v.sceneColorLevels);
        SnellRoughTaps taps = snellRoughConeTaps(lod, v.sceneColorLevels);
        vec4 c = snellRoughConeSample(sceneColor, uv, taps);
        e.fetches = e.fetches + snellRoughConeFetches(taps);
        e.color = mix(e.color, vec3(c.x, c.y, c.z), w);
      }
    }
    return e;
  }
  vec4 env = snellRoughConeSampleEnvironment(environment, world, envTaps);
  e.color = vec3(env.x, env.y, env.z);
  e.fetches = snellRoughConeFetches(envTaps);
  e.fellBack = false;
  return e;
}

/* The same for a ray that left through a thin sheet of the material: both rough interfaces, no path inside */
SNELL_FN SnellTwoInterfaceExit snellTwoInterfaceExit(vec3 origin, vec3 dir, SNELL_SCENE_BUFFERS,
                                                     SNELL_IN(SnellSlot) slot, SNELL_IN(SnellMaterial) m,
                                                     SNELL_IN(SnellView) v) {
  SnellRoughCone cone = snellRoughConeTransmit(m.roughness, snellIorToEta(m.iorOutside, m.ior), 0.0f, 0);
  return snellTwoInterfaceExitRough(origin, dir, cone, SNELL_SCENE_BUFFER_ARGS, slot, v);
}

/* Wyman 2005; Oliveira & Brauwers 2007; Mayer & Assarsson: the composed technique */
SNELL_FN SnellTwoInterfaceResult snellTwoInterfaceRefraction(vec3 frontPosition, vec3 frontNormal, float dN,
                                                             SNELL_OBJECT_BUFFERS, SNELL_SCENE_BUFFERS,
                                                             SNELL_IN(SnellTechnique) t, SNELL_IN(SnellMaterial) m,
                                                             SNELL_IN(SnellView) v) {
  bool three = m.dispersion == 3;
  float eta = snellIorToEta(m.iorOutside, three ? m.iors.y : m.ior);
  SnellTwoInterfaceResult r;
  r.reflectionHit = snellHitMiss(0);
  r.fresnel = 0.0f;
  vec3 transmitted = vec3(0.0f, 0.0f, 0.0f);
  // The green (or only) channel's path gives every field; with dispersion, red and blue follow their own
  // paths for their colour. One loop, not three copies of the trace: WebGL 2 on SwiftShader runs out of
  // shader stack with three, and every browser compiles a third of the code.
  int channels = three ? 3 : 1;
  for (int k = 0; k < 3; ++k) {
    float etaK = eta;
    if (k == 1) {
      etaK = snellIorToEta(m.iorOutside, m.iors.x);
    } else if (k == 2) {
      etaK = snellIorToEta(m.iorOutside, m.iors.z);
    }
    SnellTwoInterfacePath p =
        snellTwoInterfaceTrace(frontPosition, frontNormal, etaK, dN, SNELL_OBJECT_BUFFER_ARGS, t, m.tirPolicy);
    // An opaque surface inside the object: the refracted ray against the scene too (the exit slot's strategy);
    // nearer than the back faces, it ends the path there, unrefracted.
    bool inside = false;
    SnellHit ih = snellHitMiss(0);
    if (t.insideScene && p.hit) {
      ih = snellIntersectWith(frontPosition, p.entryDirection, sceneDepth, sceneNormal, scenePyramid, scene,
                              t.exit.intersect);
      // The hit must lie on the surface at its texel: the rule with the hit as the whole segment refuses a
      // surface nearer than the hit, i.e. a march that passed behind the card's silhouette (it did not hit it).
      ih = snellRejectForeground(ih, ih.position, sceneDepth, scene, SNELL_FOREGROUND_TOLERANCE);
      float d = length(ih.position - frontPosition);
      inside = ih.valid && d < p.entryLength;
      if (inside) {
        p.exitPoint = ih.position;
        p.exitDirection = p.entryDirection;
        p.exitUv = ih.uv;
        p.pathLength = d;
        p.tir = false;
        p.fellBack = false;
        p.exitFront = false;
        p.bounces = 0;
        p.exitIncident = vec3(0.0f, 0.0f, 0.0f);
      }
      p.fetches = p.fetches + ih.fetches;
    }
    // A path that left through a front face is resolved by the reflect slot (an if: WebGL rejects ?: on
    // structs). Only a bounce reaches a front face: testing t.bounces first makes the test a constant
    // false for a technique without bounces, so the exit slot stays the constant t.exit and its options fold.
    SnellSlot leave = t.exit;
    if (t.bounces > 0 && p.exitFront) {
      leave = t.reflect;
    }
    // Rough glass: the last interface's microfacets turn the exit ray smoothly through the critical angle,
    // where the smooth ray swings across the scene behind with every fraction of a pixel the picture moves.
    float alpha = snellRoughConeSlope(m.roughness);
    if (alpha > 0.0f && dot(p.exitIncident, p.exitIncident) > 0.0f) {
      p.exitDirection = snellRefractRough(p.exitIncident, p.exitNormal, 1.0f / etaK, alpha, m.tirPolicy).direction;
    }
    // The blur: the entry lobe carried over the path inside and both lobes over the distance behind; an
    // opaque surface inside the glass sees the entry lobe alone.
    SnellRoughCone cone = snellRoughConeTransmit(m.roughness, etaK, p.pathLength, p.bounces);
    SnellTwoInterfaceExit e;
    if (inside) {
      SnellRoughCone entry = cone;
      entry.angle = 0.0f;
      entry.exitAngle = 0.0f;
      float lod = snellRoughConeSceneLod(entry, 0.0f, ih.position, scene.clipFromView,
                                         SNELL_TEXTURE_SIZE(sceneColor, 0), v.sceneColorLevels);
      SnellRoughTaps taps = snellRoughConeTaps(lod, v.sceneColorLevels);
      vec4 c = snellRoughConeSample(sceneColor, ih.uv, taps);
      e.color = vec3(c.x, c.y, c.z);
      e.hit = ih;
      e.fellBack = false;
      e.fetches = snellRoughConeFetches(taps);
    } else {
      e = snellTwoInterfaceExitRough(p.exitPoint, p.exitDirection, cone, SNELL_SCENE_BUFFER_ARGS, leave, v);
    }
    vec3 c = e.color * snellBeerLambert(m.absorption, p.pathLength);
    // Where the reflect slot finds no scene after a front-face exit, the environment is what is there,
    // as for the first surface's reflection: not a fallback.
    bool fellBack = p.fellBack || (e.fellBack && !p.exitFront);
    if (k == 0) {
      transmitted = c;
      r.exitPoint = p.exitPoint;
      r.exitDirection = p.exitDirection;
      r.exitHit = e.hit;
      r.pathLength = p.pathLength;
      r.fetches = p.fetches + e.fetches;
      r.backHit = p.hit;
      r.fellBack = fellBack || !p.valid;
      r.tir = p.tir;
      r.bounces = p.bounces;
      r.insideHit = inside;
    } else {
      if (k == 1) {
        transmitted.x = c.x;
      } else {
        transmitted.z = c.z;
      }
      r.fetches = r.fetches + p.fetches + e.fetches;
      r.fellBack = r.fellBack || fellBack;
    }
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (k + 1 >= channels) {
      break;
    }
  }
  r.color = transmitted;
  vec3 vv = snellSafeNormalize(frontPosition);
  vec3 n1 = snellSafeNormalize(frontNormal);
  if (m.reflection && dot(vv, vv) > 0.0f && dot(n1, n1) > 0.0f) {
    float f = snellFresnelDielectric(dot(vv, n1), eta);
    // The reflect slot: the exit's call with its own slot, from P1 along R.
    SnellTwoInterfaceExit re = snellTwoInterfaceExitRough(frontPosition, reflect(vv, n1),
                                                          snellRoughConeReflect(m.roughness),
                                                          SNELL_SCENE_BUFFER_ARGS, t.reflect, v);
    r.reflectionHit = re.hit;
    r.fetches = r.fetches + re.fetches;
    r.fresnel = f;
    r.color = f * re.color + (1.0f - f) * transmitted;
  }
  return r;
}

#endif
