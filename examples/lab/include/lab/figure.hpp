// Comparison figures: the error heat map, text labels (stb_easy_font, a tiny
// built-in vector font), and panels of images side by side with a label strip.
#pragma once
#include "lab/mask.hpp"

#include <snell/bridge.hpp>

#include <string>
#include <vector>

namespace snell::lab {

// A perceptual black -> purple -> orange -> yellow -> white ramp ("inferno"-
// like, 9 control points defined in display (sRGB) space, linear in between),
// returned as *linear* RGB so it can share a panel with renders; t clamped to [0, 1].
vec3 heatColor(float t);

// Heat map of the per-pixel RMS error sqrt(mean over RGB of (a - b)^2) between
// two linear images (clamped to [0, 1], as in compareImages): 0 -> black,
// `maxRms` or more -> white. Pixels outside the mask show the reference's
// luminance dimmed to 20 % as context. Linear output.
Image errorHeatMap(const Image& reference, const Image& test, const Mask& mask, float maxRms = 0.25f);

// A horizontal colour bar of heatColor from 0 (left) to 1 (right), linear.
Image heatLegend(int width, int height);

// Draws text with its top-left corner at pixel (x, yTop) counted from the top
// of the image (the image itself is stored bottom-up). `scale` is an integer
// pixel size multiplier (1: ~7 px tall glyphs). Clipped to the image.
void drawText(Image& image, int x, int yTop, const std::string& text, vec3 color, int scale = 2);
int textWidth(const std::string& text, int scale = 2);
int textHeight(const std::string& text, int scale = 2);

// Pastes `src` into `dst` with src's top-left at (x, yTop) from dst's top. Clipped.
void blit(Image& dst, const Image& src, int x, int yTop);

struct PanelItem {
  const Image* image = nullptr;  // linear RGB
  std::string label;
};

// Images side by side (all must have the same height), `gap` pixels apart,
// on a dark background, each with its label in a strip above it; an optional
// caption below, wrapped to the width. Linear output: write with PngEncoding::Srgb.
Image composePanel(const std::vector<PanelItem>& items, const std::string& caption = "", int gap = 8,
                   int scale = 2);

}  // namespace snell::lab
