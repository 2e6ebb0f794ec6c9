// On the GL driver (llvmpipe, both backends): the colour pyramid built by the
// GL pass glsl/passes/color_pyramid.frag (snellColorPyramidReduce on the GPU,
// each level reading only the one below) equals the one
// snell::snellBuildColorPyramid builds in C++ on every level, to float
// rounding, on even, odd and 1-texel-wide sizes and with non-finite texels.
#include <gtest/gtest.h>

#include <snell/gpu/color_pyramid_pass.hpp>

#include <snell/color_pyramid.hpp>
#include <snell/gpu/context.hpp>
#include <snell/gpu/resources.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <random>
#include <string>

namespace {

namespace fs = std::filesystem;
using namespace snell::gpu;

const fs::path kRoot = SNELL_SOURCE_DIR;

snell::Image picture(int w, int h, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 3.0f);
  snell::Image img(w, h);
  for (glm::vec4& t : img.texels) t = glm::vec4(u(rng), u(rng), u(rng), 1.0f);
  return img;
}

class ColorPyramidGpu : public ::testing::TestWithParam<Backend> {};

TEST_P(ColorPyramidGpu, GlPassEqualsCppBuilderOnEveryLevel) {
  Context ctx(GetParam());
  const GlApi& gl = ctx.gl();
  const ColorPyramidPass pass(gl, kRoot / "glsl");
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  for (const auto& [w, h] : {std::pair{203, 117}, {128, 64}, {1, 37}, {640, 640}}) {
    snell::Image base = picture(w, h, unsigned(w + 7 * h));
    base.at(w / 3, h / 2) = glm::vec4(nan, 1.0f, 1.0f, 1.0f);
    base.at(w - 1, h - 1) = glm::vec4(1.0f, inf, 1.0f, 1.0f);
    const snell::Texture2D cpu = snell::snellBuildColorPyramid(base);
    const Texture texture(gl, snell::Texture2D(base));
    const ColorPyramid pyramid(gl, texture.id(), w, h);
    ASSERT_EQ(pyramid.levels(), cpu.levelCount());
    pass.build(pyramid);
    double worst = 0.0;
    for (int lod = 1; lod < cpu.levelCount(); ++lod) {
      const snell::Image got = pyramid.readLevel(lod);
      const snell::Image& want = cpu.level(lod);
      ASSERT_EQ(got.width, want.width);
      ASSERT_EQ(got.height, want.height);
      for (std::size_t i = 0; i < want.texels.size(); ++i)
        for (int c = 0; c < 4; ++c) {
          const float g = got.texels[i][c], x = want.texels[i][c];
          ASSERT_TRUE(std::isfinite(g)) << w << "x" << h << " level " << lod << " texel " << i;
          worst = std::max(worst, double(std::fabs(g - x)) / std::max(1.0, double(std::fabs(x))));
        }
    }
    std::printf("[colour pyramid] %dx%d levels %d worst relative difference %.3g\n", w, h, cpu.levelCount(), worst);
    EXPECT_LT(worst, 1e-5) << w << "x" << h;
  }
}

// The pass moves the base and max level while it draws; after it the whole chain is selectable again.
TEST_P(ColorPyramidGpu, TheWholeChainIsSelectableAfterABuild) {
  Context ctx(GetParam());
  const GlApi& gl = ctx.gl();
  const ColorPyramidPass pass(gl, kRoot / "glsl");
  const Texture texture(gl, snell::Texture2D(snell::Image(64, 64, glm::vec4(1.0f))));
  const ColorPyramid pyramid(gl, texture.id(), 64, 64);
  pass.build(pyramid);
  GLint base = -1, max = -1, minFilter = 0;
  gl.BindTexture(GL_TEXTURE_2D, texture.id());
  gl.GetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, &base);
  gl.GetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, &max);
  gl.GetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &minFilter);
  gl.BindTexture(GL_TEXTURE_2D, 0);
  EXPECT_EQ(base, 0);
  EXPECT_EQ(max, 6);
  EXPECT_EQ(minFilter, GL_LINEAR_MIPMAP_LINEAR);
}

TEST(ColorPyramidPass, BadInputIsAnError) {
  Context ctx;
  try {
    const ColorPyramidPass pass(ctx.gl(), "/nonexistent/snell/glsl");
    ADD_FAILURE() << "a pass was built without its shaders";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("cannot open GLSL file /nonexistent/snell/glsl/passes/", 0), 0u) << what;
  }
  EXPECT_THROW(ColorPyramid(ctx.gl(), 0, 64, 64), Error);
  EXPECT_THROW(ColorPyramid(ctx.gl(), 1, 0, 64), Error);
  EXPECT_THROW(ColorPyramid(ctx.gl(), 1, 64, -2), Error);
  // A texture whose level 0 is not the size given: the chain would be incomplete, and read as black.
  const Texture texture(ctx.gl(), snell::Texture2D(snell::Image(32, 16)));
  try {
    const ColorPyramid pyramid(ctx.gl(), texture.id(), 64, 64);
    ADD_FAILURE() << "a pyramid was built over a texture of another size";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("level 0 is 32x16 RGBA32F, not 64x64 RGBA32F"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(ColorPyramid(ctx.gl(), texture.id(), 32, 16));
}

INSTANTIATE_TEST_SUITE_P(Backends, ColorPyramidGpu, ::testing::ValuesIn(snell::gpu::kGlBackends),
                         snell::gpu::BackendParamName());

}  // namespace
