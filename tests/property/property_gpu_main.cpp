// Property test, GPU side: every public function, through its parity case entry on the runtimes of
// snell::gpu::runtimeList() that ask for hostile inputs (suite PropertyGpu_<runtime>), on 10,000 of them:
// inputs #n .. #n + 9,999 of the CPU property stream (property_contract.hpp),
// n being the size of the case's generator output, i.e. one hostile mutation of
// each generator input. The generator's own inputs are left out: the parity
// suite already runs them on the GPU, and it fails wherever the GPU's NaNs and
// infinities differ from those of the C++ build, which the CPU property test
// holds to the contract. All 10,000 run in one dispatch of the parity runner.
//
// Cost: the program is the parity case's own (same generated source, same
// driver), so once Parity_osmesa.<fn> has run, Mesa's shader disk cache hands it
// over without an LLVM compile: ~3 CPU-s for all functions. With a cold cache
// the compiles cost ~80 CPU-s, 50 of them snellTwoInterfaceRefraction's. The
// EGL backend loads another driver library with its own cache entries, hence
// OSMesa here.
//
// The same contract, exceptions and pending-triage list as the CPU side. The
// C++ build runs on the same inputs too, so a violation is reported as "also
// on the CPU" or "GPU only" (a driver deviation or a GLSL-only bug to chase).
//
// Prints one line per function:
//   "[property-gpu] <fn> inputs=N violations=V gpuOnly=G cpuOnly=C exempt=E".
#include <gtest/gtest.h>

#include <snell/gpu/context.hpp>

#include <cstdint>
#include <filesystem>
#include <iostream>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "parity_registry.hpp"
#include "parity_runtimes.hpp"
#include "property_contract.hpp"

namespace snell_parity {

namespace {

using property::Tally;

// SNELL_PROPERTY_GPU_INPUTS overrides it for a longer run (not in CI).
std::size_t gpuInputs() {
  const char* env = std::getenv("SNELL_PROPERTY_GPU_INPUTS");
  if (!env) return 10000;
  char* end = nullptr;
  const unsigned long long n = std::strtoull(env, &end, 10);
  if (end == env || *end != '\0' || n < 1 || n > 100000000ULL) {
    std::fprintf(stderr, "SNELL_PROPERTY_GPU_INPUTS: expected a whole number in [1, 1e8], got '%s'\n", env);
    std::exit(2);
  }
  return static_cast<std::size_t>(n);
}
class PropertyGpuTest : public ::testing::Test {
 public:
  PropertyGpuTest(const CaseSpec* spec, snell::gpu::Runtime* runtime) : spec_(spec), runtime_(runtime) {}
  void TestBody() override {
    if (spec_->setup) spec_->setup();
    const std::vector<ParityIO> base = spec_->inputs();
    ASSERT_GE(base.size(), 1000u);
    std::vector<ParityIO> inputs;
    const std::size_t count = gpuInputs();
    inputs.reserve(count);
    for (std::uint64_t i = base.size(); i < base.size() + count; ++i)
      inputs.push_back(property::propertyInput(base, i));

    const std::vector<ParityIO> gpu = runtime_->run(runtimeCase(*spec_), inputs);
    ASSERT_EQ(gpu.size(), inputs.size());

    Tally onGpu, onCpu;
    std::uint64_t gpuOnly = 0, cpuOnly = 0;
    std::string firstGpuOnly;
    for (std::size_t j = 0; j < inputs.size(); ++j) {
      const std::uint64_t index = base.size() + j;
      const ParityIO cpu = spec_->cpu(inputs[j]);
      const bool g = onGpu.add(*spec_, index, inputs[j], gpu[j]) != 0;
      const bool c = onCpu.add(*spec_, index, inputs[j], cpu) != 0;
      if (g && !c && gpuOnly++ == 0)
        firstGpuOnly = "input #" + std::to_string(index) + ": " + property::formatIO(inputs[j]) +
                       "\n  gpu output: " + property::formatIO(gpu[j]) + "\n  cpu output: " + property::formatIO(cpu);
      if (c && !g) ++cpuOnly;
    }
    std::cout << "[property-gpu] " << spec_->function << " backend=" << runtime_->name()
              << " inputs=" << onGpu.inputs << " violations=" << onGpu.violations << " gpuOnly=" << gpuOnly
              << " cpuOnly=" << cpuOnly << " exempt=" << onGpu.exempt << onGpu.byOutputText() << "\n";
    if (gpuOnly) std::cout << "[property-gpu] " << spec_->function << " first GPU-only " << firstGpuOnly << "\n";
    const auto pending = property::pendingTriage().find(spec_->function);
    if (pending != property::pendingTriage().end()) {
      std::cout << "[property-gpu] " << spec_->function << " pending triage (" << pending->second << ")"
                << (onGpu.violations ? "; first " + onGpu.first : std::string()) << "\n";
      return;
    }
    EXPECT_EQ(onGpu.violations, 0u) << spec_->function << ": non-finite GPU outputs" << onGpu.byOutputText()
                                    << " (" << gpuOnly << " where the C++ build is finite); first " << onGpu.first
                                    << (gpuOnly ? "\nfirst GPU-only " + firstGpuOnly : std::string());
  }

 private:
  const CaseSpec* spec_;
  snell::gpu::Runtime* runtime_;
};

}  // namespace
}  // namespace snell_parity

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  // The runtimes of the one list whose entry asks for the hostile inputs (runtime_list.hpp says which not).
  for (std::size_t i = 0; i < snell::gpu::runtimeList().size(); ++i) {
    if (!snell::gpu::runtimeList()[i].hostileInputs) continue;
    snell::gpu::Runtime* runtime = snell_parity::parityRuntimes()[i].get();
    const std::string suite = "PropertyGpu_" + runtime->name();
    for (const snell_parity::CaseSpec& spec : snell_parity::registry())
      ::testing::RegisterTest(suite.c_str(), spec.function.c_str(), nullptr, nullptr, __FILE__, __LINE__,
                              [&spec, runtime]() -> ::testing::Test* {
                                return new snell_parity::PropertyGpuTest(&spec, runtime);
                              });
  }
  const int result = RUN_ALL_TESTS();
  snell_parity::releaseParityRuntimes();
  return result;
}
