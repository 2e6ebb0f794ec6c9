// snellSafeNormalize against v / |v| computed in double, and the zero vector
// wherever its contract refuses the input: |v|^2 at or below 1e-30 or at or
// above FLT_MAX (computed in double, inputs near either edge left out: float's
// dot product may land on either side), NaN or infinite components.
#include <snell/optics.hpp>

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <cfloat>
#include <cmath>
#include <limits>

#include "support/rng.hpp"

namespace {

TEST(SafeNormalize, UnitWhereTheContractAllowsZeroElsewhere) {
  snell_test::Rng g(9101);
  int unit = 0, zero = 0;
  for (int i = 0; i < 20000; ++i) {
    // Magnitudes from 1e-20 to 1e20: |v|^2 across both edges.
    const glm::vec3 v = g.unit() * std::pow(10.0f, g.uniform(-20.0f, 20.0f));
    const glm::dvec3 d(v);
    const double len2 = glm::dot(d, d);
    if (std::abs(len2 / 1e-30 - 1.0) < 1e-5 || std::abs(len2 / double(FLT_MAX) - 1.0) < 1e-5) continue;
    const glm::vec3 n = snell::snellSafeNormalize(v);
    if (len2 > 1e-30 && len2 < double(FLT_MAX)) {
      const glm::dvec3 want = d / std::sqrt(len2);
      for (int k = 0; k < 3; ++k) ASSERT_NEAR(n[k], want[k], 1e-6) << "|v|^2 " << len2;
      ++unit;
    } else {
      ASSERT_EQ(n, glm::vec3(0.0f)) << "|v|^2 " << len2;
      ++zero;
    }
  }
  EXPECT_GT(unit, 10000);
  EXPECT_GT(zero, 2000);
}

TEST(SafeNormalize, NonFiniteComponentsGiveZero) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  for (const glm::vec3 v : {glm::vec3(nan, 1, 0), glm::vec3(0, 0, nan), glm::vec3(inf, 0, 0), glm::vec3(1, -inf, 1),
                            glm::vec3(inf, -inf, 0), glm::vec3(0.0f)})
    EXPECT_EQ(snell::snellSafeNormalize(v), glm::vec3(0.0f)) << v.x << " " << v.y << " " << v.z;
}

}  // namespace
