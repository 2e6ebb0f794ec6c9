// Two-interface refraction (glsl/snell/shade/two_interface*.glsl,
// technique_*.glsl, environment*.glsl) against an exact double-precision
// trace through a glass sphere (support/technique_scene.hpp): exit directions per
// preset, exit points on a painting behind the sphere (Mayer & Assarsson's
// poster case), Beer-Lambert thickness, fallbacks, the dispatcher, and the
// environment helpers.
#include <gtest/gtest.h>

#include <snell/texture_cube.hpp>
#include <snell/snell.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "support/technique_scene.hpp"
#include "support/rough_read.hpp"
#include "support/texel_density.hpp"

namespace {

using namespace snell;
using technique_test::Exact;
using technique_test::Scene;

// The technique, material and view a test varies together; a preset converts to one with the defaults.
struct Options {
  SnellTechnique t = snellTechnique();
  SnellMaterial m = snellMaterial();
  SnellView v = snellView();
  Options() = default;
  Options(const SnellTechnique& technique) : t(technique) {}  // NOLINT: a preset reads as options
};

glm::dvec3 kCentreD() { return technique_test::kCentre; }

constexpr double kIor = 1.5;
constexpr double kScale = double(SNELL_ROUGH_CONE_LOD_SCALE);

const Scene& scene() {
  static const Scene s = technique_test::makeScene(256, 256);
  return s;
}

SnellTwoInterfacePath trace(const Scene& s, const Exact& e, const Options& o, float dN) {
  return snellTwoInterfaceTrace(glm::vec3(e.p1), glm::vec3(e.n1), snellIorToEta(1.0f, float(kIor)), dN, TECH_OBJECT_ARGS(s), o.t,
                                o.m.tirPolicy);
}

struct Stats {
  std::vector<double> errors;  // per pixel
  int pixels = 0, fellBack = 0, backMiss = 0;
  double totalFetches = 0.0;
  double mean() const {
    double m = 0.0;
    for (double e : errors) m += e;
    return errors.empty() ? 0.0 : m / double(errors.size());
  }
  double quantile(double q) const {
    if (errors.empty()) return 0.0;
    std::vector<double> v = errors;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, size_t(q * double(v.size())))];
  }
  double shareBelow(double x) const {
    size_t n = 0;
    for (double e : errors) n += e <= x;
    return errors.empty() ? 0.0 : double(n) / double(errors.size());
  }
};

// Angle (degrees) between the technique's exit direction and the exact T2 over
// every sphere pixel (exact paths never TIR inside a sphere).
Stats directionErrors(const Options& o, bool exactDn = true) {
  const Scene& s = scene();
  Stats st;
  for (int j = 0; j < s.height; ++j)
    for (int i = 0; i < s.width; ++i) {
      const glm::dvec2 uv((i + 0.5) / s.width, (j + 0.5) / s.height);
      const Exact e = technique_test::exactTrace(s.front, uv, kIor);
      if (!e.hitsSphere || e.tir) continue;
      ++st.pixels;
      const SnellTwoInterfacePath p = trace(s, e, o, exactDn ? float(2.0 * technique_test::kRadius) : 0.0f);
      st.totalFetches += p.fetches;
      if (p.fellBack) {
        ++st.fellBack;
        continue;
      }
      const double c = std::clamp(glm::dot(glm::dvec3(p.exitDirection), e.t2), -1.0, 1.0);
      st.errors.push_back(std::acos(c) * 180.0 / M_PI);
    }
  return st;
}

void report(const char* name, const Stats& st) {
  std::printf("[technique] %-22s exit-direction error deg: mean %.4f p50 %.4f p95 %.4f p99 %.4f | fell back %d/%d | "
              "fetches/px %.2f\n",
              name, st.mean(), st.quantile(0.5), st.quantile(0.95), st.quantile(0.99), st.fellBack, st.pixels,
              st.totalFetches / std::max(1, st.pixels));
}

TEST(TechniqueTwoInterface, ExitDirectionPerPreset) {
  struct P {
    const char* name;
    Options o;
  };
  Options dir16 = snellPresetDir();
  dir16.t.back.intersect.cbsSteps = 16;
  const SnellDepthRange box = snellDepthRangeFromBox(
      mat4(1.0f), glm::vec3(technique_test::kCentre) - glm::vec3(float(technique_test::kRadius)),
      glm::vec3(technique_test::kCentre) + glm::vec3(float(technique_test::kRadius)));
  ASSERT_TRUE(box.valid);
  const std::vector<P> presets = {
      {"DIR (CBS 5, pyramid)", snellPresetDir()},
      {"DIR (CBS 16)", dir16},
      {"DIR bounds (CBS 5, box)", snellPresetDirBounds(box.zNearest, box.zFarthest)},
      {"ISR (exact dN)", snellPresetIsr()},
      {"Plane normal N=0", snellPresetPlaneNormal(0)},
      {"Plane normal N=1", snellPresetPlaneNormal(1)},
      {"Plane normal N=3", snellPresetPlaneNormal(3)},
      {"Plane depth N=0", snellPresetPlaneDepth(0)},
      {"Plane depth N=3", snellPresetPlaneDepth(3)},
      {"Single sample", snellPresetSingleSample()},
      {"Linear march", snellPresetLinearMarch()},
      {"DDA march", snellPresetDdaMarch()},
  };
  std::vector<Stats> all;
  for (const P& p : presets) {
    all.push_back(directionErrors(p.o));
    report(p.name, all.back());
  }
  // DIR, 5 steps: beta error <= 3.1% of the range; DIR with 16 steps is close to exact.
  EXPECT_LT(all[0].quantile(0.95), 3.0);
  // Floor: the back normal, read bilinearly at the hit (SNELL_TWO_INTERFACE_NORMAL_SAMPLE 1: p50 0.009 deg at
  // 256^2; a texel fetch of the nearest texel gave ~0.25 deg).
  EXPECT_LT(all[1].quantile(0.95), 0.5);
  EXPECT_LT(all[1].mean(), all[0].mean());
  // The bounding-box range is looser: same steps, larger error allowed, still bounded.
  EXPECT_LT(all[2].quantile(0.95), 6.0);
  // ISR with exact d_N on a sphere: Wyman's heuristic is exact at normal incidence
  // and off near the rim (d between d_V -> 0 and 2R, the true chord 2R cos(theta_t)).
  EXPECT_LT(all[3].quantile(0.5), 2.0);
  EXPECT_LT(all[3].mean(), all[9].mean());
  // Plane (normal): error falls with iterations.
  EXPECT_LT(all[5].mean(), all[4].mean());
  EXPECT_LT(all[6].mean(), all[5].mean());
  EXPECT_LT(all[6].quantile(0.95), 1.0);
  EXPECT_LT(all[8].mean(), all[7].mean());
  // Searches and marches rarely fall back inside the silhouette; the normal-based
  // plane misses ~23% of the sphere's rim rays (the plane behind W sends P off the
  // back faces: snellIntersectPlaneNormal's own valid rate, see intersect_plane_test).
  for (size_t k = 0; k < all.size(); ++k) {
    const bool planeNormal = k >= 4 && k <= 6;
    EXPECT_LT(all[k].fellBack, planeNormal ? all[k].pixels / 4 : all[k].pixels / 20) << presets[k].name;
  }
}

