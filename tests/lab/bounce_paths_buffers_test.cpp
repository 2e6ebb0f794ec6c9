// Paths with two, three and four total internal reflections in the buffers the lab renders on Mesa
// (GL rasterization of an OBJ, the depth and normal formats an engine would use), not analytic ones:
// the Porro prism (leaves through the front layer) and the light guide (through the back layer) of
// tests/support/bounce_shapes.hpp, whose textbook paths are computed there in double precision.
// snellTwoInterfaceTrace with 4 bounces (SNELL_PRESET_BOUNCES, what the shipped bounce presets
// follow) on the read-back buffers must take as many reflections, leave where and along what the
// geometry says, and stop at the (b + 1)-th face, totally reflected, when only b bounces are allowed.
#include "gpu_lab.hpp"

#include "lab/scene.hpp"

#include "lab_test_util.hpp"
#include "support/bounce_path_checks.hpp"
#include "support/bounce_shapes.hpp"

#include <snell/snell.hpp>

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <string>

namespace {

using namespace snell;
using glm::dvec2;
using glm::dvec3;
using snell_test::BounceShape;
using snell_test::PixelPath;

// The measured worst over both shapes and both followers (every third pixel; printed by each run):
// the exit 0.0003 px from the textbook one, its direction 7e-7 rad off, the path length 2.2e-6
// relative (the faces are planes, which bilinear depth reads hold exactly). The bounds leave a margin
// of 9x or more; a wrong bounce (a segment lost, a reflection not taken) is off by far more.
constexpr double kLengthRel = 2e-5;  // kBounceExitPx, kBounceDirectionRad: bounce_path_checks.hpp

// Renders the shape's back- and front-face passes with the lab's GL pipeline at 256x256, then follows
// every third pixel's path through both layers; returns the paths compared by reflection count (the
// fewest over the followers).
std::map<int, int> checkPaths(const BounceShape& shape) {
  labtest::TempDir dir;
  const std::string mesh = dir.write("shape.obj", shape.prism.obj());
  const std::string scene = dir.write(
      "shape.json", R"({"camera": {"position": [0, 0, 0], "target": [0, 0, -1], "fov": 60, "near": 0.5, "far": 20,
      "resolution": [256, 256]}, "object": {"ior": )" + std::to_string(shape.ior) + R"(, "mesh": {"type": "obj", "path": ")" +
                        mesh + R"("}}})");
  const snell::lab::SceneFrame frame = snell::lab::buildFrame(snell::lab::loadScene(scene));
  const snell::lab::ShadeConstants k = snell::lab::shadeConstants(frame, 0);
  snell::lab::GpuLab gpu("auto", frame, {}, {snell::lab::LabShader{SNELL_TECHNIQUE_SINGLE, false, -1}},
                         {SNELL_LAB_GLSL_DIR, SNELL_GLSL_DIR}, {k});
  gpu.renderStatic();
  const snell::lab::StaticBuffers sb = gpu.readStatic(0);
  const Texture2D backDepth(sb.backDepth, Filter::Nearest), backNormal(sb.backNormal, Filter::Linear);
  const Texture2D frontDepth(sb.frontDepth, Filter::Nearest), frontNormal(sb.frontNormal, Filter::Linear);
  SnellDepthSurface back = snellDepthSurface(k.params.clipFromView, k.params.zNear, k.params.zFar, SNELL_DEPTH_GL, 0.0f);
  SnellDepthSurface front = snellDepthSurface(k.params.clipFromView, k.params.zNear, k.params.zFar, SNELL_DEPTH_GL, 1.0f);
  const Texture2D backPyramid = snellBuildDepthPyramid(backDepth, back);
  // Bilinear depth reads: a plane between texel centres is read exactly, as the textbook path needs.
  back.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
  front.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
  // The shipped image-space bound with bounces, its march lengths the object's extent as the lab sets
  // them (backRange); and the normal plane inside after a march of 32 steps.
  SnellTechnique march = snellPresetImageSpaceBoundBounces();
  march.back.intersect.marchMaxDistance = k.params.backRange;
  march.inside.intersect.marchMaxDistance = k.params.backRange;
  EXPECT_EQ(march.bounces, 4);
  SnellTechnique plane = march;
  plane.inside.intersect.strategy = SNELL_STRATEGY_PLANE_NORMAL;
  plane.inside.intersect.marchSteps = 32;
  plane.inside.intersect.planeIterations = 2;
  struct Follower {
    const char* name;
    const SnellTechnique* technique;
    double minChord;  // the shortest chord its march is asked to find: a step (inside_march.glsl)
  };
  const double range = double(k.params.backRange);
  const Follower followers[] = {{"inside march", &march, range / SNELL_LINEAR_MARCH_MAX_STEPS},
                                {"inside plane", &plane, range / 32.0}};
  const double eta = 1.0 / shape.ior, px = 1.0 / 256.0;
  const glm::dmat4 clip(k.params.clipFromView), viewFromClip = glm::inverse(clip);
  const auto uvOf = [&](dvec3 p) {
    const glm::dvec4 c = clip * glm::dvec4(p, 1.0);
    return dvec2(0.5 * (c.x / c.w + 1.0), 0.5 * (c.y / c.w + 1.0));
  };
  const auto rayAt = [&](dvec2 uv) {  // scaled to z = -1
    const glm::dvec4 v = viewFromClip * glm::dvec4(2.0 * uv.x - 1.0, 2.0 * uv.y - 1.0, -1.0, 1.0);
    const dvec3 p = dvec3(v) / v.w;
    return p / -p.z;
  };
  const auto layerNormalAt = [&](dvec2 uv, bool frontLayer) -> std::optional<dvec3> {
    const auto hit = shape.prism.entry(rayAt(uv), !frontLayer);
    if (!hit) return std::nullopt;
    return hit->second;
  };
  std::map<int, int> fewest;
  for (const Follower& with : followers) {
    SCOPED_TRACE(with.name);
    std::map<int, int> paths;
    double worstPx = 0.0, worstRad = 0.0, worstRel = 0.0;
    for (int j = 1; j < 256; j += 3)
      for (int i = 1; i < 256; i += 3) {
        const std::optional<PixelPath> p = snell_test::pixelPath(shape, rayAt(dvec2(i + 0.5, j + 0.5) * px));
        if (!p) continue;
        const int n = p->inside.reflections();
        if (n < 2 || n > 4 || !snell_test::buffersHoldPath(*p, uvOf, layerNormalAt, px)) continue;
        if (snell_test::shortestChord(*p) < with.minChord) continue;
        SCOPED_TRACE(testing::Message() << shape.name << ", pixel " << i << " " << j << ", " << n << " reflections");
        const snell_test::Prism::Face& last = p->inside.faces.back();
        const SnellTwoInterfacePath all = snell_test::expectTracedPath(
            *p, with.technique->bounces,
            [&](int bounces) {
              SnellTechnique t = *with.technique;
              t.bounces = bounces;
              return snellTwoInterfaceTrace(glm::vec3(p->entry), glm::vec3(p->entryNormal), float(eta), 0.0f, backDepth,
                                            backNormal, backPyramid, back, frontDepth, frontNormal, front, t,
                                            SNELL_TIR_CRITICAL);
            },
            uvOf, px, kLengthRel);
        if (all.valid && all.bounces == n) {
          worstPx = std::max(worstPx, glm::length(uvOf(dvec3(all.exitPoint)) - uvOf(last.point)) / px);
          worstRad = std::max(worstRad, std::acos(std::min(1.0, glm::dot(glm::normalize(dvec3(all.exitDirection)),
                                                                           p->inside.out))));
          worstRel = std::max(worstRel, std::abs(double(all.pathLength) - snell_test::insideLength(*p)) /
                                            snell_test::insideLength(*p));
        }
        ++paths[n];
      }
    std::printf("[bounce paths buffers] %s, %s: %d paths with 2 reflections, %d with 3, %d with 4; worst exit %.3g px, "
                "direction %.3g rad, length %.3g relative\n",
                shape.name.c_str(), with.name, paths[2], paths[3], paths[4], worstPx, worstRad, worstRel);
    for (int n : {2, 3, 4}) fewest[n] = fewest.count(n) ? std::min(fewest[n], paths[n]) : paths[n];
  }
  return fewest;
}

TEST(LabBouncePathsBuffers, PorroPrismLeavesThroughTheFrontAfterTwoToFourReflections) {
  const std::map<int, int> n = checkPaths(snell_test::porroPrism());
  for (int k : {2, 3, 4}) EXPECT_GE(n.at(k), 20) << k << " reflections";
}

TEST(LabBouncePathsBuffers, LightGuideLeavesThroughTheBackAfterTwoToFourReflections) {
  const std::map<int, int> n = checkPaths(snell_test::lightGuide());
  for (int k : {2, 3, 4}) EXPECT_GE(n.at(k), 20) << k << " reflections";
}

}  // namespace
