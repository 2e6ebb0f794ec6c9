// The four gallery effects. Each renders its scene on `gl`, shades the effect
// pass again in C++ from the read-back buffers, runs its own exact
// comparison, writes its pictures under options.out and returns its rows.
#pragma once
#include <snell/snell.hpp>

#include "gallery.hpp"
#include "gallery_gl.hpp"

namespace snell {
#include "gallery_effects.glsl"
}  // namespace snell

namespace snell::gallery {

EffectResult runWater(const Gl& gl, const Options& options);
EffectResult runGlass(const Gl& gl, const Options& options);
EffectResult runIce(const Gl& gl, const Options& options);
EffectResult runRtm(const Gl& gl, const Options& options);

// A row from its names, cost and CPU-vs-GPU agreement.
Row makeRow(const std::string& effect, const std::string& variant, int fetches, double passMs, double plainMs,
            const gpu::FrameComparison& agreement);

// Shared by the effects' pictures.
Image downscale(const Image& image, int factor);            // box filter
Image strip(const std::vector<Image>& frames, int factor);  // frames side by side, downscaled
void savePanel(const Options& options, const std::string& name,
               const std::vector<std::pair<const Image*, std::string>>& items, const std::string& caption,
               EffectResult& result);
// The frame strip <effect>_strip.png and the frames, at half size, as
// frames/<effect>_<i>.png (scripts/gallery.sh turns them into an animated PNG).
void saveAnimation(const Options& options, const std::string& effect, const std::vector<Image>& frames,
                   EffectResult& result);
std::string fixed(double v, int digits);

}  // namespace snell::gallery
