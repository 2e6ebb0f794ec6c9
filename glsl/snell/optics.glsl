/* optics/ family aggregator: every public function of glsl/snell/optics. */
#ifndef SNELL_OPTICS_GLSL
#define SNELL_OPTICS_GLSL
#include "optics/safe_normalize.glsl"
#include "optics/refract.glsl"
#endif
