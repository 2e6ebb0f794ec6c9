// The parity suite: every registered case runs on llvmpipe through BOTH GL
// backends and in the C++ build, on the same inputs; the manifest test fails when
// a public function of glsl/ has no case. A GL context that cannot be created is a
// failure, never a skip (DESIGN.md sec. 3).
#include <gtest/gtest.h>

#include <snell/gpu/context.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <sstream>

#include "parity_registry.hpp"

namespace snell_parity {

std::vector<CaseSpec>& registry() {
  static std::vector<CaseSpec> cases;
  return cases;
}

namespace {

namespace fs = std::filesystem;
using snell::gpu::Backend;
using snell::gpu::Context;

const fs::path kRoot = SNELL_SOURCE_DIR;

// One context per backend for the whole run: creating one costs more than most
// cases. Released by main() before exit: destroying a context from a static
// destructor races Mesa's own exit-time teardown.
std::map<Backend, std::unique_ptr<Context>>& contexts() {
  static std::map<Backend, std::unique_ptr<Context>> all;
  return all;
}

Context& contextFor(Backend backend) {
  auto& slot = contexts()[backend];
  if (!slot) slot = std::make_unique<Context>(backend);
  slot->makeCurrent();
  return *slot;
}

class ParityTest : public ::testing::Test {
 public:
  ParityTest(const CaseSpec* spec, Backend backend) : spec_(spec), backend_(backend) {}
  void TestBody() override {
    if (spec_->setup) spec_->setup();
    const std::vector<ParityIO> inputs = spec_->inputs();
    ASSERT_GE(inputs.size(), 1000u) << "a parity case needs many inputs";
    std::vector<ParityIO> cpu;
    cpu.reserve(inputs.size());
    for (const ParityIO& in : inputs) cpu.push_back(spec_->cpu(in));
    Context& ctx = contextFor(backend_);
    const std::vector<ParityIO> gpu =
        snell::gpu::runParityGpu(ctx, {kRoot / "glsl", kRoot / "tests" / "parity" / "cases"}, spec_->glslFile,
                                 spec_->entry, inputs, spec_->textures);
    const snell::gpu::ParityReport r =
        snell::gpu::compareParity(gpu, cpu, spec_->discrete, spec_->outputs, spec_->tol.abs, spec_->tol.rel, &inputs);
    // The figures the closing notes quote.
    std::cout << "[parity] " << spec_->function << " backend=" << snell::gpu::backendName(backend_)
              << " cases=" << r.cases << " mismatches=" << r.mismatches << " maxAbs=" << r.maxAbs
              << " maxRel=" << r.maxRel << "\n";
    EXPECT_EQ(r.mismatches, 0u) << r.firstMismatchText;
  }

 private:
  const CaseSpec* spec_;
  Backend backend_;
};

// Cases of the prelude's texture hook macros (SNELL_SAMPLE_LOD, ...) rather than
// of a function.
bool isHookCase(const std::string& name) { return name.rfind("SNELL_", 0) == 0; }

// Public functions: every `SNELL_FN <type> snellName(` in glsl/snell.
std::set<std::string> publicGlslFunctions() {
  std::set<std::string> names;
  const std::regex fn(R"(SNELL_FN\s+\w+\s+(snell\w+)\s*\()");
  for (const auto& entry : fs::recursive_directory_iterator(kRoot / "glsl" / "snell")) {
    if (entry.path().extension() != ".glsl") continue;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    for (auto it = std::sregex_iterator(s.begin(), s.end(), fn); it != std::sregex_iterator(); ++it)
      names.insert((*it)[1].str());
  }
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

TEST(ParityManifest, CaseNamesFollowTheFunction) {
  for (const CaseSpec& c : registry()) {
    if (isHookCase(c.function)) continue;
    std::string expected = "case" + c.function;
    expected[4] = static_cast<char>(std::toupper(static_cast<unsigned char>(expected[4])));
    EXPECT_EQ(c.entry, expected) << "case entry for " << c.function;
  }
}

}  // namespace
}  // namespace snell_parity

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  using snell::gpu::Backend;
  for (const snell_parity::CaseSpec& spec : snell_parity::registry()) {
    for (Backend backend : {Backend::OSMesa, Backend::EGL}) {
      const std::string suite = std::string("Parity_") + snell::gpu::backendName(backend);
      ::testing::RegisterTest(suite.c_str(), spec.function.c_str(), nullptr, nullptr, __FILE__, __LINE__,
                              [&spec, backend]() -> ::testing::Test* {
                                return new snell_parity::ParityTest(&spec, backend);
                              });
    }
  }
  const int result = RUN_ALL_TESTS();
  snell_parity::contexts().clear();
  return result;
}
