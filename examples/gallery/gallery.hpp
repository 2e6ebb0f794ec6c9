// snell-gallery: every seed effect of the papers rendered on the GL
// driver (Mesa llvmpipe by default) and shaded again in C++ from the read-back
// buffers with the same function (examples/glsl/gallery_effects.glsl), with
// the comparisons each effect has an exact answer for, a frame strip where the
// paper animates, and one table of cost and CPU-vs-GPU agreement.
#pragma once
#include <filesystem>
#include <map>
#include <snell/bridge.hpp>
#include <string>
#include <vector>

namespace snell::gallery {

struct Options {
  int width = 512, height = 512;
  int frames = 6;         // animation frames per animated effect (the strip)
  int timingRepeats = 7;  // interleaved timing rounds; the median is reported
  std::string backend = "auto";
  std::filesystem::path out = "gallery-out";
  std::vector<std::string> effects;  // empty: all (water, glass, ice, rtm)
  std::filesystem::path labGlsl, snellGlsl;
};

// One row of the table: one effect variant.
struct Row {
  std::string effect, variant;
  int fetches = 0;                        // texture reads per shaded pixel, G-buffer reads excluded
  double passMs = 0.0;                    // the effect pass, median over the rounds
  double plainMs = 0.0;                   // the plain textured pass of the same rounds
  long pixels = 0;                        // pixels the effect shaded
  double cpuGpuMax = 0.0;                 // largest |CPU - GPU| over those pixels and RGB
  double within1 = 0.0;                   // share of those pixels with every channel within 1/255
  std::string check;                      // the effect's own comparison (leaks, crack mismatches, uv error)
  std::map<std::string, double> metrics;  // the same numbers by name, for table.json and the tests
};

struct EffectResult {
  std::vector<Row> rows;
  std::vector<std::string> pictures;  // paths relative to Options::out
  std::vector<std::string> findings;  // lines for the report, Markdown
};

const std::vector<std::string>& effectNames();

// Runs the chosen effects, writes pictures, table.md and table.json to
// options.out and returns the table. Throws snell::gpu::Error (GL) or
// snell::lab::Error (files) on failure.
std::vector<EffectResult> runGallery(const Options& options);

}  // namespace snell::gallery
