// The parity runner: execute a GLSL function on the GL driver, one case per
// compute invocation, and compare with the C++ build of the same text.
//
// A case entry has the fixed shape
//   SnellParityOut caseFoo(vec4 a, vec4 b, vec4 c, vec4 d)
// and lives in a file written in the common subset, so the same file is
// #included into the generated compute shader here and into a C++ namespace
// for the CPU side (with snell::gpu::SnellParityOut as the struct). Fixed
// shapes keep the runner generic: 4 vec4 in, 4 vec4 out, bools as 0/1.
//
//   auto gpu = runParityGpu(ctx, {"glsl", "tests/parity/cases"}, "optics.glsl",
//                           "caseSnellRefract", inputs);
//   auto report = compareParity(gpu, cpu, 0x30, 6, 1e-5f, 1e-5f);
#pragma once

#include "context.hpp"
#include "error.hpp"
#include "include_flattener.hpp"
#include "program.hpp"
#include "resources.hpp"

#include <snell/bridge.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace snell::gpu {

// One case's inputs or outputs: four vec4 = 16 floats; float k is v[k / 4][k % 4].
struct ParityIO {
  glm::vec4 v[4];
};

// C++ twin of the GLSL struct the generated shader declares for case entries.
struct SnellParityOut {
  glm::vec4 a, b, c, d;
};

inline ParityIO toParityIO(const SnellParityOut& o) {
  ParityIO r{};
  r.v[0] = o.a;
  r.v[1] = o.b;
  r.v[2] = o.c;
  r.v[3] = o.d;
  return r;
}

// A texture the case samples. The case file declares `uniform sampler2D
// <uniform>;` itself (inside `#if defined(SNELL_LANG_GLSL)`; the C++ side
// declares a snell::Texture2D of the same name); the runner uploads `texture`
// with all its levels and filter state, binds it to a unit and sets the sampler.
// A texture the compiler removed (unused by this entry) is skipped.
struct ParityTexture {
  std::string uniform;
  const snell::Texture2D* texture;
};

constexpr int kParityLocalSize = 64;

namespace detail {
// A texture's filters as the job files of the WebGPU and WebGL 2 runtimes name them.
inline const char* filterName(Filter f) { return f == Filter::Linear ? "linear" : "nearest"; }
inline const char* mipFilterName(MipFilter f) {
  return f == MipFilter::Linear ? "linear" : (f == MipFilter::Nearest ? "nearest" : "none");
}

// A texture for those runtimes' device side: every level's RGBA32F texels
// (level 0 first) in `texels`, and the JSON members naming the levels' sizes
// and the filters: "levels": [[w, h], ...], "mag": .., "min": .., "mip": ..
inline std::string textureJob(const snell::Texture2D& tex, std::vector<float>& texels) {
  std::string levels;
  for (int l = 0; l < tex.levelCount(); ++l) {
    const snell::Image& img = tex.level(l);
    levels += std::string(l ? ", " : "") + "[" + std::to_string(img.width) + ", " + std::to_string(img.height) + "]";
    for (const glm::vec4& v : img.texels) texels.insert(texels.end(), {v.x, v.y, v.z, v.w});
  }
  return "\"levels\": [" + levels + "], \"mag\": \"" + filterName(tex.magFilter) + "\", \"min\": \"" +
         filterName(tex.minFilter) + "\", \"mip\": \"" + mipFilterName(tex.mipFilter) + "\"";
}

// The statements the GLSL and the HLSL parity mains share (both languages spell
// them alike): run `entry` on input i, store its four vectors as result i.
inline std::string parityCallAndStore(const std::string& entry) {
  std::string s;
  s += "  SnellParityOut o = " + entry +
       "(snellParityIn[4u * i], snellParityIn[4u * i + 1u], snellParityIn[4u * i + 2u], snellParityIn[4u * i + 3u]);\n";
  s += "  snellParityResult[4u * i] = o.a;\n";
  s += "  snellParityResult[4u * i + 1u] = o.b;\n";
  s += "  snellParityResult[4u * i + 2u] = o.c;\n";
  s += "  snellParityResult[4u * i + 3u] = o.d;\n";
  return s;
}
}  // namespace detail

// Who compiles the generated shader: GL (the flattener resolves the includes,
// the case count is a uniform) or glslang for Vulkan (its include directive,
// the count a push constant: Vulkan has no free uniforms).
enum class ParityDialect { Gl, Vulkan };