// The painting behind the sphere (the geometric criterion): over every
// sphere pixel of the output image (256^2, the buffers' resolution) whose exact
// path does not undergo TIR and whose exact exit ray meets the painting on
// screen, the distance in output pixels between the projection of the
// technique's exit-slot hit on the painting and the projection of the exact
// double-precision hit. A pixel where the back slot finds no P2 (no exit point)
// or the exit slot finds no hit counts as a failure (infinite error): the
// denominator is every non-TIR pixel, nothing is set aside. The same measure for
// P2 itself (the exit point from the sphere, projected) is reported alongside.
struct PaintingStats : Stats {
  std::vector<double> p2Errors;  // projected P2 vs exact P2, output pixels (1e9 without a back hit)
  int exitMiss = 0;
  // Pixels whose exact first normal-based plane (the back face's tangent plane at the point behind P1, on the
  // view ray) lies behind P1 along T1: the ray never meets it (SNELL_PLANE_FACING_FALLBACK's case).
  int firstPlaneBehind = 0;
  int firstPlaneBehindWithinHalfPx = 0;
};

// The analytic test behind `firstPlaneBehind`: the ray P1 + t T1 meets the tangent plane at the back point
// on P1's line of sight for t > 0 only when T1 points towards it (dot(T1, n_out) > 0).
bool firstPlaneBehindP1(const Exact& e) {
  const glm::dvec3 q = glm::normalize(e.p1);
  const glm::dvec3 oc = -kCentreD();
  const double b = glm::dot(q, oc), cc = glm::dot(oc, oc) - technique_test::kRadius * technique_test::kRadius;
  const double sBack = -b + std::sqrt(std::max(0.0, b * b - cc));
  const glm::dvec3 nBack = (sBack * q - technique_test::kCentre) / technique_test::kRadius;
  return glm::dot(e.t1, nBack) <= 0.0;
}

PaintingStats paintingErrors(const Options& o) {
  const Scene& s = scene();
  PaintingStats st;
  for (int j = 0; j < s.height; ++j)
    for (int i = 0; i < s.width; ++i) {
      const glm::dvec2 uv((i + 0.5) / s.width, (j + 0.5) / s.height);
      const Exact e = technique_test::exactTrace(s.front, uv, kIor);
      if (!e.hitsSphere || e.tir || !e.planeHit) continue;
      const glm::dvec2 exactUv = s.plane.project(*e.planeHit);
      if (exactUv.x < 0.0 || exactUv.x > 1.0 || exactUv.y < 0.0 || exactUv.y > 1.0) continue;
      ++st.pixels;
      const SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(
          glm::vec3(e.p1), glm::vec3(e.n1), float(2.0 * technique_test::kRadius), TECH_OBJECT_ARGS(s), TECH_SCENE_ARGS(s), o.t, o.m, o.v);
      st.totalFetches += r.fetches;
      const glm::dvec2 px(s.width, s.height);
      const bool behind = firstPlaneBehindP1(e);
      st.firstPlaneBehind += behind;
      if (!r.backHit) {
        ++st.backMiss;
        st.errors.push_back(1e9);
        st.p2Errors.push_back(1e9);
        continue;
      }
      st.p2Errors.push_back(glm::length((s.plane.project(glm::dvec3(r.exitPoint)) - s.plane.project(e.p2)) * px));
      if (!r.exitHit.valid) {
        ++st.exitMiss;
        st.errors.push_back(1e9);
        continue;
      }
      st.errors.push_back(glm::length((s.plane.project(glm::dvec3(r.exitHit.position)) - exactUv) * px));
      st.firstPlaneBehindWithinHalfPx += behind && st.errors.back() <= 0.5;
    }
  return st;
}

double shareBelow(const std::vector<double>& v, double x) {
  size_t n = 0;
  for (double e : v) n += e <= x;
  return v.empty() ? 0.0 : double(n) / double(v.size());
}

TEST(TechniqueTwoInterface, PaintingBehindTheSphere) {
  struct P {
    const char* name;
    Options o;
  };
  std::vector<P> presets = {{"Plane normal N=0", snellPresetPlaneNormal(0)},
                            {"Plane normal N=2", snellPresetPlaneNormal(2)},
                            {"Plane normal N=3", snellPresetPlaneNormal(3)},
                            {"Plane normal N=4", snellPresetPlaneNormal(4)},
                            {"Plane depth N=2", snellPresetPlaneDepth(2)},
                            {"Plane depth N=3", snellPresetPlaneDepth(3)},
                            {"Plane depth N=4", snellPresetPlaneDepth(4)},
                            {"DIR (CBS 5)", snellPresetDir()},
                            {"DIR (CBS 12)", snellPresetDir()},
                            {"Single sample", snellPresetSingleSample()},
                            {"Linear march", snellPresetLinearMarch()},
                            {"DDA march", snellPresetDdaMarch()},
                            {"Plane normal N=1", snellPresetPlaneNormal(1)},
                            {"N=1 no far start", snellPresetPlaneNormal(1)},
                            {"N=2 no far start", snellPresetPlaneNormal(2)}};
  presets[8].o.t.back.intersect.cbsSteps = 12;
  presets[8].o.t.exit.intersect.cbsSteps = 12;
  for (int i : {13, 14}) presets[size_t(i)].o.t.back.intersect.planeFarStart = presets[size_t(i)].o.t.exit.intersect.planeFarStart = false;
  std::vector<PaintingStats> all;
  for (P& p : presets) {
    p.o.t.exit.source = SNELL_SOURCE_BUFFERS;
    all.push_back(paintingErrors(p.o));
    const PaintingStats& st = all.back();
    const int hits = st.pixels - st.backMiss;
    std::printf("[painting] %-16s %d non-TIR px: exit point on the painting within 0.5 px %.2f%% 1 px %.2f%% (p50 "
                "%.3f) | P2 within 0.5 px %.2f%% | no back hit %d (%.2f%%), first plane behind P1 %d (of them within 0.5 px %d), no exit hit %d "
                "| of the back hits within 0.5 px %.2f%% | fetches/px %.2f\n",
                p.name, st.pixels, 100.0 * st.shareBelow(0.5), 100.0 * st.shareBelow(1.0), st.quantile(0.5),
                100.0 * shareBelow(st.p2Errors, 0.5), st.backMiss, 100.0 * st.backMiss / std::max(1, st.pixels),
                st.firstPlaneBehind, st.firstPlaneBehindWithinHalfPx, st.exitMiss,
                100.0 * (double(st.shareBelow(0.5)) * st.pixels) / std::max(1, hits),
                st.totalFetches / std::max(1, st.pixels));
  }
  ASSERT_GT(all[0].pixels, 30000);
  // The criterion: exit points on the painting within 0.5 px for at least 99% of the non-TIR pixels
  // (every such pixel counts; a missing back or exit hit is a failure). Met by the depth-based plane with 3
  // refinements (99.85% measured at 256^2) and the normal-based plane with 4 (99.77%; 2 with the far start), thanks to
  // SNELL_PLANE_FACING_FALLBACK: without it, the back slot found no P2 at all for the rim pixels whose
  // first plane lies behind P1 (21.8% normal-based, 3.2% depth-based; 78.2% / 96.8% within 0.5 px).
  const PaintingStats& normal3 = all[2];
  const PaintingStats& normal4 = all[3];
  const PaintingStats& depth3 = all[5];
  EXPECT_GE(depth3.shareBelow(0.5), 0.99);
  EXPECT_GE(normal4.shareBelow(0.5), 0.99);
  EXPECT_GE(all[6].shareBelow(0.5), 0.99);  // depth N=4
  // The rim band is real and large on this scene (the analytic count, independent of the method), and the
  // fallback is what recovers it: most of those pixels end within 0.5 px too.
  EXPECT_GT(normal4.firstPlaneBehind, normal4.pixels / 5);
  EXPECT_GE(normal4.firstPlaneBehindWithinHalfPx, normal4.firstPlaneBehind * 98 / 100);
  for (const PaintingStats* st : std::vector<const PaintingStats*>{&normal3, &normal4, &depth3, &all[6]}) {
    EXPECT_LE(st->backMiss, st->pixels / 1000);
    EXPECT_LE(st->exitMiss, st->pixels / 1000);
  }
  // Refinement helps: one plane (N = 0) is far off, then the share grows with N (to 100% at N = 2 with the
  // far start: it cannot grow further).
  EXPECT_LT(all[0].shareBelow(0.5), 0.3);
  EXPECT_GT(all[12].shareBelow(0.5), all[0].shareBelow(0.5));
  EXPECT_GT(all[1].shareBelow(0.5), all[12].shareBelow(0.5));
  EXPECT_GE(normal3.shareBelow(0.5), all[1].shareBelow(0.5));
  EXPECT_GE(normal4.shareBelow(0.5), normal3.shareBelow(0.5));
  // The far start (intersect/plane_far_start.glsl) on this sphere: 2 refinements meet the 99% criterion that
  // the poster's first plane needs 4 for, and 1 refinement gains most (measured at 256^2: N = 1 from
  // 60.96% to 97.70%, N = 2 from 90.90% to 100.00%).
  EXPECT_GE(all[1].shareBelow(0.5), 0.99);
  EXPECT_LT(all[14].shareBelow(0.5), 0.99);
  EXPECT_GT(all[12].shareBelow(0.5), all[13].shareBelow(0.5) + 0.2);
  // The searches: DIR with 12 steps, for comparison (no rim misses, less precise where it hits).
  EXPECT_GT(all[8].shareBelow(1.0), 0.8);
}

