// snell-gallery: Sousa's water, glass and heat haze, the ice block with
// cracks and G. Oliveira's refractive texture mapping, rendered on the GL
// driver (Mesa llvmpipe by default), checked against C++ and their exact
// answers; pictures, frame strips and the table under --out.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <snell/gpu/error.hpp>

#include "gallery.hpp"
#include "lab/cli.hpp"
#include "lab/camera.hpp"
#include "lab/error.hpp"

int main(int argc, char** argv) {
  snell::gallery::Options o;
  o.labGlsl = SNELL_LAB_GLSL_DIR;
  o.snellGlsl = SNELL_GLSL_DIR;
  if (const char* env = std::getenv("SNELL_LAB_GLSL_DIR")) o.labGlsl = env;
  if (const char* env = std::getenv("SNELL_GLSL_DIR")) o.snellGlsl = env;
  CLI::App app{"snell-gallery: every seed effect rendered on Mesa and checked against C++"};
  std::string size = "512x512", out = "gallery-out";
  app.add_option("--size", size, "render size WxH (default 512x512)");
  app.add_option("--frames", o.frames, "animation frames per animated effect (default 6)")->check(CLI::Range(0, 64));
  app.add_option("--repeats", o.timingRepeats, "interleaved timing rounds (default 7)")->check(CLI::Range(1, 1000));
  app.add_option("--backend", o.backend, "GL backend: auto, osmesa or egl")
      ->check(CLI::IsMember({"auto", "osmesa", "egl"}));
  app.add_option("--effect", o.effects, "effects to run (default all): water, glass, ice, rtm")
      ->check(CLI::IsMember(snell::gallery::effectNames()));
  app.add_option("--out", out, "output directory (default gallery-out)");
  if (const int code = snell::lab::parseCommandLine(app, argc, argv); code >= 0) return code;
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(size.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') ||
      w < snell::lab::kMinRenderSize || h < snell::lab::kMinRenderSize || w > snell::lab::kMaxRenderSize ||
      h > snell::lab::kMaxRenderSize) {
    std::cerr << "snell-gallery: --size must be WxH with both in [" << snell::lab::kMinRenderSize << ", "
              << snell::lab::kMaxRenderSize << "], got \"" << size << "\"\n";
    return 2;
  }
  o.width = w;
  o.height = h;
  o.out = out;
  try {
    snell::gallery::runGallery(o);
    std::ifstream table(o.out / "table.md");
    std::cout << table.rdbuf();
    std::cout << "\nsnell-gallery: pictures and table in " << o.out.string() << "\n";
    return 0;
  } catch (const snell::lab::Error& e) {
    std::cerr << "snell-gallery: " << e.what() << "\n";
    return snell::lab::exitCode(e.kind());
  } catch (const snell::gpu::Error& e) {
    std::cerr << "snell-gallery: GL: " << e.what() << "\n";
    return 6;
  } catch (const std::exception& e) {
    std::cerr << "snell-gallery: " << e.what() << "\n";
    return 1;
  }
}
