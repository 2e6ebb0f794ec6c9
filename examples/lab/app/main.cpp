// snell-lab: every refraction technique rendered on the GL driver (Mesa
// llvmpipe by default) against a ray tracer; pictures and the error/cost table.
#include "lab_run.hpp"
#include "technique.hpp"

#include "lab/cli.hpp"
#include "lab/error.hpp"

#include <snell/gpu/error.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// The bundled default scene: the source tree's (compile definition), else
// scenes/bunny.json or share/snell/scenes/bunny.json next to / above the executable.
std::string defaultScene(const char* argv0) {
  const fs::path compiled = SNELL_LAB_DEFAULT_SCENE;
  if (fs::exists(compiled)) return compiled.string();
  std::error_code ec;
  const fs::path exe = fs::weakly_canonical(fs::path(argv0), ec).parent_path();
  for (const fs::path& p : {exe / "scenes" / "bunny.json", exe.parent_path() / "share" / "snell" / "scenes" / "bunny.json"})
    if (fs::exists(p)) return p.string();
  return compiled.string();
}

snell::lab::ShaderDirs shaderDirs() {
  snell::lab::ShaderDirs d;
  d.labGlsl = SNELL_LAB_GLSL_DIR;
  d.snellGlsl = SNELL_GLSL_DIR;
  if (const char* env = std::getenv("SNELL_LAB_GLSL_DIR")) d.labGlsl = env;
  if (const char* env = std::getenv("SNELL_GLSL_DIR")) d.snellGlsl = env;
  return d;
}

// The edit distance of a and b (Levenshtein), for "did you mean".
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// After a usage error: for each --word that is no option of `app`, the
// closest one, if it is close (a typo, not another word).
void suggestOptions(const CLI::App& app, int argc, char** argv) {
  std::vector<std::string> names;
  for (const CLI::Option* opt : app.get_options())
    for (const std::string& n : opt->get_lnames()) names.push_back("--" + n);
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg.rfind("--", 0) != 0 || arg.size() < 3) continue;
    arg = arg.substr(0, arg.find('='));
    if (std::find(names.begin(), names.end(), arg) != names.end()) continue;
    std::string best;
    std::size_t bestDistance = 3;  // at most 2 edits
    for (const std::string& n : names) {
      const std::size_t d = editDistance(arg, n);
      if (d < bestDistance) bestDistance = d, best = n;
    }
    if (!best.empty()) std::fprintf(stderr, "snell-lab: unknown option '%s'; did you mean '%s'?\n", arg.c_str(), best.c_str());
  }
}

}  // namespace

