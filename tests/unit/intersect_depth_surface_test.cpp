// glsl/snell/intersect/depth_surface.glsl: the surface's derived fields
// (snellDepthSurfaceComplete) against values computed here from the source
// fields, snellSurfaceLinearDepth against snellLinearizeDepth bit for bit (the
// reference camera_depth_test.cpp checks against GLM's projection), and
// hand-filled surfaces whose derived fields disagree with their source fields.
#include <gtest/gtest.h>

#include <snell/camera.hpp>
#include <snell/depth_pyramid.hpp>
#include <snell/intersect.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <utility>

namespace {

using namespace snell;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool infinite(int convention) {
  return convention == SNELL_DEPTH_INFINITE_GL || convention == SNELL_DEPTH_INFINITE_REVERSED;
}

// Depth values a buffer can hold and the ones it should not: the edges, values
// just inside them, denormals, out of range and non-finite.
float randomDepth(std::mt19937& rng) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::uniform_int_distribution<int> e(1, 140);
  const float hostile[] = {kNaN, kInf, -kInf, 0.0f, -0.0f, 1.0f, 1e-45f, 1e-40f, FLT_MIN, -1e-40f, 2.0f, -0.5f};
  const float k = u(rng);
  if (k < 0.10f) return hostile[static_cast<std::size_t>(e(rng)) % 12];
  if (k < 0.20f) return std::ldexp(1.0f, -e(rng));         // towards 0 (reversed far plane), into denormals
  if (k < 0.30f) return 1.0f - std::ldexp(1.0f, -e(rng) % 25);  // towards 1 (the GL far plane)
  return u(rng);
}

TEST(DepthSurface, SurfaceLinearDepthIsLinearizeDepthBitForBit) {
  std::mt19937 rng(617);
  std::uniform_real_distribution<float> logNear(-3.0f, 1.0f), logRatio(0.0f, 6.0f), u(0.0f, 1.0f);
  const float hostileRange[] = {kNaN, kInf, -kInf, 0.0f, -0.0f, -1.0f, 1e-40f, 3e38f};
  const glm::mat4 P = glm::perspective(1.0f, 1.3f, 0.1f, 100.0f);
  long compared = 0, positive = 0;
  for (int i = 0; i < 20000; ++i) {
    float n = std::pow(10.0f, logNear(rng)), f = n * std::pow(10.0f, logRatio(rng));
    if (u(rng) < 0.05f) n = hostileRange[i % 8];
    if (u(rng) < 0.05f) f = hostileRange[(i / 8) % 8];
    if (u(rng) < 0.02f) f = n;
    for (int conv = -1; conv <= SNELL_DEPTH_CONVENTION_COUNT; ++conv) {
      const SnellDepthSurface s = snellDepthSurface(P, n, f, conv, 0.0f);
      for (int k = 0; k < 4; ++k) {
        const float d = randomDepth(rng);
        const float got = snellSurfaceLinearDepth(s, d), want = snellLinearizeDepth(d, n, f, conv);
        ASSERT_TRUE(sameBits(got, want)) << "conv " << conv << " n " << n << " f " << f << " d " << d << ": " << got
                                         << " vs " << want;
        ++compared;
        positive += got > 0.0f;
      }
    }
  }
  EXPECT_GT(positive, compared / 2);  // most inputs linearize: the comparison is not of zeros
}

