/*
description: how wide rough (frosted) glass blurs what it shows, as a cone of
  light around the ray: from the roughness, the relative IOR and the path's
  lengths inside and behind the glass, its radius where the ray meets the
  scene, and the mip level of the scene colour (or the environment) whose
  texels are that wide, read twice (the lobe's narrow peak and its wide
  tail). The same glass blurs the same amount of the world at every
  resolution and distance, and the blur grows with what lies behind.
use: SnellRoughCone c = snellRoughConeTransmit(m.roughness, eta, insideLength, bounces);
     float lod = snellRoughConeSceneLod(c, distanceBehind, hitPosition, scene.clipFromView,
                                        SNELL_TEXTURE_SIZE(sceneColor, 0), v.sceneColorLevels);
     float envLod = snellRoughConeEnvironmentLod(c, v.environmentLevels);
     SnellRoughCone r = snellRoughConeReflect(m.roughness);   // the first surface's reflection
     SnellRoughTaps t = snellRoughConeTaps(lod, v.sceneColorLevels);  // the lobe as two reads
     vec4 color = snellRoughConeSample(sceneColor, uv, t);   // snellRoughConeFetches(t) fetches
     vec4 sky = snellRoughConeSampleEnvironment(environment, dirWorld,
                                                snellRoughConeTaps(envLod, v.environmentLevels));
  the scene colour's and the environment's chains built by the colour
  pyramid (color_pyramid.glsl: snell::gpu::ColorPyramidPass after each draw
  of the scene colour, snellBuildColorPyramid for an image), whose levels
  blur as the bells the levels below assume. glGenerateMipmap's box chain
  also works: the same level then blurs 0.77x as wide (part of it the
  texels' misplacement, a third of its variance; define SNELL_ROUGH_CONE_LOD_SCALE 3.0 for the same
  blur), and the read changes as the camera moves by a fraction of a pixel.
  roughness     perceptual roughness in [0, 1]; the GGX width is alpha = roughness^2
  eta           n_outside / n_inside at the entry (snellIorToEta(iorOutside, ior))
  insideLength  the path's length inside the glass (view units)
  bounces       total internal reflections inside (each off the rough surface)
  distance      from where the ray leaves the glass to where it meets the scene
  p             that point, in view space; clipFromView: the projection of the
                scene colour buffer, whose size (texels) is `size`
  levels        the texture's mip levels (base included); the environment's
                base level is taken to span 2 pi radians over 2^(levels - 1)
                texels (an equirectangular map with a full chain)
options: SNELL_ROUGH_CONE_LOD_SCALE (default 2.32): texels of the chosen level
  per unit of the cone's radius: 3, fitted against the rough ray trace with
  a box chain (below), times 0.5 / 0.645, the two chains' widths at a level
  (color_pyramid.glsl), so the colour pyramid blurs as wide as the fit.
  SNELL_ROUGH_CONE_TAIL_WEIGHT (default 0.34): the wide read's share of a rough
  read; 0 reads once, at the cone's level (one fetch instead of two).
  SNELL_ROUGH_CONE_CORE_OFFSET (default -0.52) and SNELL_ROUGH_CONE_TAIL_OFFSET
  (default 1.14): the two reads' levels from the cone's (below).
contract:
  - a cone is a radius at the surface it leaves and two angles (radians):
    radius(d) = sqrt((radius + angle d)^2 + (exitAngle d)^2) at distance d.
    The two lobes are independent, so they add in quadrature; the entry
    lobe's spread is carried along the inside path, so its radius and angle
    add linearly.
  - snellRoughConeTransmit: s = alpha = clamp(roughness, 0, 1)^2 (NaN: 0).
    Small-slope Snell's law: a microfacet tilted by s turns a ray refracted
    with relative index e by |1 - e| s. Inside, the entry lobe's angle is
    a = s sqrt((1 - eta)^2 + 4 bounces): |1 - eta| s, widened by each
    bounce's reflection (2 s) in quadrature.
    The cone leaves with radius = a insideLength, angle = a / eta (the exit
    refraction magnifies it by 1 / eta) and exitAngle = |1 / eta - 1| s (the
    exit lobe). A NaN, infinite or negative insideLength counts as 0; eta
    NaN or outside [1e-6, 1e6] counts as 1 (no bending: no blur); bounces
    clamped to [0, SNELL_MAX_BOUNCES].
  - snellRoughConeReflect: radius 0, angle 2 s (reflection doubles the
    facet's tilt), exitAngle 0.
  - snellRoughConeRadius(c, d): as above; d and the cone's fields NaN or
    negative count as 0, +inf as the largest float, and the result is
    finite (snellRoughConeHypot: max sqrt(1 + (min / max)^2), capped at the
    largest float). snellRoughConeMeasure(x): that reading of one value.
  - snellRoughConeLevel(radius, texelsPerUnit, levels): log2(scale radius
    texelsPerUnit) clamped to [0, levels - 1]; 0 when either is not
    positive or levels <= 1.
  - snellRoughConeSceneLod: the cone's radius at d in texels of the base
    level (texels per view unit at p: (size.x |P00| + size.y |P11|) / (4 w),
    w = (clipFromView p).w), times SNELL_ROUGH_CONE_LOD_SCALE, as a level:
    log2 of it clamped to [0, levels - 1]. 0 when the radius is 0, levels
    <= 1, or p does not project (a coordinate not finite, or w not positive
    and finite).
  - snellRoughConeEnvironmentLod: the same for the directions, sqrt(angle^2 +
    exitAngle^2) radians at 2^(levels - 1) / (2 pi) texels per radian.
  - every result is finite; a cone of a smooth surface (roughness 0) gives
    level 0 exactly.
  - snellRoughConeTaps(lod, levels): GGX's lobe is heavy-tailed (its slopes
    are Student's t with 2 degrees of freedom: a narrow peak, and a fifth of
    the light beyond twice its median), which one read, a bell, cannot be.
    Two reads mixed stand for it: l = lod clamped to [0, levels - 1] (NaN: 0);
    for l > 0 and a positive tail weight w, coreLod = clamp(l + CORE_OFFSET),
    tailLod = clamp(l + TAIL_OFFSET) (both to [0, levels - 1]), tailWeight = w;
    else (smooth glass, level 0, no chain) one read: coreLod = tailLod = l,
    tailWeight 0. At the top level the tail is clamped to it and the core
    still reads below (the mix stays the lobe's shape as far as the chain
    allows).
  - snellRoughConeSample(tex, uv, t): SNELL_SAMPLE_LOD at coreLod, mixed with
    SNELL_SAMPLE_LOD at tailLod by tailWeight when it is positive;
    snellRoughConeSampleEnvironment the same through SNELL_SAMPLE_ENVIRONMENT.
    snellRoughConeFetches(t): 2 with a tail, else 1.
  - the constants: with a read at level L taken as a Gaussian of standard
    deviation proportional to 2^L, the mixture of two Gaussians nearest
    to the t lobe (squared difference of their spectra, weighted as the
    1 / f^2 power spectrum of natural images weighs it) against the single
    Gaussian nearest to it: the core 0.70x its width (-0.52 levels) with
    weight 0.66, the tail 2.2x (+1.14 levels) with 0.34. The single read's
    level (SNELL_ROUGH_CONE_LOD_SCALE) stays the one fitted against the ray
    trace; the two reads take their levels from it.
source: the rough BTDF of B. Walter, S. Marschner, H. Li, K. Torrance,
  "Microfacet Models for Refraction through Rough Surfaces" (EGSR 2007): GGX
  (eq. 33) with width alpha, refraction about the microfacet normal (eq. 40);
  its small-slope linearisation here. The cone traced through the scene
  colour's mip chain, its radius growing with the distance behind the
  object and both interfaces' lobes combined: C. de Rousiers, A. Bousseau,
  K. Subr, N. Holzschuch, R. Ramamoorthi, "Real-Time Rendering of Rough
  Refraction" (TVCG 2012), cone tracing at the exit interface. GGX's slopes
  as Student's t with 2 degrees of freedom: E. Heitz, "Understanding the
  Masking-Shadowing Function in Microfacet-Based BRDFs" (JCGT 2014), its GGX
  slope distribution P22; natural images' 1 / f^2 power spectrum: D. J.
  Field, "Relations between the statistics of natural images and the
  response properties of cortical cells" (JOSA A 1987). The scale was
  fitted on the rough sphere_painting scenes against the lab's GGX ray trace
  through a box chain, checked on the rough bunny, and carried over to the
  colour pyramid at equal width (docs/lab/rough/README.md).
*/
#ifndef SNELL_SHADE_ROUGH_CONE_GLSL
#define SNELL_SHADE_ROUGH_CONE_GLSL
#include "../prelude.glsl"
#include "technique_options.glsl"
#include "environment.glsl"