int main(int argc, char** argv) {
  using namespace snell::lab;
  LabOptions o;
  o.scenePath = defaultScene(argv[0]);
  std::string size;
  std::vector<std::string> techniqueArgs;
  std::string techniqueHelp = "techniques to compare (repeat or comma-separate; default: all):";
  for (const snell::SnellTechniqueInfo& t : snell::snellTechniqueTable())
    techniqueHelp += std::string("\n  ") + t.name + ": " + snell::snellDescribeTechnique(t);
  for (const snell::SnellEngineModelInfo& m : snell::snellEngineModelTable())
    techniqueHelp += std::string("\n  ") + m.name + ": " + m.engine + " (its " + m.parameter +
                     " swept to its best value on the scene; no back-face pass)";
  techniqueHelp += "\n  engine-bevy: Bevy 0.20 transmission.wesl, three.js's point read through Bevy's spiral blur (rough "
                   "glass only, unless named; its thickness swept as three.js's)";

  CLI::App app{"snell-lab: image-space refraction techniques rendered on the GL driver (Mesa llvmpipe by default) "
               "against an Embree ray tracer. Writes per-technique panels (ground truth | technique | error), an "
               "overview, and the error/cost table (Markdown and JSON)."};
  app.footer("In the lab the marches' back-face slot walks the object's bounding-box diagonal.\n"
             "Exit codes: 0 ok, 2 usage, 3 missing file, 4 malformed file, 5 render or GL failure.\n"
             "Defaults take about a minute on 2 cores (bunny, 512x512, every technique and engine model, 15 timed frames: 55 s measured).");
  app.add_option("scene", o.scenePath,
                 "scene file (JSON, see examples/scenes/README.md); default: the bundled bunny, " + o.scenePath +
                     " (the source tree's examples/scenes, compiled in)");
  app.add_option("-t,--technique", techniqueArgs, techniqueHelp);
  app.add_option("--size", size, "render size WxH (default: the scene's, 512x512 for the bundled scenes)");
  app.add_option("--frames", o.frames, "timed frames per technique (median; all techniques interleaved)")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  app.add_option("--backend", o.backend, "GL backend: osmesa, egl, or auto (OSMesa where it works, else EGL)")
      ->check(CLI::IsMember({"auto", "osmesa", "egl"}))
      ->capture_default_str();
  app.add_option("-o,--out", o.outDir, "output directory (PNGs, table.md, table.json)")->capture_default_str();
  app.add_option("--threads", o.threads, "ray tracer and CPU shading threads (0: all cores)")->capture_default_str();
  std::string normalFilter = "linear";
  app.add_option("--normal-filter", normalFilter,
                 "how the techniques read the normal buffers: linear (filtered, renormalized; empty texels hold 0) "
                 "or nearest (the texel containing the point)")
      ->check(CLI::IsMember({"linear", "nearest"}))
      ->capture_default_str();
  std::string depthFilter = "nearest";
  app.add_option("--depth-filter", depthFilter,
                 "how every technique reads the depth buffers: nearest (the texel containing the point) or bilinear "
                 "(between texel centres where all four hold a surface; the image-space bound always does)")
      ->check(CLI::IsMember({"nearest", "bilinear"}))
      ->capture_default_str();
  std::string reflection = "scene";
  app.add_option("--reflection", reflection,
                 "what the first surface reflects: scene (the reflected ray against the opaque scene's buffers with "
                 "the exit slot's strategy, the environment where it finds nothing, as the ray tracer does) or "
                 "environment (the environment only)")
      ->check(CLI::IsMember({"scene", "environment"}))
      ->capture_default_str();
  std::string sceneLayer = "behind";
  app.add_option("--scene-layer", sceneLayer,
                 "what snell's rows read of the opaque scene: behind (only what lies beyond the object's nearest "
                 "point, so an opaque object in front of the glass does not show inside it and what it hides does) "
                 "or full (the whole scene, as an engine's colour copy holds it: hits on a foreground are refused "
                 "and fall back) or peeled (only what lies behind the object's back faces at each texel: what an "
                 "exit ray can meet, without what stands in front of the object or inside it); the engine rows "
                 "always read the whole scene")
      ->check(CLI::IsMember({"behind", "full", "peeled"}))
      ->capture_default_str();
  std::string insideScene = "auto";
  app.add_option("--inside-scene", insideScene,
                 "whether snell's rows also search the opaque scene along the refracted ray, for opaque surfaces "
                 "inside the object (SnellTechnique.insideScene): auto (when a painting reaches inside the object), "
                 "on or off")
      ->check(CLI::IsMember({"auto", "on", "off"}))
      ->capture_default_str();
  app.add_option("--truth-samples", o.truthSamples,
                 "the ray tracer's paths per pixel on rough glass (its noise is reported; smooth glass takes one)")
      ->check(CLI::Range(1, 1 << 20))
      ->capture_default_str();
  bool sequence = false;
  app.add_flag("--sequence", sequence,
               "an animated run: frames 0 to N - 1 of the scene's animation (N: its animation.frames), every row "
               "drawn and the ray tracer's truth traced per frame, and each row's flicker against the truth's own "
               "change (a second table in table.md, `flicker` per row and `sequence` in table.json)");
  int sequenceFrames = 0;
  app.add_option("--sequence-frames", sequenceFrames,
                 "the animated run's frame count instead of the scene's animation.frames (implies --sequence)")
      ->check(CLI::Range(2, 100000));
  app.add_option("--guard-band", o.guardBand,
                 "extra border of the scene and back-face buffers beyond the viewport, per side, as a share of the "
                 "render size (0: the viewport only), so that exits just off screen are found")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  app.add_option("--web-bundle", o.webBundleDir,
                 "also write the frame for the three.js page (examples/web) to this directory: the scene, the "
                 "buffers' parameters, the lab's own buffers and its picture of each technique it ran");
  bool noThreejs = false;
  app.add_flag("--no-threejs", noThreejs,
               "a glTF scene: skip the row of three.js's own renderer (which needs Node.js, three.js and Chromium: "
               "scripts/install-deps.sh)");
  app.add_flag("-q,--quiet", o.quiet, "no progress bars and no table on stdout");
  if (const int code = parseCommandLine(app, argc, argv, [&] { suggestOptions(app, argc, argv); }); code >= 0)
    return code;
  o.threejs = !noThreejs;
  o.sequenceFrames = sequenceFrames > 0 ? sequenceFrames : sequence ? -1 : 0;
  // Comma-separated here rather than by CLI11, which drops empty names: "single,," is a typo, not "single".
  std::vector<std::string> names;
  for (const std::string& arg : techniqueArgs) {
    std::size_t from = 0;
    for (;;) {
      const std::size_t comma = arg.find(',', from);
      const std::string name = arg.substr(from, comma == std::string::npos ? std::string::npos : comma - from);
      if (name.empty()) {
        std::fprintf(stderr, "snell-lab: --technique '%s': an empty name in the list; valid: %s, all\n", arg.c_str(),
                     techniqueNames().c_str());
        return 2;
      }
      names.push_back(name);
      if (comma == std::string::npos) break;
      from = comma + 1;
    }
  }
  for (const std::string& t : names) {
    if (t == "all") continue;
    const LabRowSpec row = findRow(t);
    if (!row.technique && !row.engine) {
      std::fprintf(stderr, "snell-lab: unknown technique '%s'; valid: %s, all\n", t.c_str(), techniqueNames().c_str());
      return 2;
    }
    o.techniques.push_back(t);
  }
  if (std::find(names.begin(), names.end(), "all") != names.end()) o.techniques.clear();
  if (!size.empty()) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    std::istringstream in(size);
    if (!(in >> w >> x >> h) || (x != 'x' && x != 'X') || (in >> extra) || w < kMinRenderSize || h < kMinRenderSize ||
        w > kMaxRenderSize || h > kMaxRenderSize) {
      std::fprintf(stderr, "snell-lab: --size: expected WxH with %d <= W, H <= %d (e.g. 512x512), got '%s'\n",
                   kMinRenderSize, kMaxRenderSize, size.c_str());
      return 2;
    }
    o.width = w;
    o.height = h;
  }
  o.normalFilter = normalFilter == "nearest" ? NormalFilter::Nearest : NormalFilter::Linear;
  o.depthFilter = depthFilter == "bilinear" ? SNELL_DEPTH_FILTER_BILINEAR : SNELL_DEPTH_FILTER_NEAREST;
  o.reflectSource = reflection == "environment" ? SNELL_SOURCE_ENVIRONMENT : SNELL_SOURCE_BUFFERS;
  o.sceneLayer = sceneLayer == "full" ? SceneLayer::Full : sceneLayer == "peeled" ? SceneLayer::Peeled : SceneLayer::Behind;
  o.insideScene = insideScene == "auto" ? -1 : insideScene == "on" ? 1 : 0;
  o.dirs = shaderDirs();
  try {
    const LabResult r = runLab(o);
    if (!o.quiet) {
      std::printf("%s\n%s", r.markdown.c_str(), r.targets.c_str());
      if (!o.outDir.empty())
        std::printf("\nwrote %s/{overview.png, <technique>.png, ground_truth.png, reference_two_interfaces.png, "
                    "table.md, table.json} in %.1f s (ray tracing %.1f s)\n",
                    o.outDir.c_str(), r.totalSeconds, r.traceSeconds);
    }
    return 0;
  } catch (const Error& e) {
    std::fprintf(stderr, "snell-lab: %s\n", e.what());
    return exitCode(e.kind());
  } catch (const snell::gpu::Error& e) {
    std::fprintf(stderr, "snell-lab: GL failure: %s\n", e.what());
    return 5;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "snell-lab: %s\n", e.what());
    return 5;
  }
}
