/* camera/ family aggregator: every public function of glsl/snell/camera. */
#ifndef SNELL_CAMERA_GLSL
#define SNELL_CAMERA_GLSL
#endif
