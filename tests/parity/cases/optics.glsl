/* Parity cases for glsl/snell/optics: one entry per public function.
   Inputs arrive as four vec4s, results leave as four vec4s (bools as 0/1). */
#include "snell/optics.glsl"

SNELL_FN vec4 parityBool4(bool x, bool y, bool z, bool w) {
  return vec4(x ? 1.0f : 0.0f, y ? 1.0f : 0.0f, z ? 1.0f : 0.0f, w ? 1.0f : 0.0f);
}

SNELL_FN SnellParityOut caseSnellSafeNormalize(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  vec3 n = snellSafeNormalize(vec3(a.x, a.y, a.z));
  o.a = vec4(n.x, n.y, n.z, 0.0f);
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

/* a.xyz incident, a.w eta, b.xyz normal, b.w policy. */
SNELL_FN SnellParityOut caseSnellRefract(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  SnellRefraction r = snellRefract(vec3(a.x, a.y, a.z), vec3(b.x, b.y, b.z), a.w, int(b.w));
  o.a = vec4(r.direction.x, r.direction.y, r.direction.z, 0.0f);
  o.b = parityBool4(r.tir, r.valid, false, false);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

/* a.xyz incident, a.w factor, b.xyz normal. */
SNELL_FN SnellParityOut caseSnellApproxRefract(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  vec3 t = snellApproxRefract(vec3(a.x, a.y, a.z), vec3(b.x, b.y, b.z), a.w);
  o.a = vec4(t.x, t.y, t.z, 0.0f);
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

/* Four evaluations per invocation: (a.x, a.y), (a.z, a.w), (b.x, b.y), (b.z, b.w)
   are (cosI, eta) pairs. */
SNELL_FN SnellParityOut caseSnellFresnelDielectric(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  o.a = vec4(snellFresnelDielectric(a.x, a.y), snellFresnelDielectric(a.z, a.w),
             snellFresnelDielectric(b.x, b.y), snellFresnelDielectric(b.z, b.w));
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

/* (cosI, f0) pairs as in caseSnellFresnelDielectric. */
SNELL_FN SnellParityOut caseSnellFresnelSchlick(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  o.a = vec4(snellFresnelSchlick(a.x, a.y), snellFresnelSchlick(a.z, a.w), snellFresnelSchlick(b.x, b.y),
             snellFresnelSchlick(b.z, b.w));
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

/* (nDotL, bias, power) triples: a.xyz, b.xyz, c.xyz, d.xyz. */
SNELL_FN SnellParityOut caseSnellFresnelBiasPower(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  o.a = vec4(snellFresnelBiasPower(a.x, a.y, a.z), snellFresnelBiasPower(b.x, b.y, b.z),
             snellFresnelBiasPower(c.x, c.y, c.z), snellFresnelBiasPower(d.x, d.y, d.z));
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

/* (eye, normal) pairs: (a.xyz, b.xyz) and (c.xyz, d.xyz). */
SNELL_FN SnellParityOut caseSnellFresnelCubic(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  o.a = vec4(snellFresnelCubic(vec3(a.x, a.y, a.z), vec3(b.x, b.y, b.z)),
             snellFresnelCubic(vec3(c.x, c.y, c.z), vec3(d.x, d.y, d.z)), 0.0f, 0.0f);
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

/* (iorIncident, iorTransmitted) pairs as in caseSnellFresnelDielectric. */
SNELL_FN SnellParityOut caseSnellIorToEta(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  o.a = vec4(snellIorToEta(a.x, a.y), snellIorToEta(a.z, a.w), snellIorToEta(b.x, b.y), snellIorToEta(b.z, b.w));
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

SNELL_FN SnellParityOut caseSnellIorToF0(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  o.a = vec4(snellIorToF0(a.x, a.y), snellIorToF0(a.z, a.w), snellIorToF0(b.x, b.y), snellIorToF0(b.z, b.w));
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

/* a.xyz front normal, a.w blend weight, b.xyz back normal; o.a the explicit-weight
   overload, o.b the SNELL_ICE_NORMAL_BLEND overload. */
SNELL_FN SnellParityOut caseSnellIceNormalBlend(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  vec3 f = vec3(a.x, a.y, a.z);
  vec3 k = vec3(b.x, b.y, b.z);
  vec3 r = snellIceNormalBlend(f, k, a.w);
  vec3 s = snellIceNormalBlend(f, k);
  o.a = vec4(r.x, r.y, r.z, 0.0f);
  o.b = vec4(s.x, s.y, s.z, 0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

/* a.xyz absorption, a.w distance. */
SNELL_FN SnellParityOut caseSnellBeerLambert(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  vec3 t = snellBeerLambert(vec3(a.x, a.y, a.z), a.w);
  o.a = vec4(t.x, t.y, t.z, 0.0f);
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

/* (a.xyz, b.xyz) and (c.xyz, d.xyz). */
SNELL_FN SnellParityOut caseSnellAngleBetween(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  o.a = vec4(snellAngleBetween(vec3(a.x, a.y, a.z), vec3(b.x, b.y, b.z)),
             snellAngleBetween(vec3(c.x, c.y, c.z), vec3(d.x, d.y, d.z)), 0.0f, 0.0f);
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

/* (thetaT, thetaI, dV, dN) in each of a, b, c, d. */
SNELL_FN SnellParityOut caseSnellWymanDistance(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  o.a = vec4(snellWymanDistance(a.x, a.y, a.z, a.w), snellWymanDistance(b.x, b.y, b.z, b.w),
             snellWymanDistance(c.x, c.y, c.z, c.w), snellWymanDistance(d.x, d.y, d.z, d.w));
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

/* a.xyz incident, a.w dV, b.xyz normal, b.w dN, c.xyz refracted. */
SNELL_FN SnellParityOut caseSnellWymanDistanceVec(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  o.a = vec4(snellWymanDistanceVec(vec3(a.x, a.y, a.z), vec3(b.x, b.y, b.z), vec3(c.x, c.y, c.z), a.w, b.w),
             0.0f, 0.0f, 0.0f);
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

/* a.xyz origin, b.xyz direction, c.xyz plane point, d.xyz plane normal;
   o.a = (t, position), o.b.x = valid. */
SNELL_FN SnellParityOut caseSnellRayPlane(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  SnellRayPlaneHit h = snellRayPlane(vec3(a.x, a.y, a.z), vec3(b.x, b.y, b.z), vec3(c.x, c.y, c.z),
                                     vec3(d.x, d.y, d.z));
  o.a = vec4(h.t, h.position.x, h.position.y, h.position.z);
  o.b = parityBool4(h.valid, false, false, false);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}
