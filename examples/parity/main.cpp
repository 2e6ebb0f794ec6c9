// Test your own function the way snell tests its own: the case file runs on
// the GPU (Mesa's llvmpipe through OSMesa here, no GPU needed) and in C++ on
// the same 10,000 inputs, and compareParity reports every case that differs.
//   my_parity [--deliberate-mismatch]   exit 0: every case agrees
#include <snell/gpu/context.hpp>
#include <snell/gpu/parity.hpp>
#include <snell/snell.hpp>

#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

// The same case file, compiled as C++ (SnellParityOut is snell::gpu's twin).
namespace mine {
using namespace snell;
using snell::gpu::SnellParityOut;
#include "my_cases.glsl"
}  // namespace mine

int main(int argc, char** argv) {
  using snell::gpu::ParityIO;
  const bool deliberateMismatch = argc > 1 && std::strcmp(argv[1], "--deliberate-mismatch") == 0;
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

  snell::gpu::Context ctx(snell::gpu::Backend::OSMesa);
  const std::vector<ParityIO> gpu =
      snell::gpu::runParityGpu(ctx, {SNELL_GLSL_DIR, MY_SHADER_DIR}, "my_cases.glsl", "caseMyTransmittance", inputs);
  // Output float 0, within 1e-6 + 1e-5 |cpu|.
  const snell::gpu::ParityReport r =
      snell::gpu::compareParity(gpu, cpu, {{0, "transmittance", false, 1e-6f, 1e-5f}}, &inputs);
  std::printf("my_parity: %zu cases, %zu mismatches, largest |diff| %g on %s\n", r.cases, r.mismatches,
              static_cast<double>(r.maxAbs), ctx.renderer().c_str());
  if (!r.ok()) std::printf("first mismatch: %s\n", r.firstMismatchText.c_str());
  return r.ok() ? 0 : 1;
}
