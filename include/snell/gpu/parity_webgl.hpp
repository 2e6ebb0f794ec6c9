// The parity runner on WebGL 2: a case file's entry as an ES 3.00 fragment
// shader, run by headless Chromium (its WebGL 2 is ANGLE on SwiftShader on the
// test machines, no GPU), one case per pixel. What three.js, Babylon.js and
// PlayCanvas users run: the case file flattened by snell's include flattener
// (as an engine would paste it), the precision statements of docs/recipes.md,
// and nothing else changed.
//
// The fragment shader reads case i's four input vectors from an RGBA32F
// texture (texels 4x .. 4x + 3 of row y for the case at pixel (x, y)) and
// writes its four output vectors to four RGBA32F colour attachments, read back
// as floats (EXT_color_buffer_float). The case's textures keep their uniform
// names, levels and filters (a texture without mips is clamped to level 0,
// as on GL). The browser side is tools/webgl/parity_job.js: each case starts
// tools/browser/run_page.mjs on parity_page.js, which runs it in a page of its
// own (detail::runChromiumPage, chromium_page.hpp), or, when
// SNELL_WEBGL_SERVER names the state folder of tools/webgl/webgl_server.mjs
// (ctest does), asks the page server that folder's socket leads to, whose
// tabs run every job. The renderer string the page reports is kept in the job
// folder. Source tree only: `cmake --install` leaves this header out, as it
// leaves out tools/ and its npm packages.
#pragma once

#include "chromium_page.hpp"
#include "process.hpp"
#include "include_flattener.hpp"
#include "parity.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace snell::gpu {

// Where the WebGL 2 runtime's tools are: Node.js (runs the page's server),
// Chromium (Debian's chromium package) and tools/webgl (tools/browser beside it).
struct WebGlTools {
  std::string node = "node";
  std::string chromium = "chromium";
  std::filesystem::path toolsDir;
};

// Cases per row of the input texture and of the colour attachments: four
// input texels per case keep the input texture 4096 wide, inside every
// WebGL 2 implementation's limit (MAX_TEXTURE_SIZE >= 4096 in practice).
constexpr int kParityWebGlColumns = 1024;

namespace detail {

// A case's wait for the page server: the page's own limit (SNELL_BROWSER_TIMEOUT_MS, 600 s), then the
// jobs of the other ctest jobs' cases ahead of it. Longer only if the server hangs.
constexpr int kWebGlServerTimeoutSeconds = 900;

// What run_page.mjs would exit with and print for the job in `job` (an absolute path), from the page
// server in the state folder `dir` (tools/webgl/webgl_server.mjs). Not reaching it is an error, never a
// fallback to a page per case: SNELL_WEBGL_SERVER says the server is there.
inline ToolResult askWebGlServer(const std::string& dir, const std::filesystem::path& job) {
  const std::filesystem::path d(dir);
  return askServer(d / "page.sock", "parity_job.js results.f32 " + job.string(), kWebGlServerTimeoutSeconds,
                   "the WebGL 2 runtime's page server (SNELL_WEBGL_SERVER=" + dir +
                       ": ctest starts it in the test webgl.server_start; its output is in " +
                       (d / "page_server.log").string() + ")");
}

}  // namespace detail

