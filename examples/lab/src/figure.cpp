#include "lab/figure.hpp"

#include "lab/image_io.hpp"
#include "lab/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <sstream>
#include <vector>

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wunused-function"
#endif
#include <stb/stb_easy_font.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace snell::lab {

vec3 heatColor(float t) {
  // Display-space control points, close to matplotlib's "inferno", ending in white.
  static const float kRamp[9][3] = {{0.000f, 0.000f, 0.015f}, {0.120f, 0.040f, 0.300f}, {0.320f, 0.060f, 0.430f},
                                    {0.530f, 0.130f, 0.420f}, {0.730f, 0.210f, 0.330f}, {0.890f, 0.350f, 0.190f},
                                    {0.980f, 0.560f, 0.040f}, {0.980f, 0.810f, 0.180f}, {1.000f, 1.000f, 1.000f}};
  const float c = t > 0.0f ? std::min(t, 1.0f) * 8.0f : 0.0f;
  const int i = std::min(static_cast<int>(c), 7);
  const float f = c - static_cast<float>(i);
  vec3 out;
  for (int k = 0; k < 3; ++k) out[k] = srgbDecode(kRamp[i][k] * (1.0f - f) + kRamp[i + 1][k] * f);
  return out;
}

Image errorHeatMap(const Image& reference, const Image& test, const Mask& mask, float maxRms) {
  if (reference.width != test.width || reference.height != test.height || mask.width != reference.width ||
      mask.height != reference.height)
    throw std::invalid_argument("errorHeatMap: image and mask sizes differ");
  Image out(reference.width, reference.height, vec4(0.0f, 0.0f, 0.0f, 1.0f));
  const float scale = maxRms > 0.0f ? 1.0f / maxRms : 0.0f;
  for (int y = 0; y < reference.height; ++y)
    for (int x = 0; x < reference.width; ++x) {
      if (mask.at(x, y)) {
        const float rms = static_cast<float>(std::sqrt(pixelSquaredError(reference.at(x, y), test.at(x, y))));
        out.at(x, y) = vec4(heatColor(rms * scale), 1.0f);
      } else {
        const vec4& r = reference.at(x, y);
        const float lum = 0.2126f * r.x + 0.7152f * r.y + 0.0722f * r.z;
        const float g = 0.2f * (lum > 0.0f ? std::min(lum, 1.0f) : 0.0f);
        out.at(x, y) = vec4(g, g, g, 1.0f);
      }
    }
  return out;
}

Image heatLegend(int width, int height) {
  Image out(width, height);
  for (int x = 0; x < width; ++x) {
    const vec3 c = heatColor(width > 1 ? static_cast<float>(x) / static_cast<float>(width - 1) : 0.0f);
    for (int y = 0; y < height; ++y) out.at(x, y) = vec4(c, 1.0f);
  }
  return out;
}

namespace {
struct EasyFontVertex {
  float x, y, z;
  unsigned char color[4];
};

std::vector<EasyFontVertex> layoutText(const std::string& text) {
  // stb_easy_font: ~270 bytes per character is its documented worst case.
  std::vector<EasyFontVertex> buffer(text.size() * 300 / sizeof(EasyFontVertex) + 64);
  std::string copy = text;
  const int quads = stb_easy_font_print(0.0f, 0.0f, copy.data(), nullptr, buffer.data(),
                                        static_cast<int>(buffer.size() * sizeof(EasyFontVertex)));
  buffer.resize(static_cast<std::size_t>(quads) * 4);
  return buffer;
}
}  // namespace

int textWidth(const std::string& text, int scale) {
  std::string copy = text;
  return stb_easy_font_width(copy.data()) * scale;
}

int textHeight(const std::string& text, int scale) {
  std::string copy = text;
  return stb_easy_font_height(copy.data()) * scale;
}

void drawText(Image& image, int x, int yTop, const std::string& text, vec3 color, int scale) {
  const std::vector<EasyFontVertex> v = layoutText(text);
  for (std::size_t q = 0; q + 3 < v.size(); q += 4) {
    // Axis-aligned quads in a y-down frame, in whole font units.
    const int x0 = static_cast<int>(std::lround(v[q].x)), y0 = static_cast<int>(std::lround(v[q].y));
    const int x1 = static_cast<int>(std::lround(v[q + 2].x)), y1 = static_cast<int>(std::lround(v[q + 2].y));
    for (int fy = std::min(y0, y1) * scale; fy < std::max(y0, y1) * scale; ++fy)
      for (int fx = std::min(x0, x1) * scale; fx < std::max(x0, x1) * scale; ++fx) {
        const int px = x + fx, rowFromTop = yTop + fy;
        const int py = image.height - 1 - rowFromTop;
        if (px < 0 || px >= image.width || py < 0 || py >= image.height) continue;
        image.at(px, py) = vec4(color, 1.0f);
      }
  }
}

void blit(Image& dst, const Image& src, int x, int yTop) {
  for (int sy = 0; sy < src.height; ++sy) {
    const int rowFromTop = yTop + (src.height - 1 - sy);
    const int dy = dst.height - 1 - rowFromTop;
    if (dy < 0 || dy >= dst.height) continue;
    for (int sx = 0; sx < src.width; ++sx) {
      const int dx = x + sx;
      if (dx < 0 || dx >= dst.width) continue;
      dst.at(dx, dy) = src.at(sx, sy);
    }
  }
}

Image composePanel(const std::vector<PanelItem>& items, const std::string& caption, int gap, int scale) {
  if (items.empty()) throw std::invalid_argument("composePanel: no images");
  const int h = items.front().image->height;
  int width = gap;
  for (const PanelItem& it : items) {
    if (!it.image || it.image->height != h) throw std::invalid_argument("composePanel: images differ in height");
    width += it.image->width + gap;
  }
  const int labelStrip = 7 * scale + 2 * gap;
  // The caption wrapped at spaces to the panel's width (at 256 px a technique's
  // caption is wider than the panel); a word wider than the panel stays whole.
  std::vector<std::string> lines;
  {
    std::string line, word;
    std::istringstream words(caption);
    while (words >> word) {
      const std::string longer = line.empty() ? word : line + " " + word;
      if (!line.empty() && textWidth(longer, scale) > width - 2 * gap) {
        lines.push_back(line);
        line = word;
      } else {
        line = longer;
      }
    }
    if (!line.empty()) lines.push_back(line);
  }
  const int lineHeight = 7 * scale + scale + 1;
  const int captionStrip = lines.empty() ? 0 : static_cast<int>(lines.size()) * lineHeight + gap;
  const int height = labelStrip + h + gap + captionStrip;
  Image out(width, height, vec4(0.02f, 0.02f, 0.025f, 1.0f));
  int x = gap;
  const vec3 white(0.9f);
  for (const PanelItem& it : items) {
    drawText(out, x, gap, it.label, white, scale);
    blit(out, *it.image, x, labelStrip);
    x += it.image->width + gap;
  }
  for (std::size_t i = 0; i < lines.size(); ++i)
    drawText(out, gap, labelStrip + h + gap / 2 + static_cast<int>(i) * lineHeight, lines[i], vec3(0.7f), scale);
  return out;
}

}  // namespace snell::lab
