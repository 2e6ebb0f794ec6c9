/*
description: chromatic dispersion: per-channel indices of refraction from a
  base IOR and an Abbe number (or given explicitly), and the refraction of one
  ray per colour channel. Sample the scene once per channel with the three
  directions (or their screen-space offsets) for chromatic aberration.
use: vec3 iors = snellDispersionIors(1.5168f, 64.17f);   // BK7: n_d, V_d
     SnellDispersion d = snellDispersionRefract(viewDir, n, 1.0f, iors, SNELL_TIR_CRITICAL);
     SnellDispersion d = snellDispersionRefract(viewDir, n, 1.0f, vec3(1.51f, 1.52f, 1.53f), SNELL_TIR_ZERO);
  iorD        IOR at the helium d line (587.56 nm), the usual catalogue value
  abbe        Abbe number V_d = (n_d - 1) / (n_F - n_C) (crown glass ~ 60, flint
              ~ 30, water ~ 55); larger means less dispersion
  iorOutside  IOR of the medium the ray comes from (1 for air)
  iors        IOR per channel (r, g, b) of the medium it enters
options:
  SNELL_DISPERSION_LAMBDA_R  wavelength of the red channel in nm (656.27f, the
                             hydrogen C line)
  SNELL_DISPERSION_LAMBDA_G  green (587.56f, the helium d line)
  SNELL_DISPERSION_LAMBDA_B  blue (486.13f, the hydrogen F line)
contract:
  - snellDispersionIors uses Cauchy's two-term equation n(l) = A + B / l^2
    fitted to n(587.56 nm) = iorD and n(486.13) - n(656.27) = (iorD - 1) / V:
    n(l) = iorD + (iorD - 1) / V * (1/l^2 - 1/l_d^2) / (1/l_F^2 - 1/l_C^2).
    With the default wavelengths r = n_C, g = n_d = iorD, b = n_F, so
    b - r = (iorD - 1) / V and b > g > r for iorD > 1 (blue bends most).
  - iorD NaN, below the smallest normal float or infinite: (1, 1, 1). abbe NaN,
    <= 0 or +inf: no dispersion, (iorD, iorD, iorD). abbe below 1 counts as 1.
    Each channel is clamped to [1e-6, 1e6].
  - snellDispersionRefract refracts incident about normal once per channel with
    eta_c = snellIorToEta(iorOutside, iors.c) and snellRefract(.., policy);
    red/green/blue are the directions; tir is true when any channel totally
    reflects, valid when every channel is valid (false only for a zero, NaN
    or infinite incident or normal: then all three are (0,0,0)). Invalid IORs
    give eta 1 for that channel (snellIorToEta).
source: E. Abbe's number V_d = (n_d - 1) / (n_F - n_C) (Schott optical glass
  data sheets; ISO 7944 reference wavelengths) and Cauchy's dispersion formula
  n = A + B / lambda^2 (two-term form); per-channel refraction for chromatic
  aberration, cf. Kilgard 2001 "Chromatic Aberration" (NVIDIA), which Sousa
  (GPU Gems 2 ch. 19, sec. 19.3.2) cites as the wavelength-dependent extension.
*/
#ifndef SNELL_SHADE_DISPERSION_GLSL
#define SNELL_SHADE_DISPERSION_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"
#include "../optics/refract.glsl"
#include "../optics/ior_to_eta.glsl"

#ifndef SNELL_DISPERSION_LAMBDA_R
#  define SNELL_DISPERSION_LAMBDA_R 656.27f
#endif
#ifndef SNELL_DISPERSION_LAMBDA_G
#  define SNELL_DISPERSION_LAMBDA_G 587.56f
#endif
#ifndef SNELL_DISPERSION_LAMBDA_B
#  define SNELL_DISPERSION_LAMBDA_B 486.13f
#endif

struct SnellDispersion {
  vec3 red;
  vec3 green;
  vec3 blue;
  bool tir;
  bool valid;
};

SNELL_FN vec3 snellDispersionIors(float iorD, float abbe) {
  if (isnan(iorD) || !(iorD >= SNELL_FLT_MIN) || isinf(iorD)) {
    return vec3(1.0f, 1.0f, 1.0f);
  }
  if (isnan(abbe) || !(abbe > 0.0f) || isinf(abbe)) {
    return vec3(iorD, iorD, iorD);
  }
  float v = max(abbe, 1.0f);
  // 1 / lambda^2 in 1 / um^2 (lambda in nm).
  float wC = 1e6f / (656.27f * 656.27f);
  float wD = 1e6f / (587.56f * 587.56f);
  float wF = 1e6f / (486.13f * 486.13f);
  float wR = 1e6f / (SNELL_DISPERSION_LAMBDA_R * SNELL_DISPERSION_LAMBDA_R);
  float wG = 1e6f / (SNELL_DISPERSION_LAMBDA_G * SNELL_DISPERSION_LAMBDA_G);
  float wB = 1e6f / (SNELL_DISPERSION_LAMBDA_B * SNELL_DISPERSION_LAMBDA_B);
  float k = (iorD - 1.0f) / (v * (wF - wC));
  vec3 n = vec3(iorD + k * (wR - wD), iorD + k * (wG - wD), iorD + k * (wB - wD));
  return clamp(n, vec3(1e-6f, 1e-6f, 1e-6f), vec3(1e6f, 1e6f, 1e6f));
}

SNELL_FN SnellDispersion snellDispersionRefract(vec3 incident, vec3 normal, float iorOutside, vec3 iors,
                                                int policy) {
  SnellRefraction r = snellRefract(incident, normal, snellIorToEta(iorOutside, iors.x), policy);
  SnellRefraction g = snellRefract(incident, normal, snellIorToEta(iorOutside, iors.y), policy);
  SnellRefraction b = snellRefract(incident, normal, snellIorToEta(iorOutside, iors.z), policy);
  SnellDispersion d;
  d.red = r.direction;
  d.green = g.direction;
  d.blue = b.direction;
  d.tir = r.tir || g.tir || b.tir;
  d.valid = r.valid && g.valid && b.valid;
  return d;
}

#endif
