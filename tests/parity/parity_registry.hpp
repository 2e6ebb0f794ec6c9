// Registry of parity cases: one per public GLSL function, each running that
// function on llvmpipe and in the C++ build over the same inputs.
//
// A case lives in two places:
//  - tests/parity/cases/<family>.glsl: `SnellParityOut caseSnellFoo(vec4 a, vec4 b,
//    vec4 c, vec4 d)`, written in the common subset, unpacking its arguments from
//    the four input vec4s and packing results into the four output vec4s (bools
//    as 0.0f / 1.0f). The same text is compiled for the GPU and, inside a C++
//    namespace, for the CPU.
//  - tests/parity/<family>_cases.cpp: SNELL_PARITY_CASE(...) registration with
//    an input generator (>= 10,000 inputs, edge cases included) and tolerances.
#pragma once

#include <snell/gpu/parity.hpp>

#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace snell_parity {

using snell::gpu::ParityIO;

struct Tolerance {
  float abs = 1e-5f;  // |gpu - cpu| <= abs + rel * |cpu| for continuous outputs
  float rel = 1e-5f;
};

struct CaseSpec {
  std::string function;     // the public GLSL function, e.g. "snellRefract"
  std::string glslFile;     // case file under tests/parity/cases, e.g. "optics.glsl"
  std::string entry;        // GLSL entry, "caseSnellRefract"
  std::function<std::vector<ParityIO>()> inputs;
  std::function<ParityIO(const ParityIO&)> cpu;  // the C++ build of the same entry
  std::uint16_t discrete = 0;  // bit k: output float k (v[k/4][k%4]) compared exactly
  int outputs = 16;            // how many output floats are meaningful
  Tolerance tol;
  // Textures the case samples: GLSL uniforms bound on the GPU, the same
  // snell::Texture2D objects read by the C++ build. setup() fills them first.
  std::vector<snell::gpu::ParityTexture> textures = {};
  std::function<void()> setup = {};
};

// Every case file registers into this one list, whichever executable links them
// (inline: one list across translation units, filled during static initialization).
inline std::vector<CaseSpec>& registry() {
  static std::vector<CaseSpec> cases;
  return cases;
}

struct Registrar {
  explicit Registrar(CaseSpec spec) { registry().push_back(std::move(spec)); }
};

// Random inputs with the hostile values mixed in.
class InputGen {
 public:
  explicit InputGen(std::uint32_t seed) : rng_(seed) {}
  float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  bool chance(float p) { return uniform(0.0f, 1.0f) < p; }
  glm::vec3 unitVector() {
    for (;;) {
      glm::vec3 v(uniform(-1.0f, 1.0f), uniform(-1.0f, 1.0f), uniform(-1.0f, 1.0f));
      float l2 = glm::dot(v, v);
      if (l2 > 1e-4f && l2 <= 1.0f) return v / std::sqrt(l2);
    }
  }
  // A hostile scalar: 0, -0, tiny, denormal, huge, +-inf or NaN.
  float hostile() {
    static const float values[] = {0.0f, -0.0f, 1e-38f, 1e-44f, 1e30f, -1e30f,
                                   std::numeric_limits<float>::infinity(),
                                   -std::numeric_limits<float>::infinity(),
                                   std::numeric_limits<float>::quiet_NaN(), 1.0f, -1.0f};
    return values[integer(0, static_cast<int>(sizeof(values) / sizeof(values[0])) - 1)];
  }
  glm::vec3 hostileVector() { return glm::vec3(hostile(), hostile(), hostile()); }
  std::mt19937& rng() { return rng_; }

 private:
  std::mt19937 rng_;
};

}  // namespace snell_parity

#define SNELL_PARITY_CAT2(a, b) a##b
#define SNELL_PARITY_CAT(a, b) SNELL_PARITY_CAT2(a, b)
// SNELL_PARITY_CASE({ "snellFoo", "optics.glsl", "caseSnellFoo", gen, cpu, discreteMask, outputs, tol });
#define SNELL_PARITY_CASE(...) \
  static ::snell_parity::Registrar SNELL_PARITY_CAT(snellParityRegistrar, __LINE__)(::snell_parity::CaseSpec __VA_ARGS__)
