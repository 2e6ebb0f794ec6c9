// The HLSL runtime: the case file through snell's HLSL bridge (hlsl_like/snell/bridge.hlsl) in an HLSL
// compute shader, compiled by glslang's HLSL front end to SPIR-V, validated, cross-compiled to GLSL 450 by
// spirv-cross and run on a GL backend (hlsl.hpp: runParityHlsl). The way an HLSL engine gets snell, executed.
#pragma once

#include "../hlsl.hpp"
#include "../runtime.hpp"
#include "gl.hpp"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace snell::gpu {

class HlslRuntime final : public Runtime {
 public:
  // defines: "NAME VALUE" before the bridge, e.g. {"SNELL_HLSL_FLIP_V 1"} for D3D-oriented textures.
  explicit HlslRuntime(const RuntimeSetup& setup, std::vector<std::string> defines = {})
      : setup_(setup), defines_(std::move(defines)), gl_(Backend::OSMesa, setup) {}
  std::string name() const override { return "hlsl"; }
  std::string describe() const override { return "HLSL (glslang, SPIR-V, spirv-cross GLSL 450) on OSMesa"; }
  std::string needs() const override { return "Debian glslang-tools, spirv-tools, spirv-cross; " + gl_.needs(); }
  std::vector<ParityIO> run(const RuntimeCase& c, const std::vector<ParityIO>& inputs) override {
    std::vector<std::filesystem::path> dirs = {setup_.hlslDir / "snell"};
    dirs.insert(dirs.end(), c.includeDirs.begin(), c.includeDirs.end());
    return runParityHlsl(gl_.context(), dirs, c.caseFile, c.entry, inputs, c.textures, setup_.workDir / "hlsl",
                         setup_.shaderTools, defines_, c.entrySource);
  }
  std::string renderer() override { return gl_.renderer(); }
  void release() override { gl_.release(); }

 private:
  RuntimeSetup setup_;
  std::vector<std::string> defines_;
  GlRuntime gl_;
};

}  // namespace snell::gpu