#ifndef SNELL_ROUGH_CONE_LOD_SCALE
#  define SNELL_ROUGH_CONE_LOD_SCALE 2.32f
#endif
#ifndef SNELL_ROUGH_CONE_TAIL_WEIGHT
#  define SNELL_ROUGH_CONE_TAIL_WEIGHT 0.34f
#endif
#ifndef SNELL_ROUGH_CONE_CORE_OFFSET
#  define SNELL_ROUGH_CONE_CORE_OFFSET (-0.52f)
#endif
#ifndef SNELL_ROUGH_CONE_TAIL_OFFSET
#  define SNELL_ROUGH_CONE_TAIL_OFFSET 1.14f
#endif

struct SnellRoughCone {
  float radius;     // at the surface the ray leaves (view units)
  float angle;      // grows the radius linearly (the entry lobe, carried through the glass)
  float exitAngle;  // the lobe of the surface it leaves, independent of the first
};

SNELL_FN float snellRoughConeSlope(float roughness) {
  float r = isnan(roughness) ? 0.0f : clamp(roughness, 0.0f, 1.0f);
  return r * r;
}

SNELL_FN SnellRoughCone snellRoughConeTransmit(float roughness, float eta, float insideLength, int bounces) {
  float s = snellRoughConeSlope(roughness);
  float e = (eta >= 1e-6f && eta <= 1e6f) ? eta : 1.0f;
  float len = (insideLength > 0.0f && insideLength < SNELL_FLT_MAX) ? insideLength : 0.0f;
  int b = clamp(bounces, 0, SNELL_MAX_BOUNCES);
  float a = s * sqrt((1.0f - e) * (1.0f - e) + 4.0f * float(b));
  SnellRoughCone c;
  c.radius = min(a * len, SNELL_FLT_MAX);
  c.angle = min(a / e, SNELL_FLT_MAX);
  c.exitAngle = min(s * abs(1.0f / e - 1.0f), SNELL_FLT_MAX);
  return c;
}

