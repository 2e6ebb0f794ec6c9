#include "gallery.hpp"

#include <cstdio>
#include <fstream>
#include <iomanip>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "effects.hpp"
#include "gallery_gl.hpp"
#include "lab/error.hpp"
#include "lab/figure.hpp"
#include "lab/image_io.hpp"

namespace snell::gallery {

namespace fs = std::filesystem;

const std::vector<std::string>& effectNames() {
  static const std::vector<std::string> names = {"water", "glass", "ice", "rtm"};
  return names;
}

std::string fixed(double v, int digits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

Row makeRow(const std::string& effect, const std::string& variant, int fetches, double passMs, double plainMs,
            const gpu::FrameComparison& agreement) {
  Row r;
  r.effect = effect;
  r.variant = variant;
  r.fetches = fetches;
  r.passMs = passMs;
  r.plainMs = plainMs;
  r.pixels = long(agreement.pixels);
  r.cpuGpuMax = agreement.maxAbs;
  r.within1 = agreement.shareWithin1();
  return r;
}

Image downscale(const Image& image, int factor) {
  const int f = std::max(1, factor);
  Image out(std::max(1, image.width / f), std::max(1, image.height / f));
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      vec4 sum(0.0f);
      for (int dy = 0; dy < f; ++dy)
        for (int dx = 0; dx < f; ++dx)
          sum += image.at(std::min(x * f + dx, image.width - 1), std::min(y * f + dy, image.height - 1));
      out.at(x, y) = sum / float(f * f);
    }
  return out;
}

Image strip(const std::vector<Image>& frames, int factor) {
  std::vector<Image> small;
  for (const Image& f : frames) small.push_back(downscale(f, factor));
  std::vector<lab::PanelItem> items;
  for (std::size_t i = 0; i < small.size(); ++i) items.push_back({&small[i], "t = " + std::to_string(i)});
  return lab::composePanel(items, "", 4, 1);
}

void savePanel(const Options& o, const std::string& name,
               const std::vector<std::pair<const Image*, std::string>>& items, const std::string& caption,
               EffectResult& result) {
  std::vector<lab::PanelItem> panel;
  for (const auto& it : items) panel.push_back({it.first, it.second});
  lab::writePng((o.out / name).string(), lab::composePanel(panel, caption));
  result.pictures.push_back(name);
}

void saveAnimation(const Options& o, const std::string& effect, const std::vector<Image>& frames,
                   EffectResult& result) {
  // Frames of an earlier run (more frames, another size) must not end up in this run's animation.
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(o.out / "frames", ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(effect + "_", 0) == 0 && entry.path().extension() == ".png") fs::remove(entry.path(), ec);
  }
  if (frames.empty()) return;
  const std::string stripName = effect + "_strip.png";
  lab::writePng((o.out / stripName).string(), strip(frames, 2));
  result.pictures.push_back(stripName);
  for (std::size_t f = 0; f < frames.size(); ++f)
    lab::writePng((o.out / ("frames/" + effect + "_" + std::to_string(f) + ".png")).string(), downscale(frames[f], 2));
}

namespace {

std::string tableMarkdown(const std::vector<EffectResult>& results, const std::string& gpu, const Options& o) {
  std::ostringstream t;
  t << "snell-gallery, " << o.width << "x" << o.height << ", " << gpu << "\n\n"
    << "| effect | variant | fetches/px | time ratio | pass (ms) | pixels | CPU-GPU max | CPU-GPU within 1/255 | check "
       "|\n"
    << "|---|---|---|---|---|---|---|---|---|\n";
  for (const EffectResult& r : results)
    for (const Row& row : r.rows)
      t << "| " << row.effect << " | " << row.variant << " | " << row.fetches << " | "
        << fixed(row.plainMs > 0.0 ? row.passMs / row.plainMs : 0.0, 2) << " | " << fixed(row.passMs, 2) << " | "
        << row.pixels << " | " << fixed(row.cpuGpuMax, 6) << " | " << fixed(100.0 * row.within1, 3) << " % | "
        << row.check << " |\n";
  t << "\nfetches/px: the effect pass's texture reads per shaded pixel, G-buffer reads excluded. time ratio: the "
       "effect pass over a plain pass that reads one texture per pixel of the whole frame, medians of "
    << o.timingRepeats
    << " interleaved rounds (glFinish and a steady clock; llvmpipe's milliseconds say little about a GPU). "
       "CPU-GPU: the same gallery function run in C++ on the read-back buffers, over the pixels the effect shaded.\n";
  for (const EffectResult& r : results)
    for (const std::string& f : r.findings) t << "\n" << f << "\n";
  return t.str();
}

nlohmann::json tableJson(const std::vector<EffectResult>& results, const std::string& gpu, const Options& o) {
  nlohmann::json j;
  j["size"] = {o.width, o.height};
  j["gpu"] = gpu;
  j["rows"] = nlohmann::json::array();
  for (const EffectResult& r : results)
    for (const Row& row : r.rows)
      j["rows"].push_back({{"effect", row.effect},
                           {"variant", row.variant},
                           {"fetches_per_pixel", row.fetches},
                           {"pass_ms", row.passMs},
                           {"plain_ms", row.plainMs},
                           {"time_ratio", row.plainMs > 0.0 ? row.passMs / row.plainMs : 0.0},
                           {"pixels", row.pixels},
                           {"cpu_gpu_max", row.cpuGpuMax},
                           {"cpu_gpu_within_1_255", row.within1},
                           {"check", row.check},
                           {"metrics", row.metrics}});
  return j;
}

void writeText(const fs::path& p, const std::string& text) {
  std::ofstream f(p, std::ios::binary);
  f << text;
  if (!f) throw lab::Error(lab::ErrorKind::Io, "cannot write " + p.string());
}

}  // namespace

std::vector<EffectResult> runGallery(const Options& o) {
  std::vector<std::string> chosen = o.effects.empty() ? effectNames() : o.effects;
  std::error_code ec;
  fs::create_directories(o.out / "frames", ec);
  if (ec) throw lab::Error(lab::ErrorKind::Io, "cannot create " + (o.out / "frames").string() + ": " + ec.message());
  Gl gl(o.backend, o);
  std::vector<EffectResult> results;
  for (const std::string& name : chosen) {
    std::fprintf(stderr, "snell-gallery: %s\n", name.c_str());
    if (name == "water")
      results.push_back(runWater(gl, o));
    else if (name == "glass")
      results.push_back(runGlass(gl, o));
    else if (name == "ice")
      results.push_back(runIce(gl, o));
    else if (name == "rtm")
      results.push_back(runRtm(gl, o));
    else
      throw std::invalid_argument("unknown effect \"" + name + "\"");
  }
  const std::string md = tableMarkdown(results, gl.description(), o);
  writeText(o.out / "table.md", md);
  writeText(o.out / "table.json", tableJson(results, gl.description(), o).dump(2) + "\n");
  return results;
}

}  // namespace snell::gallery
