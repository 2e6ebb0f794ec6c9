// The parity runner on WebGPU: a case file's entry as WGSL, run as compute on
// a WebGPU device (Deno's, wgpu on Mesa's lavapipe in the test suite). The
// way a WebGPU engine gets snell: Vulkan GLSL compiled by glslang to SPIR-V
// (validated by spirv-val) and translated to WGSL by naga; then the very
// inputs and textures of runParityGpu.
//
// What differs from the Vulkan shader, and why:
//   - tools/webgpu/snell_webgpu_prelude.glsl comes first: WGSL has no isnan or
//     isinf (bit tests instead);
//   - WGSL has no combined image samplers, and naga rejects a sampler2D passed
//     to a function: the case file is rewritten so each `uniform sampler2D
//     NAME;` becomes `const int NAME = k;` (a texture is its slot number,
//     SNELL_TEX2D is int) and the hooks pick texture k and its own sampler
//     (bindings 16 + 2k, 17 + 2k, with that texture's filters) by an if chain;
//   - the case count is a uniform at binding 2 (Deno's WebGPU has no push
//     constants).
// The device side is tools/webgpu/run_parity.ts (naga and the dispatch), and
// every WGSL also goes through Tint (tools/webgpu/tint_check.mjs, dawn.node's
// null backend): the npm packages deno, naga-wasm and webgpu, installed from
// tools/webgpu's lockfile. Each case starts a Deno and a Node process, or,
// when SNELL_WEBGPU_SERVER names the state folder of
// tools/webgpu/webgpu_servers.mjs (ctest does), asks the two servers that
// folder's sockets lead to. Source tree only: `cmake --install` leaves this
// header out, as it leaves out tools/.
#pragma once

#include "chromium_page.hpp"
#include "parity_job.hpp"
#include "process.hpp"
#include "shader_tools.hpp"
#include "parity.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace snell::gpu {

// Where the WebGPU runtime's tools are: the Deno binary (npm package
// @deno/linux-x64-glibc) and the directory of run_parity.ts,
// snell_webgpu_prelude.glsl and node_modules (tools/webgpu).
struct WebGpuTools {
  std::string deno;
  std::filesystem::path toolsDir;
  std::string node = "node";          // runs tint_check.mjs, and run_page.mjs for runParityWebGpuInChromium
  std::string chromium = "chromium";  // Debian's chromium: WebGPU on its SwiftShader adapter
};

constexpr int kParityWebGpuFirstTexture = 16;

namespace detail {

// The hooks for `slots` textures: a texture is its slot number.
inline std::string webGpuTextureHooks(std::size_t slots) {
  if (slots == 0) return {};
  std::string s = "#define SNELL_TEX2D int\n";
  s += "#define SNELL_SAMPLE_LOD(tex, uv, lod) snellWebgpuSampleLod(tex, uv, lod)\n";
  s += "#define SNELL_TEXEL_FETCH(tex, px, lod) snellWebgpuTexelFetch(tex, px, lod)\n";
  s += "#define SNELL_TEXTURE_SIZE(tex, lod) max(snellWebgpuTextureSize0(tex) >> (lod), ivec2(1, 1))\n";
  for (std::size_t k = 0; k < slots; ++k) {
    const std::string n = std::to_string(k);
    s += "layout(set = 0, binding = " + std::to_string(kParityWebGpuFirstTexture + 2 * k) + ") uniform texture2D snellWebgpuTex" + n + ";\n";
    s += "layout(set = 0, binding = " + std::to_string(kParityWebGpuFirstTexture + 2 * k + 1) + ") uniform sampler snellWebgpuSmp" + n + ";\n";
  }
  const auto chain = [&](const std::string& call, const std::string& otherwise) {
    std::string b;
    for (std::size_t k = 0; k < slots; ++k) {
      const std::string n = std::to_string(k);
      std::string c = call;
      for (std::size_t at; (at = c.find("K")) != std::string::npos;) c.replace(at, 1, n);
      b += std::string("  ") + (k ? "else " : "") + "if (t == " + n + ") return " + c + ";\n";
    }
    return b + "  return " + otherwise + ";\n";
  };
  s += "vec4 snellWebgpuSampleLod(int t, vec2 uv, float lod) {\n" +
       chain("textureLod(sampler2D(snellWebgpuTexK, snellWebgpuSmpK), uv, lod)", "vec4(0.0f)") + "}\n";
  s += "vec4 snellWebgpuTexelFetch(int t, ivec2 px, int lod) {\n" +
       chain("texelFetch(sampler2D(snellWebgpuTexK, snellWebgpuSmpK), px, lod)", "vec4(0.0f)") + "}\n";
  s += "ivec2 snellWebgpuTextureSize0(int t) {\n" +
       chain("textureSize(sampler2D(snellWebgpuTexK, snellWebgpuSmpK), 0)", "ivec2(0, 0)") + "}\n";
  return s;
}

// A case's wait for a server behind the other ctest jobs' cases: minutes only if it hangs.
constexpr int kWebGpuServerTimeoutSeconds = 300;

// What run_parity.ts (`name` "parity") or tint_check.mjs ("tint") would exit with and print for
// `request`, from its server in the state folder `dir` (tools/webgpu/webgpu_servers.mjs). Not reaching
// it is an error, never a fallback to a process per case: SNELL_WEBGPU_SERVER says the servers are there.
inline ToolResult askWebGpuServer(const std::string& dir, const std::string& name, const std::string& request) {
  const std::filesystem::path d(dir);
  return askServer(d / (name + ".sock"), request, kWebGpuServerTimeoutSeconds,
                   "the WebGPU runtime's " + name + " server (SNELL_WEBGPU_SERVER=" + dir +
                       ": ctest starts it in the test webgpu.servers_start; its output is in " +
                       (d / (name + "_server.log")).string() + ")");
}

}  // namespace detail