// An opaque card inside the sphere (the scene plane, nearly facing the camera, 1.8 behind the centre): with
// insideScene, a refracted ray that meets the card before the sphere's back ends there, with the card's colour
// absorbed over the chord to it; the exact answer is the closed-form ray-plane hit against the ray-sphere exit.
// Positions within a pixel for the plane (its planes land on the card), four for the searches (their last
// bracket: CBS's 5 steps, the march's 32 + 4 bisections).
TEST(TechniqueTwoInterface, OpaqueCardInsideTheSphere) {
  const glm::dvec3 cardNormal = glm::normalize(glm::dvec3(0.1, -0.05, 1.0));
  const glm::dvec3 cardPoint = technique_test::kCentre + glm::dvec3(0.0, 0.0, -1.8);
  const Scene s = technique_test::makeScene(192, 192, cardPoint, cardNormal);
  // (preset, position tolerance in pixels, the least share of sphere pixels whose flag is the exact one):
  // CBS's 5 steps end beyond the back for about 6 % of the rays that meet the card near it (measured 94.3 %).
  struct Case {
    SnellTechnique preset;
    double tolerancePixels, agreeShare;
  };
  const Case cases[] = {{snellPresetPlaneNormal(2), 1.0, 0.99}, {snellPresetDir(), 4.0, 0.93},
                        {snellPresetLinearMarch(), 4.0, 0.97}};
  for (const Case& c : cases) {
    const SnellTechnique& preset = c.preset;
    const double tolerancePixels = c.tolerancePixels;
    Options o(preset);
    o.t.exit.source = SNELL_SOURCE_BUFFERS;
    o.t.insideScene = true;
    o.m.reflection = false;
    o.m.absorption = vec3(0.3f, 0.1f, 0.2f);
    int pixels = 0, insideExact = 0, agree = 0, both = 0, within = 0, colourOk = 0;
    for (int j = 0; j < s.height; ++j)
      for (int i = 0; i < s.width; ++i) {
        const glm::dvec2 uv((i + 0.5) / s.width, (j + 0.5) / s.height);
        const Exact e = technique_test::exactTrace(s.front, uv, kIor);
        if (!e.hitsSphere) continue;
        ++pixels;
        // The exact first segment: P1 + t T1 meets the card at tCard, the sphere's back at |P2 - P1|.
        const double den = glm::dot(e.t1, cardNormal);
        const double tCard = std::abs(den) > 1e-12 ? glm::dot(cardPoint - e.p1, cardNormal) / den : -1.0;
        const bool exactInside = tCard > 0.0 && tCard < glm::length(e.p2 - e.p1);
        insideExact += exactInside;
        const SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(
            glm::vec3(e.p1), glm::vec3(e.n1), 0.0f, TECH_OBJECT_ARGS(s), TECH_SCENE_ARGS(s), o.t, o.m, o.v);
        agree += r.insideHit == exactInside;
        if (!(exactInside && r.insideHit)) continue;
        ++both;
        const glm::dvec3 card = e.p1 + tCard * e.t1;
        // Half a pixel at the card's depth.
        const double halfPixel = 0.5 * 2.0 * std::tan(0.5 * double(snell_test::kSceneFovy)) * -card.z / s.height;
        within += glm::length(glm::dvec3(r.exitPoint) - card) <= 2.0 * halfPixel * tolerancePixels;
        const glm::dvec3 expected = glm::dvec3(technique_test::paintingColor(card)) *
                                    glm::exp(-glm::dvec3(o.m.absorption) * tCard);
        colourOk += glm::length(glm::dvec3(r.color) - expected) < 0.02;
      }
    SCOPED_TRACE(preset.back.intersect.strategy);
    std::printf("[card] strategy %d: inside %d of %d, the flag agrees on %d, within %.0f px %d, colour %d\n",
                preset.back.intersect.strategy, insideExact, pixels, agree, tolerancePixels, within, colourOk);
    ASSERT_GT(pixels, 5000);
    // The card is in the way of part of the sphere's rays, not all.
    ASSERT_GT(insideExact, pixels / 4);
    ASSERT_LT(insideExact, pixels * 9 / 10);
    EXPECT_GE(agree, int(c.agreeShare * pixels));
    EXPECT_GE(within, both * 98 / 100);
    EXPECT_GE(colourOk, both * 98 / 100);
  }
  // Without the flag the card is never hit from inside (the exit rays see it only through the rule).
  Options off(snellPresetPlaneNormal(2));
  off.t.exit.source = SNELL_SOURCE_BUFFERS;
  const Exact e = technique_test::exactTrace(s.front, glm::dvec2(0.55, 0.45), kIor);
  ASSERT_TRUE(e.hitsSphere);
  EXPECT_FALSE(snellTwoInterfaceRefraction(glm::vec3(e.p1), glm::vec3(e.n1), 0.0f, TECH_OBJECT_ARGS(s),
                                           TECH_SCENE_ARGS(s), off.t, off.m, off.v)
                   .insideHit);
}

