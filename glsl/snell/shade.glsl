#ifndef SNELL_SHADE_GLSL
#define SNELL_SHADE_GLSL
#include "shade/perturb.glsl"
#include "shade/perturb_edge_fade.glsl"
#include "shade/refraction_mask.glsl"
#include "shade/refraction_mask_depth.glsl"
#include "shade/water.glsl"
#include "shade/glass.glsl"
#include "shade/ice.glsl"
#include "shade/ice_crack_clip.glsl"
#include "shade/refractive_texture_map.glsl"
#include "shade/dispersion.glsl"
#include "shade/roughness.glsl"
#endif
