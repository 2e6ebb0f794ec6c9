/* Parity cases for the Sousa / water / glass / ice / refractive-texture-map /
   dispersion / roughness functions of glsl/snell/shade: one entry per public
   function. Inputs arrive as four vec4s, results leave as four vec4s (bools as
   0/1). The textures are built by tests/parity/shade_cases.cpp. */
#include "snell/shade.glsl"

#if defined(SNELL_LANG_GLSL)
uniform sampler2D parityShadeScene;       /* LINEAR, rgb colour, alpha = Sousa's mask (0 inside) */
uniform sampler2D parityShadeReflection;  /* LINEAR, reflection / environment map */
uniform sampler2D parityShadeDepth;       /* NEAREST, opaque scene depth in .x */
#endif
#if defined(SNELL_LANG_HLSL)
Texture2D<float4> parityShadeScene;
Texture2D<float4> parityShadeReflection;
Texture2D<float4> parityShadeDepth;
#endif

SNELL_FN float shadeParityFlag(bool b) {
  return b ? 1.0f : 0.0f;
}

SNELL_FN SnellParityOut shadeParityOut(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  o.a = a;
  o.b = b;
  o.c = c;
  o.d = d;
  return o;
}

/* a.xyz texel */
SNELL_FN SnellParityOut caseSnellUnpackBump(vec4 a, vec4 b, vec4 c, vec4 d) {
  vec3 n = snellUnpackBump(vec3(a.x, a.y, a.z));
  return shadeParityOut(vec4(n.x, n.y, n.z, 0.0f), vec4(0.0f), vec4(0.0f), vec4(0.0f));
}

/* a = (uv, bump), b.x scale, b.y = 1: default-scale overload */
SNELL_FN SnellParityOut caseSnellPerturbUv(vec4 a, vec4 b, vec4 c, vec4 d) {
  vec2 p = b.y > 0.5f ? snellPerturbUv(vec2(a.x, a.y), vec2(a.z, a.w))
                      : snellPerturbUv(vec2(a.x, a.y), vec2(a.z, a.w), b.x);
  return shadeParityOut(vec4(p.x, p.y, 0.0f, 0.0f), vec4(0.0f), vec4(0.0f), vec4(0.0f));
}

/* a = (uv, bump), b.x scale */
SNELL_FN SnellParityOut caseSnellPerturbSample(vec4 a, vec4 b, vec4 c, vec4 d) {
  vec4 s = snellPerturbSample(parityShadeScene, vec2(a.x, a.y), vec2(a.z, a.w), b.x);
  return shadeParityOut(s, vec4(0.0f), vec4(0.0f), vec4(0.0f));
}

/* a = (uv, width, mode): mode 1 uses the default width */
SNELL_FN SnellParityOut caseSnellScreenEdgeFade(vec4 a, vec4 b, vec4 c, vec4 d) {
  float f = a.w > 0.5f ? snellScreenEdgeFade(vec2(a.x, a.y)) : snellScreenEdgeFade(vec2(a.x, a.y), a.z);
  return shadeParityOut(vec4(f, 0.0f, 0.0f, 0.0f), vec4(0.0f), vec4(0.0f), vec4(0.0f));
}

/* a = refrA, b = refrB */
SNELL_FN SnellParityOut caseSnellRefractionMaskBlend(vec4 a, vec4 b, vec4 c, vec4 d) {
  return shadeParityOut(snellRefractionMaskBlend(a, b), vec4(0.0f), vec4(0.0f), vec4(0.0f));
}

/* a = (uv, bump), b.x scale */
SNELL_FN SnellParityOut caseSnellRefractionMasked(vec4 a, vec4 b, vec4 c, vec4 d) {
  vec4 s = snellRefractionMasked(parityShadeScene, vec2(a.x, a.y), vec2(a.z, a.w), b.x);
  return shadeParityOut(s, vec4(0.0f), vec4(0.0f), vec4(0.0f));
}