// The generated ES 3.00 fragment shader, before flattening.
inline std::string parityWebGlSource(const std::string& caseFile, const std::string& entry,
                                     const std::string& entrySource = {}) {
  std::string s = "#version 300 es\n";
  s += "precision highp float;\nprecision highp int;\nprecision highp sampler2D;\n";
  s += "uniform sampler2D snellParityInputs;\n";
  s += "uniform int snellParityCount;\n";
  s += "layout(location = 0) out vec4 snellParityA;\n";
  s += "layout(location = 1) out vec4 snellParityB;\n";
  s += "layout(location = 2) out vec4 snellParityC;\n";
  s += "layout(location = 3) out vec4 snellParityD;\n";
  s += "struct SnellParityOut { vec4 a; vec4 b; vec4 c; vec4 d; };\n";
  s += "#include \"" + caseFile + "\"\n";
  s += entrySource;
  s += "void main() {\n";
  s += "  ivec2 p = ivec2(gl_FragCoord.xy);\n";
  s += "  if (p.y * " + std::to_string(kParityWebGlColumns) + " + p.x >= snellParityCount) {\n";
  s += "    snellParityA = vec4(0.0f); snellParityB = vec4(0.0f); snellParityC = vec4(0.0f); snellParityD = vec4(0.0f);\n";
  s += "    return;\n  }\n";
  s += "  SnellParityOut o = " + entry +
       "(texelFetch(snellParityInputs, ivec2(4 * p.x, p.y), 0), texelFetch(snellParityInputs, ivec2(4 * p.x + 1, p.y), 0),"
       " texelFetch(snellParityInputs, ivec2(4 * p.x + 2, p.y), 0), texelFetch(snellParityInputs, ivec2(4 * p.x + 3, p.y), 0));\n";
  s += "  snellParityA = o.a;\n  snellParityB = o.b;\n  snellParityC = o.c;\n  snellParityD = o.d;\n";
  s += "}\n";
  return s;
}

// Runs `entry` of `caseFile` (found through includeDirs) on every input in
// headless Chromium's WebGL 2. The job (shader, inputs, textures, results,
// renderer.txt) is left in workDir/<case file stem>.<entry>/. Returns the
// results; `renderer`, if given, receives the WebGL renderer string.
inline std::vector<ParityIO> runParityWebGl(const WebGlTools& webgl,
                                            const std::vector<std::filesystem::path>& includeDirs,
                                            const std::string& caseFile, const std::string& entry,
                                            const std::vector<ParityIO>& inputs,
                                            const std::vector<ParityTexture>& textures,
                                            const std::filesystem::path& workDir, const std::string& entrySource = {},
                                            std::string* renderer = nullptr) {
  namespace fs = std::filesystem;
  const fs::path job = workDir / (fs::path(caseFile).stem().string() + "." + entry);
  std::error_code ec;
  fs::create_directories(job, ec);
  if (ec) throw Error("runParityWebGl: cannot create " + job.string() + ": " + ec.message());
  const FlatSource src =
      flattenGlslSource(parityWebGlSource(caseFile, entry, entrySource), "<parity webgl " + entry + ">", includeDirs);
  detail::writeTextFile(job / "shader.frag", src.text);

  std::string json = "{\"count\": " + std::to_string(inputs.size()) +
                     ", \"columns\": " + std::to_string(kParityWebGlColumns) + ", \"textures\": [";
  for (std::size_t k = 0; k < textures.size(); ++k) {
    if (textures[k].texture == nullptr) throw Error("runParityWebGl: texture '" + textures[k].uniform + "' is null");
    std::vector<float> data;
    json += std::string(k ? ", " : "") + "{\"uniform\": \"" + textures[k].uniform + "\", " +
            detail::textureJob(*textures[k].texture, data) + "}";
    detail::writeFloats(job / ("tex_" + std::to_string(k) + ".f32"), data.data(), data.size());
  }
  detail::writeTextFile(job / "job.json", json + "]}\n");
  static_assert(sizeof(ParityIO) == 16 * sizeof(float), "ParityIO is 16 packed floats");
  detail::writeFloats(job / "inputs.f32", reinterpret_cast<const float*>(inputs.data()), 16 * inputs.size());
  const char* server = std::getenv("SNELL_WEBGL_SERVER");
  if (server == nullptr || *server == '\0')
    return detail::runChromiumPage(webgl.node, webgl.chromium, webgl.toolsDir / "parity_page.js", job, "results.f32",
                                   {}, inputs.size(), "the WebGL 2 runtime", &src, renderer);
  fs::remove(job / "results.f32", ec);
  return detail::pageJobResults(detail::askWebGlServer(server, fs::absolute(job)), job, "results.f32", inputs.size(),
                                "the WebGL 2 runtime", &src, renderer);
}

}  // namespace snell::gpu
