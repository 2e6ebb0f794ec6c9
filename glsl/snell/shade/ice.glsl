/*
description: the ice shader's reflection and two-sided refraction: refract the
  eye vector once about the blend of the front normal and the negated
  back-face normal (eqs. 1-2), reflect it about the front normal (eq. 3), and
  mix the two environment colours with the cubic Fresnel term (eq. 4).
use: SnellIce s = snellIce(eyeWs, frontNormalWs, backNormalWs, 0.33f, SNELL_ICE_ETA);
     SnellIce s = snellIce(eyeWs, frontNormalWs, backNormalWs);  // a, eta defaults
     vec4 refl = texture(envCube, s.reflected), refr = texture(envCube, s.refracted);
     vec4 c = snellIceCompose(refl, refr, s.fresnel);
  eye          the paper's e: from the viewer to the surface point (need not be
               unit)
  frontNormal  outward normal of the front face (need not be unit)
  backNormal   outward normal of the back face from the back-face normal buffer
               (points away from the viewer; eq. 1 negates it)
  a            share of the back-face normal in [0, 1] (snellIceNormalBlend)
  eta          n_air / n_ice
options:
  SNELL_ICE_ETA         default eta, 1.0003f / 1.3091f (about 0.7641: the paper's
                        air/ice ratio)
  SNELL_ICE_TIR_POLICY  snellRefract's TIR policy (SNELL_TIR_REFLECT); with
                        eta < 1 TIR cannot occur
  (SNELL_ICE_NORMAL_BLEND, the default a, comes from optics/ice_normal_blend.glsl)
contract:
  - blended = snellIceNormalBlend(frontNormal, backNormal, a);
    refracted = snellRefract(eye, blended, eta, SNELL_ICE_TIR_POLICY).direction;
    reflected = e - 2 (nf . e) nf with e, nf the normalized eye and front normal;
    fresnel = snellFresnelCubic(eye, frontNormal) = (1 - |e . nf|)^3.
  - eta NaN, <= 0, denormal or infinite: 1 (no bending, refracted = e).
  - valid is false when eye or frontNormal is zero, denormal-small, NaN or
    infinite: refracted = reflected = (0,0,0), fresnel = 1. An invalid
    backNormal gives one-sided refraction about nf (snellIceNormalBlend).
  - with SNELL_TIR_ZERO as the policy a TIR gives refracted = (0,0,0) and
    fresnel 1 (everything reflected); valid stays true.
  - snellIceCompose = refraction (1 - f) + reflection f with f = fresnel clamped
    to [0, 1]; a NaN fresnel counts as 1.
source: "Real-Time Ice Rendering" (ice shader report), sec. 3.2: eq. 1 (normal
  blend, a = 0.33), eq. 2 (refraction with eta = 1.0003/1.3091), eq. 3
  (r_refl = e - 2 (e.n_f) n_f), eq. 4 (f = (1 - e.n)^3) and the mix of the two
  environment samples by f.
*/
#ifndef SNELL_SHADE_ICE_GLSL
#define SNELL_SHADE_ICE_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"
#include "../optics/safe_normalize.glsl"
#include "../optics/refract.glsl"
#include "../optics/fresnel_cubic.glsl"
#include "../optics/ice_normal_blend.glsl"

#ifndef SNELL_ICE_ETA
#  define SNELL_ICE_ETA (1.0003f / 1.3091f)
#endif
#ifndef SNELL_ICE_TIR_POLICY
#  define SNELL_ICE_TIR_POLICY SNELL_TIR_REFLECT
#endif

struct SnellIce {
  vec3 refracted;
  vec3 reflected;
  float fresnel;
  bool valid;
};

SNELL_FN SnellIce snellIce(vec3 eye, vec3 frontNormal, vec3 backNormal, float a, float eta) {
  SnellIce s;
  s.refracted = vec3(0.0f, 0.0f, 0.0f);
  s.reflected = vec3(0.0f, 0.0f, 0.0f);
  s.fresnel = 1.0f;
  s.valid = false;
  vec3 e = snellSafeNormalize(eye);
  vec3 nf = snellSafeNormalize(frontNormal);
  if (dot(e, e) == 0.0f || dot(nf, nf) == 0.0f) {
    return s;
  }
  s.valid = true;
  float k = (!isnan(eta) && eta >= SNELL_FLT_MIN && eta < SNELL_FLT_MAX) ? eta : 1.0f;
  vec3 nr = snellIceNormalBlend(nf, backNormal, a);
  SnellRefraction r = snellRefract(e, nr, k, SNELL_ICE_TIR_POLICY);
  s.refracted = r.direction;
  s.reflected = e - nf * (2.0f * dot(nf, e));
  s.fresnel = dot(r.direction, r.direction) == 0.0f ? 1.0f : snellFresnelCubic(e, nf);
  return s;
}

SNELL_FN SnellIce snellIce(vec3 eye, vec3 frontNormal, vec3 backNormal) {
  return snellIce(eye, frontNormal, backNormal, SNELL_ICE_NORMAL_BLEND, SNELL_ICE_ETA);
}

SNELL_FN vec4 snellIceCompose(vec4 reflection, vec4 refraction, float fresnel) {
  // isnan first: clamp of a NaN differs between GPUs and GLM.
  float f = isnan(fresnel) ? 1.0f : clamp(fresnel, 0.0f, 1.0f);
  return refraction * (1.0f - f) + reflection * f;
}

#endif
