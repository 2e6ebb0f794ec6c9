/*
description: the engines' rough (frosted) transmission: how each engine
  blurs the scene colour it reads for a rough material, re-derived from its
  source, so the engine rows read rough glass as the engines do. three.js
  reads a mip level from the roughness through a bicubic B-spline filter over
  two levels; Bevy averages taps on a spiral around the point at level 0;
  Filament, HDRP and Godot read one trilinear sample of their mip chain at a
  level from the roughness. The point read is the geometric models' uv
  (engine_models.glsl); this file only says how it is read.
use: SnellEngineBlurRead c = snellEngineBlurRead(blur, sceneColor, e.uv, roughness, ior, p, clipFromView, levels);
     float lod = snellEngineBlurLod(blur, roughness, ior, levels, size, clipFromView);
     SnellEngineBlurRead c = snellEngineBicubicMips(sceneColor, uv, lod, levels);         // three.js's textureBicubic
     SnellEngineBlurRead c = snellEngineBevyBlur(sceneColor, uv, roughness, ior, viewZ, pixel, taps);
     SnellEngineBlurRead c = snellEngineSmoothRead(sceneColor, uv);   // the smooth read
  blur        SNELL_ENGINE_BLUR_* below
  sceneColor  the opaque scene's colour, mipmapped (levels levels, a full or
              partial chain; filtered linearly within and between levels)
  uv          where the engine reads (SnellEngineRefraction.uv; clamped to
              [0,1]^2 here, as the engines' clamp-to-edge samplers read it;
              a NaN component counts as 0)
  roughness   the material's perceptual roughness (0 smooth, 1 fully rough)
  ior         the material's index of refraction (the engines refract from air)
  p           the front-face fragment's view-space position (Bevy's blur
              width and noise; the caller's fragment)
  clipFromView  the colour buffer's projection (Filament's lod offset, Bevy's pixel)
  levels      sceneColor's mip levels (1: no mips)
  size        the colour buffer's size in texels (level 0)
  viewZ, pixel, taps  Bevy's: the fragment's view z (< 0 in front of the
              camera), its pixel centre counted from the image's top row (as
              WebGPU's frag_coord), its tap count (4, 8, 16, 32: quality Low
              .. Ultra; SNELL_BEVY_TRANSMISSION_TAPS by default)
options:
  SNELL_BEVY_TRANSMISSION_TAPS  the taps snellEngineBlurRead's Bevy blur
              takes (8: Bevy's default quality, Medium)
ids:
  SNELL_ENGINE_BLUR_THREEJS   three.js: bicubic over two mip levels
  SNELL_ENGINE_BLUR_BEVY      Bevy: spiral taps at level 0
  SNELL_ENGINE_BLUR_FILAMENT  Filament: one trilinear read
  SNELL_ENGINE_BLUR_HDRP      HDRP: one trilinear read
  SNELL_ENGINE_BLUR_GODOT     Godot: one trilinear read
  SNELL_ENGINE_BLUR_COUNT     the number of ids
contract:
  - smooth: where roughness is not > 0 (0, negative, NaN) or ior is not a
    finite positive number, every blur reads what the smooth models read:
    SNELL_SAMPLE_LOD(sceneColor, clamp(uv, 0, 1), 0), 1 fetch (every function
    clamps uv so, a NaN component to 0). (three.js
    reads its bicubic filter, and floors roughness at 0.045, even on smooth
    glass; not modelled, so a smooth material's read is one texel read.)
  - r = min(roughness, 1). levels < 1 counts as 1; L = levels - 1, the last level.
  - snellEngineBlurLod: three.js log2(size.x) max(r, 0.045) clamp(2 ior - 2,
    0, 1); Filament: with q = r (1 - clamp(3 / ior - 2, 0, 1)) and
    o = -log2(sqrt(2) (22 / 6) t / size.y), t = tan(2 atan(1 / |P11|)) (P11
    = clipFromView[1][1]), lod = max(0, (2 log2(q) + o) 0.8614) clamped to
    K - 1 with K = max(min(4, levels), levels - 4); 0 where q is 0 or t is not
    finite and positive (a vertical field of view of 90 degrees or more);
    HDRP: r^1.3 L; Godot: min(8 r, L); Bevy and ids outside the range: 0.
  - snellEngineBicubicMips(sceneColor, uv, lod, levels): lod < 0 or NaN counts
    as 0; a = floor(lod), b = ceil(lod), both clamped to L; level a filtered
    by the cubic B-spline with level a's texel size, level b with the texel
    size of level min(a + 1, L) (three.js's int(lod + 1)); mixed by lod - a.
    The B-spline is 4 bilinear reads per level (weights g, offsets h of its
    two halves), 8 fetches. Exact for the B-spline of the clamped texels at
    both levels.
  - snellEngineBevyBlur: s = r clamp(2 ior - 2, 0, 1), b = s^2 / viewZ (viewZ
    zero or not finite: the smooth read); n = clamp(taps, 1, 32) taps of
    level 0, averaged; tap i on spiral k = i / 8 of m = ceil(n / 8), offset
    SPIRAL[i & 7] (the even offsets first, then the odd) scaled by
    1 - 0.5 (k + 1) / m, rotated by -(g + k / m) 2 pi, its y scaled by the
    aspect size.x / size.y, times b (1 - 0.1 c); in snell's uv (y up) the
    offset's y is negated. g = fract(52.9829189 fract(0.06711056 x + 0.00583715
    y)) and c = (int(x) + int(y)) & 1 at the pixel (x, y) (each clamped to
    [0, 2^24]; not finite: 0). n fetches.
  - snellEngineBlurRead: uv clamped to [0,1]^2; three.js
    snellEngineBicubicMips at its lod; Bevy snellEngineBevyBlur with
    SNELL_BEVY_TRANSMISSION_TAPS taps, viewZ = p.z and the pixel under p's
    projection (x = floor(u W) + 0.5, y = H - floor(v H) - 0.5, with W, H
    the size of level 0); Filament, HDRP, Godot one SNELL_SAMPLE_LOD at
    their lod, 1 fetch; the smooth read where the contract's first rule says,
    and for ids outside the range.
  - snellEngineSmoothRead(sceneColor, uv): the smooth read above.
  - an engine model's blur: snellEngineBlurOf (engine_models.glsl).
  - Not modelled: three.js's geometryRoughness (from screen derivatives);
    Bevy's frame-varying noise (TEMPORAL_JITTER: the frame count in the noise
    and the checkerboard; frame 0 is modelled), TAA, its depth-prepass test
    that zeroes taps in front of the fragment (off without a DepthPrepass),
    its firefly limit min(rgb, normalize(rgb) / saturate(b / 2)), which never
    acts (b < 0 in front of the camera makes saturate 0); the chains' own
    kernels (Filament's 21-tap Gaussian per level, HDRP's and Godot's
    Gaussian pyramids, three.js's box chain: the host's mip chain is what
    is read; the lab's is snell's colour pyramid); HDRP's halo
    shrink at the blurred level and its clear-coat roughness.
source: three.js r187 (npm three@0.187.0, MIT),
  src/renderers/shaders/ShaderChunk/transmission_pars_fragment.glsl.js
  (applyIorToRoughness, getTransmissionSample, textureBicubic and bicubic
  with w0..w3, g0, g1, h0, h1: the 4-tap B-spline over levels floor and ceil
  of lod mixed by fract(lod)), lights_physical_fragment.glsl.js (roughness
  floor 0.045); Bevy 0.20.0-dev (MIT OR Apache-2.0) at
  4805ca792c3e94eef07afd6fa9a2712f388c9a67, crates/bevy_pbr/src/
  transmission.wesl (ior_corrected_roughness, specular_transmissive_light,
  fetch_transmissive_background), render/utils.wesl
  (interleaved_gradient_noise, SPIRAL_OFFSET_0_..7_), render/mesh.rs (taps
  4/8/16/32 by ScreenSpaceTransmissionQuality, default Medium: 8),
  render/pbr_functions.wesl (view_z); Filament (Apache-2.0)
  shaders/src/surface_light_indirect.fs at
  3681fe96573edd94dde8a98369a7e8aec588cfd0 (evaluateRefraction: the
  roughness remap by etaIR and the lod with invLog2sqrt5 = 0.8614),
  filament/src/PostProcessManager.cpp (prepareMipmapSSR: sigma0 = 22 / 6,
  texelSizeAtOneMeter = tan(verticalFieldOfView) / height, refractionLodOffset
  = -log2(sqrt(2) sigma0 texelSizeAtOneMeter), roughnessLodCount) with
  FCamera::getFieldOfView (2 atan(1 / p[1][1])); Unity HDRP Lit.hlsl
  (GetPreLightData: transparentSSMipLevel = PositivePow(perceptual
  roughness, 1.3) (_ColorPyramidLodCount - 1)); Godot scene/resources/
  material.cpp at 0059d788b03b559846087c2a1b86a0e19cbdc4ce (the refraction
  read textureLod(screen_texture, ref_ofs, ROUGHNESS * 8.0)). Re-derived
  from the engines' sources, not copied.
*/
#ifndef SNELL_SHADE_ENGINE_MODELS_ENGINE_ROUGH_GLSL
#define SNELL_SHADE_ENGINE_MODELS_ENGINE_ROUGH_GLSL
#include "../../prelude.glsl"
#include "../../camera/view_to_uv.glsl"