// The derived fields from the source fields, computed here independently.
TEST(DepthSurface, CompleteDerivesEveryFieldFromTheSourceFields) {
  std::mt19937 rng(618);
  std::uniform_real_distribution<float> fovy(0.2f, 2.8f), aspect(0.3f, 3.0f), logNear(-2.0f, 0.5f), u(0.0f, 1.0f);
  for (int i = 0; i < 4000; ++i) {
    const float n = std::pow(10.0f, logNear(rng)), f = n * 1000.0f;
    const int conv = i % SNELL_DEPTH_CONVENTION_COUNT;
    glm::mat4 m = glm::perspective(fovy(rng), aspect(rng), n, f);
    const bool sheared = i % 3 == 0;
    if (sheared) m[1][0] = 0.01f + u(rng);
    // Filled in field by field, the derived fields stale or hostile.
    SnellDepthSurface s{};
    s.clipFromView = m;
    s.zNear = n;
    s.zFar = f;
    s.convention = conv;
    s.emptyDepth = 0.5f;
    s.lod = 2;
    s.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
    s.closed = false;
    s.perspective = !sheared;
    s.perspectiveDet = kNaN;
    s.linearizable = false;
    s.depthReversed = true;
    s.nearOverFar = -kInf;
    s.depthFarBelow = 0.7f;
    s.depthFarLimit = kNaN;
    const SnellDepthSurface c = snellDepthSurfaceComplete(s);
    EXPECT_EQ(c.perspective, !sheared) << i;
    EXPECT_TRUE(sameBits(c.perspectiveDet, sheared ? 0.0f : m[0][0] * m[1][1])) << i;
    EXPECT_TRUE(c.linearizable) << i;
    EXPECT_EQ(c.depthReversed, conv == SNELL_DEPTH_REVERSED || conv == SNELL_DEPTH_INFINITE_REVERSED) << i;
    EXPECT_TRUE(sameBits(c.nearOverFar, infinite(conv) ? 0.0f : n / f)) << i;
    EXPECT_TRUE(sameBits(c.depthFarBelow, conv == SNELL_DEPTH_INFINITE_REVERSED ? FLT_MIN : 0.0f)) << i;
    EXPECT_TRUE(sameBits(c.depthFarLimit, infinite(conv) ? FLT_MAX : f)) << i;
    // The source and per-draw fields are kept.
    EXPECT_EQ(c.clipFromView, m);
    EXPECT_TRUE(c.zNear == n && c.zFar == f && c.convention == conv && c.emptyDepth == 0.5f && c.lod == 2 &&
                c.depthFilter == SNELL_DEPTH_FILTER_BILINEAR && !c.closed);
    // The constructor is the same completion.
    const SnellDepthSurface k = snellDepthSurface(m, n, f, conv, 0.5f);
    EXPECT_TRUE(k.perspective == c.perspective && sameBits(k.perspectiveDet, c.perspectiveDet) &&
                k.linearizable == c.linearizable && k.depthReversed == c.depthReversed &&
                sameBits(k.nearOverFar, c.nearOverFar) && sameBits(k.depthFarBelow, c.depthFarBelow) &&
                sameBits(k.depthFarLimit, c.depthFarLimit))
        << i;
  }
}

// What makes a surface unusable: every read is invalid, every strategy misses.
TEST(DepthSurface, InvalidSourceFieldsGiveAnUnreadableSurface) {
  const glm::mat4 P = glm::perspective(1.0f, 1.0f, 0.1f, 100.0f);
  struct Range {
    float n, f;
    int conv;
  };
  const Range bad[] = {{0.0f, 100.0f, SNELL_DEPTH_GL},   {-0.1f, 100.0f, SNELL_DEPTH_GL}, {kNaN, 100.0f, SNELL_DEPTH_GL},
                       {0.1f, 0.1f, SNELL_DEPTH_GL},     {0.1f, 0.05f, SNELL_DEPTH_REVERSED},
                       {0.1f, kInf, SNELL_DEPTH_ZERO_ONE}, {1e-40f, 10.0f, SNELL_DEPTH_INFINITE_GL},
                       {0.1f, 100.0f, -1},               {0.1f, 100.0f, SNELL_DEPTH_CONVENTION_COUNT}};
  const Texture2D depth(Image(4, 4, glm::vec4(0.5f)));
  for (const Range& r : bad) {
    const SnellDepthSurface s = snellDepthSurface(P, r.n, r.f, r.conv, 0.0f);
    EXPECT_FALSE(s.linearizable) << r.n << " " << r.f << " " << r.conv;
    EXPECT_EQ(snellSurfaceLinearDepth(s, 0.5f), 0.0f);
    EXPECT_FALSE(snellSampleSurface(depth, glm::vec2(0.5f), s).valid);
    const SnellHit h = snellIntersectSingleSample(glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 0.0f, -1.0f), depth, s);
    EXPECT_FALSE(h.valid);
  }
  // A degenerate perspective (a zero or non-finite focal term): no reconstruction.
  for (float a : {0.0f, 1e-39f, kInf, kNaN}) {  // a * b < FLT_MIN, or not finite
    glm::mat4 m = P;
    m[0][0] = a;
    const SnellDepthSurface s = snellDepthSurface(m, 0.1f, 100.0f, SNELL_DEPTH_GL, 0.0f);
    EXPECT_EQ(s.perspectiveDet, 0.0f) << a;
    EXPECT_FALSE(snellSurfaceUvZToView(s, glm::vec2(0.3f, 0.6f), -2.0f).valid) << a;
  }
}

