// A bounce shape (bounce_shapes.hpp) as the analytic buffers a technique traces it in, and the shipped
// technique fitted to it: what the analytic bounce-path tests share (tests/unit/technique_bounce_paths_test.cpp,
// tests/normal_fetch/).
#pragma once

#include <snell/depth_pyramid.hpp>
#include <snell/snell.hpp>

#include <glm/glm.hpp>

#include <optional>

#include "support/bounce_shapes.hpp"
#include "support/depth_scenes.hpp"

namespace snell_test {

// The shape's front and back layers: depth and outward normals at every texel centre, in double.
struct ShapeBuffers {
  DepthScene front, back;
  snell::Texture2D backPyramid;
  // Read bilinear: exact on a plane between texel centres, as the textbook path is.
  snell::SnellDepthSurface frontSurface, backSurface;

  // The layer's analytic normal at uv; none where the layer has no surface (buffersHoldPath's lookup).
  std::optional<glm::dvec3> layerNormalAt(glm::dvec2 uv, bool frontLayer) const {
    const AnalyticSample a = (frontLayer ? front : back).sampleAt(uv);
    if (!a.valid) return std::nullopt;
    return a.normal;
  }
  glm::dvec2 uvOf(glm::dvec3 p) const { return front.project(p); }
  // The technique's path from p's entry on these buffers, with `bounces` allowed; eta = n_outside / n_glass.
  snell::SnellTwoInterfacePath trace(const PixelPath& p, double eta, snell::SnellTechnique t, int bounces,
                                     int tirPolicy) const {
    t.bounces = bounces;
    return snell::snellTwoInterfaceTrace(glm::vec3(p.entry), glm::vec3(p.entryNormal), float(eta), 0.0f, back.depth,
                                         back.normals, backPyramid, backSurface, front.depth, front.normals,
                                         frontSurface, t, tirPolicy);
  }
};

inline ShapeBuffers shapeBuffers(const BounceShape& shape, int size) {
  const auto layer = [&shape](bool back) {
    return [&shape, back](glm::dvec3 q) {
      AnalyticSample r;
      const auto hit = shape.prism.entry(q, back);
      if (!hit) return r;
      r.s = hit->first;
      r.normal = hit->second;
      r.valid = true;
      return r;
    };
  };
  ShapeBuffers b;
  b.front = detail::makeScene("front", size, size, SNELL_DEPTH_GL, false, kScenePlane, layer(false));
  b.back = detail::makeScene("back", size, size, SNELL_DEPTH_GL, true, kScenePlane, layer(true));
  b.backPyramid = snell::snellBuildDepthPyramid(b.back.depth, b.back.surface());
  b.frontSurface = b.front.surface();
  b.backSurface = b.back.surface();
  b.frontSurface.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
  b.backSurface.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
  return b;
}

// The shipped image-space bound with bounces (4), its back and inside marches as long as the shape (the
// linear march at its limit: steps of the extent / SNELL_LINEAR_MARCH_MAX_STEPS).
inline snell::SnellTechnique shapeTechnique(const BounceShape& shape) {
  snell::SnellTechnique t = snell::snellPresetImageSpaceBoundBounces();
  t.back.intersect.marchMaxDistance = float(shape.extent);
  t.inside.intersect.marchMaxDistance = float(shape.extent);
  return t;
}

}  // namespace snell_test
