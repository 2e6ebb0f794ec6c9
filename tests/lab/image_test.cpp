// Image I/O, sRGB, the environment mapping, heat maps and panels.
#include "lab/environment.hpp"
#include "lab/figure.hpp"
#include "lab/image_io.hpp"
#include "lab/metrics.hpp"

#include "lab_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace snell::lab;
using snell::Image;
using snell::vec3;
using snell::vec4;

TEST(LabImage, SrgbRoundTrip) {
  for (int i = 0; i <= 1000; ++i) {
    const float v = static_cast<float>(i) / 1000.0f;
    EXPECT_NEAR(srgbDecode(srgbEncode(v)), v, 2e-6f);
  }
  EXPECT_FLOAT_EQ(srgbEncode(1.0f), 1.0f);
  EXPECT_FLOAT_EQ(srgbEncode(-1.0f), 0.0f);
  EXPECT_FLOAT_EQ(srgbEncode(std::nanf("")), 0.0f);
  EXPECT_NEAR(srgbEncode(0.5f), 0.735357f, 1e-5f);
}

TEST(LabImage, PngRoundTripKeepsValuesAndRowOrder) {
  const labtest::TempDir dir;
  Image img(37, 21);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      img.at(x, y) = vec4(static_cast<float>(x) / 36.0f, static_cast<float>(y) / 20.0f, 0.25f, 1.0f);
  img.at(0, img.height - 1) = vec4(1.0f, 0.0f, 0.0f, 1.0f);  // top-left pixel: red
  const std::string path = dir.file("round.png");
  writePng(path, img);
  const Image back = readImage(path);
  ASSERT_EQ(back.width, img.width);
  ASSERT_EQ(back.height, img.height);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c)  // 8-bit quantization in the sRGB domain
        EXPECT_NEAR(srgbEncode(back.at(x, y)[c]), srgbEncode(img.at(x, y)[c]), 0.5f / 255.0f + 1e-6f) << x << "," << y;
  EXPECT_EQ(back.at(0, back.height - 1), vec4(1.0f, 0.0f, 0.0f, 1.0f));
  // Linear encoding stores the values themselves.
  writePng(dir.file("lin.png"), img, PngEncoding::Linear);
  const Image lin = readImage(dir.file("lin.png"), /*linear=*/true);
  EXPECT_NEAR(lin.at(18, 10).x, img.at(18, 10).x, 0.5f / 255.0f + 1e-6f);
}

TEST(LabImage, ReadErrorsNameThePath) {
  const labtest::TempDir dir;
  const std::string missing = labtest::errorOf([] { readImage("/nonexistent/a.png"); }, ErrorKind::Io);
  EXPECT_NE(missing.find("image file not found: /nonexistent/a.png"), std::string::npos) << missing;
  const std::string junk = dir.write("junk.png", "this is not a png");
  const std::string bad = labtest::errorOf([&] { readImage(junk); }, ErrorKind::Parse);
  EXPECT_NE(bad.find(junk), std::string::npos) << bad;
  const std::string unwritable =
      labtest::errorOf([] { writePng("/nonexistent/dir/out.png", Image(2, 2)); }, ErrorKind::Io);
  EXPECT_NE(unwritable.find("/nonexistent/dir/out.png"), std::string::npos) << unwritable;
}

TEST(LabImage, EquirectMappingRoundTripsAndMatchesTheDocumentedAxes) {
  const vec3 dirs[] = {vec3(0, 0, -1), vec3(1, 0, 0), vec3(0.3f, 0.8f, 0.52f), vec3(-0.6f, -0.7f, 0.1f)};
  for (float rot : {0.0f, 37.0f}) {
    for (vec3 d : dirs) {
      d = snell::normalize(d);
      const vec3 back = equirectUvToDirection(directionToEquirectUv(d, rot), rot);
      EXPECT_NEAR(snell::dot(back, d), 1.0f, 1e-6f);
    }
  }
  EXPECT_NEAR(directionToEquirectUv(vec3(0, 0, -1), 0.0f).x, 0.5f, 1e-6f);   // -Z: centre column
  EXPECT_NEAR(directionToEquirectUv(vec3(1, 0, 0), 0.0f).x, 0.75f, 1e-6f);   // +X: a quarter turn right
  EXPECT_NEAR(directionToEquirectUv(vec3(0, 1, 0), 0.0f).y, 1.0f, 1e-6f);    // zenith: top
  // The lookup reproduces texels at their centres and wraps in longitude.
  Image img(8, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 8; ++x) img.at(x, y) = vec4(static_cast<float>(x), static_cast<float>(y), 0.0f, 1.0f);
  const Environment env(img, 0.0f, 2.0f);
  const vec3 c = env.lookup(equirectUvToDirection(snell::vec2(5.5f / 8.0f, 2.5f / 4.0f), 0.0f));
  EXPECT_NEAR(c.x, 10.0f, 1e-4f);
  EXPECT_NEAR(c.y, 4.0f, 1e-4f);
  const vec3 seam = env.lookup(equirectUvToDirection(snell::vec2(0.0f, 2.5f / 4.0f), 0.0f));
  EXPECT_NEAR(seam.x, 2.0f * 3.5f, 1e-3f);  // halfway between texel 7 and texel 0
}

