/*
description: the gallery's per-pixel effect calls (snell-gallery,
  examples/gallery): one function per effect that its full-screen pass calls
  on the GPU (gallery_*.frag) and snell-gallery calls per pixel in C++ on the
  read-back buffers, so the CPU frame and the GPU frame come from one body.
  Each takes the effect's G-buffer texels (the refracting surface's world
  position, normal, depth) and the textures the effect reads, and calls the
  library: water.glsl, glass.glsl, perturb.glsl, refraction_mask*.glsl,
  ice.glsl, ice_crack_clip.glsl, refractive_texture_map.glsl.
use: vec4 c = galleryWater(world, surfaceDepth, uv, eye, time, GALLERY_MASK_ALPHA, bump, S, sceneDepth, reflection, p);
     vec4 c = galleryPane(material, paneUv, world, uv, eye, time, mask, bump, stain, S, environment2d);
     GalleryIce i = galleryIce(front, back, world, eye, frontDepth, backDepth, crackDepths, environment);
     vec2 uv = galleryRtmUv(vertex, normal, eye, exact, eta, p);
contract: the effects as their library functions state them; the gallery adds
  only the scene's conventions: world space y up, the water plane's tangent
  frame (x, -z, y), the panes' frame (x, y, z), four bump layers at fixed
  scales and drifts, and mask modes GALLERY_MASK_OFF (the perturbed read
  always), GALLERY_MASK_ALPHA (Sousa's alpha mask) and GALLERY_MASK_DEPTH (the
  depth-aware mask). Depths are GL window depths (SNELL_DEPTH_GL).
source: see each library function.
*/
#ifndef GALLERY_EFFECTS_GLSL
#define GALLERY_EFFECTS_GLSL
#include "snell/prelude.glsl"
#include "snell/camera/conventions.glsl"
#include "snell/optics/ray_plane.glsl"
#include "snell/optics/refract.glsl"
#include "snell/shade/environment.glsl"
#include "snell/shade/glass.glsl"
#include "snell/shade/ice.glsl"
#include "snell/shade/ice_crack_clip.glsl"
#include "snell/shade/perturb.glsl"
#include "snell/shade/refraction_mask.glsl"
#include "snell/shade/refraction_mask_depth.glsl"
#include "snell/shade/refractive_texture_map.glsl"
#include "snell/shade/water.glsl"

#define GALLERY_MASK_OFF 0
#define GALLERY_MASK_ALPHA 1
#define GALLERY_MASK_DEPTH 2

/* The haze's displacement per unit of bump, in uv: the gallery's bump map
   is gentle (slopes up to about 0.3), so more than SNELL_PERTURB_SCALE. */
#define GALLERY_HAZE_SCALE 0.07f

#define GALLERY_PANE_STAINED 1.0f
#define GALLERY_PANE_HAZE 2.0f

/* Bump layer k's texture coordinate at a world point: Sousa animates four
   copies of one bump map at different scales and speeds (sec. 19.3.1). The
   bump map's content is periodic, so the coordinate wraps; the textures clamp
   to edge on both sides, which leaves a one-texel seam where it does. */
SNELL_FN vec2 galleryWaveCoord(vec3 world, float time, int layer) {
  vec2 xz = vec2(world.x, world.z);
  vec2 c = xz * 0.09f + vec2(0.011f, 0.017f) * time;
  if (layer == 1) {
    c = xz * 0.17f + vec2(-0.019f, 0.008f) * time;
  } else if (layer == 2) {
    c = xz * 0.31f + vec2(0.027f, -0.023f) * time;
  } else if (layer == 3) {
    c = xz * 0.53f + vec2(-0.031f, -0.037f) * time;
  }
  return fract(c);
}

/* Sousa's water at one water pixel. world: the water surface point;
   surfaceDepth: its window depth; uv: the pixel's viewport uv; eye: the camera
   position. GALLERY_MASK_ALPHA is snellWater itself; the other two modes read
   the refraction their own way and compose with snellWaterCompose. */
