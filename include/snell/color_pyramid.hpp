// C++-only convenience around glsl/snell/shade/color_pyramid.glsl: the colour
// pyramid for rough reads built on the CPU with the function a GL pass runs
// (snellColorPyramidReduce), level by level.
#pragma once
#include "bridge.hpp"
#include "shade.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <utility>

namespace snell {

// `base` as level 0 and every level down to 1x1 the tent reduce of the one
// below (color_pyramid.glsl), trilinear filtering: what snell::gpu::ColorPyramidPass
// leaves in a GL texture, and what the rough cone's reads expect.
// std::invalid_argument for an empty image.
inline Texture2D snellBuildColorPyramid(Image base) {
  if (base.width <= 0 || base.height <= 0 || base.texels.size() != std::size_t(base.width) * std::size_t(base.height))
    throw std::invalid_argument("snellBuildColorPyramid: the image is empty or its texels do not fill it");
  Texture2D pyramid(std::move(base), Filter::Linear, MipFilter::Linear);
  for (int lod = 0; pyramid.level(lod).width > 1 || pyramid.level(lod).height > 1; ++lod) {
    const Image& prev = pyramid.level(lod);
    Image next(std::max(1, prev.width / 2), std::max(1, prev.height / 2));
    for (int y = 0; y < next.height; ++y)
      for (int x = 0; x < next.width; ++x) next.at(x, y) = snellColorPyramidReduce(pyramid, lod, ivec2(x, y));
    pyramid.addLevel(std::move(next));
  }
  return pyramid;
}

}  // namespace snell
