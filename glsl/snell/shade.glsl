/* shade/ family aggregator: the composed refraction techniques. */
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
#include "shade/rough_cone.glsl"
#include "shade/environment_cube_face.glsl"
#include "shade/environment.glsl"
#include "shade/technique_options.glsl"
#include "shade/technique_buffers.glsl"
#include "shade/technique_presets.glsl"
#include "shade/two_interface.glsl"
#include "shade/two_interface_shade.glsl"
#include "shade/engine_models/engine_models.glsl"
#endif
