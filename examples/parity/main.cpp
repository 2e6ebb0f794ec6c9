// Test your own function the way snell tests its own: the case file runs on a GPU runtime (GLSL on Mesa's
// llvmpipe through OSMesa by default, no GPU needed; or any runtime of snell::gpu::runtimeList() by name) and
// in C++ on the same 10,000 inputs, and compareParity reports every case that differs.
//   my_parity [--runtime=NAME] [--deliberate-mismatch]   exit 0: every case agrees, 1: a mismatch, 2: usage
//   my_parity --runtimes                                  the names, one per line
#include <snell/gpu/runtime_list.hpp>
#include <snell/snell.hpp>

#include <cstdio>
#include <cstring>
#include <exception>
#include <random>
#include <string>
#include <vector>

// The same case file, compiled as C++ (SnellParityOut is snell::gpu's twin).
namespace mine {
using namespace snell;
using snell::gpu::SnellParityOut;
#include "my_cases.glsl"
}  // namespace mine

int main(int argc, char** argv) {
  using snell::gpu::ParityIO;
  std::string runtimeName = "osmesa";
  bool deliberateMismatch = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--runtimes") == 0) {
      for (const snell::gpu::RuntimeEntry& e : snell::gpu::runtimeList()) std::printf("%s\n", e.name);
      return 0;
    } else if (std::strncmp(argv[i], "--runtime=", 10) == 0) {
      runtimeName = argv[i] + 10;
    } else if (std::strcmp(argv[i], "--deliberate-mismatch") == 0) {
      deliberateMismatch = true;
    } else {
      std::fprintf(stderr, "my_parity: unknown argument '%s'\nusage: my_parity [--runtime=NAME] "
                   "[--deliberate-mismatch] | --runtimes   (runtimes: %s)\n", argv[i], snell::gpu::runtimeNames().c_str());
      return 2;
    }
  }
  // Inputs: directions towards the surface, normals, IORs; a few hostile ones too.
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), ior(1.0f, 2.5f);
  std::vector<ParityIO> inputs(10000);
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    ParityIO& in = inputs[k];
    in.v[0] = glm::vec4(u(rng), u(rng), -1.0f, 0.0f);
    in.v[1] = glm::vec4(u(rng) * 0.3f, u(rng) * 0.3f, 1.0f, 0.0f);
    in.v[2] = glm::vec4(ior(rng), 0.0f, 0.0f, 0.0f);
    if (k % 100 == 0) in.v[1] = glm::vec4(0.0f);  // a zero normal: the contract's 0
  }
  std::vector<ParityIO> cpu;
  for (const ParityIO& in : inputs)
    cpu.push_back(snell::gpu::toParityIO(mine::caseMyTransmittance(in.v[0], in.v[1], in.v[2], in.v[3])));
  if (deliberateMismatch) cpu[42].v[0].x *= 1.001f;  // what a real disagreement looks like

  snell::gpu::RuntimeSetup setup;
  setup.workDir = MY_WORK_DIR;          // the jobs' shaders, inputs and results
  setup.hlslDir = SNELL_HLSL_DIR;       // the HLSL runtime's bridge
  setup.sourceDir = MY_SNELL_SOURCE;    // a source tree's tools/: the WebGPU and WebGL 2 runtimes
  try {
    std::unique_ptr<snell::gpu::Runtime> runtime = snell::gpu::makeRuntime(runtimeName, setup);
    const std::vector<ParityIO> gpu = runtime->run({{SNELL_GLSL_DIR, MY_SHADER_DIR}, "my_cases.glsl", "caseMyTransmittance"},
                                                   inputs);
    // Output float 0, within 1e-6 + 1e-5 |cpu|.
    const snell::gpu::ParityReport r =
        snell::gpu::compareParity(gpu, cpu, {{0, "transmittance", false, 1e-6f, 1e-5f}}, &inputs);
    std::printf("my_parity: %s: %zu cases, %zu mismatches, largest |diff| %g on %s\n", runtime->name().c_str(), r.cases,
                r.mismatches, static_cast<double>(r.maxAbs), runtime->renderer().c_str());
    if (!r.ok()) std::printf("first mismatch: %s\n", r.firstMismatchText.c_str());
    runtime->release();
    return r.ok() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "my_parity: %s\n", e.what());
    return 3;
  }
}
