// The GLSL runtime: the case file as GLSL 450 core, flattened by snell's include flattener and given to the
// driver with glShaderSource, run as a compute shader on one GL backend (OSMesa or EGL: Mesa's llvmpipe on
// the test machines). The way a GL engine gets snell.
#pragma once

#include "../context.hpp"
#include "../parity.hpp"
#include "../runtime.hpp"

#include <memory>
#include <string>
#include <vector>

namespace snell::gpu {

class GlRuntime final : public Runtime {
 public:
  GlRuntime(Backend backend, const RuntimeSetup&) : backend_(backend) {}
  std::string name() const override { return backendName(backend_); }
  std::string describe() const override {
    return std::string("GLSL 450 on ") + (backend_ == Backend::EGL ? "EGL (surfaceless)" : "OSMesa");
  }
  std::string needs() const override {
    return backend_ == Backend::EGL ? "Debian libegl1, libegl-mesa0 and libgl1-mesa-dri (llvmpipe)"
                                    : "Debian libosmesa6 (llvmpipe)";
  }
  std::vector<ParityIO> run(const RuntimeCase& c, const std::vector<ParityIO>& inputs) override {
    return runParityGpu(context(), c.includeDirs, c.caseFile, c.entry, inputs, c.textures, c.entrySource);
  }
  std::string renderer() override { return context().renderer() + ", " + context().version(); }
  void release() override { context_.reset(); }
  // The context, created on first use and current on return (the HLSL runtime runs on one too).
  Context& context() {
    if (!context_) context_ = std::make_unique<Context>(backend_);
    context_->makeCurrent();
    return *context_;
  }

 private:
  Backend backend_;
  std::unique_ptr<Context> context_;
};

}  // namespace snell::gpu