// The generated compute shader. `in`/`out` are GLSL keywords, hence the names.
// `entrySource`, if given, is appended after the case file (a generated entry
// that calls what the case file declares).
inline std::string parityShaderSource(const std::string& caseFile, const std::string& entry,
                                      const std::string& entrySource = {},
                                      ParityDialect dialect = ParityDialect::Gl) {
  std::string s;
  s += "#version 450 core\n";
  if (dialect == ParityDialect::Vulkan) s += "#extension GL_GOOGLE_include_directive : require\n";
  s += "layout(local_size_x = " + std::to_string(kParityLocalSize) + ") in;\n";
  s += "layout(std430, binding = 0) readonly buffer SnellParityInputs { vec4 snellParityIn[]; };\n";
  s += "layout(std430, binding = 1) writeonly buffer SnellParityOutputs { vec4 snellParityResult[]; };\n";
  s += dialect == ParityDialect::Vulkan ? "layout(push_constant) uniform SnellParityPush { int snellParityCount; };\n"
                                        : "uniform int snellParityCount;\n";
  s += "struct SnellParityOut { vec4 a; vec4 b; vec4 c; vec4 d; };\n";
  s += "#include \"" + caseFile + "\"\n";
  s += entrySource;
  s += "void main() {\n";
  s += "  uint i = gl_GlobalInvocationID.x;\n";
  s += "  if (i >= uint(snellParityCount)) return;\n";
  s += detail::parityCallAndStore(entry);
  s += "}\n";
  return s;
}

// Runs `entry` from `caseFile` (found through searchPaths) on every input.
// Inputs are split into chunks that respect the driver's SSBO size and
// work-group count limits (llvmpipe: 128 MiB, 65535 groups).
namespace detail {
// Texture t on unit t, for t = 0..n-1; the caller points the sampler uniforms at them.
inline std::vector<Texture> uploadParityTextures(const GlApi& gl, const std::vector<ParityTexture>& textures,
                                                 const std::string& who) {
  std::vector<Texture> uploaded;
  uploaded.reserve(textures.size());
  GLint maxUnits = 0;
  gl.GetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &maxUnits);
  if (textures.size() > static_cast<std::size_t>(maxUnits))
    throw Error(who + ": " + std::to_string(textures.size()) + " textures, the driver has " +
                std::to_string(maxUnits) + " texture units");
  for (std::size_t t = 0; t < textures.size(); ++t) {
    if (textures[t].texture == nullptr) throw Error(who + ": texture '" + textures[t].uniform + "' is null");
    uploaded.emplace_back(gl, *textures[t].texture);
    uploaded.back().bind(static_cast<int>(t));
  }
  return uploaded;
}

// Runs a parity program over all inputs, in as many dispatches as the driver's
// work-group count and SSBO size limits need. Inputs are bound at SSBO binding 0,
// results at 1; passCount(n) hands the shader the case count of each dispatch.
template <class PassCount>
std::vector<ParityIO> dispatchParity(const GlApi& gl, const Program& program, const std::vector<ParityIO>& inputs,
                                     const std::string& who, PassCount passCount) {
  GLint maxGroups = 0, maxBlockBytes = 0;
  gl.GetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &maxGroups);
  gl.GetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlockBytes);
  checkGl(gl, (who + " limits query").c_str());
  const std::size_t byGroups = static_cast<std::size_t>(std::max(maxGroups, 1)) * kParityLocalSize;
  const std::size_t byBytes = static_cast<std::size_t>(std::max(maxBlockBytes, 1)) / sizeof(ParityIO);
  const std::size_t chunk = std::max<std::size_t>(1, std::min(byGroups, byBytes));

  std::vector<ParityIO> out(inputs.size());
  StorageBuffer in(gl), result(gl);
  for (std::size_t first = 0; first < inputs.size(); first += chunk) {
    const std::size_t n = std::min(chunk, inputs.size() - first);
    in.upload(inputs.data() + first, n * sizeof(ParityIO));
    result.allocate(n * sizeof(ParityIO));
    in.bindBase(0);
    result.bindBase(1);
    passCount(n);
    program.dispatch(static_cast<GLuint>((n + kParityLocalSize - 1) / kParityLocalSize));
    gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    result.download(out.data() + first, n * sizeof(ParityIO));
  }
  return out;
}
}  // namespace detail

inline std::vector<ParityIO> runParityGpu(const Context& ctx, const std::vector<std::filesystem::path>& searchPaths,
                                          const std::string& caseFile, const std::string& entry,
                                          const std::vector<ParityIO>& inputs,
                                          const std::vector<ParityTexture>& textures = {},
                                          const std::string& entrySource = {}) {
  ctx.makeCurrent();
  const GlApi& gl = ctx.gl();
  const FlatSource src =
      flattenGlslSource(parityShaderSource(caseFile, entry, entrySource), "<parity " + entry + ">", searchPaths);
  const Program program = Program::compute(gl, src);

  const std::vector<Texture> uploaded = detail::uploadParityTextures(gl, textures, "runParityGpu");
  for (std::size_t t = 0; t < textures.size(); ++t)
    if (program.hasUniform(textures[t].uniform)) program.setSampler(textures[t].uniform, static_cast<int>(t));
  return detail::dispatchParity(gl, program, inputs, "runParityGpu", [&](std::size_t n) {
    program.set("snellParityCount", static_cast<int>(n));
  });
}

