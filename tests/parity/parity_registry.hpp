// Registry of parity cases: one per public GLSL function, each running that
// function on llvmpipe and in the C++ build over the same inputs, and the
// property tests' list of functions. A case is described once, in
// tests/parity/<family>_cases.cpp, with SNELL_PARITY_CASE (parity_case.hpp):
// named inputs and outputs, each output exact or with its tolerance, the
// body in the common subset, an input generator (>= 10,000 inputs, edge cases
// included) and the contract's exceptions by name. Helpers, textures and
// macros a family's cases share live in tests/parity/cases/<family>.glsl.
#pragma once

#include <snell/gpu/parity.hpp>

#include <cstdint>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace snell_parity {

using snell::gpu::ParityIO;

// How an output float is compared (snell::gpu::ParityOutput): exactly, or
// within |gpu - cpu| <= abs + rel * |cpu| (+ scaled * |cpu of the output's
// float at scaleFirst + its component|, for an output whose conditioning the
// case reports as another output; only on a runtime that folds constants,
// snell::gpu::Runtime::foldsConstants, and on the inputs the case's scaledWhere
// names).
struct Check {
  bool exact;
  float abs, rel;
  float scaled = 0.0f;
  int scaleFirst = -1;
};
namespace checks {
inline constexpr Check exact{true, 0.0f, 0.0f};
constexpr Check within(float abs, float rel) { return Check{false, abs, rel}; }
constexpr Check within(float abs, float rel, float scaled, int scaleFirst) {
  return Check{false, abs, rel, scaled, scaleFirst};
}
}  // namespace checks

// A documented exception to "every output is finite" (the property tests): a
// non-finite value in one of the input floats `passThroughInputs` (bit k: input
// v[k/4][k%4]; a value the function uses "as given") excuses the output floats
// `outputs`; `always`: those outputs are never checked.
struct ContractException {
  std::uint16_t passThroughInputs;
  std::uint16_t outputs;
  bool always;
  std::string reason;
};

// A registered case, built from its description by describeCase()
// (parity_case.hpp): never written by hand.
struct CaseSpec {
  std::string function;    // the public GLSL function, e.g. "snellRefract"
  std::string glslFile;    // the family's helper file under tests/parity/cases, e.g. "optics.glsl"
  std::string entry;       // the generated GLSL entry, "caseSnellRefract"
  std::string entrySource; // its text, appended after glslFile
  std::function<std::vector<ParityIO>()> inputs;
  std::function<ParityIO(const ParityIO&)> cpu;  // the C++ build of the same entry
  std::vector<snell::gpu::ParityOutput> outputs;  // the described output floats
  // Textures the case samples: GLSL uniforms bound on the GPU, the same
  // snell::Texture2D objects read by the C++ build. setup() fills them first.
  std::vector<snell::gpu::ParityTexture> textures = {};
  std::function<void()> setup = {};
  std::vector<ContractException> exceptions = {};
  // The inputs on which its outputs' condition-scaled tolerances apply (every input when empty).
  std::function<bool(const ParityIO&)> scaledWhere = {};
  std::string layoutError;  // non-empty: the description is wrong (the manifest test fails)
};

// Every case file registers into this one list, whichever executable links them
// (inline: one list across translation units, filled during static initialization).
inline std::vector<CaseSpec>& registry() {
  static std::vector<CaseSpec> cases;
  return cases;
}

// Float k of a case's 16 inputs or outputs.
inline float comp(const ParityIO& io, int k) { return io.v[k / 4][k % 4]; }
inline float& comp(ParityIO& io, int k) { return io.v[k / 4][k % 4]; }

// FNV-1a over every bit of every float of `ios`: the parity runs print it for the
// inputs, the C++ results and the GPU results, so a change meant to alter no
// result (a case rewritten, a runner refactored) is proved not to by diffing
// two runs' logs.
inline std::uint64_t ioDigest(const std::vector<ParityIO>& ios) {
  std::uint64_t h = 1469598103934665603ull;
  for (const ParityIO& io : ios)
    for (int k = 0; k < 16; ++k) {
      const float x = comp(io, k);
      std::uint32_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      for (int b = 0; b < 4; ++b) h = (h ^ ((bits >> (8 * b)) & 0xFFu)) * 1099511628211ull;
    }
  return h;
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