// A surface whose derived fields disagree with its source fields is read
// through its derived fields: finite, flagged outputs for any mix, never NaN.
TEST(DepthSurface, InconsistentHandFilledSurfacesGiveFiniteResults) {
  std::mt19937 rng(619);
  std::uniform_real_distribution<float> u(0.0f, 1.0f), uv(-0.2f, 1.2f), span(-3.0f, 3.0f);
  const float hostile[] = {kNaN, kInf, -kInf, 0.0f, -0.0f, -1.0f, 1e-40f, FLT_MIN, 3e38f, -3e38f, 0.5f, 100.0f};
  const glm::mat4 P = glm::perspective(1.0f, 1.0f, 0.1f, 100.0f);
  auto pick = [&]() { return hostile[static_cast<std::size_t>(u(rng) * 12.0f) % 12]; };
  Image img(16, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) img.at(x, y) = glm::vec4((x + y) % 5 == 0 ? 0.0f : 0.2f + 0.04f * static_cast<float>(x));
  const Texture2D depth(std::move(img));
  Image nimg(16, 16, glm::vec4(0.0f, 0.3f, 1.0f, 0.0f));
  nimg.at(3, 4) = glm::vec4(0.0f);  // a zero normal: the facing fallback
  const Texture2D normal(std::move(nimg), Filter::Linear);
  const Texture2D pyramid = snellBuildDepthPyramid(depth, snellDepthSurface(P, 0.1f, 100.0f, SNELL_DEPTH_GL, 0.0f));
  auto finite = [](glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  int valid = 0;
  for (int i = 0; i < 50000; ++i) {
    SnellDepthSurface s = snellDepthSurface(P, 0.1f, 100.0f, i % SNELL_DEPTH_CONVENTION_COUNT, 0.0f);
    if (u(rng) < 0.3f) s.clipFromView[1][0] = span(rng);  // the flag now disagrees with the matrix
    if (u(rng) < 0.2f) s.clipFromView[0][0] = pick();
    if (u(rng) < 0.3f) s.perspective = !s.perspective;
    if (u(rng) < 0.3f) s.perspectiveDet = pick();
    if (u(rng) < 0.3f) s.linearizable = !s.linearizable;
    if (u(rng) < 0.3f) s.depthReversed = !s.depthReversed;
    if (u(rng) < 0.3f) s.nearOverFar = pick();
    if (u(rng) < 0.3f) s.depthFarBelow = pick();
    if (u(rng) < 0.3f) s.depthFarLimit = pick();
    if (u(rng) < 0.3f) s.zNear = pick();
    if (u(rng) < 0.2f) s.zFar = pick();
    const float d = randomDepth(rng);
    const float v = snellSurfaceLinearDepth(s, d);
    ASSERT_TRUE(v == 0.0f || (v > 0.0f && v <= FLT_MAX)) << i << " " << v;
    const glm::vec2 at(uv(rng), uv(rng));
    const SnellSurfaceSample x = snellSampleSurface(depth, at, s);
    ASSERT_TRUE(!x.valid ? x.viewZ == 0.0f : x.viewZ < 0.0f) << i;
    const SnellSurfacePoint p = snellSurfacePoint(depth, at, s);
    ASSERT_TRUE(finite(p.position)) << i;
    const glm::vec3 o(span(rng) * 0.1f, span(rng) * 0.1f, -0.5f), dir(span(rng) * 0.2f, span(rng) * 0.2f, -1.0f);
    const SnellHit h = snellIntersectSingleSample(o, dir, depth, s);
    ASSERT_TRUE(finite(h.position) && std::isfinite(h.uv.x) && std::isfinite(h.uv.y)) << i;
    const SnellHit c = snellConservativeBinarySearch(o, dir, depth, s, -0.2f, -20.0f, 5);
    ASSERT_TRUE(finite(c.position) && std::isfinite(c.uv.x) && std::isfinite(c.uv.y)) << i;
    const SnellHit m = snellLinearMarch(o, dir, depth, s, 20.0f, 16, 2);
    ASSERT_TRUE(finite(m.position) && std::isfinite(m.uv.x) && std::isfinite(m.uv.y)) << i;
    const SnellHit pl = snellIntersectPlaneNormal(o, dir, depth, normal, pyramid, s, 0.0f, 2, i % 2 == 0);
    ASSERT_TRUE(finite(pl.position) && std::isfinite(pl.uv.x) && std::isfinite(pl.uv.y)) << i;
    const glm::vec4 base = snellDepthPyramidBase(d, s);
    ASSERT_TRUE(std::isfinite(base.y) && std::isfinite(base.z) && (base.w == 0.0f || (base.y > 0.0f && base.w == 1.0f)))
        << i;
    valid += h.valid + c.valid + m.valid + pl.valid;
  }
  EXPECT_GT(valid, 1000);  // the reads are exercised, not all refused
}

}  // namespace