/* four (sceneDepth, surfaceDepth, convention) triples: a.xyz .. d.xyz */
SNELL_FN SnellParityOut caseSnellRefractionDepthAccept(vec4 a, vec4 b, vec4 c, vec4 d) {
  vec4 r = vec4(shadeParityFlag(snellRefractionDepthAccept(a.x, a.y, int(a.z))),
                shadeParityFlag(snellRefractionDepthAccept(b.x, b.y, int(b.z))),
                shadeParityFlag(snellRefractionDepthAccept(c.x, c.y, int(c.z))),
                shadeParityFlag(snellRefractionDepthAccept(d.x, d.y, int(d.z))));
  return shadeParityOut(r, vec4(0.0f), vec4(0.0f), vec4(0.0f));
}

/* a = (uv, bump), b = (scale, surfaceDepth, convention) */
SNELL_FN SnellParityOut caseSnellRefractionMaskedDepth(vec4 a, vec4 b, vec4 c, vec4 d) {
  vec4 s = snellRefractionMaskedDepth(parityShadeScene, parityShadeDepth, vec2(a.x, a.y), vec2(a.z, a.w), b.x, b.y,
                                      int(b.z));
  return shadeParityOut(s, vec4(0.0f), vec4(0.0f), vec4(0.0f));
}

/* no input; every field of the defaults */
SNELL_FN SnellParityOut caseSnellWaterParams(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellWaterParams p = snellWaterParams();
  return shadeParityOut(
      vec4(p.refractionBumpScale.x, p.refractionBumpScale.y, p.refractionBumpScale.z, p.reflectionBumpScale.x),
      vec4(p.reflectionBumpScale.y, p.reflectionBumpScale.z, p.fresnelBias, p.fresnelPower),
      vec4(p.deepDistance, p.waterColor.x, p.waterColor.y, p.waterColor.z),
      vec4(p.deepColor.x, p.deepColor.y, p.deepColor.z, 0.0f));
}

/* a.xyz .. d.xyz the four bump texels */
SNELL_FN SnellParityOut caseSnellWaterBumpAverage(vec4 a, vec4 b, vec4 c, vec4 d) {
  vec3 n = snellWaterBumpAverage(vec3(a.x, a.y, a.z), vec3(b.x, b.y, b.z), vec3(c.x, c.y, c.z), vec3(d.x, d.y, d.z));
  return shadeParityOut(vec4(n.x, n.y, n.z, 0.0f), vec4(0.0f), vec4(0.0f), vec4(0.0f));
}

/* a = (uv, viewDistance, custom), b.xyz bump normal, c.xyz eye,
   d = (fresnelBias, fresnelPower, deepDistance, bump scale) used when custom = 1 */
SNELL_FN SnellParityOut caseSnellWater(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellWaterParams p = snellWaterParams();
  if (a.w > 0.5f) {
    p.fresnelBias = d.x;
    p.fresnelPower = d.y;
    p.deepDistance = d.z;
    p.refractionBumpScale = vec3(d.w, d.w, 1.0f);
  }
  vec4 s = snellWater(parityShadeScene, parityShadeReflection, vec2(a.x, a.y), vec3(b.x, b.y, b.z),
                      vec3(c.x, c.y, c.z), a.z, p);
  return shadeParityOut(s, vec4(0.0f), vec4(0.0f), vec4(0.0f));
}

/* a reflection colour, b refraction colour, c = (bump normal, viewDistance), d.xyz eye */
SNELL_FN SnellParityOut caseSnellWaterCompose(vec4 a, vec4 b, vec4 c, vec4 d) {
  vec4 s = snellWaterCompose(a, b, vec3(c.x, c.y, c.z), vec3(d.x, d.y, d.z), c.w, snellWaterParams());
  return shadeParityOut(s, vec4(0.0f), vec4(0.0f), vec4(0.0f));
}

