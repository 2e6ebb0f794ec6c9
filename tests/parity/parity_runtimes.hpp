// The runtimes every parity case runs on, shared by the parity suite
// (parity_main.cpp) and the GPU property test (tests/property): GLSL on each
// GL backend, HLSL cross-compiled through SPIR-V, Vulkan GLSL on a Vulkan
// device, WGSL on a WebGPU device. A new runtime (WebGL 2) is one more
// ParityRuntime here.
#pragma once

#include <snell/gpu/context.hpp>
#include <snell/gpu/hlsl.hpp>
#include <snell/gpu/parity.hpp>
#include <snell/gpu/parity_vulkan.hpp>
#include <snell/gpu/parity_webgl.hpp>
#include <snell/gpu/parity_webgpu.hpp>

#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "parity_registry.hpp"

namespace snell_parity {

namespace fs = std::filesystem;
using snell::gpu::Backend;
using snell::gpu::Context;

inline const fs::path kRoot = SNELL_SOURCE_DIR;

// The HLSL tools and the folder for the cross-compiled artifacts (set by
// tests/CMakeLists.txt; PATH names and a temp folder otherwise).
#ifndef SNELL_GLSLANG_VALIDATOR
#define SNELL_GLSLANG_VALIDATOR "glslangValidator"
#endif
#ifndef SNELL_SPIRV_VAL
#define SNELL_SPIRV_VAL "spirv-val"
#endif
#ifndef SNELL_SPIRV_CROSS
#define SNELL_SPIRV_CROSS "spirv-cross"
#endif
inline snell::gpu::ShaderTools hlslTools() {
  snell::gpu::ShaderTools t;
  t.glslangValidator = SNELL_GLSLANG_VALIDATOR;
  t.spirvVal = SNELL_SPIRV_VAL;
  t.spirvCross = SNELL_SPIRV_CROSS;
  return t;
}
inline fs::path hlslWorkDir() {
#ifdef SNELL_HLSL_WORK_DIR
  return SNELL_HLSL_WORK_DIR;
#else
  return fs::temp_directory_path() / "snell_hlsl_parity";
#endif
}
constexpr Backend kHlslBackend = Backend::OSMesa;  // one backend is enough for HLSL

// One context per backend for the whole run: creating one costs more than most
// cases. Released by main() before exit: destroying a context from a static
// destructor races Mesa's own exit-time teardown.
inline std::map<Backend, std::unique_ptr<Context>>& contexts() {
  static std::map<Backend, std::unique_ptr<Context>> all;
  return all;
}

inline Context& contextFor(Backend backend) {
  auto& slot = contexts()[backend];
  if (!slot) slot = std::make_unique<Context>(backend);
  slot->makeCurrent();
  return *slot;
}

// A runtime the parity cases run on: it runs a case's entry on the case's
// inputs and returns what the GPU wrote. Every case runs on every runtime of
// parityRuntimes(); a new runtime (Vulkan, WebGPU, WebGL 2) is one more
// implementation there, and no case changes.
class ParityRuntime {
 public:
  virtual ~ParityRuntime() = default;
  virtual std::string suite() const = 0;  // the gtest suite of its runs: "Parity_osmesa"
  virtual std::string tag() const = 0;    // the report line's prefix: "[parity]"
  virtual std::string where() const = 0;  // the report's backend= field: "osmesa", "vulkan"
  virtual std::vector<ParityIO> run(const CaseSpec& spec, const std::vector<ParityIO>& inputs) const = 0;
};

// The case file as GLSL, on one GL backend.
class GlslRuntime final : public ParityRuntime {
 public:
  explicit GlslRuntime(Backend backend) : backend_(backend) {}
  std::string suite() const override { return std::string("Parity_") + snell::gpu::backendName(backend_); }
  std::string tag() const override { return "[parity]"; }
  std::string where() const override { return snell::gpu::backendName(backend_); }
  std::vector<ParityIO> run(const CaseSpec& spec, const std::vector<ParityIO>& inputs) const override {
    return snell::gpu::runParityGpu(contextFor(backend_), {kRoot / "glsl", kRoot / "tests" / "parity" / "cases"},
                                    spec.glslFile, spec.entry, inputs, spec.textures, spec.entrySource);
  }

