// Seeded random floats and unit vectors for the unit tests: every test file
// names its own seed, so a failure reproduces run after run.
#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <random>

namespace snell_test {

struct Rng {
  explicit Rng(unsigned seed) : rng(seed) {}
  std::mt19937 rng;
  float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
  // Uniform on the sphere: rejection from the cube, away from 0 so the normalization is well conditioned.
  glm::vec3 unit() {
    for (;;) {
      glm::vec3 v(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      float l2 = glm::dot(v, v);
      if (l2 > 1e-2f && l2 <= 1.0f) return v / std::sqrt(l2);
    }
  }
};

}  // namespace snell_test
