// Every runtime (runtime.hpp), in the order the suites run them: the one list the parity suite, the GPU
// property test and your own parity test (makeRuntime) take them from. A new runtime is a class in a file
// of its own under runtimes/ and one entry here. Like the Vulkan runtime it includes, it needs the Vulkan
// headers (Debian libvulkan-dev); the Vulkan loader itself is opened at run time.
#pragma once

#include "error.hpp"
#include "runtime.hpp"
#include "runtimes/gl.hpp"
#include "runtimes/hlsl.hpp"
#include "runtimes/vulkan.hpp"

// The browser and Deno runtimes run the source tree's tools/ (not installed, and neither are their headers).
#if __has_include("runtimes/webgpu.hpp") && __has_include("parity_webgpu.hpp")
#include "runtimes/webgpu.hpp"
#define SNELL_GPU_HAS_WEBGPU_RUNTIME 1
#endif
#if __has_include("runtimes/webgl.hpp") && __has_include("parity_webgl.hpp")
#include "runtimes/webgl.hpp"
#define SNELL_GPU_HAS_WEBGL_RUNTIME 1
#endif

#include <memory>
#include <string>
#include <vector>

namespace snell::gpu {

struct RuntimeEntry {
  const char* name;
  std::unique_ptr<Runtime> (*make)(const RuntimeSetup&);
  // Whether the GPU property test also runs its hostile inputs there: no where another runtime already runs
  // the same compiled code on the same device (EGL: OSMesa's GLSL on llvmpipe; HLSL: its cross-compiled
  // GLSL on llvmpipe, whose parity runs cover it).
  bool hostileInputs;
};

inline const std::vector<RuntimeEntry>& runtimeList() {
  static const std::vector<RuntimeEntry> list = {
      {"osmesa", [](const RuntimeSetup& s) -> std::unique_ptr<Runtime> { return std::make_unique<GlRuntime>(Backend::OSMesa, s); }, true},
      {"egl", [](const RuntimeSetup& s) -> std::unique_ptr<Runtime> { return std::make_unique<GlRuntime>(Backend::EGL, s); }, false},
      {"hlsl", [](const RuntimeSetup& s) -> std::unique_ptr<Runtime> { return std::make_unique<HlslRuntime>(s); }, false},
      {"vulkan", [](const RuntimeSetup& s) -> std::unique_ptr<Runtime> { return std::make_unique<VulkanRuntime>(s); }, true},
#ifdef SNELL_GPU_HAS_WEBGPU_RUNTIME
      {"webgpu", [](const RuntimeSetup& s) -> std::unique_ptr<Runtime> { return std::make_unique<WebGpuRuntime>(s); }, true},
#endif
#ifdef SNELL_GPU_HAS_WEBGL_RUNTIME
      {"webgl2", [](const RuntimeSetup& s) -> std::unique_ptr<Runtime> { return std::make_unique<WebGlRuntime>(s); }, true},
#endif
  };
  return list;
}

// "osmesa, egl, hlsl, vulkan, webgpu, webgl2": for usage messages.
inline std::string runtimeNames() {
  std::string names;
  for (const RuntimeEntry& e : runtimeList()) names += (names.empty() ? "" : ", ") + std::string(e.name);
  return names;
}

// The runtime called `name`; an Error listing the names when there is none.
inline std::unique_ptr<Runtime> makeRuntime(const std::string& name, const RuntimeSetup& setup) {
  for (const RuntimeEntry& e : runtimeList())
    if (name == e.name) return e.make(setup);
  throw Error("no runtime '" + name + "' (runtimes: " + runtimeNames() + ")");
}

}  // namespace snell::gpu