TEST(LabImage, MetricsAndHeatMap) {
  Image a(4, 2, vec4(0.5f, 0.5f, 0.5f, 1.0f)), b = a;
  b.at(1, 1) = vec4(0.8f, 0.5f, 2.0f, 1.0f);  // 2.0 is clamped to 1 before the difference
  Mask m(4, 2);
  m.set(1, 1, true);
  m.set(2, 1, true);
  const ErrorStats s = compareImages(a, b, m);
  EXPECT_EQ(s.pixels, 2u);
  EXPECT_NEAR(s.mse, (0.09 + 0.25) / 3.0 / 2.0, 1e-6);
  const Image heat = errorHeatMap(a, b, m, 0.5f);
  EXPECT_GT(heat.at(1, 1).x, heat.at(2, 1).x);
  EXPECT_EQ(heat.at(2, 1), vec4(heatColor(0.0f), 1.0f));
  EXPECT_LT(heat.at(0, 0).x, 0.2f);  // outside the mask: dimmed context
  EXPECT_NEAR(heatColor(1.0f).x, 1.0f, 1e-6f);
  EXPECT_NEAR(heatColor(0.0f).x, 0.0f, 1e-3f);
  EXPECT_THROW(compareImages(a, Image(3, 2), m), std::invalid_argument);
}

TEST(LabImage, PanelPutsImagesSideBySideWithLabels) {
  const Image red(20, 10, vec4(1, 0, 0, 1)), green(30, 10, vec4(0, 1, 0, 1));
  const Image panel = composePanel({{&red, "ground truth"}, {&green, "plane"}}, "MSE 1e-3", 4, 1);
  EXPECT_EQ(panel.width, 4 + 20 + 4 + 30 + 4);
  // Both images are present, in order, below the label strip.
  const int labelStrip = 7 + 8;
  const int imageRow = panel.height - 1 - (labelStrip + 5);
  EXPECT_EQ(panel.at(4 + 10, imageRow), vec4(1, 0, 0, 1));
  EXPECT_EQ(panel.at(4 + 20 + 4 + 15, imageRow), vec4(0, 1, 0, 1));
  // Label text is drawn (light pixels in the strip).
  int lit = 0;
  for (int y = panel.height - labelStrip; y < panel.height; ++y)
    for (int x = 0; x < panel.width; ++x) lit += panel.at(x, y).x > 0.5f ? 1 : 0;
  EXPECT_GT(lit, 20);
  EXPECT_GT(textWidth("abc", 2), textWidth("abc", 1));
}

// At 256 px a technique's caption is wider than its panel; it wraps
// onto more lines instead of running off the edge.
TEST(LabImage, PanelCaptionWrapsToTheWidth) {
  const Image a(40, 10, vec4(0, 0, 0, 1));
  const std::string caption = "sphere_painting, normal plane, 1 it.: MSE 0.0303 (two-interface ref. 0.0343)";
  ASSERT_GT(textWidth(caption, 1), 40 + 2 * 4);
  const Image wide = composePanel({{&a, "x"}, {&a, "y"}, {&a, "z"}}, "short", 4, 1);
  const Image wrapped = composePanel({{&a, "x"}, {&a, "y"}, {&a, "z"}}, caption, 4, 1);
  EXPECT_GT(wrapped.height, wide.height);
  // Nothing is drawn in the last column: every line fits.
  for (int y = 0; y < wrapped.height; ++y) EXPECT_LT(wrapped.at(wrapped.width - 1, y).x, 0.5f) << y;
  // Every word is there: the caption's lit pixels (the labels x, y, z aside) equal
  // those of the same caption drawn on one line of a wide panel.
  const auto caption_lit = [](const Image& img, int fromTop) {
    int lit = 0;
    for (int y = 0; y < img.height - fromTop; ++y)
      for (int x = 0; x < img.width; ++x) lit += img.at(x, y).x > 0.5f ? 1 : 0;
    return lit;
  };
  const Image b(2000, 10, vec4(0, 0, 0, 1));
  const Image oneLine = composePanel({{&b, ""}}, caption, 4, 1);
  const int imageBottom = 7 + 8 + 10;  // label strip and image, from the top
  EXPECT_EQ(caption_lit(wrapped, imageBottom), caption_lit(oneLine, imageBottom));
}