/* a.xy uv, b.xyz bump texel, c.xyz eye, d diffuse */
SNELL_FN SnellParityOut caseSnellGlass(vec4 a, vec4 b, vec4 c, vec4 d) {
  vec4 s = snellGlass(parityShadeScene, parityShadeReflection, vec2(a.x, a.y), vec3(b.x, b.y, b.z), d,
                      vec3(c.x, c.y, c.z));
  return shadeParityOut(s, vec4(0.0f), vec4(0.0f), vec4(0.0f));
}

/* a = (eye, a), b = (frontNormal, eta), c = (backNormal, mode): mode 1 uses the
   defaults overload. out a = (refracted, fresnel), b = (reflected, valid) */
SNELL_FN SnellParityOut caseSnellIce(vec4 a, vec4 b, vec4 c, vec4 d) {
  vec3 e = vec3(a.x, a.y, a.z);
  vec3 nf = vec3(b.x, b.y, b.z);
  vec3 nb = vec3(c.x, c.y, c.z);
  SnellIce s = c.w > 0.5f ? snellIce(e, nf, nb) : snellIce(e, nf, nb, a.w, b.w);
  return shadeParityOut(vec4(s.refracted.x, s.refracted.y, s.refracted.z, s.fresnel),
                        vec4(s.reflected.x, s.reflected.y, s.reflected.z, shadeParityFlag(s.valid)), vec4(0.0f),
                        vec4(0.0f));
}

/* a reflection, b refraction, c.x fresnel */
SNELL_FN SnellParityOut caseSnellIceCompose(vec4 a, vec4 b, vec4 c, vec4 d) {
  return shadeParityOut(snellIceCompose(a, b, c.x), vec4(0.0f), vec4(0.0f), vec4(0.0f));
}

/* four (crack, front, back, convention) quadruples */
SNELL_FN SnellParityOut caseSnellIceCrackKeep(vec4 a, vec4 b, vec4 c, vec4 d) {
  vec4 r = vec4(shadeParityFlag(snellIceCrackKeep(a.x, a.y, a.z, int(a.w))),
                shadeParityFlag(snellIceCrackKeep(b.x, b.y, b.z, int(b.w))),
                shadeParityFlag(snellIceCrackKeep(c.x, c.y, c.z, int(c.w))),
                shadeParityFlag(snellIceCrackKeep(d.x, d.y, d.z, int(d.w))));
  return shadeParityOut(r, vec4(0.0f), vec4(0.0f), vec4(0.0f));
}

/* a = (extentMin, extentMax), b = (restY, depth, factor); every field out */
SNELL_FN SnellParityOut caseSnellRefractiveTextureMapParams(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellRefractiveTextureMapParams p =
      snellRefractiveTextureMapParams(vec2(a.x, a.y), vec2(a.z, a.w), b.x, b.y, b.z);
  return shadeParityOut(vec4(p.extentMin.x, p.extentMin.y, p.extentMax.x, p.extentMax.y),
                        vec4(p.restY, p.depth, p.refractionFactor, float(p.policy)),
                        vec4(p.uvMin, p.uvMax, 0.0f, 0.0f), vec4(0.0f));
}

/* four (x, lo, hi) triples */
SNELL_FN SnellParityOut caseSnellRefractiveTextureMapAxis(vec4 a, vec4 b, vec4 c, vec4 d) {
  vec4 r = vec4(snellRefractiveTextureMapAxis(a.x, a.y, a.z), snellRefractiveTextureMapAxis(b.x, b.y, b.z),
                snellRefractiveTextureMapAxis(c.x, c.y, c.z), snellRefractiveTextureMapAxis(d.x, d.y, d.z));
  return shadeParityOut(r, vec4(0.0f), vec4(0.0f), vec4(0.0f));
}

/* a = (vertex, factor), b = (normal, depth), c = (eye, restY), d = (extentMin, extentMax).
   Four policies/intervals: constructor (CLAMP [0,1]), SHRINK [0.1, 0.9], CLAMP
   with swapped bounds (0.8, 0.3), SHRINK with (NaN, 2) (-> [0, 1]).
   out a = (uv1, uv2), b = (uv3, uv4), c = (position, valid), d.x inRange */
