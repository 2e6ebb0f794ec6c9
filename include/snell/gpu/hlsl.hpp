// HLSL on llvmpipe: compile an HLSL compute shader with glslang's HLSL front end
// (glslangValidator -D) to SPIR-V, validate it (spirv-val), cross-compile it to
// GLSL 450 (spirv-cross --version 450 --no-es) and run that on the GL context.
// The parity runner runParityHlsl() does this for a parity case: the same case
// file and inputs as runParityGpu(), wrapped in an HLSL compute shader instead
// of a GLSL one, so the HLSL bridge (hlsl_like/snell/bridge.hlsl) is executed
// and compared with the C++ build, not just compiled.
//
//   snell::gpu::ShaderTools tools;  // names on PATH, or absolute paths (shader_tools.hpp)
//   auto gpu = runParityHlsl(ctx, {"hlsl_like/snell", "glsl", "tests/parity/cases"},
//                            "optics.glsl", "caseSnellRefract", inputs, {}, "build/hlsl_parity", tools);
//
// The tools run as child processes (runTool, process.hpp: posix_spawnp, no shell); a missing tool is
// an Error naming the Debian package that provides it. Every intermediate
// (.hlsl wrapper, .spv, cross-compiled .glsl) is written to a work directory
// you choose (a build directory: the cross-compiled text is a test artifact,
// never shipped). Results are cached there per shader: a rerun with the same
// flattened source and tools skips the tools.
//
// Samplers: HLSL separates Texture2D and SamplerState; spirv-cross turns each
// (texture, sampler) pair used into a combined `sampler2D
// SPIRV_Cross_Combined<texture><sampler>` (a texture read with Load gets
// `SPIRV_Cross_DummySampler`), inheriting the texture's binding. The runner maps
// every combined sampler back to the texture unit of its texture, and binds no
// GL sampler object, so the GL texture's own filter and wrap state applies
// whatever SamplerState the HLSL names, as it does for the GLSL run.
#pragma once

#include "context.hpp"
#include "error.hpp"
#include "include_flattener.hpp"
#include "parity.hpp"
#include "parity_job.hpp"
#include "process.hpp"
#include "program.hpp"
#include "resources.hpp"
#include "shader_tools.hpp"

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <system_error>
#include <vector>

namespace snell::gpu {


// The result of crossCompileHlslCompute.
struct HlslCrossCompiled {
  std::string glsl;                       // GLSL 450 from spirv-cross
  std::filesystem::path hlslFile, spvFile, glslFile;  // the artifacts
  // Combined sampler uniforms of the GLSL, e.g.
  // "SPIRV_Cross_CombinedmyTexsnellLinearClampSampler".
  std::vector<std::string> combinedSamplers;
  bool fromCache = false;
};

namespace detail {

inline std::vector<std::string> combinedSamplerUniforms(const std::string& glsl) {
  static const std::regex decl(R"(uniform\s+sampler2D\s+(\w+)\s*;)");
  std::vector<std::string> names;
  for (auto it = std::sregex_iterator(glsl.begin(), glsl.end(), decl); it != std::sregex_iterator(); ++it)
    names.push_back((*it)[1].str());
  return names;
}


}  // namespace detail

// HLSL compute source -> validated SPIR-V -> GLSL 450. `name` names the
// artifacts in `workDir` (created if needed): <name>.hlsl, .spv, .glsl.
// `includeDirs` are glslang -I directories (the folder of bridge.hlsl, glsl/,
// ...). Throws an Error with the tool's output (and the artifact path) when a
// step fails.
inline HlslCrossCompiled crossCompileHlslCompute(const std::string& hlslSource, const std::string& name,
                                                 const std::vector<std::filesystem::path>& includeDirs,
                                                 const std::filesystem::path& workDir,
                                                 const ShaderTools& tools = {}, const std::string& entryPoint = "main") {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(workDir, ec);
  if (ec) throw Error("cannot create the HLSL work directory " + workDir.string() + ": " + ec.message());
  HlslCrossCompiled r;
  r.hlslFile = workDir / (name + ".hlsl");
  r.spvFile = workDir / (name + ".spv");
  r.glslFile = workDir / (name + ".glsl");
  const fs::path keyFile = workDir / (name + ".key");

  std::vector<std::string> glslangArgs = {"-D", "-e", entryPoint, "-S", "comp", "-V", "--auto-map-bindings",
                                          "-o", r.spvFile.string()};
  for (const fs::path& d : includeDirs) glslangArgs.push_back("-I" + d.string());
  glslangArgs.push_back(r.hlslFile.string());
  const std::vector<std::string> crossArgs = {"--version", "450", "--no-es", "--combined-samplers-inherit-bindings",
                                              "--output", r.glslFile.string(), r.spvFile.string()};

  // Cache key: the source with every include spliced in (the GLSL flattener
  // reads HLSL includes the same way), the tools and their arguments.
  std::string key;
  try {
    std::vector<fs::path> search(includeDirs.begin(), includeDirs.end());
    std::string k = flattenGlslSource(hlslSource, name, search).text;
    k += "\n" + tools.glslangValidator + "\n" + tools.spirvVal + "\n" + tools.spirvCross + "\n";
    for (const std::string& a : glslangArgs) k += a + " ";
    for (const std::string& a : crossArgs) k += a + " ";
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(detail::fnv1a(k)));
    key = hex;
  } catch (const Error&) {
    key.clear();  // unresolved include: let glslang report it
  }
  if (!key.empty() && detail::readTextFile(keyFile) == key && fs::exists(r.glslFile) &&
      detail::readTextFile(r.hlslFile) == hlslSource) {
    r.glsl = detail::readTextFile(r.glslFile);
    if (!r.glsl.empty()) {
      r.combinedSamplers = detail::combinedSamplerUniforms(r.glsl);
      r.fromCache = true;
      return r;
    }
  }
  fs::remove(keyFile, ec);