#ifndef SNELL_BEVY_TRANSMISSION_TAPS
#  define SNELL_BEVY_TRANSMISSION_TAPS 8
#endif

#define SNELL_ENGINE_BLUR_THREEJS 0
#define SNELL_ENGINE_BLUR_BEVY 1
#define SNELL_ENGINE_BLUR_FILAMENT 2
#define SNELL_ENGINE_BLUR_HDRP 3
#define SNELL_ENGINE_BLUR_GODOT 4
#define SNELL_ENGINE_BLUR_COUNT 5

/* uv clamped to [0,1]^2, a NaN component 0: clamp of a NaN differs between GPUs and GLM. */
#define SNELL_ENGINE_BLUR_UV(uv) vec2(isnan((uv).x) ? 0.0f : clamp((uv).x, 0.0f, 1.0f), isnan((uv).y) ? 0.0f : clamp((uv).y, 0.0f, 1.0f))

struct SnellEngineBlurRead {
  vec3 color;
  int fetches;
};

/* The engines' mip level for a rough material (0 where the read is smooth) */
SNELL_FN float snellEngineBlurLod(int blur, float roughness, float ior, int levels, vec2 size, mat4 clipFromView) {
  // isnan first: clamp and max of a NaN differ between GPUs and GLM.
  if (isnan(roughness) || !(roughness > 0.0f) || isnan(ior) || !SNELL_FINITE(ior) || !(ior > 0.0f)) {
    return 0.0f;
  }
  float r = min(roughness, 1.0f);
  float last = float(max(levels, 1) - 1);
  if (blur == SNELL_ENGINE_BLUR_THREEJS) {
    float w = isnan(size.x) ? 1.0f : max(size.x, 1.0f);
    return log2(w) * max(r, 0.045f) * clamp(2.0f * ior - 2.0f, 0.0f, 1.0f);
  }
  if (blur == SNELL_ENGINE_BLUR_FILAMENT) {
    float q = r * (1.0f - clamp(3.0f / ior - 2.0f, 0.0f, 1.0f));
    // tan(2 atan(x)) = 2 x / (1 - x^2), x = 1 / |P11|: positive and finite below 90 degrees.
    float x = 1.0f / abs(clipFromView[1][1]);
    float t = 2.0f * x / (1.0f - x * x);
    float h = isnan(size.y) ? 1.0f : max(size.y, 1.0f);
    if (!(q > 0.0f) || isnan(t) || !SNELL_FINITE(t) || !(t > 0.0f)) {
      return 0.0f;
    }
    float offset = -log2(1.41421356f * (22.0f / 6.0f) * t / h);
    float lod = max((2.0f * log2(q) + offset) * 0.8614f, 0.0f);
    int count = max(min(4, max(levels, 1)), max(levels, 1) - 4);
    return min(lod, float(count - 1));
  }
  if (blur == SNELL_ENGINE_BLUR_HDRP) {
    return pow(r, 1.3f) * last;
  }
  if (blur == SNELL_ENGINE_BLUR_GODOT) {
    return min(8.0f * r, last);
  }
  return 0.0f;
}