TEST(TechniqueTwoInterface, BeerLambertUsesTheFoundChord) {
  const Scene& s = scene();
  Options o = snellPresetDir();
  o.t.back.intersect.cbsSteps = 16;
  o.m.reflection = false;
  o.m.absorption = glm::vec3(0.1f, 0.3f, 0.6f);
  double maxRel = 0.0, maxColor = 0.0;
  int n = 0;
  for (int j = 0; j < s.height; j += 3)
    for (int i = 0; i < s.width; i += 3) {
      const glm::dvec2 uv((i + 0.5) / s.width, (j + 0.5) / s.height);
      const Exact e = technique_test::exactTrace(s.front, uv, kIor);
      if (!e.hitsSphere || e.tir) continue;
      const SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(
          glm::vec3(e.p1), glm::vec3(e.n1), 0.0f, TECH_OBJECT_ARGS(s),
          TECH_SCENE_ARGS(s), o.t, o.m, o.v);
      if (r.fellBack) continue;
      ++n;
      const double chord = glm::length(e.p2 - e.p1);
      if (chord > 0.5) maxRel = std::max(maxRel, std::fabs(double(r.pathLength) - chord) / chord);
      // The colour is the environment along T2 attenuated over pathLength.
      const glm::vec3 w = r.exitDirection;
      const glm::vec4 env = snellSampleEquirect(s.env, w, 0.0f);
      const glm::vec3 expect = glm::vec3(env) * glm::exp(-o.m.absorption * r.pathLength);
      maxColor = std::max(maxColor, double(glm::length(r.color - expect)));
    }
  std::printf("[beer] %d px: max relative chord error %.4f, max colour error %.2g\n", n, maxRel, maxColor);
  EXPECT_GT(n, 1000);
  EXPECT_LT(maxRel, 0.02);
  EXPECT_LT(maxColor, 1e-5);
}

TEST(TechniqueTwoInterface, FallbackWhenTheExitLeavesTheScreen) {
  const Scene& s = scene();
  // An empty scene buffer: every exit-slot search fails.
  Texture2D emptyDepth(Image(s.width, s.height, glm::vec4(1.0f, 0.0f, 0.0f, 0.0f)));
  const Texture2D emptyPyramid = snellBuildDepthPyramid(emptyDepth, s.sceneSurface());
  for (int fallback : {SNELL_FALLBACK_ENVIRONMENT, SNELL_FALLBACK_EDGE_FADE}) {
    Options o = snellPresetPlaneNormal(2);
    o.t.exit.source = SNELL_SOURCE_BUFFERS;
    o.t.exit.fallback = fallback;
    o.m.reflection = false;
    int n = 0, bad = 0;
    for (int j = 0; j < s.height; j += 4)
      for (int i = 0; i < s.width; i += 4) {
        const glm::dvec2 uv((i + 0.5) / s.width, (j + 0.5) / s.height);
        const Exact e = technique_test::exactTrace(s.front, uv, kIor);
        if (!e.hitsSphere) continue;
        const SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(
            glm::vec3(e.p1), glm::vec3(e.n1), 0.0f, TECH_OBJECT_ARGS(s),
            emptyDepth, s.sceneNormalMips, emptyPyramid, s.sceneColor, s.sceneSurface(), s.env, o.t, o.m, o.v);
        ++n;
        EXPECT_TRUE(r.fellBack);
        EXPECT_FALSE(r.exitHit.valid);
        const bool finite = std::isfinite(r.color.x) && std::isfinite(r.color.y) && std::isfinite(r.color.z);
        if (!finite || r.color.x + r.color.y + r.color.z < 0.1f) ++bad;
        if (fallback == SNELL_FALLBACK_ENVIRONMENT) {
          const glm::vec4 env = snellSampleEquirect(s.env, r.exitDirection, 0.0f);
          EXPECT_LT(glm::length(r.color - glm::vec3(env)), 1e-6f);
        }
      }
    EXPECT_GT(n, 100);
    EXPECT_EQ(bad, 0) << "fallback " << fallback << " produced black or non-finite colours";
  }
  // Exit rays leaving the screen sideways: from the sphere's edge region outwards.
  Options o = snellPresetDir();
  o.t.exit.source = SNELL_SOURCE_BUFFERS;
  o.t.exit.fallback = SNELL_FALLBACK_EDGE_FADE;
  const SnellTwoInterfaceExit ex =
      snellTwoInterfaceExit(glm::vec3(2.0f, 0.0f, -5.0f), glm::vec3(1.0f, 0.0f, -0.05f), TECH_SCENE_ARGS(s), o.t.exit, o.m, o.v);
  EXPECT_TRUE(ex.fellBack);
  EXPECT_FALSE(ex.hit.valid);
  const glm::vec4 env = snellSampleEquirect(s.env, glm::normalize(glm::vec3(1.0f, 0.0f, -0.05f)), 0.0f);
  EXPECT_LT(glm::length(ex.color - glm::vec3(env)), 1e-6f);  // projection off screen: fade 0, environment
}

// Regression (property test inputs #14557 of snellTwoInterfaceTrace and
// #12414 of snellTwoInterfaceRefraction): ISR with d_N = 1e30 puts P2 ~2e29
// units away, on screen over the sphere, so the back hit was accepted and
// pathLength = length(P2 - P1) overflowed to +inf. By contract such a hit
// counts as none: fallback with exitPoint = P1, pathLength 0, exit along T1
// (checked against a double-precision Snell refraction). d_N = 1e18 (|P2 - P1|
// still finite) is a hit.
TEST(TechniqueTwoInterface, BackHitBeyondFloatLengthFallsBack) {
  const Scene& s = scene();
  Options isr = snellPresetIsr();
  isr.m.tirPolicy = SNELL_TIR_REFLECT;
  {
    const glm::vec3 p1(-0.88325721f, 0.6121943f, -4.33259392f), n1(0.0f, 0.369179219f, 0.757911861f);
    const float ior = 1.28285468f;
    const float eta = snellIorToEta(1.0f, ior);
    const glm::dvec3 v = glm::normalize(glm::dvec3(p1)), n = glm::normalize(glm::dvec3(n1));
    const glm::dvec3 t1 = glm::refract(v, glm::dot(v, n) > 0.0 ? -n : n, double(eta));
    auto run = [&](float dN) {
      return snellTwoInterfaceTrace(p1, n1, eta, dN, TECH_OBJECT_ARGS(s),
                                    isr.t, isr.m.tirPolicy);
    };
    const SnellTwoInterfacePath far = run(1e30f);
    EXPECT_TRUE(far.valid);
    EXPECT_FALSE(far.hit);
    EXPECT_TRUE(far.fellBack);
    EXPECT_EQ(far.pathLength, 0.0f);
    EXPECT_EQ(far.exitPoint, p1);
    EXPECT_LT(glm::length(glm::dvec3(far.exitDirection) - t1), 1e-5);
    const SnellTwoInterfacePath near = run(1e18f);
    EXPECT_TRUE(near.hit);
    EXPECT_TRUE(std::isfinite(near.pathLength));
    EXPECT_NEAR(near.pathLength, glm::length(glm::dvec3(near.exitPoint) - glm::dvec3(p1)), 1e12);
  }
  {
    const glm::vec3 p1(1.19292653f, 0.687132239f, -4.1956501f), n1(0.405875713f, 0.403241932f, 0.820159018f);
    Options o = isr;
    o.m.ior = 1.70045829f;
    o.m.iors = glm::vec3(o.m.ior * 0.98f, o.m.ior, o.m.ior * 1.02f);
    o.m.dispersion = 3;
    o.m.tirPolicy = SNELL_TIR_ZERO;
    o.t.exit.fallback = SNELL_FALLBACK_EDGE_FADE;
    const SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(
        p1, n1, 1e30f, TECH_OBJECT_ARGS(s), TECH_SCENE_ARGS(s), o.t, o.m, o.v);
    EXPECT_FALSE(r.backHit);
    EXPECT_TRUE(r.fellBack);
    EXPECT_EQ(r.pathLength, 0.0f);
    EXPECT_EQ(r.exitPoint, p1);
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(std::isfinite(r.color[k])) << k;
      EXPECT_TRUE(std::isfinite(r.exitDirection[k])) << k;
    }
  }
}

