// What a runtime is, for the parity suite and for a parity test of your own: a language and a device that
// run a parity case file's entry on its inputs (parity.hpp) and return what the device wrote, to be
// compared with the C++ build (compareParity). One class per runtime, each in a file of its own under
// runtimes/, and one list of them (runtime_list.hpp):
//
//   snell::gpu::RuntimeSetup setup;                    // where the jobs' files go, the tools' names
//   setup.workDir = "build/parity_jobs";
//   std::unique_ptr<snell::gpu::Runtime> rt = snell::gpu::makeRuntime("vulkan", setup);
//   std::vector<snell::gpu::ParityIO> gpu = rt->run({{SNELL_GLSL_DIR, MY_SHADER_DIR}, "my_cases.glsl",
//                                                    "caseMyTransmittance"}, inputs);
//   std::printf("%s on %s\n", rt->name().c_str(), rt->renderer().c_str());
//
// A runtime whose tools or device are missing throws an Error naming what to install from the first run()
// or renderer(), never returns an empty result.
#pragma once

#include "parity.hpp"
#include "shader_tools.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace snell::gpu {

// A parity case as a runtime runs it: the case file (found through includeDirs, with snell's glsl/), its
// entry (SnellParityOut entry(vec4, vec4, vec4, vec4)), the textures it reads, and source after the case
// file (a generated entry), if any.
struct RuntimeCase {
  std::vector<std::filesystem::path> includeDirs;
  std::string caseFile;
  std::string entry;
  std::vector<ParityTexture> textures;
  std::string entrySource;
};

// What the runtimes need to know of the machine and the project.
struct RuntimeSetup {
  std::filesystem::path workDir;  // each job's files (shaders, inputs, results): a build folder
  ShaderTools shaderTools;        // glslangValidator, spirv-val, spirv-cross (names on PATH, or paths)
  std::filesystem::path hlslDir;  // snell's hlsl_like/ (SNELL_HLSL_DIR): the HLSL runtime's bridge
  // snell's source tree (its tools/ and their npm packages): the WebGPU and WebGL 2 runtimes run its
  // scripts. Those runtimes exist in a source tree only (their headers are not installed).
  std::filesystem::path sourceDir;
  std::string node = "node";          // Node.js: the browser runtimes' page server, Tint
  std::string chromium = "chromium";  // Debian's chromium
};

class Runtime {
 public:
  virtual ~Runtime() = default;
  // The name it is chosen by (makeRuntime, the suites' names: Parity_<name>, PropertyGpu_<name>).
  virtual std::string name() const = 0;
  // The language and the device, for a report: "GLSL 450 on OSMesa", "WGSL on Deno's WebGPU".
  virtual std::string describe() const = 0;
  // What it needs installed (Debian or npm packages), named in its errors too.
  virtual std::string needs() const = 0;
  // Whether its device flushes denormal floats to zero (the suite then also accepts a result that matches
  // the C++ build on the inputs with denormals flushed). Declared, and checked by the parity suite.
  virtual bool flushesDenormals() const { return false; }
  // Whether its compiler reassociates constants in an expression not declared precise, as GLSL allows
  // ((hi - x) - lo into (hi - lo) - x, which loses lo when hi - lo rounds to hi): an output whose case
  // allows for that (a condition-scaled tolerance) gets the allowance only there. Every compiler measured
  // does (the parity suite checks each declaration).
  virtual bool foldsConstants() const { return true; }
  // Compiles the case for its language and runs it on every input: one result per input.
  virtual std::vector<ParityIO> run(const RuntimeCase& c, const std::vector<ParityIO>& inputs) = 0;
  // What it runs on, from the device itself: the GL and Vulkan runtimes start their device to ask it; the
  // WebGPU and WebGL 2 runtimes, whose device lives in another process, know it after their first run().
  virtual std::string renderer() = 0;
  // Frees the device before exit (GL contexts and Vulkan devices must not be destroyed by static
  // destructors, which race Mesa's own teardown). The runtime starts it again if run once more.
  virtual void release() {}
};

}  // namespace snell::gpu
