// The Vulkan runtime: the case file as Vulkan GLSL, compiled by glslang -V to SPIR-V, validated and run as
// a compute shader on a Vulkan device (Mesa's lavapipe on the test machines; parity_vulkan.hpp). The way a
// Vulkan engine gets snell.
#pragma once

#include "../parity_vulkan.hpp"
#include "../runtime.hpp"
#include "../vulkan_compute.hpp"

#include <memory>
#include <string>
#include <vector>

namespace snell::gpu {

class VulkanRuntime final : public Runtime {
 public:
  explicit VulkanRuntime(const RuntimeSetup& setup) : setup_(setup) {}
  std::string name() const override { return "vulkan"; }
  std::string describe() const override { return "Vulkan GLSL (glslang -V, SPIR-V) on a Vulkan device"; }
  std::string needs() const override {
    return "Debian libvulkan1 and mesa-vulkan-drivers (lavapipe), glslang-tools, spirv-tools";
  }
  std::vector<ParityIO> run(const RuntimeCase& c, const std::vector<ParityIO>& inputs) override {
    return runParityVulkan(device(), c.includeDirs, c.caseFile, c.entry, inputs, c.textures, setup_.workDir / "vulkan",
                           setup_.shaderTools, c.entrySource);
  }
  std::string renderer() override { return device().description(); }
  void release() override { device_.reset(); }

 private:
  VulkanCompute& device() {
    if (!device_) device_ = std::make_unique<VulkanCompute>();
    return *device_;
  }
  RuntimeSetup setup_;
  std::unique_ptr<VulkanCompute> device_;
};

}  // namespace snell::gpu
