// The parity runner on Vulkan: a case file's entry compiled by glslang to
// SPIR-V (-V, Vulkan GLSL 450, the way a Vulkan engine compiles snell),
// validated by spirv-val, its samplers bound where glslang's automatic
// binding put them (read back with spirv-cross --reflect), and run as compute
// on a VulkanCompute device (lavapipe in the test suite) over the same inputs
// and textures as runParityGpu. The differences from the GL shader are
// Vulkan's own: the case count is a push constant, and the samplers the case
// file declares without a binding get one from glslang (--auto-map-bindings,
// shifted past the two storage buffers).
#pragma once

#include "parity_job.hpp"
#include "process.hpp"
#include "shader_tools.hpp"
#include "parity.hpp"
#include "vulkan_compute.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

namespace snell::gpu {

// Samplers get bindings from here on; 0 and 1 are the input and result buffers.
constexpr std::uint32_t kParityVulkanFirstSampler = 16;

namespace detail {

// The live samplers of a SPIR-V module and their bindings, from spirv-cross
// --reflect: glslang leaves the ones the entry never reads at binding 0.
inline std::map<std::string, std::uint32_t> liveSamplerBindings(const std::string& reflectJson) {
  std::map<std::string, std::uint32_t> out;
  const std::size_t textures = reflectJson.find("\"textures\"");
  if (textures == std::string::npos) return out;
  const std::size_t end = reflectJson.find(']', textures);
  const std::string block = reflectJson.substr(textures, end == std::string::npos ? std::string::npos : end - textures);
  static const std::regex entry(R"re("name"\s*:\s*"(\w+)"[^}]*?"binding"\s*:\s*(\d+))re");
  for (auto it = std::sregex_iterator(block.begin(), block.end(), entry); it != std::sregex_iterator(); ++it) {
    const std::uint32_t binding = static_cast<std::uint32_t>(std::stoul((*it)[2].str()));
    if (binding >= kParityVulkanFirstSampler) out[(*it)[1].str()] = binding;
  }
  return out;
}

inline std::vector<std::uint32_t> readSpirv(const std::filesystem::path& file) {
  const std::string bytes = readTextFile(file);
  if (bytes.empty() || bytes.size() % 4 != 0) throw Error("not a SPIR-V module: " + file.string());
  std::vector<std::uint32_t> words(bytes.size() / 4);
  std::memcpy(words.data(), bytes.data(), bytes.size());
  return words;
}

}  // namespace detail

// Runs `entry` of `caseFile` (found through includeDirs) on every input on `vk`.
// The SPIR-V and its reflection are left in workDir (name: case file stem and entry).
inline std::vector<ParityIO> runParityVulkan(const VulkanCompute& vk, const std::vector<std::filesystem::path>& includeDirs,
                                             const std::string& caseFile, const std::string& entry,
                                             const std::vector<ParityIO>& inputs,
                                             const std::vector<ParityTexture>& textures,
                                             const std::filesystem::path& workDir, const ShaderTools& tools = {},
                                             const std::string& entrySource = {}) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(workDir, ec);
  if (ec) throw Error("runParityVulkan: cannot create " + workDir.string() + ": " + ec.message());
  const std::string name = fs::path(caseFile).stem().string() + "." + entry;
  const fs::path source = workDir / (name + ".comp"), spv = workDir / (name + ".spv"),
                 reflect = workDir / (name + ".json");
  detail::writeTextFile(source, parityShaderSource(caseFile, entry, entrySource, ParityDialect::Vulkan));
  detail::compileVulkanSpirv(tools, source, spv,
                             {"--auto-map-bindings", "--shift-texture-binding", std::to_string(kParityVulkanFirstSampler)},
                             includeDirs);
  ToolResult t = runTool(tools.spirvCross, {spv.string(), "--reflect", "--output", reflect.string()}, "spirv-cross");
  if (t.exitCode != 0) throw Error("spirv-cross --reflect failed on " + spv.string() + ":\n" + detail::indent(t.output));
  const std::map<std::string, std::uint32_t> samplers = detail::liveSamplerBindings(detail::readTextFile(reflect));

  // The live samplers' images, each from the case texture of that name.
  std::vector<std::unique_ptr<VulkanCompute::Image>> images;
  std::vector<VulkanCompute::Binding> imageBindings;
  for (const auto& [uniform, binding] : samplers) {
    const ParityTexture* found = nullptr;
    for (const ParityTexture& pt : textures)
      if (pt.uniform == uniform) found = &pt;
    if (found == nullptr || found->texture == nullptr)
      throw Error("runParityVulkan: " + source.string() + " samples '" + uniform + "', which names none of the case's textures");
    images.push_back(std::make_unique<VulkanCompute::Image>(vk, *found->texture));
    imageBindings.push_back({binding, nullptr, images.back().get()});
  }

  const std::vector<std::uint32_t> words = detail::readSpirv(spv);
  std::vector<VulkanCompute::Binding> layout = {{0, nullptr, nullptr}, {1, nullptr, nullptr}};
  layout.insert(layout.end(), imageBindings.begin(), imageBindings.end());
  // Layout only: the descriptor types come from whether a binding holds an image.
  const VulkanCompute::Pipeline pipeline(vk, words, layout, sizeof(std::int32_t));

  const std::size_t byGroups = static_cast<std::size_t>(vk.limits().maxComputeWorkGroupCount[0]) * kParityLocalSize;
  const std::size_t byBytes = static_cast<std::size_t>(vk.limits().maxStorageBufferRange) / sizeof(ParityIO);
  const std::size_t chunk = std::max<std::size_t>(1, std::min(byGroups, byBytes));
  std::vector<ParityIO> out(inputs.size());
  for (std::size_t first = 0; first < inputs.size(); first += chunk) {
    const std::size_t n = std::min(chunk, inputs.size() - first);
    const VulkanCompute::Buffer in(vk, n * sizeof(ParityIO), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    const VulkanCompute::Buffer result(vk, n * sizeof(ParityIO), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    std::memcpy(in.data(), inputs.data() + first, n * sizeof(ParityIO));
    std::memset(result.data(), 0, n * sizeof(ParityIO));
    std::vector<VulkanCompute::Binding> bindings = {{0, &in, nullptr}, {1, &result, nullptr}};
    bindings.insert(bindings.end(), imageBindings.begin(), imageBindings.end());
    const std::int32_t count = static_cast<std::int32_t>(n);
    std::vector<std::uint8_t> push(sizeof count);
    std::memcpy(push.data(), &count, sizeof count);
    pipeline.run(bindings, push, static_cast<std::uint32_t>((n + kParityLocalSize - 1) / kParityLocalSize));
    std::memcpy(out.data() + first, result.data(), n * sizeof(ParityIO));
  }
  return out;
}

}  // namespace snell::gpu
