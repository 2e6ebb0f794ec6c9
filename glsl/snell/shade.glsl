/* shade/ family aggregator: the composed refraction techniques. */
#ifndef SNELL_SHADE_GLSL
#define SNELL_SHADE_GLSL
#endif