/* three.js textureBicubic: the cubic B-spline of two mip levels, 4 bilinear reads each, mixed by fract(lod) */
SNELL_FN SnellEngineBlurRead snellEngineBicubicMips(SNELL_TEX2D sceneColor, vec2 uv, float lod, int levels) {
  vec2 c0 = SNELL_ENGINE_BLUR_UV(uv);
  int last = max(levels, 1) - 1;
  float l = isnan(lod) ? 0.0f : clamp(lod, 0.0f, float(last));
  int a = int(floor(l));
  int b = min(int(ceil(l)), last);
  int sizeB = min(a + 1, last);
  float mixB = l - floor(l);
  vec3 sum = vec3(0.0f, 0.0f, 0.0f);
  for (int k = 0; k < 2; ++k) {
    int level = k == 0 ? a : b;
    ivec2 si = SNELL_TEXTURE_SIZE(sceneColor, k == 0 ? a : sizeB);
    vec2 s = vec2(float(si.x), float(si.y));
    vec2 inv = vec2(1.0f / s.x, 1.0f / s.y);
    vec2 x = c0 * s + vec2(0.5f, 0.5f);
    vec2 i = floor(x);
    vec2 f = x - i;
    // The B-spline's four weights per axis, then its two halves' weights g and offsets h.
    vec2 w0 = (1.0f / 6.0f) * (f * (f * (-f + 3.0f) - 3.0f) + 1.0f);
    vec2 w1 = (1.0f / 6.0f) * (f * f * (3.0f * f - 6.0f) + 4.0f);
    vec2 w2 = (1.0f / 6.0f) * (f * (f * (-3.0f * f + 3.0f) + 3.0f) + 1.0f);
    vec2 w3 = (1.0f / 6.0f) * (f * f * f);
    vec2 g0 = w0 + w1;
    vec2 g1 = w2 + w3;
    vec2 h0 = w1 / (w0 + w1) - 1.0f;
    vec2 h1 = w3 / (w2 + w3) + 1.0f;
    vec2 p0 = (vec2(i.x + h0.x, i.y + h0.y) - 0.5f) * inv;
    vec2 p1 = (vec2(i.x + h1.x, i.y + h0.y) - 0.5f) * inv;
    vec2 p2 = (vec2(i.x + h0.x, i.y + h1.y) - 0.5f) * inv;
    vec2 p3 = (vec2(i.x + h1.x, i.y + h1.y) - 0.5f) * inv;
    float lf = float(level);
    vec4 c = g0.y * (g0.x * SNELL_SAMPLE_LOD(sceneColor, p0, lf) + g1.x * SNELL_SAMPLE_LOD(sceneColor, p1, lf)) +
             g1.y * (g0.x * SNELL_SAMPLE_LOD(sceneColor, p2, lf) + g1.x * SNELL_SAMPLE_LOD(sceneColor, p3, lf));
    float weight = k == 0 ? 1.0f - mixB : mixB;
    sum = sum + weight * vec3(c.x, c.y, c.z);
  }
  SnellEngineBlurRead r;
  r.color = sum;
  r.fetches = 8;
  return r;
}

