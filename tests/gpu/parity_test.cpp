// The parity runner on a real case file, and compareParity's rules.
#include <snell/gpu/parity.hpp>

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#ifndef SNELL_SOURCE_DIR
#  error "SNELL_SOURCE_DIR (the repository root) must be defined by the build"
#endif

namespace {

namespace fs = std::filesystem;
using snell::gpu::compareParity;
using snell::gpu::ParityIO;

const float kInf = std::numeric_limits<float>::infinity();
const float kNaN = std::numeric_limits<float>::quiet_NaN();

std::vector<fs::path> searchPaths() {
  const fs::path root(SNELL_SOURCE_DIR);
  return {root / "glsl", root / "tests" / "parity" / "cases"};
}

ParityIO io(glm::vec4 a, glm::vec4 b = glm::vec4(0.0f), glm::vec4 c = glm::vec4(0.0f), glm::vec4 d = glm::vec4(0.0f)) {
  ParityIO r{};
  r.v[0] = a;
  r.v[1] = b;
  r.v[2] = c;
  r.v[3] = d;
  return r;
}

// A hand-written entry, appended after the case file (as the parity suite's
// generated entries are): snellSafeNormalize of a.xyz into o.a.xyz.
const std::string kSafeNormalizeEntry =
    "SNELL_FN SnellParityOut caseSafeNormalize(vec4 a, vec4 b, vec4 c, vec4 d) {\n"
    "  vec3 n = snellSafeNormalize(vec3(a.x, a.y, a.z));\n"
    "  SnellParityOut o;\n"
    "  o.a = vec4(n.x, n.y, n.z, 0.0f);\n"
    "  o.b = vec4(0.0f, 0.0f, 0.0f, 0.0f);\n"
    "  o.c = o.b;\n"
    "  o.d = o.b;\n"
    "  return o;\n"
    "}\n";

TEST(Parity, SafeNormalizeOnTheGpuMatchesHandComputedValues) {
  snell::gpu::Context ctx;
  // Expected values worked out by hand (double precision), not by the C++ build.
  struct Case {
    glm::vec3 in, out;
  };
  const std::vector<Case> cases = {
      {{3.0f, 4.0f, 0.0f}, {0.6f, 0.8f, 0.0f}},
      {{0.0f, 0.0f, -2.0f}, {0.0f, 0.0f, -1.0f}},
      {{1.0f, 1.0f, 1.0f}, {0.57735026919f, 0.57735026919f, 0.57735026919f}},
      {{1e10f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}},            // |v|^2 = 1e20, still finite
      {{2e-15f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}},           // |v|^2 = 4e-30 > 1e-30
      {{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}},             // zero
      {{1e-20f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}},           // |v|^2 = 1e-40 (denormal or flushed): too small
      {{1e20f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}},            // |v|^2 overflows to inf
      {{kInf, 1.0f, 0.0f}, {0.0f, 0.0f, 0.0f}},             // infinite component
      {{kNaN, 1.0f, 0.0f}, {0.0f, 0.0f, 0.0f}},             // NaN component
      {{-5.0f, 0.0f, 12.0f}, {-5.0f / 13.0f, 0.0f, 12.0f / 13.0f}},
  };
  std::vector<ParityIO> inputs, expected;
  // Repeat past one work group (and not a multiple of 64) to exercise the tail.
  for (int rep = 0; rep < 13; ++rep)
    for (const Case& c : cases) {
      inputs.push_back(io(glm::vec4(c.in, 0.0f)));
      expected.push_back(io(glm::vec4(c.out, 0.0f)));
    }
  const std::vector<ParityIO> gpu =
      snell::gpu::runParityGpu(ctx, searchPaths(), "optics.glsl", "caseSafeNormalize", inputs, {}, kSafeNormalizeEntry);
  ASSERT_EQ(gpu.size(), inputs.size());
  const snell::gpu::ParityReport r = compareParity(gpu, expected, 0, 16, 1e-6f, 1e-6f, &inputs);
  EXPECT_EQ(r.mismatches, 0u) << r.firstMismatchText;
  EXPECT_EQ(r.cases, inputs.size());
  // Spot check that something was actually computed (not an all-zero buffer).
  EXPECT_NEAR(gpu[0].v[0].x, 0.6f, 1e-6f);
  EXPECT_NEAR(gpu[2].v[0].y, 0.57735026919f, 1e-6f);
}

TEST(Parity, ManyInputsAndCaseErrorsPointAtTheCaseFile) {
  snell::gpu::Context ctx;
  // 100,003 cases: many groups and a ragged last group.
  std::vector<ParityIO> inputs(100003);
  for (std::size_t i = 0; i < inputs.size(); ++i)
    inputs[i] = io(glm::vec4(static_cast<float>(i % 1000) + 1.0f, 0.0f, 0.0f, 0.0f));
  const std::vector<ParityIO> gpu =
      snell::gpu::runParityGpu(ctx, searchPaths(), "optics.glsl", "caseSafeNormalize", inputs, {}, kSafeNormalizeEntry);
  // x * inversesqrt(x * x) is not always exactly 1 on llvmpipe (0.99999994 for some x).
  const std::vector<ParityIO> expected(inputs.size(), io(glm::vec4(1.0f, 0.0f, 0.0f, 0.0f)));
  const auto r = compareParity(gpu, expected, 0, 16, 1e-6f, 0.0f, &inputs);
  EXPECT_EQ(r.mismatches, 0u) << r.firstMismatchText;

  // An unknown entry or a broken case file is reported with the file it came from.
  try {
    snell::gpu::runParityGpu(ctx, searchPaths(), "optics.glsl", "caseDoesNotExist", inputs, {}, kSafeNormalizeEntry);
    FAIL() << "an unknown entry must throw";
  } catch (const snell::gpu::Error& e) {
    EXPECT_NE(std::string(e.what()).find("caseDoesNotExist"), std::string::npos) << e.what();
  }
}

TEST(Parity, TexturesAndCompileErrorsInUserCaseFiles) {
  snell::gpu::Context ctx;
  std::random_device rd;
  const fs::path dir = fs::temp_directory_path() / ("snell_parity_" + std::to_string(::getpid()) + "_" + std::to_string(rd()));
  fs::create_directories(dir);
  std::ofstream(dir / "fetch.glsl") << "/* a user's own case file */\n"
                                       "#include \"snell/prelude.glsl\"\n"
                                       "#if defined(SNELL_LANG_GLSL)\n"
                                       "uniform sampler2D parityTex;\n"
                                       "uniform sampler2D parityOther;\n"
                                       "#endif\n"
                                       "SNELL_FN SnellParityOut caseFetch(vec4 a, vec4 b, vec4 c, vec4 d) {\n"
                                       "  SnellParityOut o;\n"
                                       "  o.a = SNELL_TEXEL_FETCH(parityTex, ivec2(int(a.x), int(a.y)), int(a.z));\n"
                                       "  ivec2 s = SNELL_TEXTURE_SIZE(parityTex, 0);\n"
                                       "  o.b = vec4(float(s.x), float(s.y), 0.0f, 0.0f);\n"
                                       "  o.c = SNELL_TEXEL_FETCH(parityOther, ivec2(0, 0), 0);\n"
                                       "  o.d = vec4(0.0f);\n"
                                       "  return o;\n"
                                       "}\n";
  std::ofstream(dir / "broken.glsl") << "SnellParityOut caseBroken(vec4 a, vec4 b, vec4 c, vec4 d) {\n"
                                        "  SnellParityOut o;\n"
                                        "  o.a = notDeclared;\n"
                                        "  return o;\n"
                                        "}\n";
  std::vector<fs::path> paths = searchPaths();
  paths.push_back(dir);

  snell::Texture2D tex(snell::Image(4, 2));
  tex.generateMipmaps();
  for (int lod = 0; lod < tex.levelCount(); ++lod)
    for (int y = 0; y < tex.level(lod).height; ++y)
      for (int x = 0; x < tex.level(lod).width; ++x)
        tex.level(lod).at(x, y) = glm::vec4(static_cast<float>(x), static_cast<float>(y), static_cast<float>(lod), 7.0f);
  std::vector<ParityIO> inputs;
  for (int lod = 0; lod < tex.levelCount(); ++lod)
    for (int y = 0; y < tex.level(lod).height; ++y)
      for (int x = 0; x < tex.level(lod).width; ++x)
        inputs.push_back(io(glm::vec4(static_cast<float>(x), static_cast<float>(y), static_cast<float>(lod), 0.0f)));
  const snell::Texture2D other(snell::Image(1, 1, glm::vec4(-9.0f)));
  const auto gpu = snell::gpu::runParityGpu(ctx, paths, "fetch.glsl", "caseFetch", inputs,
                                            {{"parityTex", &tex}, {"parityOther", &other}, {"parityUnused", &other}});
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const glm::ivec3 p(inputs[i].v[0]);
    EXPECT_EQ(gpu[i].v[0], tex.fetch(glm::ivec2(p.x, p.y), p.z)) << i;
    // Level 0 only: llvmpipe's textureSize takes one lane's lod for a whole
    // SIMD batch, so a per-invocation lod would read other cases' sizes.
    EXPECT_EQ(gpu[i].v[1], glm::vec4(4.0f, 2.0f, 0.0f, 0.0f)) << i;
    EXPECT_EQ(gpu[i].v[2], glm::vec4(-9.0f)) << i;  // the second texture, on its own unit
  }