// The boundaries the contracts state exactly: uv in the closed [0,1]^2 (0 and 1 read, the next float past
// them does not); the smallest zNear and perspective determinant that count (FLT_MIN itself); the fields
// snellDepthSurface sets; a miss reads as viewZ 0.
TEST(IntersectDepthSurface, BoundariesAreWhereTheContractsPutThem) {
  Texture2D depth(Image(4, 4, glm::vec4(0.5f, 0.0f, 0.0f, 0.0f)));
  const SnellDepthSurface s = snellDepthSurface(glm::perspective(1.0f, 1.0f, 0.5f, 20.0f), 0.5f, 20.0f, SNELL_DEPTH_GL, 1.0f);
  EXPECT_EQ(s.depthFilter, SNELL_DEPTH_FILTER_NEAREST);
  EXPECT_TRUE(s.closed);
  EXPECT_EQ(s.lod, 0);
  const float below0 = -std::numeric_limits<float>::denorm_min(), above1 = std::nextafter(1.0f, 2.0f);
  for (const glm::vec2 uv : {glm::vec2(0.0f, 0.5f), glm::vec2(1.0f, 0.5f), glm::vec2(0.5f, 0.0f), glm::vec2(0.5f, 1.0f),
                             glm::vec2(0.0f, 0.0f), glm::vec2(1.0f, 1.0f), glm::vec2(1e-40f, 0.5f)}) {
    const SnellSurfaceSample x = snellSampleSurface(depth, uv, s);
    EXPECT_TRUE(x.valid) << uv.x << "," << uv.y;
    EXPECT_LT(x.viewZ, 0.0f) << uv.x << "," << uv.y;
  }
  for (const glm::vec2 uv : {glm::vec2(below0, 0.5f), glm::vec2(above1, 0.5f), glm::vec2(0.5f, below0),
                             glm::vec2(0.5f, above1)}) {
    const SnellSurfaceSample x = snellSampleSurface(depth, uv, s);
    EXPECT_FALSE(x.valid) << uv.x << "," << uv.y;
    EXPECT_EQ(x.viewZ, 0.0f) << uv.x << "," << uv.y;
    EXPECT_FALSE(x.interpolated);
  }
  // zNear = FLT_MIN linearizes (the smallest normal float is accepted); depth 0 is then FLT_MIN away.
  const SnellDepthSurface tiny = snellDepthSurface(glm::mat4(1.0f), FLT_MIN, 1.0f, SNELL_DEPTH_GL, 1.0f);
  EXPECT_TRUE(tiny.linearizable);
  EXPECT_EQ(snellSurfaceLinearDepth(tiny, 0.0f), FLT_MIN);
  EXPECT_FALSE(snellDepthSurface(glm::mat4(1.0f), FLT_MIN / 2.0f, 1.0f, SNELL_DEPTH_GL, 1.0f).linearizable);
  // A perspective matrix whose x and y scales multiply to exactly FLT_MIN keeps its determinant.
  glm::mat4 p = glm::perspective(1.0f, 1.0f, 0.5f, 20.0f);
  p[0][0] = 1.0f;
  p[1][1] = FLT_MIN;
  const SnellDepthSurface edge = snellDepthSurface(p, 0.5f, 20.0f, SNELL_DEPTH_GL, 1.0f);
  ASSERT_TRUE(edge.perspective);
  EXPECT_EQ(edge.perspectiveDet, FLT_MIN);
  p[1][1] = FLT_MIN / 2.0f;
  EXPECT_EQ(snellDepthSurface(p, 0.5f, 20.0f, SNELL_DEPTH_GL, 1.0f).perspectiveDet, 0.0f);
}