SNELL_FN SnellParityOut caseSnellRefractiveTextureMap(vec4 a, vec4 b, vec4 c, vec4 d) {
  vec3 v = vec3(a.x, a.y, a.z);
  vec3 n = vec3(b.x, b.y, b.z);
  vec3 e = vec3(c.x, c.y, c.z);
  SnellRefractiveTextureMapParams p = snellRefractiveTextureMapParams(vec2(d.x, d.y), vec2(d.z, d.w), c.w, b.w, a.w);
  SnellRefractiveTextureMapHit h1 = snellRefractiveTextureMap(v, n, e, p);
  p.policy = SNELL_RTM_SHRINK;
  p.uvMin = 0.1f;
  p.uvMax = 0.9f;
  SnellRefractiveTextureMapHit h2 = snellRefractiveTextureMap(v, n, e, p);
  p.policy = SNELL_RTM_CLAMP;
  p.uvMin = 0.8f;
  p.uvMax = 0.3f;
  SnellRefractiveTextureMapHit h3 = snellRefractiveTextureMap(v, n, e, p);
  p.policy = SNELL_RTM_SHRINK;
  p.uvMin = uintBitsToFloat(0x7fc00000u);  /* quiet NaN */
  p.uvMax = 2.0f;
  SnellRefractiveTextureMapHit h4 = snellRefractiveTextureMap(v, n, e, p);
  return shadeParityOut(vec4(h1.uv.x, h1.uv.y, h2.uv.x, h2.uv.y), vec4(h3.uv.x, h3.uv.y, h4.uv.x, h4.uv.y),
                        vec4(h1.position.x, h1.position.y, h1.position.z, shadeParityFlag(h1.valid)),
                        vec4(shadeParityFlag(h1.inRange), 0.0f, 0.0f, 0.0f));
}

/* four (iorD, abbe) pairs: (a.x, a.y), (a.z, a.w), (b.x, b.y), (b.z, b.w) */
SNELL_FN SnellParityOut caseSnellDispersionIors(vec4 a, vec4 b, vec4 c, vec4 d) {
  vec3 n0 = snellDispersionIors(a.x, a.y);
  vec3 n1 = snellDispersionIors(a.z, a.w);
  vec3 n2 = snellDispersionIors(b.x, b.y);
  vec3 n3 = snellDispersionIors(b.z, b.w);
  return shadeParityOut(vec4(n0.x, n0.y, n0.z, 0.0f), vec4(n1.x, n1.y, n1.z, 0.0f), vec4(n2.x, n2.y, n2.z, 0.0f),
                        vec4(n3.x, n3.y, n3.z, 0.0f));
}

/* a = (incident, iorOutside), b = (normal, policy), c.xyz iors.
   out a, b, c = red, green, blue directions, d = (tir, valid) */
SNELL_FN SnellParityOut caseSnellDispersionRefract(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDispersion s =
      snellDispersionRefract(vec3(a.x, a.y, a.z), vec3(b.x, b.y, b.z), a.w, vec3(c.x, c.y, c.z), int(b.w));
  return shadeParityOut(vec4(s.red.x, s.red.y, s.red.z, 0.0f), vec4(s.green.x, s.green.y, s.green.z, 0.0f),
                        vec4(s.blue.x, s.blue.y, s.blue.z, 0.0f),
                        vec4(shadeParityFlag(s.tir), shadeParityFlag(s.valid), 0.0f, 0.0f));
}

/* four (roughness, levels) pairs: (a.x, a.y), (a.z, a.w), (b.x, b.y), (b.z, b.w) */
SNELL_FN SnellParityOut caseSnellRoughnessToLod(vec4 a, vec4 b, vec4 c, vec4 d) {
  vec4 r = vec4(snellRoughnessToLod(a.x, int(a.y)), snellRoughnessToLod(a.z, int(a.w)),
                snellRoughnessToLod(b.x, int(b.y)), snellRoughnessToLod(b.z, int(b.w)));
  return shadeParityOut(r, vec4(0.0f), vec4(0.0f), vec4(0.0f));
}
