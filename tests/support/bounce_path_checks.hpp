// One pixel's path through a bounce shape (bounce_shapes.hpp) as a technique traced it, against the
// textbook path in double: the checks the analytic-buffer test (tests/unit/technique_bounce_paths_test.cpp)
// and the lab's GL-buffer test (tests/lab/bounce_paths_buffers_test.cpp) share.
#pragma once

#include <snell/snell.hpp>

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <cmath>
#include <functional>

#include "support/bounce_shapes.hpp"

namespace snell_test {

constexpr double kBounceExitPx = 0.01, kBounceDirectionRad = 1e-5;

// trace(b): the technique's path from the pixel's entry with at most b bounces; `bounces` the technique's
// own count. With it, the path must leave through the last face of p (its layer, exit point within
// kBounceExitPx pixels, direction within kBounceDirectionRad, length within lengthRel); with fewer allowed,
// it must stop at its (b + 1)-th face, totally reflected there. Returns the full path.
inline snell::SnellTwoInterfacePath expectTracedPath(const PixelPath& p, int bounces,
                                                     const std::function<snell::SnellTwoInterfacePath(int)>& trace,
                                                     const std::function<glm::dvec2(glm::dvec3)>& uvOf, double px,
                                                     double lengthRel) {
  const int n = p.inside.reflections();
  const Prism::Face& last = p.inside.faces.back();
  const snell::SnellTwoInterfacePath all = trace(bounces);
  EXPECT_TRUE(all.valid);
  EXPECT_EQ(all.bounces, n);
  EXPECT_FALSE(all.fellBack);
  EXPECT_FALSE(all.tir);
  EXPECT_EQ(all.exitFront, onFrontLayer(last));
  EXPECT_LT(glm::length(uvOf(glm::dvec3(all.exitPoint)) - uvOf(last.point)), kBounceExitPx * px);
  EXPECT_GT(glm::dot(glm::normalize(glm::dvec3(all.exitDirection)), p.inside.out), std::cos(kBounceDirectionRad));
  EXPECT_NEAR(all.pathLength, insideLength(p), lengthRel * insideLength(p));
  for (int b = 0; b < n; ++b) {
    SCOPED_TRACE(testing::Message() << b << " bounces allowed");
    const snell::SnellTwoInterfacePath part = trace(b);
    const Prism::Face& f = p.inside.faces[static_cast<std::size_t>(b)];
    EXPECT_TRUE(part.valid);
    EXPECT_EQ(part.bounces, b);
    EXPECT_TRUE(part.tir);
    EXPECT_FALSE(part.fellBack);
    EXPECT_EQ(part.exitFront, b > 0 && onFrontLayer(f));
    EXPECT_LT(glm::length(uvOf(glm::dvec3(part.exitPoint)) - uvOf(f.point)), kBounceExitPx * px);
  }
  return all;
}

}  // namespace snell_test
