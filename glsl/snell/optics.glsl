/* optics/ family aggregator: every public function of glsl/snell/optics. */
#ifndef SNELL_OPTICS_GLSL
#define SNELL_OPTICS_GLSL
#include "optics/safe_normalize.glsl"
#include "optics/refract.glsl"
#include "optics/refract_rough.glsl"
#include "optics/approx_refract.glsl"
#include "optics/fresnel_dielectric.glsl"
#include "optics/fresnel_schlick.glsl"
#include "optics/fresnel_bias_power.glsl"
#include "optics/fresnel_cubic.glsl"
#include "optics/ior_to_eta.glsl"
#include "optics/ior_to_f0.glsl"
#include "optics/ice_normal_blend.glsl"
#include "optics/beer_lambert.glsl"
#include "optics/angle_between.glsl"
#include "optics/wyman_distance.glsl"
#include "optics/ray_plane.glsl"
#endif