TEST(TechniqueTwoInterface, DispatcherMatchesTheStrategies) {
  const Scene& s = scene();
  const SnellDepthSurface b = s.backSurface();
  const SnellDepthRange range = snellDepthRangeFromPyramid(s.backPyramid);
  ASSERT_TRUE(range.valid);
  int lod0Differs = 0;
  for (int k = 0; k < 200; ++k) {
    const glm::dvec2 uv(0.3 + 0.4 * (k % 20) / 20.0, 0.3 + 0.4 * (k / 20) / 10.0);
    const Exact e = technique_test::exactTrace(s.front, uv, kIor);
    if (!e.hitsSphere) continue;
    const glm::vec3 o(e.p1), d(e.t1);
    auto same = [](const SnellHit& x, const SnellHit& y, int extraFetches) {
      return x.valid == y.valid && x.uv == y.uv && x.position == y.position && x.fetches == y.fetches + extraFetches;
    };
    EXPECT_TRUE(same(snellIntersectWith(o, d, s.back.depth, s.backNormalMips, s.backPyramid, b,
                                        snellIntersectOptions(SNELL_STRATEGY_SINGLE)),
                     snellIntersectSingleSample(o, d, s.back.depth, b), 0));
    EXPECT_TRUE(same(snellIntersectWith(o, d, s.back.depth, s.backNormalMips, s.backPyramid,
                                        b, snellIntersectOptions(SNELL_STRATEGY_PLANE_NORMAL)),
                     snellIntersectPlaneNormal(o, d, s.back.depth, s.backNormalMips, s.backPyramid, b, 0.0f, SNELL_PLANE_ITERATIONS, true), 0));
    EXPECT_TRUE(same(snellIntersectWith(o, d, s.back.depth, s.backNormalMips, s.backPyramid,
                                        b, snellIntersectOptions(SNELL_STRATEGY_PLANE_DEPTH)),
                     snellIntersectPlaneDepth(o, d, s.backPyramid, b, s.backPyramid.levelCount() - 1,
                                              SNELL_PLANE_ITERATIONS, true),
                     0));
    EXPECT_TRUE(same(snellIntersectWith(o, d, s.back.depth, s.backNormalMips, s.backPyramid, b,
                                        snellIntersectOptions(SNELL_STRATEGY_CBS)),
                     snellConservativeBinarySearch(o, d, s.back.depth, b, range.zNearest, range.zFarthest), 1));
    EXPECT_TRUE(same(snellIntersectWith(o, d, s.back.depth, s.backNormalMips, s.backPyramid, b,
                                        snellIntersectOptions(SNELL_STRATEGY_BINARY)),
                     snellBinarySearch(o, d, s.back.depth, b, range.zNearest, range.zFarthest), 1));
    EXPECT_TRUE(same(snellIntersectWith(o, d, s.back.depth, s.backNormalMips,
                                        s.backPyramid, b, snellIntersectOptions(SNELL_STRATEGY_LINEAR_BINARY)),
                     snellLinearBinarySearch(o, d, s.back.depth, b, range.zNearest, range.zFarthest), 1));
    EXPECT_TRUE(same(snellIntersectWith(o, d, s.back.depth, s.backNormalMips,
                                        s.backPyramid, b, snellIntersectOptions(SNELL_STRATEGY_LINEAR_MARCH)),
                     snellLinearMarch(o, d, s.back.depth, b), 0));
    EXPECT_TRUE(same(snellIntersectWith(o, d, s.back.depth, s.backNormalMips, s.backPyramid, b,
                                        snellIntersectOptions(SNELL_STRATEGY_DDA)),
                     snellDdaMarch(o, d, s.back.depth, b), 0));
    const SnellHit unknown = snellIntersectWith(o, d, s.back.depth, s.backNormalMips, s.backPyramid, b,
                                                snellIntersectOptions(42));
    EXPECT_FALSE(unknown.valid);
    EXPECT_EQ(unknown.fetches, 0);
    // planeMaxLod 0 is a level like any other (only a negative one means the top level).
    SnellIntersectOptions depth0 = snellIntersectOptions(SNELL_STRATEGY_PLANE_DEPTH);
    depth0.planeMaxLod = 0;
    const SnellHit at0 = snellIntersectWith(o, d, s.back.depth, s.backNormalMips, s.backPyramid, b, depth0);
    EXPECT_TRUE(same(at0, snellIntersectPlaneDepth(o, d, s.backPyramid, b, 0, SNELL_PLANE_ITERATIONS, true), 0));
    lod0Differs += !same(at0, snellIntersectPlaneDepth(o, d, s.backPyramid, b, s.backPyramid.levelCount() - 1,
                                                       SNELL_PLANE_ITERATIONS, true), 0);
    // Each count is the field named after its strategy, and the explicit range is read as given.
    SnellIntersectOptions cbs = snellIntersectOptions(SNELL_STRATEGY_CBS);
    cbs.cbsSteps = 9;
    cbs.binarySteps = 1;  // another strategy's field: not read
    cbs.rangeSource = SNELL_RANGE_EXPLICIT;
    cbs.range = snellDepthRangeFromBox(mat4(1.0f), glm::vec3(technique_test::kCentre) - glm::vec3(2.5f),
                                       glm::vec3(technique_test::kCentre) + glm::vec3(2.5f));
    ASSERT_TRUE(cbs.range.valid);
    EXPECT_TRUE(same(snellIntersectWith(o, d, s.back.depth, s.backNormalMips, s.backPyramid, b, cbs),
                     snellConservativeBinarySearch(o, d, s.back.depth, b, cbs.range.zNearest, cbs.range.zFarthest, 9),
                     0));
    SnellIntersectOptions lin = snellIntersectOptions(SNELL_STRATEGY_LINEAR_BINARY);
    lin.linearSteps = 7;
    lin.binarySteps = 3;
    lin.cbsSteps = 1;
    EXPECT_TRUE(same(snellIntersectWith(o, d, s.back.depth, s.backNormalMips, s.backPyramid, b, lin),
                     snellLinearBinarySearch(o, d, s.back.depth, b, range.zNearest, range.zFarthest, 7, 3), 1));
    SnellIntersectOptions march = snellIntersectOptions(SNELL_STRATEGY_LINEAR_MARCH);
    march.marchSteps = 48;
    march.marchBisections = 6;
    march.marchMaxDistance = 4.4f;
    march.ddaMaxDistance = 0.1f;
    EXPECT_TRUE(same(snellIntersectWith(o, d, s.back.depth, s.backNormalMips, s.backPyramid, b, march),
                     snellLinearMarch(o, d, s.back.depth, b, 4.4f, 48, 6), 0));
    SnellIntersectOptions plane = snellIntersectOptions(SNELL_STRATEGY_PLANE_NORMAL);
    plane.planeIterations = 3;
    EXPECT_TRUE(same(snellIntersectWith(o, d, s.back.depth, s.backNormalMips, s.backPyramid, b, plane),
                     snellIntersectPlaneNormal(o, d, s.back.depth, s.backNormalMips, s.backPyramid, b, 0.0f, 3, true), 0));
    // An explicit range that is not valid (an empty box, say) is a miss without a fetch.
    cbs.range = snellDepthRangeInvalid();
    const SnellHit none = snellIntersectWith(o, d, s.back.depth, s.backNormalMips, s.backPyramid, b, cbs);
    EXPECT_FALSE(none.valid);
    EXPECT_EQ(none.fetches, 0);
  }
  EXPECT_GT(lod0Differs, 0);  // level 0 and the top level give different hits on some rays: the choice shows
}

