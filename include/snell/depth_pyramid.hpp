// C++-only conveniences around glsl/snell/intersect/depth_pyramid.glsl: build the
// depth min/max pyramid of a depth texture on the CPU with the very functions a
// GL pass runs (snellDepthPyramidBase, snellDepthMinMaxReduce), and the
// mipmapped normal texture the normal-based plane strategy can read.
#pragma once
#include "bridge.hpp"
#include "intersect.hpp"

#include <algorithm>
#include <stdexcept>

namespace snell {

// The pyramid of `depth` (its level surface.lod, depth value in .x) down to 1x1:
// level 0 = snellDepthPyramidBase of every texel, level L+1 =
// snellDepthMinMaxReduce of level L (texel layout in depth_pyramid.glsl).
// NEAREST filtering with NEAREST mip selection, so SNELL_SAMPLE_LOD reads whole
// levels; the searches use SNELL_TEXEL_FETCH. Read it with a SnellDepthSurface
// equal to `surface` (lod set to the level wanted); the top level's y and z are
// the buffer's nearest and farthest view distances (0, 0 when it is empty).
inline Texture2D snellBuildDepthPyramid(const Texture2D& depth, const SnellDepthSurface& surface) {
  const ivec2 size = depth.size(surface.lod);
  if (size.x <= 0 || size.y <= 0) throw std::invalid_argument("snellBuildDepthPyramid: the depth level is missing");
  Image base(size.x, size.y);
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) base.at(x, y) = snellDepthPyramidBase(depth.fetch(ivec2(x, y), surface.lod).x, surface);
  Texture2D pyramid(std::move(base), Filter::Nearest, MipFilter::Nearest);
  for (int lod = 0; pyramid.level(lod).width > 1 || pyramid.level(lod).height > 1; ++lod) {
    const Image& prev = pyramid.level(lod);
    Image next(std::max(1, prev.width / 2), std::max(1, prev.height / 2));
    for (int y = 0; y < next.height; ++y)
      for (int x = 0; x < next.width; ++x) next.at(x, y) = snellDepthMinMaxReduce(pyramid, lod, ivec2(x, y), surface.emptyDepth);
    pyramid.addLevel(std::move(next));
  }
  return pyramid;
}

// A copy of level 0 of `normals` with a box-filtered mip chain (what
// glGenerateMipmap makes for power-of-two sizes) and trilinear filtering, for
// snellIntersectPlaneNormal's normalLod (Mayer & Assarsson: blurrier levels for
// drastic refraction). Coverage (w) is filtered along, xyz need not be unit.
inline Texture2D snellBuildNormalMips(const Texture2D& normals) {
  Texture2D t(normals.level(0), Filter::Linear, MipFilter::Linear);
  t.generateMipmaps();
  return t;
}

}  // namespace snell
