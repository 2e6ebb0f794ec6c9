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