// snellIntersectOptions: the strategy as given and every field's documented default.
TEST(TechniqueTwoInterface, IntersectOptionsHaveTheDocumentedDefaults) {
  for (int strategy : {SNELL_STRATEGY_SINGLE, SNELL_STRATEGY_PLANE_DEPTH, SNELL_STRATEGY_DDA, -1, 42}) {
    const SnellIntersectOptions o = snellIntersectOptions(strategy);
    EXPECT_EQ(o.strategy, strategy);
    EXPECT_EQ(o.depthFilter, SNELL_DEPTH_FILTER_NEAREST);
    EXPECT_EQ(o.planeIterations, SNELL_PLANE_ITERATIONS);
    EXPECT_EQ(o.planeNormalLod, 0.0f);
    EXPECT_EQ(o.planeFarStart, SNELL_PLANE_FAR_START != 0);
    EXPECT_EQ(o.planeMaxLod, -1);
    EXPECT_EQ(o.cbsSteps, SNELL_CBS_STEPS);
    EXPECT_EQ(o.binarySteps, SNELL_BINARY_SEARCH_STEPS);
    EXPECT_EQ(o.linearSteps, SNELL_LINEAR_SEARCH_STEPS);
    EXPECT_EQ(o.rangeSource, SNELL_RANGE_PYRAMID);
    EXPECT_FALSE(o.range.valid);
    EXPECT_EQ(o.marchSteps, SNELL_LINEAR_MARCH_STEPS);
    EXPECT_EQ(o.marchBisections, SNELL_LINEAR_MARCH_REFINE_STEPS);
    EXPECT_EQ(o.marchMaxDistance, SNELL_LINEAR_MARCH_MAX_DISTANCE);
    EXPECT_EQ(o.ddaSteps, SNELL_DDA_STEPS);
    EXPECT_EQ(o.ddaMaxDistance, SNELL_DDA_MAX_DISTANCE);
    EXPECT_EQ(o.ddaThickness, SNELL_DDA_THICKNESS);
    EXPECT_EQ(o.ddaStride, SNELL_DDA_STRIDE);
  }
}

TEST(TechniqueTwoInterface, DispersionTracesThreeChannels) {
  const Scene& s = scene();
  Options o = snellPresetDir();
  o.m.reflection = false;
  const Exact e = technique_test::exactTrace(s.front, glm::dvec2(0.62, 0.55), kIor);
  ASSERT_TRUE(e.hitsSphere);
  auto run = [&](const Options& opt) {
    return snellTwoInterfaceRefraction(glm::vec3(e.p1), glm::vec3(e.n1), 0.0f, TECH_OBJECT_ARGS(s), TECH_SCENE_ARGS(s), opt.t, opt.m, opt.v);
  };
  const SnellTwoInterfaceResult one = run(o);
  Options o3 = o;
  o3.m.dispersion = 3;
  o3.m.iors = glm::vec3(1.5f, 1.5f, 1.5f);
  const SnellTwoInterfaceResult same = run(o3);
  EXPECT_EQ(one.color, same.color);  // equal IORs: the same image, three times the work
  EXPECT_EQ(same.fetches, 3 * one.fetches);
  o3.m.iors = snellDispersionIors(1.5168f, 20.0f);
  const SnellTwoInterfaceResult disp = run(o3);
  Options oR = o, oB = o;
  oR.m.ior = o3.m.iors.x;
  oB.m.ior = o3.m.iors.z;
  EXPECT_EQ(disp.color.x, run(oR).color.x);
  EXPECT_EQ(disp.color.z, run(oB).color.z);
}

// A scene colour whose level k holds the value k everywhere: trilinear filtering returns the level read.
Texture2D levelTexture(int w, int h) {
  Texture2D t(Image(w, h, glm::vec4(0.0f)), Filter::Linear, MipFilter::Linear);
  for (int k = 1; w > 1 || h > 1; ++k) {
    w = std::max(1, w / 2);
    h = std::max(1, h / 2);
    t.addLevel(Image(w, h, glm::vec4(float(k))));
  }
  return t;
}

// Rough glass reads the scene colour at the level whose texels are as wide as the cone of light through it
// (shade/rough_cone.glsl): the entry lobe carried over the exact chord inside, both lobes over the exact
// distance behind, at the exact hit's texel density; the reflection's cone is twice the slope over its own
// distance. Checked with a colour whose level k reads k, against the exact sphere trace.
TEST(TechniqueTwoInterface, RoughGlassReadsTheLevelOfItsCone) {
  Scene s = technique_test::makeScene(256, 256);
  s.sceneColor = levelTexture(s.width, s.height);
  const double eta = 1.0 / kIor;
  int checked = 0;
  for (float roughness : {0.1f, 0.3f, 0.6f}) {
    Options o = snellPresetPlaneNormal(4);
    o.m.reflection = false;
    o.t.exit.source = SNELL_SOURCE_BUFFERS;
    o.m.roughness = roughness;
    o.v.sceneColorLevels = s.sceneColor.levelCount();
    for (glm::dvec2 uv : {glm::dvec2(0.5, 0.5), glm::dvec2(0.42, 0.55), glm::dvec2(0.56, 0.47)}) {
      const Exact e = technique_test::exactTrace(s.front, uv, kIor);
      ASSERT_TRUE(e.hitsSphere && !e.tir && e.planeHit);
      const SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(glm::vec3(e.p1), glm::vec3(e.n1), 0.0f,
                                                                    TECH_OBJECT_ARGS(s), TECH_SCENE_ARGS(s), o.t, o.m,
                                                                    o.v);
      ASSERT_TRUE(r.exitHit.valid);
      const double a = double(roughness) * double(roughness) * (1.0 - eta);  // the entry lobe inside
      const double behind = glm::length(*e.planeHit - e.p2);
      const double radius = std::hypot(a * glm::length(e.p2 - e.p1) + a / eta * behind,
                                       double(roughness) * double(roughness) * (1.0 / eta - 1.0) * behind);
      const double lod = std::clamp(
          std::log2(kScale * radius *
                    snell_test::texelsPerUnit(s.sceneSurface().clipFromView, *e.planeHit, s.width, s.height)),
          0.0, double(s.sceneColor.levelCount() - 1));
      EXPECT_NEAR(r.color.x, snell_test::roughReadOfLevelTexture(lod, s.sceneColor.levelCount()), 0.02)
          << roughness << " at " << uv.x << ", " << uv.y;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 9);
  // The reflection: the environment read through a cone of twice the slope (the environment's level k reads k).
  Options o = snellPresetPlaneNormal(4);
  o.m.roughness = 0.5f;
  o.v.environmentLevels = 9;
  const Texture2D env = levelTexture(256, 128);
  const Exact e = technique_test::exactTrace(s.front, glm::dvec2(0.5, 0.5), kIor);
  const SnellTwoInterfaceExit re =
      snellTwoInterfaceExitRough(glm::vec3(e.p1), glm::reflect(glm::vec3(glm::normalize(e.p1)), glm::vec3(e.n1)),
                                 snellRoughConeReflect(0.5f), s.plane.depth, s.sceneNormalMips, s.scenePyramid,
                                 s.sceneColor, s.sceneSurface(), env, o.t.reflect, o.v);
  const double envLod = std::log2(kScale * 2.0 * 0.25 * 256.0 / (2.0 * M_PI));
  EXPECT_NEAR(re.color.x, snell_test::roughReadOfLevelTexture(envLod, 9), 0.02);
  // Smooth glass reads level 0.
  o.m.roughness = 0.0f;
  o.m.reflection = false;
  o.t.exit.source = SNELL_SOURCE_BUFFERS;
  o.v.sceneColorLevels = s.sceneColor.levelCount();
  const SnellTwoInterfaceResult smooth = snellTwoInterfaceRefraction(
      glm::vec3(e.p1), glm::vec3(e.n1), 0.0f, TECH_OBJECT_ARGS(s), TECH_SCENE_ARGS(s), o.t, o.m, o.v);
  EXPECT_EQ(smooth.color.x, 0.0f);
}

TEST(TechniqueEnvironment, Atan2MatchesTheLibrary) {
  double maxErr = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const double a = 2.0 * M_PI * i / 20000.0;
    const float x = float(std::cos(a)) * 3.0f, y = float(std::sin(a)) * 3.0f;
    maxErr = std::max(maxErr, std::fabs(double(snellAtan2(y, x)) - std::atan2(double(y), double(x))));
  }
  EXPECT_LT(maxErr, 2e-5);
  EXPECT_EQ(snellAtan2(0.0f, 0.0f), 0.0f);
  EXPECT_NEAR(snellAtan2(0.0f, -1.0f), float(M_PI), 1e-6f);
  EXPECT_EQ(snellAtan2(std::numeric_limits<float>::quiet_NaN(), 1.0f), 0.0f);
  const glm::vec2 fwd = snellEquirectUv(glm::vec3(0.0f, 0.0f, -1.0f));
  EXPECT_NEAR(fwd.x, 0.5f, 1e-6f);
  EXPECT_NEAR(fwd.y, 0.5f, 1e-6f);
  EXPECT_NEAR(snellEquirectUv(glm::vec3(0.0f, 1.0f, 0.0f)).y, 1.0f, 1e-6f);
  EXPECT_NEAR(snellEquirectUv(glm::vec3(1.0f, 0.0f, 0.0f)).x, 0.75f, 1e-5f);
}