  try {
    snell::gpu::runParityGpu(ctx, paths, "broken.glsl", "caseBroken", inputs);
    FAIL() << "a broken case file must throw";
  } catch (const snell::gpu::Error& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "broken.glsl").string() + ":3("), std::string::npos) << e.what();
  }
  std::error_code ec;
  fs::remove_all(dir, ec);
}

TEST(CompareParity, ContinuousTolerance) {
  const std::vector<ParityIO> cpu = {io({1.0f, 100.0f, 0.0f, 1e-7f})};
  // abs 1e-5 + rel 1e-3: tolerances 1.001e-3, 0.10001, 1e-5, ~1e-5.
  EXPECT_EQ(compareParity({io({1.0009f, 100.1f, 9e-6f, 0.0f})}, cpu, 0, 4, 1e-5f, 1e-3f).mismatches, 0u);
  const auto bad = compareParity({io({1.0f, 100.2f, 0.0f, 1e-7f})}, cpu, 0, 4, 1e-5f, 1e-3f);
  EXPECT_EQ(bad.mismatches, 1u);
  EXPECT_EQ(bad.firstMismatch, 0u);
  EXPECT_NE(bad.firstMismatchText.find("case 0, output 1"), std::string::npos) << bad.firstMismatchText;
  EXPECT_NE(bad.firstMismatchText.find("gpu 100.19"), std::string::npos) << bad.firstMismatchText;
  EXPECT_NEAR(bad.maxAbs, 0.2f, 1e-5f);
  EXPECT_NEAR(bad.maxRel, 0.002f, 1e-6f);
  // maxRel ignores outputs at or below absTol (1e-7 vs 0 would be 100 %).
  const auto tiny = compareParity({io({1.0f, 100.0f, 0.0f, 0.0f})}, cpu, 0, 4, 1e-5f, 1e-3f);
  EXPECT_EQ(tiny.mismatches, 0u);
  EXPECT_EQ(tiny.maxRel, 0.0f);
  EXPECT_NEAR(tiny.maxAbs, 1e-7f, 1e-12f);
  // Outputs beyond `outputs` are not compared.
  EXPECT_EQ(compareParity({io({1.0f, 100.0f, 0.0f, 1e-7f}, glm::vec4(5.0f))}, cpu, 0, 4, 0.0f, 0.0f).mismatches, 0u);
  EXPECT_EQ(compareParity({io({1.0f, 100.0f, 0.0f, 1e-7f}, glm::vec4(5.0f))}, cpu, 0, 5, 0.0f, 0.0f).mismatches, 1u);
}

