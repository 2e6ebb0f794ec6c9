// snell-gallery end to end at a small size: every effect renders on
// Mesa, the C++ frame agrees with the GPU frame, and each effect's own
// comparison holds: the masks remove every leak the unmasked pass shows, the
// clipped cracks match the analytic solid, the per-vertex uvs agree and the
// approximate ray's error grows with the wave amplitude.
#include "gallery.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "effects.hpp"

namespace fs = std::filesystem;
using snell::gallery::EffectResult;
using snell::gallery::Row;

namespace {

const std::vector<EffectResult>& results() {
  static const std::vector<EffectResult> r = [] {
    snell::gallery::Options o;
    o.width = 128;
    o.height = 128;
    o.frames = 2;
    o.timingRepeats = 1;
    o.out = fs::path(SNELL_GALLERY_TEST_OUT);
    o.labGlsl = SNELL_LAB_GLSL_DIR;
    o.snellGlsl = SNELL_GLSL_DIR;
    return snell::gallery::runGallery(o);
  }();
  return r;
}

const Row& row(const std::string& effect, const std::string& variantStart) {
  for (const EffectResult& e : results())
    for (const Row& r : e.rows)
      if (r.effect == effect && r.variant.rfind(variantStart, 0) == 0) return r;
  throw std::runtime_error("no row " + effect + " / " + variantStart);
}

}  // namespace

TEST(Gallery, EveryFrameAgreesWithC) {
  int rows = 0;
  for (const EffectResult& e : results())
    for (const Row& r : e.rows) {
      ++rows;
      EXPECT_GT(r.pixels, 200) << r.effect << " / " << r.variant << ": the effect shaded (almost) nothing";
      EXPECT_GE(r.within1, 0.999) << r.effect << " / " << r.variant;
      EXPECT_GT(r.passMs, 0.0);
      EXPECT_GT(r.plainMs, 0.0);
    }
  EXPECT_EQ(rows, 9);
}

TEST(Gallery, TheAlphaMaskRemovesEveryLeak) {
  // The scenes must show the leak at all, or the masks prove nothing.
  EXPECT_GT(row("Sousa water", "mask off").metrics.at("leaks_nearest"), 0.0);
  EXPECT_GT(row("Sousa glass + heat haze", "haze without mask").metrics.at("leaks_nearest"), 0.0);
  // Sousa's alpha mask is exact per texel: no leak when S is read by nearest texel.
  EXPECT_EQ(row("Sousa water", "alpha mask").metrics.at("leaks_nearest"), 0.0);
  EXPECT_EQ(row("Sousa glass + heat haze", "haze, alpha mask").metrics.at("leaks_nearest"), 0.0);
  // The depth mask compares with this pixel's surface depth, so it passes objects in front of the
  // water elsewhere but behind it here; fewer than without a mask.
  EXPECT_LT(row("Sousa water", "depth mask").metrics.at("leaks_nearest"),
            row("Sousa water", "mask off").metrics.at("leaks_nearest"));
  // The leak counts do not depend on the build.
  for (const EffectResult& e : results())
    for (const Row& r : e.rows) {
      if (!r.metrics.count("leaks_bilinear")) continue;
      EXPECT_NEAR(r.metrics.at("leaks_bilinear"), r.metrics.at("leaks_cpu_bilinear"), 0.002 * double(r.pixels) + 2.0)
          << r.effect << " / " << r.variant;
    }
}

TEST(Gallery, CracksAreClippedToTheSolid) {
  const Row& r = row("ice", "with cracks");
  ASSERT_GT(r.metrics.at("crack_analytic"), 100.0);
  // Pixels where rasterization and the analytic ray disagree lie on the block's or a crack's edge.
  EXPECT_LE(r.metrics.at("crack_missed") + r.metrics.at("crack_extra"), 0.02 * r.metrics.at("crack_analytic"));
  EXPECT_EQ(r.metrics.at("crack_bits_cpu_differ"), 0.0);
}

TEST(Gallery, RefractiveTextureMappingAgreesPerVertexAndDriftsWithAmplitude) {
  const Row& approx = row("refractive texture mapping", "approximate");
  const Row& exact = row("refractive texture mapping", "Snell");
  EXPECT_LT(approx.metrics.at("vertex_uv_gpu_cpu_max_texels"), 0.05);
  EXPECT_LT(exact.metrics.at("vertex_uv_gpu_cpu_max_texels"), 0.05);
  const double flat = approx.metrics.at("approx_error_mean_texels_a0.00");
  const double rough = approx.metrics.at("approx_error_mean_texels_a0.15");
  EXPECT_LT(flat, rough);
  // Per pixel, Snell's law at the vertices is off by the interpolation only; the approximate ray by more.
  EXPECT_LT(exact.metrics.at("snell_vertex_pixel_error_mean_texels_a0.06"),
            approx.metrics.at("approx_pixel_error_mean_texels_a0.06"));
}

TEST(Gallery, WritesPicturesAndTables) {
  for (const EffectResult& e : results())
    for (const std::string& p : e.pictures) EXPECT_TRUE(fs::exists(fs::path(SNELL_GALLERY_TEST_OUT) / p)) << p;
  EXPECT_TRUE(fs::exists(fs::path(SNELL_GALLERY_TEST_OUT) / "table.md"));
  EXPECT_TRUE(fs::exists(fs::path(SNELL_GALLERY_TEST_OUT) / "table.json"));
}