SNELL_FN SnellRoughCone snellRoughConeReflect(float roughness) {
  SnellRoughCone c;
  c.radius = 0.0f;
  c.angle = 2.0f * snellRoughConeSlope(roughness);
  c.exitAngle = 0.0f;
  return c;
}

/* A length or angle as the cone reads it: NaN or not positive counts as 0, +inf as the largest float (so
   no product of two of them is NaN, and min / max never see a NaN, whose result differs between GPUs). */
SNELL_FN float snellRoughConeMeasure(float x) {
  return x > 0.0f ? min(x, SNELL_FLT_MAX) : 0.0f;
}

/* sqrt(x^2 + y^2) without overflow: max sqrt(1 + (min / max)^2); x, y as snellRoughConeMeasure reads them. */
SNELL_FN float snellRoughConeHypot(float x, float y) {
  float a = snellRoughConeMeasure(x);
  float b = snellRoughConeMeasure(y);
  float hi = max(a, b);
  if (!(hi > 0.0f)) {
    return 0.0f;
  }
  float q = min(a, b) / hi;
  return min(hi * sqrt(1.0f + q * q), SNELL_FLT_MAX);
}

SNELL_FN float snellRoughConeRadius(SNELL_IN(SnellRoughCone) c, float distance) {
  float d = snellRoughConeMeasure(distance);
  float carried = min(snellRoughConeMeasure(c.radius) + min(snellRoughConeMeasure(c.angle) * d, SNELL_FLT_MAX),
                      SNELL_FLT_MAX);
  return snellRoughConeHypot(carried, snellRoughConeMeasure(c.exitAngle) * d);
}

/* log2(scale radius texelsPerUnit) clamped to [0, levels - 1], as a sum of logs so no product overflows. */
SNELL_FN float snellRoughConeLevel(float radius, float texelsPerUnit, int levels) {
  if (levels <= 1 || !(radius > 0.0f) || !(texelsPerUnit > 0.0f)) {
    return 0.0f;
  }
  float lod = log2(SNELL_ROUGH_CONE_LOD_SCALE) + log2(clamp(radius, SNELL_FLT_MIN, SNELL_FLT_MAX)) +
              log2(clamp(texelsPerUnit, SNELL_FLT_MIN, SNELL_FLT_MAX));
  return clamp(lod, 0.0f, float(levels - 1));
}

