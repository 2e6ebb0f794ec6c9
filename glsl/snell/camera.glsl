/* camera/ family aggregator: every public function of glsl/snell/camera. */
#ifndef SNELL_CAMERA_GLSL
#define SNELL_CAMERA_GLSL
#include "camera/conventions.glsl"
#include "camera/linearize_depth.glsl"
#include "camera/depth_to_ndc_z.glsl"
#include "camera/perspective.glsl"
#include "camera/view_to_clip.glsl"
#include "camera/view_to_uv.glsl"
#include "camera/pixel_to_uv.glsl"
#include "camera/uv_depth_to_view.glsl"
#include "camera/uv_z_to_view.glsl"
#include "camera/tex_ray.glsl"
#endif