// Counts are per case: a case mismatches if any of its outputs does.
struct ParityReport {
  std::size_t cases = 0, mismatches = 0;
  // Cases that matched only the C++ result on their inputs with denormals flushed to 0 (see
  // flushDenormals): the runtime flushed a denormal input.
  std::size_t flushedMatches = 0;
  float maxAbs = 0, maxRel = 0;  // over finite continuous outputs; maxRel only where |cpu| > absTol
  std::size_t firstMismatch = SIZE_MAX;
  std::string firstMismatchText;
  bool ok() const { return mismatches == 0; }
};

// The prelude's rule for data (positions, directions, matrix entries): a runtime may flush a
// denormal to 0 (SwiftShader, most GPUs) or keep it (llvmpipe, the CPU), and the result is the
// function's on either. The input with every denormal replaced by a zero of its sign.
inline bool isDenormal(float x) { return std::fpclassify(x) == FP_SUBNORMAL; }
inline ParityIO flushDenormals(const ParityIO& in) {
  ParityIO r = in;
  for (glm::vec4& v : r.v)
    for (int k = 0; k < 4; ++k)
      if (isDenormal(v[k])) v[k] = std::copysign(0.0f, v[k]);
  return r;
}
inline bool hasDenormal(const ParityIO& in) {
  for (const glm::vec4& v : in.v)
    for (int k = 0; k < 4; ++k)
      if (isDenormal(v[k])) return true;
  return false;
}

namespace detail {
inline std::string formatFloat(float f) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(f));
  return buf;
}
inline std::string formatIO(const ParityIO& io) {
  std::string s = "(";
  for (int i = 0; i < 4; ++i) {
    s += i ? ", (" : "(";
    for (int k = 0; k < 4; ++k) s += (k ? ", " : "") + formatFloat(io.v[i][k]);
    s += ")";
  }
  return s + ")";
}
}  // namespace detail

// How one output float is compared: `exact` (equal, NaN == NaN) or within
// |gpu - cpu| <= abs + rel * |cpu|; a NaN or infinity on either side must be
// matched exactly (NaN by NaN, inf by the same inf). `name` labels a mismatch.
struct ParityOutput {
  int index;  // float index: v[index / 4][index % 4]
  std::string name;
  bool exact = false;
  float abs = 0.0f, rel = 0.0f;
  // An ill-conditioned output's tolerance grows by scaled * |cpu float scaleIndex| (another output
  // of the case that measures the conditioning); scaleIndex -1: none.
  float scaled = 0.0f;
  int scaleIndex = -1;
};

namespace detail {
// One output of one case: whether it matches, its |diff| (finite continuous outputs, else -1) and,
// for a mismatch, why. `scaled`: whether the output's condition-scaled tolerance applies to the case.
inline bool parityOutputMatches(float g, const ParityIO& cpu, const ParityOutput& o, float& diff, std::string& why,
                                bool scaled = true) {
  const float c = cpu.v[o.index / 4][o.index % 4];
  diff = -1.0f;
  if (std::isnan(g) || std::isnan(c)) return std::isnan(g) && std::isnan(c);
  if (o.exact || std::isinf(g) || std::isinf(c)) return g == c;
  diff = std::fabs(g - c);
  float tol = o.abs + o.rel * std::fabs(c);
  if (scaled && o.scaleIndex >= 0) tol += o.scaled * std::fabs(cpu.v[o.scaleIndex / 4][o.scaleIndex % 4]);
  why = " (|diff| " + formatFloat(diff) + " > tol " + formatFloat(tol) + ")";
  return diff <= tol;
}
}  // namespace detail