namespace {

// The GL convention's view distance in double, from its equation
// (camera/linearize_depth.glsl): v = n / ((1 - d) + d n / f).
double glDistance(double d, double n, double f) { return n / ((1.0 - d) + d * n / f); }

}  // namespace

// BILINEAR's four texels are clamped to the edge: within half a texel of a border the read is the
// edge texels' own depth along that axis, never a blend with a texel past the border (which would
// be none, or the texel on the far side). Window depth affine in the texel index (a plane) is what
// bilinear filtering reproduces exactly, so the expected depth is that plane at the texel
// coordinate clamped into [0, W-1] x [0, H-1].
TEST(IntersectDepthSurface, BilinearReadsClampToTheEdgeTexels) {
  const int W = 5, H = 4;
  auto planeDepth = [](double x, double y) { return 0.30 + 0.06 * x + 0.035 * y; };
  Image img(W, H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) img.at(x, y) = glm::vec4(static_cast<float>(planeDepth(x, y)));
  const Texture2D depth(std::move(img));
  const float n = 0.5f, f = 20.0f;
  SnellDepthSurface s = snellDepthSurface(glm::perspective(1.0f, 1.0f, n, f), n, f, SNELL_DEPTH_GL, 1.0f);
  s.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
  // Every edge band (and the corners), the borders themselves, and an interior point for reference.
  const float us[] = {0.0f, 0.03f, 0.09f, 0.5f, 0.93f, 0.97f, 1.0f};
  const float vs[] = {0.0f, 0.04f, 0.11f, 0.5f, 0.9f, 0.96f, 1.0f};
  for (float u : us)
    for (float v : vs) {
      const double tx = std::min(std::max(static_cast<double>(u) * W - 0.5, 0.0), W - 1.0);
      const double ty = std::min(std::max(static_cast<double>(v) * H - 0.5, 0.0), H - 1.0);
      const double want = -glDistance(planeDepth(tx, ty), n, f);
      const SnellSurfaceSample x = snellSampleSurface(depth, glm::vec2(u, v), s);
      ASSERT_TRUE(x.valid) << u << "," << v;
      EXPECT_TRUE(x.interpolated) << u << "," << v;
      EXPECT_NEAR(x.viewZ, want, 2e-6 * -want) << u << "," << v;
    }
}