  detail::writeTextFile(r.hlslFile, hlslSource);
  ToolResult t = runTool(tools.glslangValidator, glslangArgs, "glslang-tools");
  if (t.exitCode != 0)
    throw Error("glslangValidator -D failed on " + r.hlslFile.string() + " (exit " + std::to_string(t.exitCode) +
                "):\n" + detail::indent(t.output));
  t = runTool(tools.spirvVal, {r.spvFile.string()}, "spirv-tools");
  if (t.exitCode != 0)
    throw Error("spirv-val rejected " + r.spvFile.string() + " (from " + r.hlslFile.string() + "):\n" +
                detail::indent(t.output));
  t = runTool(tools.spirvCross, crossArgs, "spirv-cross");
  if (t.exitCode != 0)
    throw Error("spirv-cross failed on " + r.spvFile.string() + ":\n" + detail::indent(t.output));
  r.glsl = detail::readTextFile(r.glslFile);
  if (r.glsl.empty()) throw Error("spirv-cross wrote no GLSL to " + r.glslFile.string());
  r.combinedSamplers = detail::combinedSamplerUniforms(r.glsl);
  if (!key.empty()) detail::writeTextFile(keyFile, key);
  return r;
}

// The HLSL twin of parityShaderSource(): the case file's entry run once per
// invocation over a StructuredBuffer of inputs. `declareTextures`: Texture2D
// declarations the wrapper adds before the case file, "Texture2D<float4> name"
// (for case files without their own `#if defined(SNELL_LANG_HLSL)` block). `defines`: lines
// `#define <d>` before everything, e.g. "SNELL_HLSL_FLIP_V 1".
inline std::string parityHlslShaderSource(const std::string& caseFile, const std::string& entry,
                                          const std::vector<std::string>& declareTextures = {},
                                          const std::vector<std::string>& defines = {},
                                          const std::string& entrySource = {}) {
  std::string s;
  s += "// Generated by snell::gpu::parityHlslShaderSource (test artifact).\n";
  for (const std::string& d : defines) s += "#define " + d + "\n";
  s += "#include \"bridge.hlsl\"\n";
  s += "struct SnellParityOut { float4 a; float4 b; float4 c; float4 d; };\n";
  for (const std::string& t : declareTextures) s += t + ";\n";
  s += "#include \"" + caseFile + "\"\n";
  s += entrySource;
  s += "StructuredBuffer<float4> snellParityIn : register(t0);\n";
  s += "RWStructuredBuffer<float4> snellParityResult : register(u1);\n";
  s += "cbuffer SnellParityParams : register(b0) { uint snellParityCount; };\n";
  s += "[numthreads(" + std::to_string(kParityLocalSize) + ", 1, 1)]\n";
  s += "void main(uint3 id : SV_DispatchThreadID) {\n";
  s += "  uint i = id.x;\n";
  s += "  if (i >= snellParityCount) return;\n";
  s += detail::parityCallAndStore(entry);
  s += "}\n";
  return s;
}