// Compares the listed output floats of every case. `inputs`, if given, are
// printed with the first mismatch. `cpuFlushed`, if given, is the C++ result on
// each input with its denormals flushed (flushDenormals): a case that does not
// match `cpu` but matches it in every output counts in flushedMatches, not as
// a mismatch. `scaledCases`, if given, names the cases (true) on which the
// outputs' condition-scaled tolerances apply; without it they apply to every case.
inline ParityReport compareParity(const std::vector<ParityIO>& gpu, const std::vector<ParityIO>& cpu,
                                  const std::vector<ParityOutput>& outputs,
                                  const std::vector<ParityIO>* inputs = nullptr,
                                  const std::vector<ParityIO>* cpuFlushed = nullptr,
                                  const std::vector<bool>* scaledCases = nullptr) {
  if (gpu.size() != cpu.size())
    throw std::invalid_argument("compareParity: " + std::to_string(gpu.size()) + " GPU results but " +
                                std::to_string(cpu.size()) + " CPU results");
  for (const ParityOutput& o : outputs)
    if (o.index < 0 || o.index > 15 || o.scaleIndex < -1 || o.scaleIndex > 15)
      throw std::invalid_argument("compareParity: output and scale indices must be in 0..15");
  if (inputs && inputs->size() != gpu.size())
    throw std::invalid_argument("compareParity: inputs and results differ in count");
  if (cpuFlushed && cpuFlushed->size() != gpu.size())
    throw std::invalid_argument("compareParity: flushed-input results and results differ in count");
  if (scaledCases && scaledCases->size() != gpu.size())
    throw std::invalid_argument("compareParity: scaled-case flags and results differ in count");
  auto scaledOn = [&](std::size_t i) { return !scaledCases || (*scaledCases)[i]; };
  ParityReport r;
  r.cases = gpu.size();
  // Whether case i matches `ref` in every output; its largest differences go to maxAbs/maxRel.
  auto caseMatches = [&](std::size_t i, const ParityIO& ref, float& maxAbs, float& maxRel) {
    bool all = true;
    for (const ParityOutput& o : outputs) {
      const int k = o.index;
      float diff = 0.0f;
      std::string why;
      const float c = ref.v[k / 4][k % 4];
      all = detail::parityOutputMatches(gpu[i].v[k / 4][k % 4], ref, o, diff, why, scaledOn(i)) && all;
      if (diff >= 0.0f) {
        maxAbs = std::max(maxAbs, diff);
        if (std::fabs(c) > o.abs) maxRel = std::max(maxRel, diff / std::fabs(c));
      }
    }
    return all;
  };
  for (std::size_t i = 0; i < gpu.size(); ++i) {
    float a = 0.0f, rel = 0.0f;
    if (caseMatches(i, cpu[i], a, rel)) {
      r.maxAbs = std::max(r.maxAbs, a);
      r.maxRel = std::max(r.maxRel, rel);
      continue;
    }
    float fa = 0.0f, frel = 0.0f;
    if (cpuFlushed && caseMatches(i, (*cpuFlushed)[i], fa, frel)) {
      ++r.flushedMatches;
      r.maxAbs = std::max(r.maxAbs, fa);
      r.maxRel = std::max(r.maxRel, frel);
      continue;
    }
    r.maxAbs = std::max(r.maxAbs, a);
    r.maxRel = std::max(r.maxRel, rel);
    ++r.mismatches;
    if (r.firstMismatch != SIZE_MAX) continue;
    for (const ParityOutput& o : outputs) {
      const int k = o.index;
      const float g = gpu[i].v[k / 4][k % 4];
      const float c = cpu[i].v[k / 4][k % 4];
      float diff = 0.0f;
      std::string why;
      if (detail::parityOutputMatches(g, cpu[i], o, diff, why, scaledOn(i))) continue;
      r.firstMismatch = i;
      r.firstMismatchText = "case " + std::to_string(i) + ", output " + std::to_string(k) +
                            (o.name.empty() ? std::string() : " '" + o.name + "'") + " (v[" + std::to_string(k / 4) +
                            "]." + "xyzw"[k % 4] + ", " + (o.exact ? "discrete" : "continuous") + "): gpu " +
                            detail::formatFloat(g) + ", cpu " + detail::formatFloat(c) + (diff >= 0.0f ? why : "");
      if (inputs) r.firstMismatchText += "; inputs " + detail::formatIO((*inputs)[i]);
      r.firstMismatchText += "; gpu outputs " + detail::formatIO(gpu[i]) + ", cpu outputs " + detail::formatIO(cpu[i]);
      if (cpuFlushed) r.firstMismatchText += ", cpu outputs on the flushed inputs " + detail::formatIO((*cpuFlushed)[i]);
      break;
    }
  }
  return r;
}

// The first `outputs` floats, those of bit k of `discreteMask` exactly, the
// others within absTol + relTol * |cpu|.
inline ParityReport compareParity(const std::vector<ParityIO>& gpu, const std::vector<ParityIO>& cpu,
                                  std::uint16_t discreteMask, int outputs, float absTol, float relTol,
                                  const std::vector<ParityIO>* inputs = nullptr) {
  if (outputs < 0 || outputs > 16) throw std::invalid_argument("compareParity: outputs must be in 0..16");
  std::vector<ParityOutput> list;
  for (int k = 0; k < outputs; ++k) list.push_back({k, std::string(), ((discreteMask >> k) & 1u) != 0, absTol, relTol});
  return compareParity(gpu, cpu, list, inputs);
}

}  // namespace snell::gpu
