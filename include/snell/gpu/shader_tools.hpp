// The shader tools of Debian's glslang-tools, spirv-tools and spirv-cross packages, as the HLSL, Vulkan and
// WebGPU runtimes call them: names looked up on PATH, or absolute paths.
//
//   snell::gpu::ShaderTools tools;                 // glslangValidator, spirv-val, spirv-cross on PATH
//   tools.glslangValidator = "/opt/glslang/bin/glslangValidator";
#pragma once

#include "error.hpp"
#include "process.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace snell::gpu {

struct ShaderTools {
  std::string glslangValidator = "glslangValidator";  // Debian: glslang-tools
  std::string spirvVal = "spirv-val";                 // Debian: spirv-tools
  std::string spirvCross = "spirv-cross";             // Debian: spirv-cross
};

namespace detail {

// glslang -V (Vulkan 1.1 SPIR-V) with `options` and the include directories, then spirv-val: the
// Vulkan and WebGPU parity runtimes compile their compute shaders this way. Throws with the tool's
// output on failure.
inline void compileVulkanSpirv(const ShaderTools& tools, const std::filesystem::path& source,
                               const std::filesystem::path& spv, std::vector<std::string> options,
                               const std::vector<std::filesystem::path>& includeDirs) {
  std::vector<std::string> args = {"-V", "--target-env", "vulkan1.1", "-o", spv.string()};
  args.insert(args.end(), options.begin(), options.end());
  for (const std::filesystem::path& d : includeDirs) args.push_back("-I" + d.string());
  args.push_back(source.string());
  ToolResult t = runTool(tools.glslangValidator, args, "glslang-tools");
  if (t.exitCode != 0)
    throw Error("glslangValidator -V failed on " + source.string() + " (exit " + std::to_string(t.exitCode) + "):\n" +
                indent(t.output));
  t = runTool(tools.spirvVal, {"--target-env", "vulkan1.1", spv.string()}, "spirv-tools");
  if (t.exitCode != 0) throw Error("spirv-val rejected " + spv.string() + ":\n" + indent(t.output));
}

}  // namespace detail

}  // namespace snell::gpu