// A runtime that flushed a denormal input matches the C++ result on the flushed input: counted apart,
// not a mismatch; a result that matches neither is one, and names both C++ results.
TEST(CompareParity, FlushedDenormalInputs) {
  const ParityIO in = io(glm::vec4(1e-39f, 2.0f, -1e-40f, 0.0f));
  ASSERT_TRUE(snell::gpu::hasDenormal(in));
  const ParityIO flushed = snell::gpu::flushDenormals(in);
  EXPECT_EQ(flushed.v[0].x, 0.0f);
  EXPECT_TRUE(std::signbit(flushed.v[0].z));
  EXPECT_EQ(flushed.v[0].y, 2.0f);
  EXPECT_FALSE(snell::gpu::hasDenormal(flushed));
  // The "function": x / 1e-38 (a denormal scaled up into a normal result).
  const std::vector<ParityIO> cpu = {io(glm::vec4(in.v[0].x / 1e-38f))}, cpuFlushed = {io(glm::vec4(flushed.v[0].x / 1e-38f))};
  const std::vector<ParityIO> inputs = {in};
  auto r = compareParity({io(glm::vec4(0.0f))}, cpu, {{0, "q", false, 1e-6f, 1e-6f}}, &inputs, &cpuFlushed);
  EXPECT_EQ(r.mismatches, 0u);
  EXPECT_EQ(r.flushedMatches, 1u);
  r = compareParity({io(glm::vec4(0.1f))}, cpu, {{0, "q", false, 1e-6f, 1e-6f}}, &inputs, &cpuFlushed);
  EXPECT_EQ(r.mismatches, 0u);
  EXPECT_EQ(r.flushedMatches, 0u);
  r = compareParity({io(glm::vec4(0.05f))}, cpu, {{0, "q", false, 1e-6f, 1e-6f}}, &inputs, &cpuFlushed);
  EXPECT_EQ(r.mismatches, 1u);
  EXPECT_NE(r.firstMismatchText.find("on the flushed inputs"), std::string::npos) << r.firstMismatchText;
  // Without the flushed results the flushing runtime mismatches.
  EXPECT_EQ(compareParity({io(glm::vec4(0.0f))}, cpu, {{0, "q", false, 1e-6f, 1e-6f}}, &inputs).mismatches, 1u);
}

