// The gallery's procedural textures, the same texels on both sides: the
// environment (equirectangular), a tiling bump map, the stained glass's
// colour cells and the pool floor under the refractive texture mapping.
#pragma once
#include <snell/bridge.hpp>

namespace snell::gallery {

// A sky over a darker ground with a sun (linear RGB), equirectangular,
// width = 2 height.
Image environmentImage(int height);
// Unit tangent-space normals (z up) of a sum of sine ripples that tiles on
// [0,1]^2, packed to [0,1] (n * 0.5 + 0.5).
Image bumpImage(int size);
// Coloured glass cells between dark lead lines; alpha 1.
Image stainImage(int size);
// The pool floor: tiles with a coloured ring and a grid of dots, so a uv
// error of a texel shows.
Image floorImage(int size);

}  // namespace snell::gallery