// A level one texel wide or tall (the top of a mip chain, a 1-pixel strip) is a level like any
// other: its texels read.
TEST(IntersectDepthSurface, OneTexelWideOrTallLevelsRead) {
  const float n = 0.5f, f = 20.0f;
  const SnellDepthSurface s = snellDepthSurface(glm::perspective(1.0f, 1.0f, n, f), n, f, SNELL_DEPTH_GL, 1.0f);
  for (const glm::ivec2 size : {glm::ivec2(1, 4), glm::ivec2(4, 1), glm::ivec2(1, 1)}) {
    Image img(size.x, size.y);
    for (int y = 0; y < size.y; ++y)
      for (int x = 0; x < size.x; ++x) img.at(x, y) = glm::vec4(0.2f + 0.1f * static_cast<float>(x + y));
    const Texture2D depth(std::move(img));
    for (int y = 0; y < size.y; ++y)
      for (int x = 0; x < size.x; ++x) {
        const glm::vec2 uv((static_cast<float>(x) + 0.5f) / static_cast<float>(size.x),
                           (static_cast<float>(y) + 0.5f) / static_cast<float>(size.y));
        const double want = -glDistance(0.2f + 0.1f * static_cast<float>(x + y), n, f);
        const SnellSurfaceSample r = snellSampleSurface(depth, uv, s);
        ASSERT_TRUE(r.valid) << size.x << "x" << size.y << " texel " << x << "," << y;
        EXPECT_NEAR(r.viewZ, want, 2e-6 * -want);
      }
  }
}

// The smallest distance a surface can hold, zNear = FLT_MIN at depth 0 (GL: depth 0 is the near
// plane), is a surface like any other: a valid read at -FLT_MIN.
TEST(IntersectDepthSurface, ASurfaceAtTheSmallestNearPlaneReads) {
  const Texture2D depth(Image(2, 2, glm::vec4(0.0f)));
  const SnellDepthSurface s = snellDepthSurface(glm::mat4(1.0f), FLT_MIN, 1.0f, SNELL_DEPTH_GL, 1.0f);
  const SnellSurfaceSample x = snellSampleSurface(depth, glm::vec2(0.3f, 0.7f), s);
  EXPECT_TRUE(x.valid);
  EXPECT_EQ(x.viewZ, -FLT_MIN);
}

// On a surface that cannot linearize (zNear 0), four surface texels are still no read: the sample
// is invalid and, as every invalid sample, not interpolated.
TEST(IntersectDepthSurface, AnUnreadableBilinearSampleIsNotInterpolated) {
  const Texture2D depth(Image(4, 4, glm::vec4(0.5f)));
  SnellDepthSurface s = snellDepthSurface(glm::perspective(1.0f, 1.0f, 0.5f, 20.0f), 0.0f, 20.0f, SNELL_DEPTH_GL, 1.0f);
  s.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
  for (const glm::vec2 uv : {glm::vec2(0.5f), glm::vec2(0.3f, 0.6f), glm::vec2(0.0f), glm::vec2(1.0f)}) {
    const SnellSurfaceSample x = snellSampleSurface(depth, uv, s);
    EXPECT_FALSE(x.valid);
    EXPECT_FALSE(x.interpolated);
    EXPECT_EQ(x.viewZ, 0.0f);
  }
}

// Above 2^23 texels (SNELL_PIXEL_ON_SCREEN's domain reaches 2^24) floats are a whole texel apart, and
// at uv = 1 the texel coordinate uv W - 0.5 is a tie that rounds to the even W itself: the first
// texel is still clamped into the level, so the read is the last texel's depth, as at any smaller size.
TEST(IntersectDepthSurface, BilinearAtTheFarEdgeOfAVeryWideLevel) {
  const int wide = (1 << 23) + 2;
  ASSERT_EQ(static_cast<float>(wide) - 0.5f, static_cast<float>(wide));  // the tie this test is about
  const float n = 0.5f, f = 20.0f;
  SnellDepthSurface s = snellDepthSurface(glm::perspective(1.0f, 1.0f, n, f), n, f, SNELL_DEPTH_GL, 1.0f);
  s.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
  const double want = -glDistance(0.5, n, f);
  for (const glm::ivec2 size : {glm::ivec2(wide, 1), glm::ivec2(1, wide)}) {
    const Texture2D depth(Image(size.x, size.y, glm::vec4(0.5f)));
    const SnellSurfaceSample x = snellSampleSurface(depth, glm::vec2(1.0f), s);
    ASSERT_TRUE(x.valid) << size.x << "x" << size.y;
    EXPECT_NEAR(x.viewZ, want, 2e-6 * -want) << size.x << "x" << size.y;
  }
}