SNELL_FN float snellRoughConeSceneLod(SNELL_IN(SnellRoughCone) c, float distance, vec3 p, mat4 clipFromView,
                                      ivec2 size, int levels) {
  // Smooth glass and chains without mips return before the projection: the smooth technique pays two tests.
  float radius = levels > 1 ? snellRoughConeRadius(c, distance) : 0.0f;
  if (!(radius > 0.0f)) {
    return 0.0f;
  }
  // A point with a NaN or infinite coordinate does not project (a matrix product may or may not carry
  // it into w, differently on each runtime).
  if (!SNELL_FINITE(p.x) || !SNELL_FINITE(p.y) || !SNELL_FINITE(p.z)) {
    return 0.0f;
  }
  vec4 clip = SNELL_MUL(clipFromView, vec4(p, 1.0f));
  if (!(clip.w > 0.0f) || !(clip.w < SNELL_FLT_MAX)) {
    return 0.0f;
  }
  float span = float(size.x) * abs(clipFromView[0][0]) + float(size.y) * abs(clipFromView[1][1]);
  float texelsPerUnit = min(span / (4.0f * clip.w), SNELL_FLT_MAX);
  return snellRoughConeLevel(radius, texelsPerUnit, levels);
}

SNELL_FN float snellRoughConeEnvironmentLod(SNELL_IN(SnellRoughCone) c, int levels) {
  if (levels <= 1) {
    return 0.0f;
  }
  // 2^(levels - 1) texels over 2 pi, with levels - 1 capped so the power stays finite.
  float texelsPerRadian = exp2(float(min(levels - 1, 100))) / (2.0f * SNELL_PI);
  return snellRoughConeLevel(snellRoughConeHypot(c.angle, c.exitAngle), texelsPerRadian, levels);
}

/* The two reads a rough read takes at a cone's level (lod from snellRoughConeSceneLod or
   snellRoughConeEnvironmentLod, levels: that texture's): the lobe's peak and its tail. */
struct SnellRoughTaps {
  float coreLod;
  float tailLod;
  float tailWeight;  // the tail read's share; 0: one read, at coreLod
};

SNELL_FN SnellRoughTaps snellRoughConeTaps(float lod, int levels) {
  float top = float(max(levels - 1, 0));
  float l = lod > 0.0f ? min(lod, top) : 0.0f;
  SnellRoughTaps t;
  t.coreLod = l;
  t.tailLod = l;
  t.tailWeight = 0.0f;
  if (l > 0.0f && SNELL_ROUGH_CONE_TAIL_WEIGHT > 0.0f) {
    t.coreLod = clamp(l + SNELL_ROUGH_CONE_CORE_OFFSET, 0.0f, top);
    t.tailLod = clamp(l + SNELL_ROUGH_CONE_TAIL_OFFSET, 0.0f, top);
    t.tailWeight = SNELL_ROUGH_CONE_TAIL_WEIGHT;
  }
  return t;
}

SNELL_FN int snellRoughConeFetches(SNELL_IN(SnellRoughTaps) t) {
  return t.tailWeight > 0.0f ? 2 : 1;
}

SNELL_FN vec4 snellRoughConeSample(SNELL_TEX2D tex, vec2 uv, SNELL_IN(SnellRoughTaps) t) {
  vec4 c = SNELL_SAMPLE_LOD(tex, uv, t.coreLod);
  if (t.tailWeight > 0.0f) {
    c = mix(c, SNELL_SAMPLE_LOD(tex, uv, t.tailLod), t.tailWeight);
  }
  return c;
}

SNELL_FN vec4 snellRoughConeSampleEnvironment(SNELL_ENVIRONMENT_TEX env, vec3 dir, SNELL_IN(SnellRoughTaps) t) {
  vec4 c = SNELL_SAMPLE_ENVIRONMENT(env, dir, t.coreLod);
  if (t.tailWeight > 0.0f) {
    c = mix(c, SNELL_SAMPLE_ENVIRONMENT(env, dir, t.tailLod), t.tailWeight);
  }
  return c;
}

#endif