TEST(TechniqueEnvironment, CubeFaceSelectionFollowsTheGlTable) {
  struct C {
    glm::vec3 d;
    int face;
    glm::vec2 uv;
  };
  // GL 4.5 table 8.19: s = (sc/|ma| + 1)/2, t = (tc/|ma| + 1)/2.
  const C cases[] = {{{1.0f, 0.5f, 0.25f}, 0, {0.375f, 0.25f}},  {{-1.0f, 0.5f, 0.25f}, 1, {0.625f, 0.25f}},
                     {{0.5f, 1.0f, 0.25f}, 2, {0.75f, 0.625f}},  {{0.5f, -1.0f, 0.25f}, 3, {0.75f, 0.375f}},
                     {{0.5f, 0.25f, 1.0f}, 4, {0.75f, 0.375f}},  {{0.5f, 0.25f, -1.0f}, 5, {0.25f, 0.375f}}};
  for (const C& c : cases) {
    const SnellCubeFace f = snellCubeFaceUv(c.d * 3.0f);
    EXPECT_TRUE(f.valid);
    EXPECT_EQ(f.face, c.face);
    EXPECT_NEAR(f.uv.x, c.uv.x, 1e-6f);
    EXPECT_NEAR(f.uv.y, c.uv.y, 1e-6f);
  }
  EXPECT_FALSE(snellCubeFaceUv(glm::vec3(0.0f)).valid);
  EXPECT_FALSE(snellCubeFaceUv(glm::vec3(std::numeric_limits<float>::quiet_NaN(), 1.0f, 0.0f)).valid);
  // TextureCube reads the selected face at the face uv.
  std::array<Texture2D, 6> faces;
  for (int k = 0; k < 6; ++k) faces[size_t(k)] = Texture2D(Image(4, 4, glm::vec4(float(k))));
  const TextureCube cube(faces);
  for (const C& c : cases) EXPECT_EQ(cube.sampleLod(c.d, 0.0f).x, float(c.face));
}

TEST(TechniqueRange, PyramidAndBox) {
  const Scene& s = scene();
  const SnellDepthRange r = snellDepthRangeFromPyramid(s.backPyramid);
  ASSERT_TRUE(r.valid);
  // The back hemisphere spans view z from about -(6 - 0) to -(6 + 2.2).
  EXPECT_LT(r.zNearest, -5.0f);
  EXPECT_GT(r.zFarthest, -8.3f);
  EXPECT_GT(r.zNearest, r.zFarthest);
  EXPECT_EQ(snellTextureTopLod(s.backPyramid), s.backPyramid.levelCount() - 1);
  const SnellDepthRange b = snellDepthRangeFromBox(mat4(1.0f), glm::vec3(-1.0f, -1.0f, -9.0f), glm::vec3(1.0f, 1.0f, -4.0f));
  EXPECT_TRUE(b.valid);
  EXPECT_EQ(b.zNearest, -4.0f);
  EXPECT_EQ(b.zFarthest, -9.0f);
  EXPECT_FALSE(snellDepthRangeFromBox(mat4(1.0f), glm::vec3(-1.0f, -1.0f, 1.0f), glm::vec3(1.0f, 1.0f, 2.0f)).valid);
  Texture2D empty(Image(8, 8, glm::vec4(0.0f)));
  EXPECT_FALSE(snellDepthRangeFromPyramid(snellBuildDepthPyramid(empty, s.backSurface())).valid);
}

}  // namespace

// The image-space bound (snellPresetImageSpaceBound) is what the lab measures every technique against, so
// it must be the march converged, not one more approximation: against the exact double-precision trace
// through the analytic sphere onto the analytic painting plane, and against itself with half the steps.
TEST(TechniqueBound, ConvergesToTheExactExitPoints) {
  Options o = snellPresetImageSpaceBound();
  o.t.exit.source = SNELL_SOURCE_BUFFERS;
  o.t.back.intersect.marchMaxDistance = float(2.0 * technique_test::kRadius);  // the sphere's diameter: every chord fits
  o.t.exit.intersect.marchMaxDistance = 20.0f;  // beyond the painting from anywhere on the sphere
  Options half = o;
  half.t.back.intersect.marchSteps /= 2;
  half.t.exit.intersect.marchSteps /= 2;
  const PaintingStats full = paintingErrors(o);
  const PaintingStats coarse = paintingErrors(half);
  ASSERT_EQ(full.errors.size(), coarse.errors.size());
  std::vector<double> change;  // per pixel, output pixels; a miss in either is a change of 1e9
  for (std::size_t i = 0; i < full.errors.size(); ++i)
    change.push_back(full.errors[i] >= 1e9 || coarse.errors[i] >= 1e9 ? (full.errors[i] == coarse.errors[i] ? 0.0 : 1e9)
                                                                         : std::abs(full.errors[i] - coarse.errors[i]));
  std::printf("[bound] %d non-TIR px: exit point on the painting within 0.5 px %.3f%% 1 px %.3f%% (p50 %.3f px, p99 "
              "%.3f px), no back hit %d, no exit hit %d; half the steps: within 0.5 px %.3f%%, |change| p99.9 %.4f px\n",
              full.pixels, 100.0 * full.shareBelow(0.5), 100.0 * full.shareBelow(1.0), full.quantile(0.5),
              full.quantile(0.99), full.backMiss, full.exitMiss, 100.0 * coarse.shareBelow(0.5),
              [&] { std::vector<double> c = change; std::sort(c.begin(), c.end()); return c[c.size() * 999 / 1000]; }());
  ASSERT_GT(full.pixels, 30000);
  // Against the analytic answer: only the buffers' own discretization is left.
  EXPECT_GE(full.shareBelow(0.5), 0.995);
  EXPECT_LE(full.backMiss + full.exitMiss, full.pixels / 1000);
  // Converged: halving the step count moves 99.9% of the exit points by less than 0.05 px.
  EXPECT_GE(shareBelow(change, 0.05), 0.999);
}

