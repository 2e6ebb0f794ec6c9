// The runtimes every parity case runs on, shared by the parity suite (parity_main.cpp) and the GPU property
// test (tests/property): snell::gpu's own list (runtime_list.hpp), set up with this build's tools and
// folders. A new runtime is a class in include/snell/gpu/runtimes/ and an entry in that list; nothing here.
#pragma once

#include <snell/gpu/runtime_list.hpp>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "parity_registry.hpp"

namespace snell_parity {

namespace fs = std::filesystem;

inline const fs::path kRoot = SNELL_SOURCE_DIR;

// The shader tools and the folder for the jobs' files (set by tests/CMakeLists.txt; PATH names and a temp
// folder otherwise).
#ifndef SNELL_GLSLANG_VALIDATOR
#define SNELL_GLSLANG_VALIDATOR "glslangValidator"
#endif
#ifndef SNELL_SPIRV_VAL
#define SNELL_SPIRV_VAL "spirv-val"
#endif
#ifndef SNELL_SPIRV_CROSS
#define SNELL_SPIRV_CROSS "spirv-cross"
#endif
inline snell::gpu::RuntimeSetup runtimeSetup() {
  snell::gpu::RuntimeSetup s;
#ifdef SNELL_HLSL_WORK_DIR
  s.workDir = SNELL_HLSL_WORK_DIR;
#else
  s.workDir = fs::temp_directory_path() / "snell_parity_jobs";
#endif
  s.shaderTools.glslangValidator = SNELL_GLSLANG_VALIDATOR;
  s.shaderTools.spirvVal = SNELL_SPIRV_VAL;
  s.shaderTools.spirvCross = SNELL_SPIRV_CROSS;
  s.hlslDir = kRoot / "hlsl_like";
  s.sourceDir = kRoot;
  return s;
}

// A case as the runtimes run it: snell's GLSL and the case files on the include path.
inline snell::gpu::RuntimeCase runtimeCase(const CaseSpec& spec) {
  return {{kRoot / "glsl", kRoot / "tests" / "parity" / "cases"}, spec.glslFile, spec.entry, spec.textures,
          spec.entrySource};
}

// Every runtime of the list, made once for the run: its device (a GL context, a Vulkan device) is created
// on first use and kept, since creating one costs more than most cases.
inline const std::vector<std::unique_ptr<snell::gpu::Runtime>>& parityRuntimes() {
  static const std::vector<std::unique_ptr<snell::gpu::Runtime>> all = [] {
    std::vector<std::unique_ptr<snell::gpu::Runtime>> r;
    for (const snell::gpu::RuntimeEntry& e : snell::gpu::runtimeList()) r.push_back(e.make(runtimeSetup()));
    return r;
  }();
  return all;
}

// A runtime's gtest suites: Parity_<name> here, PropertyGpu_<name> in the property test.
inline std::string paritySuite(const snell::gpu::Runtime& r) { return "Parity_" + r.name(); }

// Releases the runtimes' devices and contexts; main() calls it before exit: destroying them from static
// destructors races Mesa's own exit-time teardown.
inline void releaseParityRuntimes() {
  for (const auto& r : parityRuntimes()) r->release();
}

}  // namespace snell_parity