/* The read every blur makes on smooth glass: one texel read at level 0 */
SNELL_FN SnellEngineBlurRead snellEngineSmoothRead(SNELL_TEX2D sceneColor, vec2 uv) {
  vec4 c = SNELL_SAMPLE_LOD(sceneColor, SNELL_ENGINE_BLUR_UV(uv), 0.0f);
  SnellEngineBlurRead r;
  r.color = vec3(c.x, c.y, c.z);
  r.fetches = 1;
  return r;
}

/* Bevy fetch_transmissive_background: spiral taps at level 0 (frame 0 of its noise) */
SNELL_FN SnellEngineBlurRead snellEngineBevyBlur(SNELL_TEX2D sceneColor, vec2 uv, float roughness, float ior,
                                                 float viewZ, vec2 pixel, int taps) {
  vec2 c0 = SNELL_ENGINE_BLUR_UV(uv);
  bool rough = !isnan(roughness) && roughness > 0.0f && !isnan(ior) && SNELL_FINITE(ior) && ior > 0.0f;
  float s = rough ? min(roughness, 1.0f) * clamp(2.0f * ior - 2.0f, 0.0f, 1.0f) : 0.0f;
  if (!(s > 0.0f) || isnan(viewZ) || !SNELL_FINITE(viewZ) || viewZ == 0.0f) {
    return snellEngineSmoothRead(sceneColor, c0);
  }
  float b = s * s / viewZ;
  ivec2 si = SNELL_TEXTURE_SIZE(sceneColor, 0);
  float aspect = float(si.x) / float(si.y);
  int n = clamp(taps, 1, 32);
  int spirals = (n + 7) / 8;
  float px = (isnan(pixel.x) || !SNELL_FINITE(pixel.x)) ? 0.0f : clamp(pixel.x, 0.0f, 16777216.0f);
  float py = (isnan(pixel.y) || !SNELL_FINITE(pixel.y)) ? 0.0f : clamp(pixel.y, 0.0f, 16777216.0f);
  float t = 0.06711056f * px + 0.00583715f * py;
  t = 52.9829189f * (t - floor(t));
  float noise = t - floor(t);
  float checker = float((int(px) + int(py)) & 1);
  float scale = b * (1.0f - 0.1f * checker);
  vec3 sum = vec3(0.0f, 0.0f, 0.0f);
  // Every pass runs and the taps past n add nothing, not the end-of-pass break of docs/DESIGN.md's common
  // subset: with that break Vulkan's llvmpipe summed other taps than GL and C++ (7625 of 12000 parity cases
  // off, 0 this way). The idle passes cost llvmpipe time, which an engine's model in the lab can afford.
  for (int i = 0; i < 32; ++i) {
    if (i >= n) {
      continue;
    }
    int k = i >> 3;
    int j = i & 7;
    // Bevy's order: the even offsets of the spiral first, then the odd (4 taps still go round once).
    vec2 o = vec2(-0.7071f, 0.7071f);
    if (j == 1) {
      o = vec2(0.5303f, 0.5303f);
    } else if (j == 2) {
      o = vec2(0.3536f, -0.3536f);
    } else if (j == 3) {
      o = vec2(-0.1768f, -0.1768f);
    } else if (j == 4) {
      o = vec2(0.0f, -0.875f);
    } else if (j == 5) {
      o = vec2(-0.625f, 0.0f);
    } else if (j == 6) {
      o = vec2(0.0f, 0.375f);
    } else if (j == 7) {
      o = vec2(0.125f, 0.0f);
    }
    o = o * (1.0f - 0.5f * float(k + 1) / float(spirals));
    float angle = (noise + float(k) / float(spirals)) * (2.0f * SNELL_PI);
    float sa = sin(angle);
    float ca = cos(angle);
    vec2 d = vec2(ca * o.x + sa * o.y, (ca * o.y - sa * o.x) * aspect) * scale;
    // Bevy's uv runs down the image, snell's up: the offset's y turns over.
    vec2 tap = clamp(c0 + vec2(d.x, -d.y), vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
    vec4 c = SNELL_SAMPLE_LOD(sceneColor, tap, 0.0f);
    sum = sum + vec3(c.x, c.y, c.z);
  }
  SnellEngineBlurRead r;
  r.color = sum / float(n);
  r.fetches = n;
  return r;
}

/* The scene colour an engine reads at uv for a material of that roughness and ior */
SNELL_FN SnellEngineBlurRead snellEngineBlurRead(int blur, SNELL_TEX2D sceneColor, vec2 uv, float roughness, float ior,
                                                 vec3 p, mat4 clipFromView, int levels) {
  vec2 c0 = SNELL_ENGINE_BLUR_UV(uv);
  ivec2 si = SNELL_TEXTURE_SIZE(sceneColor, 0);
  vec2 size = vec2(float(si.x), float(si.y));
  if (blur == SNELL_ENGINE_BLUR_BEVY) {
    vec2 f = snellViewToUv(clipFromView, p).uv;
    vec2 pixel = vec2(floor(f.x * size.x) + 0.5f, size.y - floor(f.y * size.y) - 0.5f);
    return snellEngineBevyBlur(sceneColor, c0, roughness, ior, p.z, pixel, SNELL_BEVY_TRANSMISSION_TAPS);
  }
  bool rough = !isnan(roughness) && roughness > 0.0f && !isnan(ior) && SNELL_FINITE(ior) && ior > 0.0f;
  if (!rough || blur < 0 || blur >= SNELL_ENGINE_BLUR_COUNT) {
    return snellEngineSmoothRead(sceneColor, c0);
  }
  float lod = snellEngineBlurLod(blur, roughness, ior, levels, size, clipFromView);
  if (blur == SNELL_ENGINE_BLUR_THREEJS) {
    return snellEngineBicubicMips(sceneColor, c0, lod, levels);
  }
  vec4 c = SNELL_SAMPLE_LOD(sceneColor, c0, lod);
  SnellEngineBlurRead r;
  r.color = vec3(c.x, c.y, c.z);
  r.fetches = 1;
  return r;
}

#endif
