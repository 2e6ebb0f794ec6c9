// snell_compile_times: how long each technique's shader program takes to
// compile where engines run it. examples/glsl/two_interface_refraction.frag is
// built once per row of the technique table (EXAMPLE_TECHNIQUE), with
// SNELL_INTERSECT_STRATEGIES set to the strategies that row's slots call
// (snellStrategiesUsed: the documented default for engines) and without it
// (every strategy compiled in), and timed
//   - in headless Chromium's WebGL 2 (ANGLE on SwiftShader, no GPU), as ES 3.00:
//     compile + link, then the first draw; one browser per program, so every
//     compile is cold (tools/webgl/compile_page.js, tools/browser/run_page.mjs);
//   - on Mesa llvmpipe through OSMesa, as GLSL 450 with Mesa's shader cache
//     off: compile + link, then the first draw (llvmpipe compiles its JIT code
//     there).
// Prints a Markdown table (docs/recipes.md keeps the last one). Times, not
// asserted: the machine and its load move them.
//
//   snell_compile_times [--techniques a,b,...] [--no-unmasked] [--chromium PATH] [--node PATH]
#include <snell/gpu/chromium_page.hpp>
#include <snell/gpu/context.hpp>
#include <snell/gpu/include_flattener.hpp>
#include <snell/gpu/program.hpp>
#include <snell/technique_table.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct Timing {
  double compileMs = 0.0, drawMs = 0.0;
  double total() const { return compileMs + drawMs; }
};

// The example as the host builds it: `version` replaces its first line; the include directive's extension goes
// (the flattener resolves the includes).
std::string exampleSource(std::string text, const std::string& version) {
  const std::size_t firstLine = text.find('\n');
  text = version + text.substr(firstLine);
  const std::size_t ext = text.find("#extension GL_GOOGLE_include_directive");
  if (ext != std::string::npos) text.erase(ext, text.find('\n', ext) - ext);
  return text;
}

std::vector<std::string> definesFor(const snell::SnellTechniqueInfo& t, bool masked) {
  std::vector<std::string> d = {"EXAMPLE_TECHNIQUE " + std::to_string(t.id)};
  if (masked) {
    // The example's slots: the preset's, the exit slot on the scene's buffers, the default material.
    snell::SnellTechnique technique = snell::snellTechniquePreset(t.id);
    technique.exit.source = SNELL_SOURCE_BUFFERS;
    d.push_back("SNELL_INTERSECT_STRATEGIES " +
                std::to_string(snell::snellStrategiesUsed(technique, snell::snellMaterial())));
  }
  return d;
}

Timing timeLlvmpipe(const snell::gpu::Context& ctx, const snell::gpu::FlatSource& fragment) {
  using namespace snell::gpu;
  const GlApi& gl = ctx.gl();
  const FlatSource vertex = flattenGlslSource(
      "#version 450 core\nout vec3 vsPosition;\nout vec3 vsNormal;\nvoid main() {\n"
      "  vec2 q = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2)) * 2.0 - 1.0;\n"
      "  vsPosition = vec3(q, -2.0);\n  vsNormal = vec3(0.0, 0.0, 1.0);\n  gl_Position = vec4(q, 0.0, 1.0);\n}\n",
      "fullscreen.vert", {});
  Timing t;
  gl.Finish();
  const auto t0 = Clock::now();
  Program program = Program::graphics(gl, vertex, fragment);
  const auto t1 = Clock::now();
  Framebuffer fb(gl, 1, 1, 1, false);
  fb.bind();
  UniformBuffer frame(gl, nullptr, 512);
  frame.bindBase(0);  // the example's Frame block, zeros: the draw only has to run the shader
  VertexArray vao(gl);
  vao.bind();
  program.use();
  gl.DrawArrays(GL_TRIANGLES, 0, 3);
  gl.Finish();
  const auto t2 = Clock::now();
  checkGl(gl, "compile-time draw");
  t.compileMs = std::chrono::duration<double, std::milli>(t1 - t0).count();
  t.drawMs = std::chrono::duration<double, std::milli>(t2 - t1).count();
  return t;
}