// A condition-scaled tolerance (abs + rel |cpu| + scaled |cpu condition|) applies to every case, or,
// with the flags, only to the cases flagged true.
TEST(CompareParity, ScaledToleranceOnlyOnFlaggedCases) {
  // Output 0 with its condition in output 1: tolerance 0 + 0 + 1e-3 * 100 = 0.1.
  const std::vector<snell::gpu::ParityOutput> outputs = {{0, "uv", false, 0.0f, 0.0f, 1e-3f, 1}};
  const std::vector<ParityIO> cpu = {io({1.0f, 100.0f, 0.0f, 0.0f}), io({1.0f, 100.0f, 0.0f, 0.0f})};
  const std::vector<ParityIO> gpu = {io({1.05f, 100.0f, 0.0f, 0.0f}), io({1.05f, 100.0f, 0.0f, 0.0f})};
  EXPECT_EQ(compareParity(gpu, cpu, outputs).mismatches, 0u);
  const std::vector<bool> second = {false, true};
  const auto r = compareParity(gpu, cpu, outputs, nullptr, nullptr, &second);
  EXPECT_EQ(r.mismatches, 1u);
  EXPECT_EQ(r.firstMismatch, 0u);
  const std::vector<bool> wrongCount = {true};
  EXPECT_THROW(compareParity(gpu, cpu, outputs, nullptr, nullptr, &wrongCount), std::invalid_argument);
}

