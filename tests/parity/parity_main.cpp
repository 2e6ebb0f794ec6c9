// The parity suite: every registered case runs on every runtime of snell::gpu::runtimeList() (suite
// Parity_<runtime>: GLSL on both GL backends, HLSL, Vulkan, WebGPU, WebGL 2) and in the C++ build, on the
// same inputs; the manifest tests fail when a public function of glsl/ has no case, or no HLSL entry / run.
// A runtime that cannot start is a failure, never a skip (DESIGN.md sec. 3).
#include <gtest/gtest.h>

#include <snell/gpu/process.hpp>
#include <snell/gpu/runtimes/hlsl.hpp>
#include <snell/gpu/runtimes/webgpu_chromium.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <sstream>

#include "parity_case.hpp"
#include "parity_registry.hpp"
#include "parity_runtimes.hpp"

namespace snell_parity {

namespace {

using snell::gpu::Backend;

// The C++ build on each input with its denormals flushed, where it has one (the C++ result on the
// input itself otherwise): the prelude's rule for denormal data lets a runtime give either.
std::vector<ParityIO> cpuOnFlushedInputs(const CaseSpec& spec, const std::vector<ParityIO>& inputs,
                                         const std::vector<ParityIO>& cpu) {
  std::vector<ParityIO> flushed = cpu;
  for (std::size_t i = 0; i < inputs.size(); ++i)
    if (snell::gpu::hasDenormal(inputs[i])) flushed[i] = spec.cpu(snell::gpu::flushDenormals(inputs[i]));
  return flushed;
}

// compareParity with the runtime's declared float rules (runtime_floats_test.cpp holds each runtime to its
// word): the results on the inputs with denormals flushed count only where its device flushes them, and an
// output's condition-scaled tolerance applies only where its compiler folds constants, on the inputs the
// case names (CaseExtras::scaledWhere).
snell::gpu::ParityReport compareOn(const CaseSpec& spec, const snell::gpu::Runtime& runtime,
                                   const std::vector<ParityIO>& gpu, const std::vector<ParityIO>& cpu,
                                   const std::vector<ParityIO>& inputs) {
  const std::vector<ParityIO> cpuFlushed =
      runtime.flushesDenormals() ? cpuOnFlushedInputs(spec, inputs, cpu) : std::vector<ParityIO>();
  std::vector<bool> scaled(inputs.size(), runtime.foldsConstants());
  if (spec.scaledWhere)
    for (std::size_t i = 0; i < inputs.size(); ++i) scaled[i] = scaled[i] && spec.scaledWhere(inputs[i]);
  return snell::gpu::compareParity(gpu, cpu, spec.outputs, &inputs, cpuFlushed.empty() ? nullptr : &cpuFlushed,
                                   &scaled);
}

class ParityTest : public ::testing::Test {
 public:
  ParityTest(const CaseSpec* spec, snell::gpu::Runtime* runtime) : spec_(spec), runtime_(runtime) {}
  void TestBody() override {
    ASSERT_TRUE(spec_->layoutError.empty()) << spec_->function << "'s description: " << spec_->layoutError;
    if (spec_->setup) spec_->setup();
    const std::vector<ParityIO> inputs = spec_->inputs();
    ASSERT_GE(inputs.size(), 1000u) << "a parity case needs many inputs";
    std::vector<ParityIO> cpu;
    cpu.reserve(inputs.size());
    for (const ParityIO& in : inputs) cpu.push_back(spec_->cpu(in));
    const std::vector<ParityIO> gpu = runtime_->run(runtimeCase(*spec_), inputs);
    const snell::gpu::ParityReport r = compareOn(*spec_, *runtime_, gpu, cpu, inputs);
    // The figures the closing notes quote.
    std::cout << "[parity] " << spec_->function << " file=" << spec_->glslFile << " backend=" << runtime_->name()
              << " cases=" << r.cases << " mismatches=" << r.mismatches << " flushed=" << r.flushedMatches
              << " maxAbs=" << r.maxAbs
              << " maxRel=" << r.maxRel << std::hex << " digests in=" << ioDigest(inputs) << " cpu=" << ioDigest(cpu)
              << " gpu=" << ioDigest(gpu) << std::dec << " runtime=\"" << runtime_->describe() << "\" renderer=\""
              << runtime_->renderer() << "\"\n";
    EXPECT_EQ(r.mismatches, 0u) << r.firstMismatchText;
  }

