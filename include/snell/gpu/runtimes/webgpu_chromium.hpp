// WGSL on Chromium's WebGPU (Dawn: Tint compiles it, SwiftShader runs it here): the WebGPU runtime's WGSL of a
// case executed a second time, by the other major WGSL implementation. Not in runtimeList(): the parity suite
// runs it on a few cases (a browser per case costs more than the case), as a smoke run. Source tree only.
#pragma once

#include "../parity_webgpu.hpp"
#include "../runtime.hpp"
#include "webgpu.hpp"

#include <string>
#include <vector>

namespace snell::gpu {

class WebGpuChromiumRuntime final : public Runtime {
 public:
  explicit WebGpuChromiumRuntime(const RuntimeSetup& setup) : setup_(setup), webgpu_(setup) {}
  std::string name() const override { return "webgpu-chromium"; }
  std::string describe() const override { return "WGSL (glslang -V, naga) on Chromium's WebGPU (Dawn, Tint)"; }
  std::string needs() const override { return webgpu_.needs() + ", Debian chromium"; }
  bool flushesDenormals() const override { return true; }  // SwiftShader
  std::vector<ParityIO> run(const RuntimeCase& c, const std::vector<ParityIO>& inputs) override {
    const std::filesystem::path work = setup_.workDir / "webgpu_chromium";
    runParityWebGpu(webgpu_.tools(), c.includeDirs, c.caseFile, c.entry, inputs, c.textures, work, setup_.shaderTools,
                    c.entrySource);
    return runParityWebGpuInChromium(webgpu_.tools(), work, c.caseFile, c.entry, inputs.size(), &adapter_);
  }
  std::string renderer() override { return adapter_.empty() ? "(known after its first run)" : adapter_; }

 private:
  RuntimeSetup setup_;
  WebGpuRuntime webgpu_;
  std::string adapter_;
};

}  // namespace snell::gpu
