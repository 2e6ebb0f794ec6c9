// Each runtime's declared float rules (snell::gpu::Runtime::flushesDenormals) against what it does: a
// probe of plain arithmetic on chosen floats runs on every runtime, and its results are compared with
// values computed here (the inputs themselves, and products in double rounded once). A runtime that
// flushes a denormal but declares it keeps them fails, and so does one that declares it may flush
// but flushed none (the declaration would widen its checks for nothing). The rules decide how the
// parity suite compares a runtime's results (parity_main.cpp: the flushed-input results), so they
// are measured, not assumed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <snell/gpu/runtimes/webgpu_chromium.hpp>

#include "parity_case.hpp"
#include "parity_runtimes.hpp"

namespace snell_parity {
namespace {

using checks::exact;

// Every runtime with float rules: the parity suite's, and Chromium's WebGPU (a smoke run of a few cases).
std::vector<snell::gpu::Runtime*> probedRuntimes() {
  static snell::gpu::WebGpuChromiumRuntime chromium(runtimeSetup());
  std::vector<snell::gpu::Runtime*> r;
  for (const auto& runtime : parityRuntimes()) r.push_back(runtime.get());
  r.push_back(&chromium);
  return r;
}
std::vector<std::string> probedNames() {
  std::vector<std::string> names;
  for (const snell::gpu::Runtime* r : probedRuntimes()) {
    std::string n = r->name();
    for (char& c : n)
      if (c == '-') c = '_';  // a gtest parameter name
    names.push_back(n);
  }
  return names;
}
snell::gpu::Runtime& runtimeNamed(const std::string& name) {
  const std::vector<std::string> names = probedNames();
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return *probedRuntimes()[i];
  throw std::invalid_argument("no runtime " + name);
}
const char* denormalRule(const snell::gpu::Runtime& r) { return r.flushesDenormals() ? "may flush" : "kept"; }

using snell::gpu::isDenormal;
std::uint32_t bitsOf(float x) {
  std::uint32_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// --- Denormals: a denormal copied, multiplied by 1, added to 0, compared with 0, and one made by a
// product of two normal floats.
constexpr const char* kDenormalBody =
    "copied = x; scaled = x * one; summed = x + vec4(zero, zero, zero, zero); made = a * b; nonzero = x.x != 0.0f;";
ParityIO denormalProbeCpu(const ParityIO& in) {  // kDenormalBody in C++
  const glm::vec4 x = in.v[0];
  const float one = in.v[1].x, zero = in.v[1].y, a = in.v[1].z, b = in.v[1].w;
  ParityIO out{};
  out.v[0] = x;
  out.v[1] = x * one;
  out.v[2] = x + glm::vec4(zero, zero, zero, zero);
  out.v[3].x = a * b;
  out.v[3].y = x.x != 0.0f ? 1.0f : 0.0f;
  return out;
}
CaseSpec denormalProbe() {
  return describeCase("probeDenormals", "runtime_probes.glsl", nullptr, &denormalProbeCpu,
                      {{"vec4", "x", 0}, {"float", "one", 4}, {"float", "zero", 5}, {"float", "a", 6}, {"float", "b", 7}},
                      {{"vec4", "copied", 0, exact}, {"vec4", "scaled", 4, exact}, {"vec4", "summed", 8, exact},
                       {"float", "made", 12, exact}, {"bool", "nonzero", 13, exact}},
                      kDenormalBody, {});
}
std::vector<ParityIO> denormalInputs() {
  const float denormals[] = {1.4e-45f, -1.4e-45f, 1e-40f, -1e-40f, 5.9e-39f, -3e-39f,
                             std::nextafter(1.17549435e-38f, 0.0f), -std::nextafter(1.17549435e-38f, 0.0f)};
  const float normals[] = {1.0f, -2.5f, 1.17549435e-38f, 1e-30f};
  // Pairs of normal floats whose product is a denormal, and one whose product is normal.
  const float products[][2] = {{1e-20f, 1e-20f}, {1.17549435e-38f, 0.5f}, {3e-23f, 2e-22f}, {-1e-19f, 1e-21f},
                               {1e-10f, 1e-10f}};
  std::vector<ParityIO> v;
  for (int i = 0; i < 1024; ++i) {
    ParityIO in{};
    for (int k = 0; k < 4; ++k)
      in.v[0][k] = (i + k) % 5 == 4 ? normals[(i / 5 + k) % 4] : denormals[(3 * i + 5 * k) % 8];
    in.v[1] = glm::vec4(1.0f, 0.0f, products[i % 5][0], products[i % 5][1]);
    v.push_back(in);
  }
  return v;
}

// What an output float is against the value computed here: kept (bit for bit), flushed (a denormal
// expected, a zero given) or wrong.
struct Tally {
  int kept = 0, flushed = 0, wrong = 0;
  std::string firstWrong;
  void add(float got, float want, const std::string& what) {
    if (bitsOf(got) == bitsOf(want)) {
      kept += isDenormal(want);
    } else if (isDenormal(want) && got == 0.0f) {
      ++flushed;
    } else {
      if (!wrong++) firstWrong = what + ": got " + std::to_string(got) + ", want " + std::to_string(want);
    }
  }
  std::string text() const {
    return "kept " + std::to_string(kept) + ", flushed " + std::to_string(flushed) + ", wrong " + std::to_string(wrong);
  }
};

class RuntimeFloats : public ::testing::TestWithParam<std::string> {};

TEST_P(RuntimeFloats, DenormalsAsDeclared) {
  snell::gpu::Runtime& runtime = runtimeNamed(GetParam());
  const CaseSpec spec = denormalProbe();
  ASSERT_TRUE(spec.layoutError.empty()) << spec.layoutError;
  const std::vector<ParityIO> inputs = denormalInputs();
  const std::vector<ParityIO> gpu = runtime.run(runtimeCase(spec), inputs);
  ASSERT_EQ(gpu.size(), inputs.size());
  const char* names[] = {"copied", "scaled", "summed", "made", "nonzero"};
  Tally by[5], all;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const glm::vec4 x = inputs[i].v[0];
    const float made = float(double(inputs[i].v[1].z) * double(inputs[i].v[1].w));
    const std::string at = "input " + std::to_string(i);
    for (int k = 0; k < 4; ++k) {
      for (int o = 0; o < 3; ++o) {
        by[o].add(gpu[i].v[o][k], x[k], at + " " + names[o]);
        all.add(gpu[i].v[o][k], x[k], at + " " + names[o]);
      }
    }
    by[3].add(gpu[i].v[3].x, made, at + " made");
    all.add(gpu[i].v[3].x, made, at + " made");
    // nonzero: 1 for a kept denormal, 0 for one the comparison read as 0.
    const float nz = gpu[i].v[3].y;
    if (nz == 1.0f) {
      by[4].kept += isDenormal(x.x);
      all.kept += isDenormal(x.x);
    } else if (nz == 0.0f && isDenormal(x.x)) {
      ++by[4].flushed;
      ++all.flushed;
    } else {
      by[4].add(nz, 1.0f, at + " nonzero");
      all.add(nz, 1.0f, at + " nonzero");
    }
  }
  std::ostringstream line;
  line << "[runtime-floats] " << runtime.name() << " denormals declared " << denormalRule(runtime) << ":";
  for (int o = 0; o < 5; ++o) line << " " << names[o] << " (" << by[o].text() << ")";
  std::cout << line.str() << "\n";
  EXPECT_EQ(all.wrong, 0) << all.firstWrong;
  ASSERT_GT(all.kept + all.flushed, 1000);
  if (!runtime.flushesDenormals())
    EXPECT_EQ(all.flushed, 0) << runtime.name() << " declares it keeps denormals, but flushed " << all.flushed
                              << " of " << all.kept + all.flushed << " (its flushesDenormals() should say true)";
  else
    EXPECT_GT(all.flushed, 0) << runtime.name() << " declares it may flush denormals, but kept all " << all.kept
                              << " (its flushesDenormals() should say false)";
}

// --- Constants: snellPerspectiveWithDepth reduces tan's argument above pi/4 with pi/2 in two parts,
// (hi - x) - lo (Cephes), which a compiler that reassociates folds into (hi - lo) - x: hi - lo rounds
// to hi, so the result loses lo. GLSL lets a compiler do this to any expression not declared
// precise; the C++ build (no -ffast-math) evaluates it as written.
constexpr float kHalfPiHi = 1.57079637050628662f, kHalfPiLo = 4.37113900018624283e-8f;
ParityIO constantsProbeCpu(const ParityIO& in) {
  ParityIO out{};
  for (int k = 0; k < 4; ++k) out.v[0][k] = (kHalfPiHi - in.v[0][k]) - kHalfPiLo;
  return out;
}
CaseSpec constantsProbe() {
  return describeCase("probeConstants", "runtime_probes.glsl", nullptr, &constantsProbeCpu, {{"vec4", "x", 0}},
                      {{"vec4", "r", 0, exact}},
                      "r = vec4((1.57079637050628662f - x.x) - 4.37113900018624283e-8f, "
                      "(1.57079637050628662f - x.y) - 4.37113900018624283e-8f, "
                      "(1.57079637050628662f - x.z) - 4.37113900018624283e-8f, "
                      "(1.57079637050628662f - x.w) - 4.37113900018624283e-8f);",
                      {});
}

TEST_P(RuntimeFloats, ConstantsAsDeclared) {
  snell::gpu::Runtime& runtime = runtimeNamed(GetParam());
  const CaseSpec spec = constantsProbe();
  ASSERT_TRUE(spec.layoutError.empty()) << spec.layoutError;
  // x in [pi/4, pi/2): the half field of view of the reduction's branch.
  std::mt19937 rng(52);
  std::uniform_real_distribution<float> half(0.78539818525f, 1.5707f);
  std::vector<ParityIO> inputs(1024);
  for (ParityIO& in : inputs)
    for (int k = 0; k < 4; ++k) in.v[0][k] = half(rng);
  const std::vector<ParityIO> gpu = runtime.run(runtimeCase(spec), inputs);
  ASSERT_EQ(gpu.size(), inputs.size());
  // As written: two roundings in order; folded: hi - lo rounded first (to hi), then one subtraction.
  const float folded = kHalfPiHi - kHalfPiLo;
  ASSERT_EQ(folded, kHalfPiHi);
  int asWritten = 0, wasFolded = 0, wrong = 0;
  std::string first;
  for (std::size_t i = 0; i < inputs.size(); ++i)
    for (int k = 0; k < 4; ++k) {
      const float x = inputs[i].v[0][k], got = gpu[i].v[0][k];
      const float written = float(double(float(double(kHalfPiHi) - double(x))) - double(kHalfPiLo));
      const float fold = float(double(folded) - double(x));
      if (written == fold) continue;  // this x does not tell them apart
      if (got == written) {
        ++asWritten;
      } else if (got == fold) {
        ++wasFolded;
      } else if (!wrong++) {
        first = "x " + std::to_string(x) + ": got " + std::to_string(got);
      }
    }
  std::cout << "[runtime-floats] " << runtime.name() << " constants declared "
            << (runtime.foldsConstants() ? "folded" : "as written") << ": (hi - x) - lo as written " << asWritten
            << ", folded to (hi - lo) - x " << wasFolded << ", neither " << wrong << "\n";
  EXPECT_EQ(wrong, 0) << first;
  ASSERT_GT(asWritten + wasFolded, 1000);
  if (!runtime.foldsConstants())
    EXPECT_EQ(wasFolded, 0) << runtime.name() << " declares it evaluates constants as written, but folded them "
                            << wasFolded << " times (its foldsConstants() should say true)";
  else
    EXPECT_EQ(asWritten, 0) << runtime.name() << " declares it folds constants, but evaluated " << asWritten
                            << " as written (its foldsConstants() should say false)";
}

INSTANTIATE_TEST_SUITE_P(ParityRuntimeFloats, RuntimeFloats, ::testing::ValuesIn(probedNames()),
                         [](const ::testing::TestParamInfo<std::string>& param) { return param.param; });

}  // namespace
}  // namespace snell_parity
