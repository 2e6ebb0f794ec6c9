// The whole-frame GPU-vs-C++ comparison: one function's image from the GL
// driver against the same function run in C++ on the read-back inputs, pixel
// by pixel over RGB, as snell-lab, snell-gallery and the GPU tests judge it.
//
//   snell::gpu::FrameComparison c = snell::gpu::compareFrames(gpuImage, cpuImage,
//       [&](int x, int y) { return coverage.at(x, y).w > 0.0f; });
//   EXPECT_GE(c.shareWithin1(), 0.999);
//
// A pixel's difference is the largest |gpu - cpu| of its three channels,
// computed in float (with ClampChannels::ToUnit both sides are first clamped
// to [0, 1], the displayable values). A NaN on either side never agrees: the
// pixel counts in nanPixels and beyond 4/255 (onBeyond4 is called), and maxAbs
// stays the largest finite difference, so reports stay numbers. Within 1/255:
// difference <= 1/255; beyond 4/255: difference > 4/255 (float thresholds).
#pragma once

#include <snell/bridge.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace snell::gpu {

enum class ClampChannels { No, ToUnit };

struct FrameComparison {
  std::size_t pixels = 0;   // pixels compared
  std::size_t within1 = 0;  // every channel within 1/255
  std::size_t beyond4 = 0;  // some channel beyond 4/255, or a NaN
  std::size_t nanPixels = 0;  // a NaN on either side
  double maxAbs = 0.0;      // the largest finite difference
  int worstX = -1, worstY = -1;  // where maxAbs was first reached (-1: no pixel differs)

  double shareWithin1() const { return pixels ? double(within1) / double(pixels) : 0.0; }
  double shareBeyond1() const { return pixels ? double(pixels - within1) / double(pixels) : 0.0; }
  double shareBeyond4() const { return pixels ? double(beyond4) / double(pixels) : 0.0; }
};

namespace detail {
inline float frameChannel(float v, ClampChannels c) {
  return c == ClampChannels::ToUnit ? std::min(std::max(v, 0.0f), 1.0f) : v;
}
struct NoBeyond4 {
  void operator()(int, int) const {}
};
}  // namespace detail

// Compares the pixels (x, y) for which compared(x, y) holds; onBeyond4(x, y)
// is called for each one beyond 4/255 (to classify it, e.g. as a rounding tie).
// Throws std::invalid_argument when the sizes differ.
template <class Compared, class OnBeyond4 = detail::NoBeyond4>
FrameComparison compareFrames(const snell::Image& gpu, const snell::Image& cpu, Compared compared,
                              ClampChannels clamp = ClampChannels::No, OnBeyond4 onBeyond4 = {}) {
  if (gpu.width != cpu.width || gpu.height != cpu.height)
    throw std::invalid_argument("compareFrames: the GPU image is " + std::to_string(gpu.width) + "x" +
                                std::to_string(gpu.height) + ", the C++ image " + std::to_string(cpu.width) + "x" +
                                std::to_string(cpu.height));
  FrameComparison r;
  for (int y = 0; y < gpu.height; ++y)
    for (int x = 0; x < gpu.width; ++x) {
      if (!compared(x, y)) continue;
      ++r.pixels;
      float d = 0.0f;
      bool nan = false;
      for (int c = 0; c < 3; ++c) {
        const float e =
            std::abs(detail::frameChannel(gpu.at(x, y)[c], clamp) - detail::frameChannel(cpu.at(x, y)[c], clamp));
        if (std::isnan(e)) nan = true;
        else d = std::max(d, e);
      }
      if (nan) {
        ++r.nanPixels;
        ++r.beyond4;
        onBeyond4(x, y);
        continue;
      }
      if (static_cast<double>(d) > r.maxAbs) {
        r.maxAbs = static_cast<double>(d);
        r.worstX = x;
        r.worstY = y;
      }
      r.within1 += d <= 1.0f / 255.0f;
      if (d > 4.0f / 255.0f) {
        ++r.beyond4;
        onBeyond4(x, y);
      }
    }
  return r;
}

}  // namespace snell::gpu