SNELL_FN vec4 galleryWater(vec3 world, float surfaceDepth, vec2 uv, vec3 eye, float time, int mask, SNELL_TEX2D bump,
                           SNELL_TEX2D sceneColor, SNELL_TEX2D sceneDepth, SNELL_TEX2D reflection,
                           SnellWaterParams p) {
  vec4 t0 = SNELL_SAMPLE_LOD(bump, galleryWaveCoord(world, time, 0), 0.0f);
  vec4 t1 = SNELL_SAMPLE_LOD(bump, galleryWaveCoord(world, time, 1), 0.0f);
  vec4 t2 = SNELL_SAMPLE_LOD(bump, galleryWaveCoord(world, time, 2), 0.0f);
  vec4 t3 = SNELL_SAMPLE_LOD(bump, galleryWaveCoord(world, time, 3), 0.0f);
  vec3 n = snellWaterBumpAverage(vec3(t0.x, t0.y, t0.z), vec3(t1.x, t1.y, t1.z), vec3(t2.x, t2.y, t2.z),
                                 vec3(t3.x, t3.y, t3.z));
  vec3 e = eye - world;
  vec3 eyeTs = vec3(e.x, -e.z, e.y);  // tangent frame of the plane y = const: x, -z, normal +y
  float dist = length(e);
  if (mask == GALLERY_MASK_ALPHA) {
    return snellWater(sceneColor, reflection, uv, n, eyeTs, dist, p);
  }
  vec3 refrBump = n * p.refractionBumpScale;
  vec3 reflBump = n * p.reflectionBumpScale;
  vec2 uvRefl = clamp(snellPerturbUv(uv, vec2(reflBump.x, reflBump.y), 1.0f), vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
  vec4 refl = SNELL_SAMPLE_LOD(reflection, uvRefl, 0.0f);
  vec4 refr = mask == GALLERY_MASK_DEPTH
                  ? snellRefractionMaskedDepth(sceneColor, sceneDepth, uv, vec2(refrBump.x, refrBump.y), 1.0f,
                                               surfaceDepth, SNELL_DEPTH_GL)
                  : snellPerturbSample(sceneColor, uv, vec2(refrBump.x, refrBump.y), 1.0f);
  return snellWaterCompose(refl, refr, n, eyeTs, dist, p);
}

/* One pane pixel: GALLERY_PANE_STAINED is Sousa's stained glass (snellGlass,
   which always uses the alpha mask); GALLERY_PANE_HAZE is heat haze, the
   basic perturbation with the bump map drifting upwards, with the alpha mask
   (mask != GALLERY_MASK_OFF) or without. paneUv: the pane's own [0,1]^2
   coordinate; the panes face +z, so the eye's tangent-space vector is its
   world vector. */
SNELL_FN vec4 galleryPane(float material, vec2 paneUv, vec3 world, vec2 uv, vec3 eye, float time, int mask,
                          SNELL_TEX2D bump, SNELL_TEX2D stain, SNELL_TEX2D sceneColor, SNELL_TEX2D environment) {
  if (material == GALLERY_PANE_STAINED) {
    vec4 b = SNELL_SAMPLE_LOD(bump, fract(paneUv * 1.5f), 0.0f);
    vec4 d = SNELL_SAMPLE_LOD(stain, paneUv, 0.0f);
    return snellGlass(sceneColor, environment, uv, vec3(b.x, b.y, b.z), d, eye - world);
  }
  vec4 h = SNELL_SAMPLE_LOD(bump, fract(paneUv * 0.8f + vec2(0.0f, -0.25f) * time), 0.0f);
  vec3 bh = snellUnpackBump(vec3(h.x, h.y, h.z));
  // The haze fades out towards the pane's border, where hot air mixes with the room's.
  float fadeU = min(paneUv.x, 1.0f - paneUv.x);
  float fadeV = min(paneUv.y, 1.0f - paneUv.y);
  float fade = clamp(min(fadeU, fadeV) * 5.0f, 0.0f, 1.0f);
  vec2 d = vec2(bh.x, bh.y) * fade;
  if (mask == GALLERY_MASK_OFF) {
    return snellPerturbSample(sceneColor, uv, d, GALLERY_HAZE_SCALE);
  }
  return snellRefractionMasked(sceneColor, uv, d, GALLERY_HAZE_SCALE);
}

#define GALLERY_CRACKS 4

struct GalleryIce {
  vec4 color;
  int cracks;  // bit k set: crack surface k is kept at this pixel
};

/* The ice block at one front-face pixel: snellIce about the front and back
   normals (world space), both directions looked up in the equirectangular
   environment, composed with the cubic Fresnel term and tinted; then each
   crack surface whose depth at the pixel lies between the front and back
   depths (snellIceCrackKeep) whitens it. crackDepth[k] > 1: crack k does not
   cover the pixel. */
SNELL_FN GalleryIce galleryIce(vec3 frontNormal, vec3 backNormal, vec3 world, vec3 eye, float frontDepth,
                               float backDepth, vec4 crackDepth, bool withCracks, SNELL_TEX2D environment) {
  GalleryIce r;
  SnellIce s = snellIce(world - eye, frontNormal, backNormal);
  vec4 refl = snellSampleEquirect(environment, s.reflected, 0.0f);
  vec4 refr = snellSampleEquirect(environment, s.refracted, 0.0f) * vec4(0.78f, 0.9f, 1.0f, 1.0f);
  vec4 c = snellIceCompose(refl, refr, s.fresnel);
  r.cracks = 0;
  if (withCracks) {
    for (int k = 0; k < GALLERY_CRACKS; ++k) {
      if (snellIceCrackKeep(crackDepth[k], frontDepth, backDepth, SNELL_DEPTH_GL)) {
        r.cracks += 1 << k;
        c = c * 0.7f + vec4(0.95f, 0.97f, 1.0f, 1.0f) * 0.3f;
      }
    }
  }
  r.color = vec4(c.x, c.y, c.z, 1.0f);
  return r;
}

/* The planar map's uv seen through one vertex of the refractive water mesh:
   G. Oliveira's approximate ray (snellRefractiveTextureMap) or, with exact,
   Snell's law (snellRefract with eta) to the same plane, mapped with the
   same eqs. 12-13 and clamp policy. */
SNELL_FN vec2 galleryRtmUv(vec3 vertex, vec3 normal, vec3 eye, bool exact, float eta,
                           SnellRefractiveTextureMapParams p) {
  SnellRefractiveTextureMapHit h = snellRefractiveTextureMap(vertex, normal, eye, p);
  if (!exact) {
    return h.uv;
  }
  SnellRefraction t = snellRefract(vertex - eye, normal, eta, SNELL_TIR_ZERO);
  SnellRayPlaneHit hit =
      snellRayPlane(vertex, t.direction, vec3(0.0f, p.restY - p.depth, 0.0f), vec3(0.0f, 1.0f, 0.0f));
  if (!t.valid || t.tir || !hit.valid || !(t.direction.y < 0.0f)) {
    return h.uv;
  }
  vec2 e = vec2(snellRefractiveTextureMapAxis(hit.position.x, p.extentMin.x, p.extentMax.x),
                snellRefractiveTextureMapAxis(hit.position.z, p.extentMin.y, p.extentMax.y));
  return clamp(e, vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
}

#endif
