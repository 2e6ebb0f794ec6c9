#include "pictures.hpp"
#include "report.hpp"

#include "lab/error.hpp"
#include "lab/figure.hpp"
#include "lab/image_io.hpp"
#include "lab/metrics.hpp"

#include <algorithm>

namespace snell::lab {

namespace fs = std::filesystem;

namespace {

Image downscale(const Image& img, int factor) {
  if (factor <= 1) return img;
  Image out(std::max(1, img.width / factor), std::max(1, img.height / factor));
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      vec4 s(0.0f);
      for (int dy = 0; dy < factor; ++dy)
        for (int dx = 0; dx < factor; ++dx) s += img.at(x * factor + dx, y * factor + dy);
      out.at(x, y) = s / static_cast<float>(factor * factor);
    }
  return out;
}

}  // namespace

void writeOutputs(const fs::path& out, const References& refs, const std::vector<Image>& images,
                  const std::vector<Image>& rendererImages,
                  const std::string& gpuDescription, LabResult& result,
                  std::chrono::steady_clock::time_point start) {
  const Image& full = refs.full.color;
  const Image& two = refs.two.color;
  const int W = result.width, H = result.height;
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw Error(ErrorKind::Io, "cannot create output directory " + out.string() + ": " + ec.message());
  writePng((out / "ground_truth.png").string(), full);
  const Image modelHeat = errorHeatMap(full, two, refs.full.mask);
  writePng((out / "reference_two_interfaces.png").string(),
           composePanel({{&full, "ray traced (full)"}, {&two, "two interfaces"}, {&modelHeat, "error"}},
                        result.scene + ": two-interface model, MSE " + fmt("%.3g", result.mseTwoVsFull)));
  if (result.mseCompositedVsFull >= 0.0) {
    const Image& comp = refs.composited.color;
    const Image heat = errorHeatMap(full, comp, refs.full.mask);
    writePng((out / "reference_composited.png").string(),
             composePanel({{&full, "ray traced (full)"}, {&comp, "objects composited"}, {&heat, "error"}},
                          result.scene + ": composited two-interface model, MSE " + fmt("%.3g", result.mseCompositedVsFull)));
  }
  const int factor = W >= 512 ? 2 : 1;
  std::vector<Image> tiles;
  std::vector<std::string> labels;
  tiles.push_back(downscale(full, factor));
  labels.push_back("ray traced");
  tiles.push_back(downscale(two, factor));
  labels.push_back("two interfaces " + fmt("%.2g", result.mseTwoVsFull));
  for (std::size_t i = 0; i < result.rows.size(); ++i) {
    const TechniqueRow& r = result.rows[i];
    const Image heat = errorHeatMap(full, images[i], refs.full.mask);
    // The time ratio is to single sample when it ran, else to the first row (as in the table).
    const bool singleRan = result.costUnitRow() != nullptr;
    char numbers[256];
    std::snprintf(numbers, sizeof numbers, ": MSE %.3g (two-interface ref. %.3g), invalid %.1f%%, %.1f fetches/px, %.2fx ",
                  r.mseFull, r.mseTwo, 100.0 * r.invalidShare, r.fetchesPerPixel, r.costRatio);
    const std::string caption = result.scene + ", " + r.label + numbers +
                                (singleRan ? "single sample's time" : "the time of " + result.rows.front().label);
    writePng((out / (r.name + ".png")).string(),
             composePanel({{&full, "ray traced"}, {&images[i], r.label}, {&heat, "error (RMS, white 0.25)"}}, caption));
    tiles.push_back(downscale(images[i], factor));
    labels.push_back(r.label + " " + fmt("%.2g", r.mseFull) + " " + fmt("%.2fx", r.costRatio));
  }
  for (std::size_t i = 0; i < result.renderers.size(); ++i) {
    const RendererRow& r = result.renderers[i];
    const Image heat = errorHeatMap(full, rendererImages[i], refs.full.mask);
    writePng((out / (r.name + ".png")).string(),
             composePanel({{&full, "ray traced"}, {&rendererImages[i], r.label}, {&heat, "error (RMS, white 0.25)"}},
                          result.scene + ", " + r.label + ": MSE " + fmt("%.3g", r.mseFull) + " (two-interface ref. " +
                              fmt("%.3g", r.mseTwo) + "), " + r.renderer));
    tiles.push_back(downscale(rendererImages[i], factor));
    labels.push_back(r.label + " " + fmt("%.2g", r.mseFull));
  }
  // Overview: rows of four tiles.
  const int perRow = 4, scale = 1;
  std::vector<Image> rows;
  for (std::size_t i = 0; i < tiles.size(); i += perRow) {
    std::vector<PanelItem> items;
    for (std::size_t j = i; j < std::min(tiles.size(), i + perRow); ++j) items.push_back({&tiles[j], labels[j]});
    rows.push_back(composePanel(items, "", 6, scale));
  }
  int cw = 0, ch = 0;
  for (const Image& r : rows) {
    cw = std::max(cw, r.width);
    ch += r.height;
  }
  const std::string title = result.scene + ": MSE vs ray tracing, time vs single sample (" + std::to_string(W) + "x" +
                            std::to_string(H) + ", " + gpuDescription.substr(0, gpuDescription.find(',')) + ")";
  const int titleH = textHeight(title, 1) + 8;
  Image overview(std::max(cw, textWidth(title, 1) + 12), ch + titleH, vec4(0.06f, 0.06f, 0.07f, 1.0f));
  drawText(overview, 6, 4, title, vec3(1.0f), 1);
  int yTop = titleH;
  for (const Image& r : rows) {
    blit(overview, r, 0, yTop);
    yTop += r.height;
  }
  writePng((out / "overview.png").string(), overview);
  writeText(out / "table.md", "# snell-lab: " + result.scene + "\n\n" + result.markdown + "\n" + result.targets);
  result.totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  writeJson(out / "table.json", result);
}

}  // namespace snell::lab
