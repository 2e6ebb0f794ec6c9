// snell-lab-reference: the lab's ground truth on its own. Loads a scene,
// ray-traces it with the Embree reference tracer (full Fresnel + TIR, or the
// two-interface model) and writes the image, the object mask and timing.
#include "lab/error.hpp"
#include "lab/figure.hpp"
#include "lab/metrics.hpp"
#include "lab/image_io.hpp"
#include "lab/scene.hpp"
#include "lab/tracer.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv) {
  using namespace snell::lab;
  CLI::App app{"Render the ray-traced ground truth of a snell lab scene to PNG."};
  std::string scenePath = SNELL_LAB_DEFAULT_SCENE;
  std::string output = "reference.png";
  std::string maskOutput;
  std::string panelOutput;
  std::string mode = "full";
  int frame = 0, threads = 0, width = 0, height = 0, maxDepth = 16;
  bool quiet = false, noFresnel = false;
  app.add_option("scene", scenePath, "scene file (JSON, see examples/scenes/README.md)")->capture_default_str();
  app.add_option("-o,--output", output, "output PNG (sRGB)")->capture_default_str();
  app.add_option("--mask", maskOutput, "also write the object mask PNG here");
  app.add_option("--panel", panelOutput,
                 "also render the other mode and write \"full | two interfaces | error\" here (model + TIR error)");
  app.add_option("--mode", mode, "full: Fresnel + TIR at every interface; two: refract in, refract out, look up")
      ->check(CLI::IsMember({"full", "two"}))
      ->capture_default_str();
  app.add_option("--frame", frame,
                 "animation frame (time = time_start + frame * time_step; the camera panned by frame * "
                 "camera_pan_pixels)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--width", width, "override the scene's resolution (with --height)")->check(CLI::PositiveNumber);
  app.add_option("--height", height, "override the scene's resolution (with --width)")->check(CLI::PositiveNumber);
  app.add_option("--max-depth", maxDepth, "interface events per path (full mode)")->capture_default_str();
  app.add_option("--threads", threads, "worker threads (0: all cores)")->capture_default_str();
  app.add_flag("--no-fresnel", noFresnel, "transmission only");
  app.add_flag("-q,--quiet", quiet, "no progress bar");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    Scene scene = loadScene(scenePath);
    if (width > 0) scene.camera.width = width;
    if (height > 0) scene.camera.height = height;
    const SceneFrame f = buildAnimationFrame(scene, frame);
    const ReferenceTracer tracer(f);
    TraceOptions opt;
    opt.mode = mode == "two" ? TraceMode::TwoInterfaces : TraceMode::Full;
    opt.fresnel = !noFresnel;
    opt.maxDepth = maxDepth;
    opt.threads = threads;
    opt.progress = !quiet;
    const TraceResult r = tracer.render(f.camera, opt);
    writePng(output, r.color);
    if (!maskOutput.empty()) {
      snell::Image m(r.mask.width, r.mask.height);
      for (int y = 0; y < m.height; ++y)
        for (int x = 0; x < m.width; ++x) m.at(x, y) = snell::vec4(r.mask.at(x, y) ? 1.0f : 0.0f);
      writePng(maskOutput, m, PngEncoding::Linear);
    }
    if (!panelOutput.empty()) {
      TraceOptions other = opt;
      other.mode = opt.mode == TraceMode::Full ? TraceMode::TwoInterfaces : TraceMode::Full;
      other.progress = false;
      const TraceResult o = tracer.render(f.camera, other);
      const TraceResult& full = opt.mode == TraceMode::Full ? r : o;
      const TraceResult& two = opt.mode == TraceMode::Full ? o : r;
      const ErrorStats e = compareImages(full.color, two.color, full.mask);
      const snell::Image heat = errorHeatMap(full.color, two.color, full.mask);
      char caption[160];
      std::snprintf(caption, sizeof caption, "%s: MSE(two interfaces vs full) %.3g over %zu object pixels",
                    scene.name.c_str(), e.mse, e.pixels);
      writePng(panelOutput, composePanel({{&full.color, "ray traced (full)"},
                                          {&two.color, "two interfaces"},
                                          {&heat, "error (RMS, white = 0.25)"}},
                                         caption));
    }
    const double pixels = static_cast<double>(f.camera.width) * f.camera.height;
    std::size_t triangles = 0;
    for (const FrameObject& o : f.objects) triangles += o.mesh.triangleCount();
    std::printf("%s: %dx%d, %zu triangles, %s mode: %.3f s (%.0f ms/Mpixel), %.2f Mrays/s, object pixels %llu, "
                "TIR %llu, leaks %llu, truncated %llu -> %s\n",
                scene.name.c_str(), f.camera.width, f.camera.height, triangles, mode.c_str(),
                r.stats.seconds, 1e3 * r.stats.seconds / (pixels / 1e6),
                static_cast<double>(r.stats.rays) / r.stats.seconds / 1e6,
                static_cast<unsigned long long>(r.stats.objectPixels), static_cast<unsigned long long>(r.stats.tirEvents),
                static_cast<unsigned long long>(r.stats.leaks), static_cast<unsigned long long>(r.stats.truncated),
                output.c_str());
    return 0;
  } catch (const Error& e) {
    std::fprintf(stderr, "snell-lab-reference: %s\n", e.what());
    return exitCode(e.kind());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "snell-lab-reference: %s\n", e.what());
    return 1;
  }
}