 private:
  Backend backend_;
};

// The case file through the HLSL bridge, cross-compiled to GLSL 450.
class HlslRuntime final : public ParityRuntime {
 public:
  std::string suite() const override { return std::string("ParityHlsl_") + snell::gpu::backendName(kHlslBackend); }
  std::string tag() const override { return "[parity-hlsl]"; }
  std::string where() const override { return snell::gpu::backendName(kHlslBackend); }
  std::vector<ParityIO> run(const CaseSpec& spec, const std::vector<ParityIO>& inputs) const override {
    return snell::gpu::runParityHlsl(
        contextFor(kHlslBackend), {kRoot / "hlsl_like" / "snell", kRoot / "glsl", kRoot / "tests" / "parity" / "cases"},
        spec.glslFile, spec.entry, inputs, spec.textures, hlslWorkDir(), hlslTools(), {}, spec.entrySource);
  }
};

// The one Vulkan device of the run (lavapipe on the test machines): created on
// first use, released by main() before exit like the GL contexts. No device is
// a failure of every Vulkan case, naming what is missing.
inline std::unique_ptr<snell::gpu::VulkanCompute>& vulkanDevice() {
  static std::unique_ptr<snell::gpu::VulkanCompute> device;
  return device;
}

// The case file as Vulkan GLSL: glslang -V to SPIR-V, run as compute on the Vulkan device.
class VulkanRuntime final : public ParityRuntime {
 public:
  std::string suite() const override { return "ParityVulkan"; }
  std::string tag() const override { return "[parity-vulkan]"; }
  std::string where() const override { return "vulkan"; }
  std::vector<ParityIO> run(const CaseSpec& spec, const std::vector<ParityIO>& inputs) const override {
    auto& device = vulkanDevice();
    if (!device) {
      device = std::make_unique<snell::gpu::VulkanCompute>();
      std::cout << "[parity-vulkan] device: " << device->description() << "\n";
    }
    return snell::gpu::runParityVulkan(*device, {kRoot / "glsl", kRoot / "tests" / "parity" / "cases"}, spec.glslFile,
                                       spec.entry, inputs, spec.textures, hlslWorkDir() / "vulkan", hlslTools(),
                                       spec.entrySource);
  }
};

// The WebGPU runtime's tools (tools/webgpu, its npm packages installed by scripts/install-deps.sh).
#ifndef SNELL_WEBGPU_TOOLS_DIR
#define SNELL_WEBGPU_TOOLS_DIR SNELL_SOURCE_DIR "/tools/webgpu"
#endif
inline snell::gpu::WebGpuTools webGpuTools() {
  snell::gpu::WebGpuTools t;
  t.toolsDir = SNELL_WEBGPU_TOOLS_DIR;
  t.deno = (t.toolsDir / "node_modules" / "@deno" / "linux-x64-glibc" / "deno").string();
  return t;
}

// The case file as WGSL (glslang -V, naga), run as compute on Deno's WebGPU (lavapipe here).
class WebGpuRuntime final : public ParityRuntime {
 public:
  std::string suite() const override { return "ParityWebGpu"; }
  std::string tag() const override { return "[parity-webgpu]"; }
  std::string where() const override { return "webgpu"; }
  std::vector<ParityIO> run(const CaseSpec& spec, const std::vector<ParityIO>& inputs) const override {
    return snell::gpu::runParityWebGpu(webGpuTools(), {kRoot / "glsl", kRoot / "tests" / "parity" / "cases"},
                                       spec.glslFile, spec.entry, inputs, spec.textures, hlslWorkDir() / "webgpu",
                                       hlslTools(), spec.entrySource);
  }
};

// The WebGL 2 runtime's tools: tools/webgl, Node.js and Chromium from PATH.
#ifndef SNELL_WEBGL_TOOLS_DIR
#define SNELL_WEBGL_TOOLS_DIR SNELL_SOURCE_DIR "/tools/webgl"
#endif
inline snell::gpu::WebGlTools webGlTools() {
  snell::gpu::WebGlTools t;
  t.toolsDir = SNELL_WEBGL_TOOLS_DIR;
  return t;
}

// The case file as an ES 3.00 fragment shader in headless Chromium's WebGL 2
// (ANGLE on SwiftShader here). The renderer string is printed once per run.
class WebGlRuntime final : public ParityRuntime {
 public:
  std::string suite() const override { return "ParityWebGl"; }
  std::string tag() const override { return "[parity-webgl]"; }
  std::string where() const override { return "webgl2"; }
  std::vector<ParityIO> run(const CaseSpec& spec, const std::vector<ParityIO>& inputs) const override {
    std::string renderer;
    std::vector<ParityIO> out = snell::gpu::runParityWebGl(
        webGlTools(), {kRoot / "glsl", kRoot / "tests" / "parity" / "cases"}, spec.glslFile, spec.entry, inputs,
        spec.textures, hlslWorkDir() / "webgl", spec.entrySource, &renderer);
    static bool printed = false;
    if (!printed) std::cout << "[parity-webgl] renderer: " << renderer << "\n";
    printed = true;
    return out;
  }
};

// Every runtime, in the order their suites run.
inline const std::vector<std::unique_ptr<ParityRuntime>>& parityRuntimes() {
  static const std::vector<std::unique_ptr<ParityRuntime>> all = [] {
    std::vector<std::unique_ptr<ParityRuntime>> r;
    for (Backend backend : snell::gpu::kGlBackends) r.push_back(std::make_unique<GlslRuntime>(backend));
    r.push_back(std::make_unique<HlslRuntime>());
    r.push_back(std::make_unique<VulkanRuntime>());
    r.push_back(std::make_unique<WebGpuRuntime>());
    r.push_back(std::make_unique<WebGlRuntime>());
    return r;
  }();
  return all;
}

// Releases the runtimes' devices and contexts; main() calls it before exit:
// destroying them from static destructors races Mesa's own exit-time teardown.
inline void releaseParityRuntimes() {
  vulkanDevice().reset();
  contexts().clear();
}

}  // namespace snell_parity
