// Property test (issue 7): every public function, through the C++ build of its
// parity case entry (tests/parity/*_cases.cpp, compiled here again without any
// GL context), on >= 1,000,000 inputs: the case's own generator (10-12k inputs,
// hostile values included) plus mutations of them (random components replaced
// by NaN, +-Inf, 0, -0, denormals, +-1e30; vectors scaled by 0, 1e-20, 1e20).
//
// The generic contract every snell function documents in its header block:
// every output is finite (invalid results are flagged and carry finite
// numbers, e.g. snellHitMiss). The few documented exceptions are listed in
// kExceptions below, each with the contract sentence that allows it.
//
// Prints one line per function: "[property] <fn> inputs=N violations=V exempt=E".
#include <gtest/gtest.h>

#include <cstdlib>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "parity_registry.hpp"

namespace snell_parity {

std::vector<CaseSpec>& registry() {
  static std::vector<CaseSpec> cases;
  return cases;
}

namespace {

constexpr std::size_t kDefaultInputs = 1000000;

// Cases too heavy for 1M inputs in the CI time budget (each input runs a full
// technique: two interfaces, marches of up to hundreds of fetches). They still
// get their generator's inputs plus mutations; the count is reported.
const std::map<std::string, std::size_t>& inputOverrides() {
  static const std::map<std::string, std::size_t> m = {};
  return m;
}

// Documented exceptions to "every output is finite". An exception names the
// input floats (bit k: input v[k/4][k%4]) that a function uses "as given"
// (colours passed through, by contract): when one of them is not finite, the
// outputs in `outputs` are not checked for that input. Every other output is.
// always: the outputs are never checked (the contract allows overflow too).
struct Exception {
  std::uint16_t passThroughInputs;
  std::uint16_t outputs;
  bool always;
  const char* reason;
};
const std::map<std::string, Exception>& exceptions() {
  static const std::map<std::string, Exception> m = {
      {"snellViewToClip",
       {0xFFFF, 0x000F, true,
        "camera/view_to_clip.glsl: 'clipFromView * vec4(pView, 1), nothing else: no check, NaN and Inf "
        "propagate as the matrix product makes them' (snellClipToNdc is the checked step)"}},
      {"snellUnpackBump",
       {0x0007, 0x0007, false, "shade/perturb.glsl: 'snellUnpackBump(t) = 2 t - 1, nothing else: NaN propagates'"}},
      {"snellRefractionMaskBlend",
       {0x00F7, 0x000F, false,
        "shade/refraction_mask.glsl: 'Colours are blended as given (NaN colours propagate)'; the mask alpha "
        "(input 3) is checked"}},
      {"snellIceCompose",
       {0x00FF, 0x000F, false,
        "shade/ice.glsl: a mix of the two given colours (reflection a, refraction b); the fresnel weight is "
        "checked"}},
      {"snellGlass", {0x8000, 0x0008, false, "shade/glass.glsl: 'Other colours (texels, diffuse.a) are used as given'"}},
      {"snellDepthSurface",
       {0xFF00, 0xFFFF, false,
        "a plain constructor: the case packs back the matrix and (zNear, zFar, convention, emptyDepth) it stores"}},
      {"snellRefractiveTextureMapParams",
       {0x00FF, 0x007F, false,
        "a plain constructor: the case packs back the extents, restY, depth and factor it stores (uvMin/uvMax, "
        "which it sanitizes, are checked)"}},
      {"snellDepthRangeInvalid", {0x0001, 0x0008, false, "the case echoes its input a.x in output 3 (not the function's)"}},
      {"snellPresetDirBounds",
       {0x0003, 0x3000, false, "a preset constructor: stores the bounds it is given (outputs 12-13)"}},
      {"snellDepthPyramidBase",
       {0x0010, 0x0001, false,
        "intersect/depth_pyramid.glsl: an invalid texel is vec4(emptyDepth, 0, 0, 0), the emptyDepth given"}},
  };
  return m;
}

// Violations found by the first run (issue 7) and not yet triaged: each is
// either a documented pass-through (a constructor or colour used "as given", to
// move to exceptions() with its contract sentence) or a bug to fix in
// glsl/snell. Listed here so the suite stays green while they are worked on;
// the counts are still printed, and any function NOT listed fails on its
// first non-finite output. Remove an entry once fixed or moved.
const std::map<std::string, const char*>& pendingTriage() {
  static const std::map<std::string, const char*> m = {};
  return m;
}

// SNELL_PROPERTY_INPUTS lowers the count for slow builds (the sanitizer run in
// scripts/test.sh); the normal build runs the full count.
std::size_t inputCount(const CaseSpec& spec) {
  const auto it = inputOverrides().find(spec.function);
  std::size_t n = it == inputOverrides().end() ? kDefaultInputs : it->second;
  if (const char* env = std::getenv("SNELL_PROPERTY_INPUTS")) {
    const long v = std::atol(env);
    if (v > 0) n = std::min(n, static_cast<std::size_t>(v));
  }
  return n;
}

float comp(const ParityIO& io, int k) { return io.v[k / 4][k % 4]; }
float& comp(ParityIO& io, int k) { return io.v[k / 4][k % 4]; }

// Components holding a small whole number are left alone by the mutations: the
// case entries pass policies, step counts, lods, conventions and pixel indices
// as floats and convert them with int(), and int() of NaN, Inf or 1e30 is
// undefined (C++ [conv.fpint], GLSL likewise), so mutating them would test the
// harness, not the function (UBSan reports it: -2147483648 * 2 in a pixel index).
// Float inputs that happen to be whole in one base input (0, 1, eta = 1) are
// still mutated through the other base inputs, where they are not.
bool intLike(float x) { return std::fabs(x) <= 1e6f && x == std::floor(x); }

// Input `index` >= base.size(): a mutation of base[index % size], seeded by index.
ParityIO mutate(const ParityIO& base, std::uint64_t index) {
  static const float hostile[] = {std::numeric_limits<float>::quiet_NaN(),
                                  std::numeric_limits<float>::infinity(),
                                  -std::numeric_limits<float>::infinity(),
                                  0.0f,
                                  -0.0f,
                                  std::numeric_limits<float>::denorm_min(),
                                  -1e-40f,
                                  1e-44f,
                                  1e30f,
                                  -1e30f};
  static const float scales[] = {0.0f, 1e-20f, 1e20f};
  // splitmix64: a cheap, well-mixed stream per input (seeding a Mersenne
  // twister per input would cost more than most functions under test).
  std::uint64_t state = index * 0x9E3779B97F4A7C15ull + 1u;
  auto rng = [&state]() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  };
  ParityIO in = base;
  const int mode = static_cast<int>(rng() % 4u);
  if (mode == 3) {  // scale one vec4's xyz
    const int v = static_cast<int>(rng() % 4u);
    const float s = scales[rng() % 3u];
    for (int k = 0; k < 3; ++k)
      if (!intLike(in.v[v][k])) in.v[v][k] *= s;
  } else {  // replace mode + 1 random components
    for (int n = 0; n <= mode; ++n) {
      float& x = comp(in, static_cast<int>(rng() % 16u));
      const float h = hostile[rng() % 10u];
      if (!intLike(x)) x = h;
    }
  }
  return in;
}

std::string formatIO(const ParityIO& io) {
  std::ostringstream s;
  s.precision(9);
  for (int k = 0; k < 16; ++k) s << (k ? (k % 4 == 0 ? " | " : ", ") : "") << comp(io, k);
  return s.str();
}

struct Result {
  std::uint64_t inputs = 0, violations = 0, exempt = 0;
  std::map<int, std::uint64_t> byOutput;  // output float index -> violations
  std::string first;
};

Result runChunk(const CaseSpec& spec, const std::vector<ParityIO>& base, std::uint64_t begin, std::uint64_t end) {
  Result r;
  const auto ex = exceptions().find(spec.function);
  const Exception* e = ex == exceptions().end() ? nullptr : &ex->second;
  for (std::uint64_t i = begin; i < end; ++i) {
    const ParityIO in = i < base.size() ? base[i] : mutate(base[i % base.size()], i);
    const ParityIO out = spec.cpu(in);
    ++r.inputs;
    std::uint16_t skip = 0;
    if (e) {
      for (int k = 0; k < 16; ++k)
        if ((e->passThroughInputs >> k & 1u) && !std::isfinite(comp(in, k))) skip = e->outputs;
      if (e->always) skip = e->outputs;
      if (skip) ++r.exempt;
    }
    bool bad = false;
    for (int k = 0; k < spec.outputs; ++k) {
      if (skip >> k & 1u) continue;
      if (!std::isfinite(comp(out, k))) {
        bad = true;
        ++r.byOutput[k];
      }
    }
    if (bad) {
      if (r.violations == 0)
        r.first = "input #" + std::to_string(i) + ": " + formatIO(in) + "\n  output: " + formatIO(out);
      ++r.violations;
    }
  }
  return r;
}

class PropertyTest : public ::testing::Test {
 public:
  explicit PropertyTest(const CaseSpec* spec) : spec_(spec) {}
  void TestBody() override {
    if (spec_->setup) spec_->setup();
    const std::vector<ParityIO> base = spec_->inputs();
    ASSERT_GE(base.size(), 1000u);
    const std::uint64_t total = std::max<std::uint64_t>(inputCount(*spec_), base.size());
    // The generator and setup ran above (textures built, read-only from here), so
    // the CPU entry can run on several threads.
    const unsigned threads = std::max(1u, std::min(4u, std::thread::hardware_concurrency()));
    std::vector<Result> results(threads);
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t) {
      const std::uint64_t b = total * t / threads, en = total * (t + 1) / threads;
      pool.emplace_back([&, t, b, en] { results[t] = runChunk(*spec_, base, b, en); });
    }
    for (std::thread& th : pool) th.join();
    Result sum;
    for (const Result& r : results) {
      sum.inputs += r.inputs;
      sum.violations += r.violations;
      sum.exempt += r.exempt;
      for (const auto& [k, n] : r.byOutput) sum.byOutput[k] += n;
      if (sum.first.empty()) sum.first = r.first;
    }
    std::ostringstream outs;
    for (const auto& [k, n] : sum.byOutput) outs << " out" << k << "=" << n;
    std::cout << "[property] " << spec_->function << " inputs=" << sum.inputs << " violations=" << sum.violations
              << " exempt=" << sum.exempt << outs.str() << "\n";
    EXPECT_GE(sum.inputs, inputCount(*spec_));
    const auto pending = pendingTriage().find(spec_->function);
    if (pending != pendingTriage().end()) {
      std::cout << "[property] " << spec_->function << " pending triage (" << pending->second
                << "); first " << sum.first << "\n";
      return;
    }
    EXPECT_EQ(sum.violations, 0u) << spec_->function << ": non-finite outputs" << outs.str() << "; first "
                                  << sum.first;
  }

 private:
  const CaseSpec* spec_;
};

}  // namespace
}  // namespace snell_parity

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  for (const snell_parity::CaseSpec& spec : snell_parity::registry()) {
    ::testing::RegisterTest("Property", spec.function.c_str(), nullptr, nullptr, __FILE__, __LINE__,
                            [&spec]() -> ::testing::Test* { return new snell_parity::PropertyTest(&spec); });
  }
  return RUN_ALL_TESTS();
}
