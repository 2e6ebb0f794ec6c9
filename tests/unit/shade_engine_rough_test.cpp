// The engines' rough transmission (shade/engine_models/engine_rough.glsl) against the engines' formulas written
// out again here in double: the lod each engine computes from roughness, ior and the buffer; three.js's bicubic
// read as the cubic B-spline summed over the clamped texels of a synthetic mip chain; Bevy's spiral taps placed in
// its own uv (y down) with its rotation matrix as WGSL builds it, read by a bilinear filter written here. Smooth
// glass reads the one texel it read before the blurs existed, bit for bit.
#include <snell/engine_model_table.hpp>
#include <snell/shade.hpp>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>

#include "support/rng.hpp"

namespace {

using glm::dvec2;
using glm::dvec3;
using glm::mat4;
using glm::vec2;
using glm::vec3;
using glm::vec4;
using snell::SnellEngineBlurRead;
using snell::Texture2D;

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

mat4 projection(float fovyDegrees) { return glm::perspective(glm::radians(fovyDegrees), 1.25f, 0.1f, 100.0f); }

// A W x H chain of `levels` levels whose texels are random in every level (not a box filter of the one above), so
// a read from the wrong level or the wrong texel shows.
Texture2D randomChain(int w, int h, int levels, std::uint64_t seed) {
  snell_test::Rng g(static_cast<std::uint32_t>(seed));
  auto level = [&](int lw, int lh) {
    snell::Image im(lw, lh);
    for (auto& t : im.texels) t = vec4(g.uniform(0.0f, 1.0f), g.uniform(0.0f, 1.0f), g.uniform(0.0f, 1.0f), 1.0f);
    return im;
  };
  Texture2D t(level(w, h), snell::Filter::Linear, snell::MipFilter::Linear);
  for (int l = 1; l < levels; ++l) t.addLevel(level(std::max(1, w >> l), std::max(1, h >> l)));
  return t;
}

// A smooth picture (sines), mipmapped: Bevy's taps read level 0 where float and double noise may differ slightly.
Texture2D smoothPicture(int w, int h) {
  snell::Image im(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      im.at(x, y) = vec4(0.5f + 0.4f * std::sin(0.21f * float(x) + 0.05f * float(y)),
                         0.5f + 0.4f * std::cos(0.13f * float(y)), 0.5f + 0.3f * std::sin(0.07f * float(x + y)), 1.0f);
  Texture2D t(im, snell::Filter::Linear, snell::MipFilter::Linear);
  t.generateMipmaps();
  return t;
}

dvec3 texel(const snell::Image& im, int x, int y) {
  const vec4 c = im.at(std::clamp(x, 0, im.width - 1), std::clamp(y, 0, im.height - 1));
  return dvec3(c.x, c.y, c.z);
}

// GL's bilinear filter with clamp-to-edge, in double.
dvec3 bilinear(const snell::Image& im, dvec2 uv) {
  const double x = uv.x * im.width - 0.5, y = uv.y * im.height - 0.5;
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const double fx = x - x0, fy = y - y0;
  return (1 - fy) * ((1 - fx) * texel(im, x0, y0) + fx * texel(im, x0 + 1, y0)) +
         fy * ((1 - fx) * texel(im, x0, y0 + 1) + fx * texel(im, x0 + 1, y0 + 1));
}

// The uniform cubic B-spline centred on 0.
double bspline(double t) {
  t = std::abs(t);
  if (t < 1.0) return (4.0 - 6.0 * t * t + 3.0 * t * t * t) / 6.0;
  if (t < 2.0) return (2.0 - t) * (2.0 - t) * (2.0 - t) / 6.0;
  return 0.0;
}

// The B-spline filter of one level: every texel whose centre lies within 2 texels, clamped to the edge.
dvec3 bsplineLevel(const snell::Image& im, dvec2 uv) {
  const double x = uv.x * im.width, y = uv.y * im.height;
  dvec3 sum(0.0);
  for (int j = int(std::floor(y)) - 3; j <= int(std::floor(y)) + 3; ++j)
    for (int i = int(std::floor(x)) - 3; i <= int(std::floor(x)) + 3; ++i)
      sum += bspline(x - (i + 0.5)) * bspline(y - (j + 0.5)) * texel(im, i, j);
  return sum;
}

// --- the lod each engine computes -------------------------------------------------------------------------

TEST(EngineBlurLod, EachEngineGivesItsSourcesLevel) {
  const mat4 proj = projection(45.0f);
  const int levels = 10;
  const vec2 size(640.0f, 512.0f);
  snell_test::Rng g(9301);
  for (int k = 0; k < 500; ++k) {
    const double r = g.uniform(0.001f, 1.0f), ior = g.uniform(1.0f, 2.4f);
    // three.js: log2(transmissionSamplerSize.x) * applyIorToRoughness(max(roughness, 0.045), ior).
    const double three = std::log2(640.0) * std::max(r, 0.045) * std::clamp(ior * 2.0 - 2.0, 0.0, 1.0);
    // Filament: the host's refractionLodOffset from the vertical field of view and the height, the shader's
    // remap by etaIR and its invLog2sqrt5, the chain's roughnessLodCount.
    const double fov = 2.0 * std::atan(1.0 / double(proj[1][1]));
    const double offset = -std::log2(std::sqrt(2.0) * (22.0 / 6.0) * std::tan(fov) / 512.0);
    const double pr = r * (1.0 - std::clamp((1.0 / ior) * 3.0 - 2.0, 0.0, 1.0));
    const double count = std::max(std::min(4, levels), levels - 4);
    const double filament =
        pr > 0.0 ? std::min(std::max(0.0, (2.0 * std::log2(pr) + offset) * 0.8614), count - 1.0) : 0.0;
    // HDRP: PositivePow(perceptualRoughness, 1.3) * (_ColorPyramidLodCount - 1); Godot: ROUGHNESS * 8, within
    // the chain.
    const double hdrp = std::pow(r, 1.3) * (levels - 1);
    const double godot = std::min(8.0 * r, double(levels - 1));
    const float rf = float(r), iorf = float(ior);
    EXPECT_NEAR(snell::snellEngineBlurLod(SNELL_ENGINE_BLUR_THREEJS, rf, iorf, levels, size, proj), three, 1e-4);
    EXPECT_NEAR(snell::snellEngineBlurLod(SNELL_ENGINE_BLUR_FILAMENT, rf, iorf, levels, size, proj), filament, 1e-4)
        << "r " << r << " ior " << ior;
    EXPECT_NEAR(snell::snellEngineBlurLod(SNELL_ENGINE_BLUR_HDRP, rf, iorf, levels, size, proj), hdrp, 1e-4);
    EXPECT_NEAR(snell::snellEngineBlurLod(SNELL_ENGINE_BLUR_GODOT, rf, iorf, levels, size, proj), godot, 1e-4);
    EXPECT_EQ(snell::snellEngineBlurLod(SNELL_ENGINE_BLUR_BEVY, rf, iorf, levels, size, proj), 0.0f);
  }
}

TEST(EngineBlurLod, SmoothOrBadInputReadsLevelZero) {
  const mat4 proj = projection(45.0f);
  for (int blur = -1; blur <= SNELL_ENGINE_BLUR_COUNT; ++blur) {
    for (float r : {0.0f, -0.5f, kNaN})
      EXPECT_EQ(snell::snellEngineBlurLod(blur, r, 1.5f, 10, vec2(512.0f), proj), 0.0f) << blur << " r " << r;
    for (float ior : {0.0f, -1.5f, kNaN, kInf})
      EXPECT_EQ(snell::snellEngineBlurLod(blur, 0.5f, ior, 10, vec2(512.0f), proj), 0.0f) << blur << " ior " << ior;
  }
  // Filament at a vertical field of view of 90 degrees or more: its tan is not positive, the lod 0.
  EXPECT_EQ(snell::snellEngineBlurLod(SNELL_ENGINE_BLUR_FILAMENT, 0.5f, 1.5f, 10, vec2(512.0f), projection(100.0f)),
            0.0f);
  // Above 1 the roughness is 1.
  EXPECT_EQ(snell::snellEngineBlurLod(SNELL_ENGINE_BLUR_GODOT, 7.0f, 1.5f, 10, vec2(512.0f), proj), 8.0f);
  // One level: nothing to blur with for the chain readers.
  EXPECT_EQ(snell::snellEngineBlurLod(SNELL_ENGINE_BLUR_HDRP, 0.5f, 1.5f, 1, vec2(512.0f), proj), 0.0f);
  EXPECT_EQ(snell::snellEngineBlurLod(SNELL_ENGINE_BLUR_GODOT, 0.5f, 1.5f, 0, vec2(512.0f), proj), 0.0f);
}

// --- three.js's bicubic ----------------------------------------------------------------------------------

TEST(EngineBicubicMips, IsTheBSplineOfTwoLevelsMixedByTheLodsFraction) {
  const Texture2D t = randomChain(24, 20, 5, 9302);
  snell_test::Rng g(9303);
  for (int k = 0; k < 400; ++k) {
    const vec2 uv(g.uniform(-0.05f, 1.05f), g.uniform(-0.05f, 1.05f));
    const float lod = g.uniform(0.0f, 4.5f);
    const double l = std::min(double(lod), 4.0);
    const int a = int(std::floor(l)), b = std::min(int(std::ceil(l)), 4);
    const double f = l - a;
    // The centre is clamped to the image first (the contract), the B-spline's taps then reach past it.
    const dvec2 centre(std::clamp(double(uv.x), 0.0, 1.0), std::clamp(double(uv.y), 0.0, 1.0));
    const dvec3 want = (1.0 - f) * bsplineLevel(t.level(a), centre) + f * bsplineLevel(t.level(b), centre);
    const SnellEngineBlurRead got = snell::snellEngineBicubicMips(t, uv, lod, 5);
    EXPECT_EQ(got.fetches, 8);
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(got.color[c], want[c], 2e-5) << "uv " << uv.x << " " << uv.y << " lod " << lod << " channel " << c;
  }
  // A NaN uv component is 0.
  const SnellEngineBlurRead nanUv = snell::snellEngineBicubicMips(t, vec2(kNaN, 0.5f), 1.5f, 5);
  EXPECT_EQ(nanUv.color, snell::snellEngineBicubicMips(t, vec2(0.0f, 0.5f), 1.5f, 5).color);
  EXPECT_EQ(snell::snellEngineSmoothRead(t, vec2(0.5f, kNaN)).color,
            snell::snellEngineSmoothRead(t, vec2(0.5f, 0.0f)).color);
  // A negative or NaN lod is level 0.
  const vec2 uv(0.3f, 0.6f);
  const dvec3 zero = bsplineLevel(t.level(0), dvec2(uv));
  for (float lod : {-2.0f, kNaN}) {
    const SnellEngineBlurRead got = snell::snellEngineBicubicMips(t, uv, lod, 5);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got.color[c], zero[c], 2e-5) << lod;
  }
}

// --- Bevy's spiral -----------------------------------------------------------------------------------------

// Bevy's fetch_transmissive_background at frame 0, in its own uv (origin top-left), written from its source.
dvec3 bevyBlur(const snell::Image& im, dvec2 uvUp, double roughness, double ior, double viewZ, dvec2 fragCoord,
               int taps) {
  const dvec2 offsets[8] = {{-0.7071, 0.7071}, {-0.0000, -0.8750}, {0.5303, 0.5303}, {-0.6250, -0.0000},
                            {0.3536, -0.3536}, {-0.0000, 0.3750},  {-0.1768, -0.1768}, {0.1250, 0.0000}};
  const int order[8] = {0, 2, 4, 6, 1, 3, 5, 7};  // its switch over i & 7
  const double tr = roughness * std::clamp(ior * 2.0 - 2.0, 0.0, 1.0);
  const double blur = tr * tr / viewZ;
  const double aspect = double(im.width) / im.height;
  const int spirals = int(std::ceil(taps / 8.0));
  const double xy = 0.06711056 * fragCoord.x + 0.00583715 * fragCoord.y;
  const double inner = 52.9829189 * (xy - std::floor(xy));
  const double noise = inner - std::floor(inner);
  const int checker = (int(fragCoord.x) + int(fragCoord.y)) % 2;
  const dvec2 pos(uvUp.x, 1.0 - uvUp.y);
  dvec3 sum(0.0);
  for (int i = 0; i < taps; ++i) {
    const int spiral = i >> 3;
    const double angle = (noise + double(spiral) / spirals) * 2.0 * M_PI;
    const dvec2 m(std::sin(angle), std::cos(angle));
    dvec2 o = offsets[order[i & 7]] * (1.0 - 0.5 * double(spiral + 1) / spirals);
    // WGSL mat2x2(m.y, -m.x, m.x, m.y): columns (m.y, -m.x) and (m.x, m.y).
    const dvec2 rotated = dvec2(m.y, -m.x) * o.x + dvec2(m.x, m.y) * o.y;
    const dvec2 tap = pos + rotated * dvec2(1.0, aspect) * blur * (1.0 - checker * 0.1);
    const dvec2 up(std::clamp(tap.x, 0.0, 1.0), std::clamp(1.0 - tap.y, 0.0, 1.0));
    sum += bilinear(im, up);
  }
  return sum / double(taps);
}

TEST(EngineBevyBlur, AveragesItsSpiralTapsAtLevelZero) {
  const Texture2D t = smoothPicture(80, 64);
  snell_test::Rng g(9304);
  for (int taps : {4, 8, 16, 32})
    for (int k = 0; k < 150; ++k) {
      const vec2 uv(g.uniform(0.0f, 1.0f), g.uniform(0.0f, 1.0f));
      const float r = g.uniform(0.05f, 1.0f), ior = g.uniform(1.05f, 2.0f), z = -g.uniform(0.5f, 6.0f);
      const vec2 pixel(std::floor(g.uniform(0.0f, 79.99f)) + 0.5f, std::floor(g.uniform(0.0f, 63.99f)) + 0.5f);
      const dvec3 want = bevyBlur(t.level(0), dvec2(uv), r, ior, z, dvec2(pixel), taps);
      const SnellEngineBlurRead got = snell::snellEngineBevyBlur(t, uv, r, ior, z, pixel, taps);
      EXPECT_EQ(got.fetches, taps);
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(got.color[c], want[c], 2e-3) << "taps " << taps << " uv " << uv.x << " " << uv.y << " r " << r;
    }
}

TEST(EngineBevyBlur, NoBlurOrBadInputReadsTheSmoothTexel) {
  const Texture2D t = smoothPicture(80, 64);
  const vec2 uv(0.4f, 0.7f);
  const vec4 smooth = t.sampleLod(uv, 0.0f);
  auto isSmooth = [&](const SnellEngineBlurRead& r) {
    return r.fetches == 1 && r.color == vec3(smooth.x, smooth.y, smooth.z);
  };
  // ior 1 scales Bevy's roughness to 0: its non-rough path.
  EXPECT_TRUE(isSmooth(snell::snellEngineBevyBlur(t, uv, 0.5f, 1.0f, -2.0f, vec2(3.5f), 8)));
  for (float r : {0.0f, -1.0f, kNaN}) EXPECT_TRUE(isSmooth(snell::snellEngineBevyBlur(t, uv, r, 1.5f, -2.0f, vec2(3.5f), 8)));
  for (float z : {0.0f, kNaN, -kInf}) EXPECT_TRUE(isSmooth(snell::snellEngineBevyBlur(t, uv, 0.5f, 1.5f, z, vec2(3.5f), 8)));
  // Tap counts outside 1..32 are clamped; a pixel that is not finite counts as (0, 0).
  EXPECT_EQ(snell::snellEngineBevyBlur(t, uv, 0.5f, 1.5f, -2.0f, vec2(3.5f), 0).fetches, 1);
  EXPECT_EQ(snell::snellEngineBevyBlur(t, uv, 0.5f, 1.5f, -2.0f, vec2(3.5f), 99).fetches, 32);
  const SnellEngineBlurRead nan = snell::snellEngineBevyBlur(t, uv, 0.5f, 1.5f, -2.0f, vec2(kNaN, kInf), 8);
  const SnellEngineBlurRead origin = snell::snellEngineBevyBlur(t, uv, 0.5f, 1.5f, -2.0f, vec2(0.0f), 8);
  EXPECT_EQ(nan.color, origin.color);
}

// --- the dispatcher ---------------------------------------------------------------------------------------

TEST(EngineBlurRead, SmoothGlassReadsTodaysTexelForEveryBlur) {
  const Texture2D t = randomChain(32, 32, 6, 9305);
  const mat4 proj = projection(45.0f);
  snell_test::Rng g(9306);
  for (int k = 0; k < 200; ++k) {
    const vec2 uv(g.uniform(-0.2f, 1.2f), g.uniform(-0.2f, 1.2f));
    const vec3 p(g.uniform(-1.0f, 1.0f), g.uniform(-1.0f, 1.0f), -g.uniform(1.0f, 5.0f));
    // What labEngineShade read before the blurs: SNELL_SAMPLE_LOD at lod 0 of the clamped uv.
    const vec4 today = t.sampleLod(glm::clamp(uv, vec2(0.0f), vec2(1.0f)), 0.0f);
    for (int blur = -1; blur <= SNELL_ENGINE_BLUR_COUNT; ++blur) {
      const SnellEngineBlurRead r = snell::snellEngineBlurRead(blur, t, uv, 0.0f, 1.5f, p, proj, 6);
      ASSERT_EQ(r.color, vec3(today.x, today.y, today.z)) << "blur " << blur;
      ASSERT_EQ(r.fetches, 1);
      ASSERT_EQ(snell::snellEngineSmoothRead(t, uv).color, r.color);
    }
  }
}

TEST(EngineBlurRead, RoughGlassReadsThroughEachEnginesBlur) {
  const Texture2D t = randomChain(32, 32, 6, 9307);
  const mat4 proj = projection(45.0f);
  snell_test::Rng g(9308);
  for (int k = 0; k < 200; ++k) {
    const vec2 uv(g.uniform(0.0f, 1.0f), g.uniform(0.0f, 1.0f));
    const vec3 p(g.uniform(-1.0f, 1.0f), g.uniform(-1.0f, 1.0f), -g.uniform(1.0f, 5.0f));
    const float r = g.uniform(0.05f, 1.0f), ior = g.uniform(1.2f, 2.0f);
    for (int blur : {SNELL_ENGINE_BLUR_FILAMENT, SNELL_ENGINE_BLUR_HDRP, SNELL_ENGINE_BLUR_GODOT}) {
      const float lod = snell::snellEngineBlurLod(blur, r, ior, 6, vec2(32.0f), proj);
      const vec4 want = t.sampleLod(uv, lod);
      const SnellEngineBlurRead got = snell::snellEngineBlurRead(blur, t, uv, r, ior, p, proj, 6);
      ASSERT_EQ(got.color, vec3(want.x, want.y, want.z)) << blur;
      ASSERT_EQ(got.fetches, 1);
    }
    const float lod = snell::snellEngineBlurLod(SNELL_ENGINE_BLUR_THREEJS, r, ior, 6, vec2(32.0f), proj);
    ASSERT_EQ(snell::snellEngineBlurRead(SNELL_ENGINE_BLUR_THREEJS, t, uv, r, ior, p, proj, 6).color,
              snell::snellEngineBicubicMips(t, uv, lod, 6).color);
    // Bevy's pixel: the texel under p's projection, its row counted from the top.
    const glm::vec4 clip = proj * glm::vec4(p, 1.0f);
    const vec2 f = vec2(clip.x / clip.w, clip.y / clip.w) * 0.5f + 0.5f;
    const vec2 pixel(std::floor(f.x * 32.0f) + 0.5f, 32.0f - std::floor(f.y * 32.0f) - 0.5f);
    const SnellEngineBlurRead bevy = snell::snellEngineBlurRead(SNELL_ENGINE_BLUR_BEVY, t, uv, r, ior, p, proj, 6);
    ASSERT_EQ(bevy.color, snell::snellEngineBevyBlur(t, uv, r, ior, p.z, pixel, SNELL_BEVY_TRANSMISSION_TAPS).color);
    ASSERT_EQ(bevy.fetches, SNELL_BEVY_TRANSMISSION_TAPS);
  }
}

TEST(EngineBlurRead, EveryEngineModelHasItsEnginesBlur) {
  EXPECT_EQ(snell::snellEngineBlurOf(SNELL_ENGINE_THREEJS), SNELL_ENGINE_BLUR_THREEJS);
  EXPECT_EQ(snell::snellEngineBlurOf(SNELL_ENGINE_FILAMENT_SOLID), SNELL_ENGINE_BLUR_FILAMENT);
  EXPECT_EQ(snell::snellEngineBlurOf(SNELL_ENGINE_FILAMENT_THIN), SNELL_ENGINE_BLUR_FILAMENT);
  EXPECT_EQ(snell::snellEngineBlurOf(SNELL_ENGINE_HDRP_SPHERE), SNELL_ENGINE_BLUR_HDRP);
  EXPECT_EQ(snell::snellEngineBlurOf(SNELL_ENGINE_HDRP_BOX), SNELL_ENGINE_BLUR_HDRP);
  EXPECT_EQ(snell::snellEngineBlurOf(SNELL_ENGINE_GODOT), SNELL_ENGINE_BLUR_GODOT);
  EXPECT_EQ(snell::snellEngineBlurOf(-1), -1);
  EXPECT_EQ(snell::snellEngineBlurOf(SNELL_ENGINE_MODEL_COUNT), -1);
}

}  // namespace