 private:
  const CaseSpec* spec_;
  snell::gpu::Runtime* runtime_;
};

// SNELL_HLSL_FLIP_V (bridge.hlsl, D3D-oriented textures): the hooks cases run
// as HLSL with the option on and every texture level stored upside down (row 0
// at the top, as a D3D render target) must give what the C++ build gives on the
// GL-oriented textures. Nearest reads move off texel edges first: there GL's
// floor() picks the texel above the edge, which a mirror turns into the one
// below (level 0: into the texel interior; every level: by 1e-4 in uv).
enum class EdgeNudge { None, Level0Interior, AllLevels };
snell::Texture2D flipRows(const snell::Texture2D& t) {
  auto flip = [](const snell::Image& img) {
    snell::Image f(img.width, img.height);
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) f.at(x, img.height - 1 - y) = img.at(x, y);
    return f;
  };
  snell::Texture2D r(flip(t.level(0)), t.minFilter, t.mipFilter);
  r.magFilter = t.magFilter;
  for (int l = 1; l < t.levelCount(); ++l) r.addLevel(flip(t.level(l)));
  return r;
}

void runFlipV(const std::string& function, EdgeNudge nudge) {
  const CaseSpec* spec = nullptr;
  for (const CaseSpec& c : registry())
    if (c.function == function) spec = &c;
  ASSERT_NE(spec, nullptr) << "no parity case of " << function;
  if (spec->setup) spec->setup();
  std::vector<ParityIO> inputs = spec->inputs();
  std::vector<snell::Texture2D> flipped;
  flipped.reserve(spec->textures.size());
  std::vector<snell::gpu::ParityTexture> textures;
  for (const snell::gpu::ParityTexture& t : spec->textures) {
    flipped.push_back(flipRows(*t.texture));
    textures.push_back({t.uniform, &flipped.back()});
  }
  if (nudge == EdgeNudge::AllLevels) {
    for (ParityIO& in : inputs) {
      in.v[0].x += 1e-4f;
      in.v[0].y += 1e-4f;
    }
  } else if (nudge == EdgeNudge::Level0Interior) {
    const glm::ivec2 size = spec->textures.front().texture->size(0);  // every hooks texture has one base size
    for (ParityIO& in : inputs)
      for (int k = 0; k < 2; ++k) {
        const float n = static_cast<float>(size[k]);
        const float t = in.v[0][k] * n;
        in.v[0][k] = (std::floor(t) + 0.25f + 0.5f * (t - std::floor(t))) / n;
      }
  }
  std::vector<ParityIO> cpu;
  for (const ParityIO& in : inputs) cpu.push_back(spec->cpu(in));
  snell::gpu::HlslRuntime flipV(runtimeSetup(), {"SNELL_HLSL_FLIP_V 1"});
  snell::gpu::RuntimeCase upsideDown = runtimeCase(*spec);
  upsideDown.textures = textures;
  const std::vector<ParityIO> gpu = flipV.run(upsideDown, inputs);
  flipV.release();
  const snell::gpu::ParityReport r = compareOn(*spec, flipV, gpu, cpu, inputs);
  std::cout << "[parity-hlsl-flipv] " << spec->function << " cases=" << r.cases << " mismatches=" << r.mismatches
            << " maxAbs=" << r.maxAbs << " maxRel=" << r.maxRel << "\n";
  EXPECT_EQ(r.mismatches, 0u) << r.firstMismatchText;
}

TEST(ParityHlslFlipV, TexelFetchSizeAndNearest) { runFlipV("SNELL_TEXEL_FETCH_and_SIZE", EdgeNudge::Level0Interior); }
TEST(ParityHlslFlipV, SampleLodLinear) { runFlipV("SNELL_SAMPLE_LOD", EdgeNudge::None); }
TEST(ParityHlslFlipV, SampleLodMipmaps) { runFlipV("SNELL_SAMPLE_LOD_mipmaps", EdgeNudge::AllLevels); }

// The WGSL of a few cases (every family, textures with mips and LINEAR float
// filtering, the whole two-interface trace) executed a second time, by
// Chromium's WebGPU (Dawn: Tint compiles it, SwiftShader runs it), and compared
// with the C++ build like every runtime: the smoke run that shows the WGSL
// snell's users get runs under both major WGSL implementations, not only wgpu.
void runWebGpuInChromium(const std::string& function) {
  const CaseSpec* spec = nullptr;
  for (const CaseSpec& c : registry())
    if (c.function == function) spec = &c;
  ASSERT_NE(spec, nullptr) << "no parity case of " << function;
  if (spec->setup) spec->setup();
  const std::vector<ParityIO> inputs = spec->inputs();
  std::vector<ParityIO> cpu;
  for (const ParityIO& in : inputs) cpu.push_back(spec->cpu(in));
  snell::gpu::WebGpuChromiumRuntime chromium(runtimeSetup());
  const std::vector<ParityIO> gpu = chromium.run(runtimeCase(*spec), inputs);
  const snell::gpu::ParityReport r = compareOn(*spec, chromium, gpu, cpu, inputs);
  std::cout << "[parity-webgpu-chromium] " << spec->function << " adapter=\"" << chromium.renderer() << "\" cases=" << r.cases
            << " mismatches=" << r.mismatches << " flushed=" << r.flushedMatches << " maxAbs=" << r.maxAbs
            << " maxRel=" << r.maxRel << "\n";
  EXPECT_EQ(r.mismatches, 0u) << r.firstMismatchText;
}

TEST(ParityWebGpuChromium, Refract) { runWebGpuInChromium("snellRefract"); }
TEST(ParityWebGpuChromium, PerspectiveInverse) { runWebGpuInChromium("snellPerspectiveInverse"); }
TEST(ParityWebGpuChromium, SampleLodMipmaps) { runWebGpuInChromium("SNELL_SAMPLE_LOD_mipmaps"); }
TEST(ParityWebGpuChromium, IntersectPlaneNormal) { runWebGpuInChromium("snellIntersectPlaneNormal"); }
TEST(ParityWebGpuChromium, TwoInterfaceTrace) { runWebGpuInChromium("snellTwoInterfaceTrace"); }

// The tests gtest holds, per suite, read back from gtest itself (filtered-out ones included): what it can run,
// whatever main()'s loop meant to register.
std::map<std::string, std::multiset<std::string>> gtestRegistry() {
  std::map<std::string, std::multiset<std::string>> tests;
  const ::testing::UnitTest& unit = *::testing::UnitTest::GetInstance();
  for (int i = 0; i < unit.total_test_suite_count(); ++i) {
    const ::testing::TestSuite* suite = unit.GetTestSuite(i);
    for (int j = 0; j < suite->total_test_count(); ++j) tests[suite->name()].insert(suite->GetTestInfo(j)->name());
  }
  return tests;
}

// Cases of the prelude's texture hook macros (SNELL_SAMPLE_LOD, ...) rather than
// of a function.
bool isHookCase(const std::string& name) { return name.rfind("SNELL_", 0) == 0; }

// Public functions: every `SNELL_FN <type> snellName(` in glsl/snell, with its
// family (the folder under glsl/snell: optics, camera, intersect, shade).
std::map<std::string, std::string> publicGlslFunctionFamilies() {
  std::map<std::string, std::string> names;
  const std::regex fn(R"(SNELL_FN(?:_INLINE)?\s+\w+\s+(snell\w+)\s*\()");
  const fs::path base = kRoot / "glsl" / "snell";
  for (const auto& entry : fs::recursive_directory_iterator(base)) {
    if (entry.path().extension() != ".glsl") continue;
    const fs::path rel = entry.path().lexically_relative(base);
    const std::string family = std::distance(rel.begin(), rel.end()) > 1 ? rel.begin()->string() : std::string();
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    for (auto it = std::sregex_iterator(s.begin(), s.end(), fn); it != std::sregex_iterator(); ++it)
      names[(*it)[1].str()] = family;
  }
  return names;
}

std::set<std::string> publicGlslFunctions() {
  std::set<std::string> names;
  for (const auto& [name, family] : publicGlslFunctionFamilies()) names.insert(name);
  return names;
}

// Functions defined after the HLSL preprocessor ran over an hlsl_like entry
// file (glslangValidator -D -E): what an HLSL shader including it can call.
std::set<std::string> hlslDefinedFunctions(const std::string& entryFile) {
  const fs::path file = kRoot / "hlsl_like" / "snell" / entryFile;
  const snell::gpu::ToolResult r =
      snell::gpu::runTool(runtimeSetup().shaderTools.glslangValidator, {"-D", "-E", "-S", "frag", file.string()},
                          "glslang-tools");
  if (r.exitCode != 0) throw snell::gpu::Error("glslangValidator -D -E " + file.string() + " failed:\n" + r.output);
  std::set<std::string> names;
  const std::regex def(R"((\w+)\s+(snell\w+)\s*\([^;{}]*\)\s*\{)");
  for (auto it = std::sregex_iterator(r.output.begin(), r.output.end(), def); it != std::sregex_iterator(); ++it)
    if ((*it)[1].str() != "return") names.insert((*it)[2].str());
  return names;
}

TEST(ParityManifest, EveryPublicGlslFunctionHasAParityCase) {
  const std::set<std::string> publicNames = publicGlslFunctions();
  ASSERT_GT(publicNames.size(), 0u) << "no public functions found under " << (kRoot / "glsl");
  std::set<std::string> covered;
  for (const CaseSpec& c : registry()) covered.insert(c.function);
  for (const std::string& name : publicNames)
    EXPECT_TRUE(covered.count(name)) << name << " has no parity case (tests/parity/*_cases.cpp)";
  for (const std::string& name : covered)
    EXPECT_TRUE(publicNames.count(name) || isHookCase(name)) << "parity case for unknown function " << name;
}

// Every public GLSL function is defined by hlsl_like/snell/snell.hlsl and by its
// family's entry file (its HLSL run: EveryCaseRunsOnEveryRuntime).
TEST(ParityManifest, EveryPublicGlslFunctionHasAnHlslEntryAndRun) {
  const std::map<std::string, std::string> families = publicGlslFunctionFamilies();
  ASSERT_GT(families.size(), 0u);
  const std::set<std::string> all = hlslDefinedFunctions("snell.hlsl");
  std::map<std::string, std::set<std::string>> byEntry;
  for (const std::string family : {"optics", "camera", "intersect", "shade"})
    byEntry[family] = hlslDefinedFunctions(family + ".hlsl");
  for (const auto& [name, family] : families) {
    EXPECT_TRUE(all.count(name)) << name << " is not defined by hlsl_like/snell/snell.hlsl";
    const auto entry = byEntry.find(family);
    if (entry == byEntry.end()) {
      ADD_FAILURE() << name << " (glsl/snell/" << family << ") belongs to no HLSL family entry file";
    } else {
      EXPECT_TRUE(entry->second.count(name)) << name << " is not defined by hlsl_like/snell/" << family << ".hlsl";
    }
  }
}

// Every case runs on every runtime, once: each runtime's suite in gtest's registry holds exactly one test per
// case, named after it.
TEST(ParityManifest, EveryCaseRunsOnEveryRuntime) {
  ASSERT_GE(parityRuntimes().size(), 3u);
  std::multiset<std::string> cases;
  for (const CaseSpec& c : registry()) cases.insert(c.function);
  const std::map<std::string, std::multiset<std::string>> tests = gtestRegistry();
  for (const auto& runtime : parityRuntimes()) {
    const std::string name = paritySuite(*runtime);
    const auto suite = tests.find(name);
    ASSERT_NE(suite, tests.end()) << "gtest has no suite " << name;
    for (const std::string& c : cases)
      EXPECT_EQ(suite->second.count(c), 1u) << "parity case " << c << " runs " << suite->second.count(c)
                                            << " times on " << name;
    for (const std::string& c : suite->second) EXPECT_TRUE(cases.count(c)) << name << "." << c << " is no parity case";
  }
}

// The layout check itself: each wrong description is reported (and nothing is
// generated from it), a right one is not.
TEST(ParityManifest, WrongLayoutsAreReportedNotGenerated) {
  using snell_parity::CaseVar;
  using snell_parity::checks::exact;
  using snell_parity::checks::within;
  auto zeros = [](const ParityIO&) { return ParityIO{}; };
  auto none = [] { return std::vector<ParityIO>(); };
  auto layout = [&](std::vector<CaseVar> ins, std::vector<CaseVar> outs, snell_parity::CaseExtras extras = {}) {
    return snell_parity::describeCase("snellTest", "optics.glsl", none, +zeros, std::move(ins), std::move(outs), "",
                                      std::move(extras));
  };
  const CaseSpec good = layout({{"vec3", "v", 0}}, {{"vec3", "n", 13, within(1e-6f, 0.0f)}});
  EXPECT_TRUE(good.layoutError.empty()) << good.layoutError;
  EXPECT_EQ(good.outputs.size(), 3u);
  EXPECT_NE(good.entrySource.find("vec3 v = vec3(parityA.x, parityA.y, parityA.z);"), std::string::npos) << good.entrySource;
  const std::vector<CaseSpec> bad = {
      layout({{"vec3", "v", 0}}, {{"vec3", "n", 14, exact}}),                    // past float 15
      layout({{"vec3", "v", -1}}, {{"float", "n", 0, exact}}),                   // before float 0
      layout({{"vec3", "v", 0}, {"float", "w", 2}}, {{"float", "n", 0, exact}}), // two inputs on float 2
      layout({{"mat3", "m", 0}}, {{"float", "n", 0, exact}}),                    // not a case type
      layout({{"float", "x", 0}}, {{"bool", "valid", 0, within(1e-5f, 1e-5f)}}), // a flag within a tolerance
      layout({{"float", "x", 0}}, {{"float", "n", 0, within(-1.0f, 0.0f)}}),     // a negative tolerance
      layout({{"float", "parityA", 0}}, {{"float", "n", 0, exact}}),             // a generated name
      layout({{"float", "x", 0}}, {{"float", "n", 0, exact}},
             snell_parity::CaseExtras().passThrough({"y"}, {"n"}, "names no input of the case")),
  };
  for (std::size_t i = 0; i < bad.size(); ++i) {
    EXPECT_FALSE(bad[i].layoutError.empty()) << "bad description " << i;
    EXPECT_TRUE(bad[i].entrySource.empty()) << "bad description " << i;
    EXPECT_TRUE(bad[i].outputs.empty()) << "bad description " << i;
  }
}

// Every description lays its inputs and outputs out on distinct floats of
// known types, names only what it has in its exceptions, and has outputs.
TEST(ParityManifest, EveryCaseDescriptionIsWellFormed) {
  std::set<std::string> functions;
  for (const CaseSpec& c : registry()) {
    EXPECT_TRUE(c.layoutError.empty()) << c.function << ": " << c.layoutError;
    EXPECT_FALSE(c.outputs.empty()) << c.function << " describes no output";
    EXPECT_TRUE(functions.insert(c.function).second) << c.function << " is described twice";
  }
}

}  // namespace
}  // namespace snell_parity

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  for (const snell_parity::CaseSpec& spec : snell_parity::registry())
    for (const auto& runtime : snell_parity::parityRuntimes()) {
      snell::gpu::Runtime* r = runtime.get();
      ::testing::RegisterTest(snell_parity::paritySuite(*r).c_str(), spec.function.c_str(), nullptr, nullptr, __FILE__,
                              __LINE__, [&spec, r]() -> ::testing::Test* { return new snell_parity::ParityTest(&spec, r); });
    }
  const int result = RUN_ALL_TESTS();
  snell_parity::releaseParityRuntimes();
  return result;
}