// Runs `entry` of `caseFile` (found through includeDirs) on every input on
// WebGPU. The job (shader, SPIR-V, WGSL, inputs, textures, results) is left in
// workDir/<case file stem>.<entry>/. `adapter`, if given, receives the WebGPU
// adapter's description.
inline std::vector<ParityIO> runParityWebGpu(const WebGpuTools& webgpu,
                                             const std::vector<std::filesystem::path>& includeDirs,
                                             const std::string& caseFile, const std::string& entry,
                                             const std::vector<ParityIO>& inputs,
                                             const std::vector<ParityTexture>& textures,
                                             const std::filesystem::path& workDir, const ShaderTools& tools = {},
                                             const std::string& entrySource = {}, std::string* adapter = nullptr) {
  namespace fs = std::filesystem;
  const fs::path job = workDir / (fs::path(caseFile).stem().string() + "." + entry);
  // The rewritten case file goes into the job's own folder: tests of other functions of the same case
  // file run in parallel (ctest -j) and would rewrite a shared copy while this one compiles.
  const fs::path cases = job / "cases";
  std::error_code ec;
  fs::create_directories(job, ec);
  fs::create_directories(cases, ec);
  if (ec) throw Error("runParityWebGpu: cannot create " + job.string() + ": " + ec.message());

  // The case file with its samplers turned into slot numbers, first on the include path.
  const std::string caseText = detail::readCaseFile(includeDirs, caseFile, "runParityWebGpu");
  static const std::regex decl(R"(uniform\s+sampler2D\s+(\w+)\s*;)");
  std::vector<std::string> slots;
  std::string rewritten;
  auto last = caseText.cbegin();
  for (auto it = std::sregex_iterator(caseText.begin(), caseText.end(), decl); it != std::sregex_iterator(); ++it) {
    rewritten.append(last, (*it)[0].first);
    rewritten += "const int " + (*it)[1].str() + " = " + std::to_string(slots.size()) + ";";
    slots.push_back((*it)[1].str());
    last = (*it)[0].second;
  }
  rewritten.append(last, caseText.cend());
  detail::writeTextFile(cases / caseFile, rewritten);

  std::string s = "#version 450 core\n#extension GL_GOOGLE_include_directive : require\n";
  s += "layout(local_size_x = " + std::to_string(kParityLocalSize) + ") in;\n";
  s += "layout(std430, set = 0, binding = 0) readonly buffer SnellParityInputs { vec4 snellParityIn[]; };\n";
  s += "layout(std430, set = 0, binding = 1) writeonly buffer SnellParityOutputs { vec4 snellParityResult[]; };\n";
  s += "layout(std140, set = 0, binding = 2) uniform SnellParityParams { int snellParityCount; };\n";
  s += "struct SnellParityOut { vec4 a; vec4 b; vec4 c; vec4 d; };\n";
  s += "#include \"snell_webgpu_prelude.glsl\"\n";
  s += detail::webGpuTextureHooks(slots.size());
  s += "#include \"" + caseFile + "\"\n";
  s += entrySource;
  s += "void main() {\n  uint i = gl_GlobalInvocationID.x;\n  if (i >= uint(snellParityCount)) return;\n";
  s += detail::parityCallAndStore(entry);
  s += "}\n";
  const fs::path source = job / "shader.comp", spv = job / "shader.spv";
  detail::writeTextFile(source, s);
  detail::compileVulkanSpirv(tools, source, spv, {"-I" + cases.string(), "-I" + webgpu.toolsDir.string()}, includeDirs);

  // The job: the slots' textures (every level, level 0 first), the inputs, the count. A texture the case
  // file declares but this case does not give gets one black texel: naga drops what the entry never
  // reads, and a read of it would show as a mismatch.
  std::string json = "{\"count\": " + std::to_string(inputs.size()) + ", \"textures\": [";
  const Texture2D unused(Image(1, 1));
  for (std::size_t k = 0; k < slots.size(); ++k) {
    const ParityTexture* found = nullptr;
    for (const ParityTexture& pt : textures)
      if (pt.uniform == slots[k]) found = &pt;
    if (found != nullptr && found->texture == nullptr)
      throw Error("runParityWebGpu: texture '" + slots[k] + "' is null");
    const Texture2D& tex = found ? *found->texture : unused;
    std::vector<float> data;
    json += std::string(k ? ", " : "") + "{" + detail::textureJob(tex, data) + "}";
    detail::writeFloats(job / ("tex_" + std::to_string(k) + ".f32"), data.data(), data.size());
  }
  detail::writeTextFile(job / "job.json", json + "]}\n");
  static_assert(sizeof(ParityIO) == 16 * sizeof(float), "ParityIO is 16 packed floats");
  detail::writeFloats(job / "inputs.f32", reinterpret_cast<const float*>(inputs.data()), 16 * inputs.size());
  fs::remove(job / "results.f32", ec);

  if (!fs::exists(webgpu.deno) || !fs::exists(webgpu.toolsDir / "node_modules" / "naga-wasm"))
    throw Error("the WebGPU runtime needs Deno and naga from npm: no " + webgpu.deno + " or " +
                (webgpu.toolsDir / "node_modules" / "naga-wasm").string() + " (run `npm ci` in " +
                webgpu.toolsDir.string() + "; scripts/install-deps.sh does)");
  const char* server = std::getenv("SNELL_WEBGPU_SERVER");
  const bool served = server != nullptr && *server != '\0';
  ToolResult t = served ? detail::askWebGpuServer(server, "parity", fs::absolute(job).string())
                        : runTool(webgpu.deno,
                                  {"run", "--quiet", "--allow-read", "--allow-write", "--allow-env",
                                   "--node-modules-dir=manual", (webgpu.toolsDir / "run_parity.ts").string(), job.string()},
                                  "deno");
  if (t.exitCode != 0)
    throw Error("the WebGPU runtime failed on " + job.string() + " (deno exit " + std::to_string(t.exitCode) + "):\n" +
                detail::indent(t.output));
  // The same WGSL through Tint (Dawn's compiler, Chrome's): the two WGSL compilers disagree on some input.
  const fs::path wgsl = job / "shader.wgsl";
  t = served ? detail::askWebGpuServer(server, "tint", fs::absolute(wgsl).string())
             : runTool(webgpu.node, {(webgpu.toolsDir / "tint_check.mjs").string(), wgsl.string()}, "nodejs");
  if (t.exitCode != 0) throw Error("Tint rejects the WGSL of " + job.string() + ":\n" + detail::indent(t.output));
  if (adapter) {
    *adapter = detail::readTextFile(job / "adapter.txt");
    while (!adapter->empty() && adapter->back() == '\n') adapter->pop_back();
  }
  return detail::readParityResults(job / "results.f32", inputs.size(), "the WebGPU runtime");
}

// The WGSL of a job runParityWebGpu left in workDir (its shader.wgsl, inputs and textures), run
// again on Chromium's WebGPU (Dawn and Tint; the SwiftShader adapter, no GPU) by
// tools/webgpu/chromium_page.js: the second WGSL implementation executing the same WGSL.
// `adapter`, if given, receives the adapter's description.
inline std::vector<ParityIO> runParityWebGpuInChromium(const WebGpuTools& webgpu, const std::filesystem::path& workDir,
                                                       const std::string& caseFile, const std::string& entry,
                                                       std::size_t count, std::string* adapter = nullptr) {
  namespace fs = std::filesystem;
  const fs::path job = workDir / (fs::path(caseFile).stem().string() + "." + entry);
  if (!fs::exists(job / "shader.wgsl"))
    throw Error("runParityWebGpuInChromium: no " + (job / "shader.wgsl").string() + " (run runParityWebGpu first)");
  return detail::runChromiumPage(webgpu.node, webgpu.chromium, webgpu.toolsDir / "chromium_page.js", job,
                                 "results_chromium.f32", {"--webgpu"}, count, "Chromium's WebGPU", nullptr, adapter);
}

}  // namespace snell::gpu