TEST(CompareParity, DiscreteOutputsMustBeEqual) {
  const std::vector<ParityIO> cpu = {io({0.5f, 1.0f, 0.0f, 0.0f}), io({0.5f, 0.0f, 3.0f, 0.0f})};
  // Output 1 is a flag, output 2 a step count: discrete mask 0b0110.
  const std::vector<ParityIO> gpu = {io({0.5f, 1.0f, 0.0f, 0.0f}), io({0.5f, 1.0f, 3.0f, 0.0f})};
  auto r = compareParity(gpu, cpu, 0x6, 4, 10.0f, 10.0f);  // huge tolerances do not apply to discrete outputs
  EXPECT_EQ(r.mismatches, 1u);
  EXPECT_EQ(r.firstMismatch, 1u);
  EXPECT_NE(r.firstMismatchText.find("case 1, output 1"), std::string::npos) << r.firstMismatchText;
  EXPECT_NE(r.firstMismatchText.find("discrete"), std::string::npos) << r.firstMismatchText;
  // Without the mask the same difference is inside the tolerance.
  EXPECT_EQ(compareParity(gpu, cpu, 0, 4, 10.0f, 10.0f).mismatches, 0u);
  // Inputs are named when given.
  const std::vector<ParityIO> inputs = {io({9.0f, 8.0f, 7.0f, 6.0f}), io({1.25f, 2.5f, 3.75f, 5.0f})};
  r = compareParity(gpu, cpu, 0x6, 4, 10.0f, 10.0f, &inputs);
  EXPECT_NE(r.firstMismatchText.find("inputs ((1.25, 2.5, 3.75, 5)"), std::string::npos) << r.firstMismatchText;
}

TEST(CompareParity, NaNAndInfinityRules) {
  const std::vector<ParityIO> cpu = {io({kNaN, kInf, -kInf, kNaN})};
  // NaN == NaN (continuous and discrete), inf must match exactly.
  EXPECT_EQ(compareParity({io({kNaN, kInf, -kInf, kNaN})}, cpu, 0x8, 4, 1e-5f, 1e-5f).mismatches, 0u);
  EXPECT_EQ(compareParity({io({0.0f, kInf, -kInf, kNaN})}, cpu, 0, 4, 1e30f, 1e30f).mismatches, 1u);   // number vs NaN
  EXPECT_EQ(compareParity({io({kNaN, 3e38f, -kInf, kNaN})}, cpu, 0, 4, 1e30f, 1e30f).mismatches, 1u);  // finite vs inf
  EXPECT_EQ(compareParity({io({kNaN, kInf, kInf, kNaN})}, cpu, 0, 4, 1e30f, 1e30f).mismatches, 1u);   // inf sign
  EXPECT_EQ(compareParity({io({kNaN, kInf, -kInf, 1.0f})}, cpu, 0x8, 4, 1e30f, 1e30f).mismatches, 1u);  // discrete NaN
  // A finite gpu value against a finite cpu one never reports NaN statistics.
  const auto r = compareParity({io({kNaN, kInf, -kInf, kNaN})}, cpu, 0, 4, 0.0f, 0.0f);
  EXPECT_EQ(r.maxAbs, 0.0f);
  EXPECT_EQ(r.maxRel, 0.0f);
  EXPECT_THROW(compareParity({io(glm::vec4(0.0f))}, {}, 0, 4, 0.0f, 0.0f), std::invalid_argument);
}

TEST(CompareParity, CountsCasesNotOutputs) {
  const std::vector<ParityIO> cpu(3, io({1.0f, 1.0f, 1.0f, 1.0f}));
  const std::vector<ParityIO> gpu = {io({1.0f, 1.0f, 1.0f, 1.0f}), io({2.0f, 2.0f, 2.0f, 2.0f}),
                                     io({1.0f, 1.0f, 1.0f, 3.0f})};
  const auto r = compareParity(gpu, cpu, 0, 4, 0.0f, 0.0f);
  EXPECT_EQ(r.cases, 3u);
  EXPECT_EQ(r.mismatches, 2u);
  EXPECT_EQ(r.firstMismatch, 1u);
  EXPECT_EQ(r.maxAbs, 2.0f);
  EXPECT_EQ(r.maxRel, 2.0f);
  EXPECT_NE(r.firstMismatchText.find("case 1, output 0"), std::string::npos) << r.firstMismatchText;
}

}  // namespace
