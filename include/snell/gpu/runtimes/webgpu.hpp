// The WebGPU runtime: the case file as Vulkan GLSL, compiled by glslang -V to SPIR-V, translated to WGSL by
// naga and run as a compute shader on Deno's WebGPU (wgpu on lavapipe on the test machines), the WGSL also
// compiled by Tint (parity_webgpu.hpp). The way a WebGPU engine gets snell. Source tree only: it runs
// tools/webgpu with its npm packages (npm ci --prefix tools/webgpu, which scripts/install-deps.sh runs).
#pragma once

#include "../parity_webgpu.hpp"
#include "../runtime.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace snell::gpu {

class WebGpuRuntime final : public Runtime {
 public:
  explicit WebGpuRuntime(const RuntimeSetup& setup) : setup_(setup) {
    tools_.toolsDir = setup.sourceDir / "tools" / "webgpu";
    tools_.deno = (tools_.toolsDir / "node_modules" / "@deno" / "linux-x64-glibc" / "deno").string();
    tools_.node = setup.node;
    tools_.chromium = setup.chromium;
  }
  std::string name() const override { return "webgpu"; }
  std::string describe() const override { return "WGSL (glslang -V, naga; Tint) on Deno's WebGPU"; }
  std::string needs() const override {
    return "npm deno, naga-wasm and webgpu (npm ci --prefix tools/webgpu), Node.js, Debian glslang-tools, "
           "spirv-tools, mesa-vulkan-drivers";
  }
  std::vector<ParityIO> run(const RuntimeCase& c, const std::vector<ParityIO>& inputs) override {
    return runParityWebGpu(tools_, c.includeDirs, c.caseFile, c.entry, inputs, c.textures, setup_.workDir / "webgpu",
                           setup_.shaderTools, c.entrySource, &adapter_);
  }
  std::string renderer() override { return adapter_.empty() ? "(known after its first run)" : adapter_; }
  const WebGpuTools& tools() const { return tools_; }

 private:
  RuntimeSetup setup_;
  WebGpuTools tools_;
  std::string adapter_;
};

}  // namespace snell::gpu