// Which texture a combined sampler samples: the longest texture name that
// prefixes the part after "SPIRV_Cross_Combined". -1 if none.
inline int combinedSamplerTexture(const std::string& combined, const std::vector<ParityTexture>& textures) {
  static const std::string prefix = "SPIRV_Cross_Combined";
  if (combined.rfind(prefix, 0) != 0) return -1;
  const std::string rest = combined.substr(prefix.size());
  int best = -1;
  std::size_t bestLen = 0;
  for (std::size_t t = 0; t < textures.size(); ++t) {
    const std::string& u = textures[t].uniform;
    if (u.size() < rest.size() && rest.compare(0, u.size(), u) == 0 && u.size() > bestLen) {
      best = static_cast<int>(t);
      bestLen = u.size();
    }
  }
  return best;
}

// Runs `entry` of `caseFile` as HLSL on every input: wraps it with
// parityHlslShaderSource, cross-compiles (crossCompileHlslCompute, artifacts
// in workDir) and dispatches the GLSL like runParityGpu does. `includeDirs`
// must reach bridge.hlsl, the glsl/ tree and the case file. A case file that
// has no `SNELL_LANG_HLSL` block of its own gets an HLSL texture declaration
// for each `uniform sampler2D|samplerCube` it declares and for each of `textures`.
// `defines` go before the bridge, `entrySource` (a generated entry) after the
// case file (parityHlslShaderSource).
inline std::vector<ParityIO> runParityHlsl(const Context& ctx, const std::vector<std::filesystem::path>& includeDirs,
                                           const std::string& caseFile, const std::string& entry,
                                           const std::vector<ParityIO>& inputs,
                                           const std::vector<ParityTexture>& textures,
                                           const std::filesystem::path& workDir, const ShaderTools& tools = {},
                                           const std::vector<std::string>& defines = {},
                                           const std::string& entrySource = {}) {
  namespace fs = std::filesystem;
  // Does the case file declare its HLSL textures itself?
  const std::string caseText = detail::readCaseFile(includeDirs, caseFile, "runParityHlsl");
  // If not, declare the GLSL sampler uniforms it has (any #if block) and the
  // case's textures as HLSL textures.
  std::vector<std::string> declare;
  if (caseText.find("SNELL_LANG_HLSL") == std::string::npos) {
    std::set<std::string> seen;
    static const std::regex uniform(R"(uniform\s+(sampler2D|samplerCube)\s+(\w+)\s*;)");
    for (auto it = std::sregex_iterator(caseText.begin(), caseText.end(), uniform); it != std::sregex_iterator(); ++it)
      if (seen.insert((*it)[2].str()).second)
        declare.push_back(std::string((*it)[1].str() == "samplerCube" ? "TextureCube<float4> " : "Texture2D<float4> ") +
                          (*it)[2].str());
    for (const ParityTexture& t : textures)
      if (seen.insert(t.uniform).second) declare.push_back("Texture2D<float4> " + t.uniform);
  }

  std::string name = fs::path(caseFile).stem().string() + "." + entry;
  for (const std::string& d : defines) {
    name += ".";
    for (char c : d) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  }
  const HlslCrossCompiled cc = crossCompileHlslCompute(parityHlslShaderSource(caseFile, entry, declare, defines, entrySource),
                                                       name, includeDirs, workDir, tools);

  ctx.makeCurrent();
  const GlApi& gl = ctx.gl();
  FlatSource src;
  src.text = cc.glsl;
  src.files = {cc.glslFile.string()};
  const Program program = Program::compute(gl, src);

  // No sampler object: the GL texture's own filters apply, whatever SamplerState
  // the HLSL names.
  const std::vector<Texture> uploaded = detail::uploadParityTextures(gl, textures, "runParityHlsl");
  for (const std::string& combined : cc.combinedSamplers) {
    const int t = combinedSamplerTexture(combined, textures);
    if (t < 0)
      throw Error("runParityHlsl: " + cc.glslFile.string() + " samples '" + combined +
                  "', which names none of the case's textures");
    if (program.hasUniform(combined)) program.setSampler(combined, t);
  }

  StorageBuffer params(gl);
  std::vector<ParityIO> out = detail::dispatchParity(gl, program, inputs, "runParityHlsl", [&](std::size_t n) {
    const std::uint32_t count[4] = {static_cast<std::uint32_t>(n), 0u, 0u, 0u};  // std140: 16 bytes
    params.upload(count, sizeof count);
    gl.BindBufferBase(GL_UNIFORM_BUFFER, 0, params.id());  // register(b0); in t0, out u1
  });
  gl.BindBufferBase(GL_UNIFORM_BUFFER, 0, 0);
  return out;
}

}  // namespace snell::gpu