// `renderer` receives the renderer string the page reported.
Timing timeChromium(const std::string& node, const std::string& chromium, const fs::path& page, const fs::path& job,
                    const std::string& source, std::string* renderer) {
  fs::create_directories(job);
  snell::gpu::detail::writeTextFile(job / "shader.frag", source);
  snell::gpu::detail::writeTextFile(job / "job.json", "{\"programs\": [\"shader.frag\"]}\n");
  const std::vector<snell::gpu::ParityIO> r = snell::gpu::detail::runChromiumPage(
      node, chromium, page, job, "times.f32", {}, 1, "snell_compile_times (Chromium WebGL 2)", nullptr, renderer);
  Timing t;
  t.compileMs = static_cast<double>(r[0].v[0].x);
  t.drawMs = static_cast<double>(r[0].v[0].y);
  return t;
}

std::string seconds(double ms) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f s", ms / 1000.0);
  return b;
}

}  // namespace

int main(int argc, char** argv) {
  std::string only, chromium = "chromium", node = "node";
  bool unmasked = true;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--techniques" && i + 1 < argc) only = std::string(",") + argv[++i] + ",";
    else if (a == "--no-unmasked") unmasked = false;
    else if (a == "--chromium" && i + 1 < argc) chromium = argv[++i];
    else if (a == "--node" && i + 1 < argc) node = argv[++i];
    else {
      std::fprintf(stderr, "usage: snell_compile_times [--techniques a,b,...] [--no-unmasked] [--chromium PATH] [--node PATH]\n");
      return 2;
    }
  }
  // Every compile cold: no Mesa shader cache (set before the first context).
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  const fs::path root = SNELL_SOURCE_DIR;
  const fs::path example = root / "examples/glsl/two_interface_refraction.frag";
  const fs::path page = root / "tools/webgl/compile_page.js";
  const fs::path work = fs::temp_directory_path() / ("snell_compile_times_" + std::to_string(getpid()));
  try {
    const std::string exampleText = snell::gpu::detail::readTextFile(example);
    if (exampleText.empty()) throw snell::gpu::Error("cannot read " + example.string());
    const std::string esText = exampleSource(exampleText, "#version 300 es");
    const std::string desktopText = exampleSource(exampleText, "#version 450 core");
    snell::gpu::Context ctx(snell::gpu::Backend::OSMesa);
    std::string chromiumRenderer;
    std::printf("| technique | strategies compiled | Chromium WebGL 2: compile + link, first draw | llvmpipe: compile + link, first draw |");
    if (unmasked) std::printf(" every strategy: Chromium | every strategy: llvmpipe |");
    std::printf("\n|---|---|---:|---:|%s\n", unmasked ? "---:|---:|" : "");
    std::fflush(stdout);
    for (const snell::SnellTechniqueInfo& t : snell::snellTechniqueTable()) {
      if (!only.empty() && only.find(std::string(",") + t.name + ",") == std::string::npos) continue;
      std::string row = std::string("| ") + t.label + " | ";
      std::vector<bool> variants = {true};
      if (unmasked) variants.push_back(false);
      for (bool masked : variants) {
        const std::vector<std::string> defines = definesFor(t, masked);
        if (masked) row += defines[1].substr(defines[1].find(' ') + 1) + " | ";
        const snell::gpu::FlatSource es =
            snell::gpu::flattenGlslSource(esText, example.string(), {root / "glsl"}, defines);
        const fs::path job = work / (std::string(t.name) + (masked ? "" : "_all"));
        const Timing browser = timeChromium(node, chromium, page, job, es.text, &chromiumRenderer);
        const snell::gpu::FlatSource desktop =
            snell::gpu::flattenGlslSource(desktopText, example.string(), {root / "glsl"}, defines);
        const Timing mesa = timeLlvmpipe(ctx, desktop);
        if (masked) {
          row += seconds(browser.compileMs) + " + " + seconds(browser.drawMs) + " | " + seconds(mesa.compileMs) + " + " +
                 seconds(mesa.drawMs) + " |";
        } else {
          row += " " + seconds(browser.total()) + " | " + seconds(mesa.total()) + " |";
        }
      }
      std::printf("%s\n", row.c_str());
      std::fflush(stdout);
    }
    std::printf("\nChromium: %s. llvmpipe: %s, OpenGL %s. examples/glsl/two_interface_refraction.frag per row "
                "(EXAMPLE_TECHNIQUE); strategies compiled: the SNELL_INTERSECT_STRATEGIES mask, bit k = strategy k.\n",
                chromiumRenderer.c_str(), ctx.renderer().c_str(), ctx.version().c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "snell_compile_times: %s\n", e.what());
    std::error_code ec;
    fs::remove_all(work, ec);
    return 1;
  }
  std::error_code ec;
  fs::remove_all(work, ec);
  return 0;
}