// The reflect slot with SNELL_SOURCE_BUFFERS: at the sphere's rim the first surface reflects the painting
// behind it (grazing rays keep going away from the camera). The slot must find the reflected ray's hit on
// the painting where the exact double-precision reflection meets the analytic plane, and the colour it
// adds is then the painting's there, not the environment's.
TEST(TechniqueReflection, FindsTheMirroredPaintingAtTheAnalyticPosition) {
  const Scene& s = scene();
  for (const int strategy : {SNELL_STRATEGY_PLANE_NORMAL, SNELL_STRATEGY_LINEAR_MARCH}) {
    Options o = snellPresetSingleSample();
    o.t.exit.source = SNELL_SOURCE_BUFFERS;
    o.t.reflect.source = SNELL_SOURCE_BUFFERS;
    o.t.reflect.intersect = snellIntersectOptions(strategy);
    if (strategy == SNELL_STRATEGY_LINEAR_MARCH) {
      o.t.reflect.intersect.marchSteps = 256;
      o.t.reflect.intersect.marchBisections = 16;
      o.t.reflect.intersect.marchMaxDistance = 20.0f;
    }
    std::vector<double> errors;
    int environment = 0, misses = 0;
    for (int j = 0; j < s.height; ++j)
      for (int i = 0; i < s.width; ++i) {
        const glm::dvec2 uv((i + 0.5) / s.width, (j + 0.5) / s.height);
        const Exact e = technique_test::exactTrace(s.front, uv, kIor);
        if (!e.hitsSphere) continue;
        const glm::dvec3 r = glm::reflect(glm::normalize(e.p1), e.n1);
        const double den = glm::dot(r, technique_test::kPlaneNormal);
        const double t = den != 0.0 ? glm::dot(technique_test::kPlanePoint - e.p1, technique_test::kPlaneNormal) / den : -1.0;
        const SnellTwoInterfaceResult res = snellTwoInterfaceRefraction(
            glm::vec3(e.p1), glm::vec3(e.n1), 0.0f, TECH_OBJECT_ARGS(s),
            TECH_SCENE_ARGS(s), o.t, o.m, o.v);
        const glm::dvec2 q = t > 0.0 ? s.plane.project(e.p1 + t * r) : glm::dvec2(-1.0);
        const bool onScreen = q.x > 0.0 && q.x < 1.0 && q.y > 0.0 && q.y < 1.0;
        if (!onScreen) {
          environment += !res.reflectionHit.valid;
          continue;
        }
        if (!res.reflectionHit.valid) {
          ++misses;
          errors.push_back(1e9);
          continue;
        }
        errors.push_back(glm::length((s.plane.project(glm::dvec3(res.reflectionHit.position)) - q) *
                                     glm::dvec2(s.width, s.height)));
      }
    std::sort(errors.begin(), errors.end());
    const double within = shareBelow(errors, 0.5);
    std::printf("[reflection] strategy %d: %zu rim pixels reflect the painting on screen: within 0.5 px %.2f%% (p50 "
                "%.4f px), misses %d; reflections off screen left to the environment: %d\n",
                strategy, errors.size(), 100.0 * within, errors.empty() ? 0.0 : errors[errors.size() / 2], misses,
                environment);
    EXPECT_GT(errors.size(), 500u) << strategy;
    EXPECT_GE(within, 0.99) << strategy;
  }
  // Environment mode never reads the scene for the reflection.
  Options env = snellPresetSingleSample();
  const Exact e = technique_test::exactTrace(s.front, glm::dvec2(0.5, 0.5), kIor);
  const SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(
      glm::vec3(e.p1), glm::vec3(e.n1), 0.0f, TECH_OBJECT_ARGS(s),
      TECH_SCENE_ARGS(s), env.t, env.m, env.v);
  EXPECT_FALSE(r.reflectionHit.valid);
  EXPECT_EQ(r.reflectionHit.fetches, 0);
}

// The guard band: buffers rendered with a wider field of view than the viewport (snell-lab's
// ShadeConstants::params.clipFromView) hold the surface beyond the viewport's edge, and every strategy reads them through
// the surface's own projection, so an exit ray that leaves the viewport is still resolved, at the analytic
// point. Here the viewport is the central 80% of the buffer's field of view in each direction.
TEST(TechniqueGuardBand, FindsExitsBeyondTheViewportAtTheAnalyticPoint) {
  const snell_test::DepthScene buffer = snell_test::slantedPlane(160, 120);  // the guard-banded buffer
  const double viewportShare = 0.8;
  int offViewport = 0, found = 0;
  std::vector<double> errors;
  for (int k = 0; k < 400; ++k) {
    // A target on the plane in the band between the viewport's edge and the buffer's.
    const double side = (k % 4 < 2 ? 1.0 : -1.0);
    const double band = viewportShare + (1.0 - viewportShare) * (0.1 + 0.8 * ((k / 4) % 10) / 10.0);
    const double along = -0.8 + 1.6 * ((k / 40) % 10) / 10.0;
    const glm::dvec2 ndc = k % 2 ? glm::dvec2(side * band, along) : glm::dvec2(along, side * band);
    const glm::dvec2 uv = 0.5 * (ndc + 1.0);
    const snell_test::AnalyticSample a = buffer.sampleAt(uv);
    ASSERT_TRUE(a.valid);
    const glm::dvec3 target = buffer.pixelRay(uv) * a.s;
    // The ray starts on the viewport's side: from a point in front of the plane near the view axis.
    const glm::dvec3 origin(0.2 * along, 0.1, -2.5);
    const glm::dvec3 dir = glm::normalize(target - origin);
    const glm::dvec2 viewportNdc = glm::dvec2(target.x, target.y) / (-target.z) /
                                   (glm::dvec2(buffer.tanHalfX, buffer.tanHalfY) * viewportShare);
    offViewport += std::abs(viewportNdc.x) > 1.0 || std::abs(viewportNdc.y) > 1.0;
    SnellIntersectOptions o = snellIntersectOptions(SNELL_STRATEGY_LINEAR_MARCH);
    o.marchSteps = 256;
    o.marchBisections = 16;
    o.marchMaxDistance = 20.0f;
    o.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;  // the image-space bound's reads: exact on the plane
    const SnellHit h = snellIntersectWith(glm::vec3(origin), glm::vec3(dir), buffer.depth, buffer.normals,
                                          buffer.depth, buffer.surface(), o);
    if (!h.valid) continue;
    ++found;
    errors.push_back(glm::length(glm::dvec3(h.position) - target) / glm::length(target - origin));
  }
  EXPECT_EQ(offViewport, 400);  // every target lies outside the viewport
  EXPECT_GE(found, 396);
  std::sort(errors.begin(), errors.end());
  ASSERT_FALSE(errors.empty());
  EXPECT_LT(errors[errors.size() * 99 / 100], 1e-4);  // relative to the ray's length
}
