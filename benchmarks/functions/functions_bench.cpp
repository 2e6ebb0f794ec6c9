// Calls/s of every public function's C++ build, table-driven from the parity
// case registry (tests/parity/*_cases.cpp, the snell_parity_cases object
// library; no GL context needed): one benchmark per registered case,
// "BM_Function/<family>/<function>", cycling through the case's own inputs
// (10-12k each: realistic ranges with a few per cent of edge cases, hostile
// values among them, so early outs are in the mix as they are in the tests).
//
// Each call goes through the case entry (unpack four vec4s, call, pack the
// result) and a std::function: a few ns that dominate the cheapest functions
// (snellIorToEta, snellPixelToUv); compare those by order of magnitude only.
// For the intersect/ and shade/ functions the entry's cost is the function's.
// A new public function gets its benchmark with its parity case.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "parity_registry.hpp"

namespace {

using snell_parity::CaseSpec;
using snell_parity::ParityIO;

std::string family(const std::string& glslFile) {
  const std::size_t dot = glslFile.rfind('.');
  return dot == std::string::npos ? glslFile : glslFile.substr(0, dot);
}

void runCase(benchmark::State& state, const CaseSpec* spec, const std::vector<ParityIO>* inputs) {
  std::size_t i = 0;
  const std::size_t n = inputs->size();
  for (auto _ : state) {
    ParityIO out = spec->cpu((*inputs)[i]);
    benchmark::DoNotOptimize(out);
    if (++i == n) i = 0;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  state.counters["inputs"] = static_cast<double>(n);
}

}  // namespace

int main(int argc, char** argv) {
  // The cases register themselves during static initialisation of the other
  // translation units, so the benchmarks are registered here, after it.
  static std::vector<std::vector<ParityIO>> inputs;
  std::vector<CaseSpec>& cases = snell_parity::registry();
  inputs.reserve(cases.size());
  for (CaseSpec& spec : cases) {
    if (spec.setup) spec.setup();  // fills the textures the case samples
    inputs.push_back(spec.inputs());
    if (inputs.back().empty()) continue;
    const std::string name = "BM_Function/" + family(spec.glslFile) + "/" + spec.function;
    benchmark::RegisterBenchmark(name.c_str(), runCase, &spec, &inputs.back());
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
