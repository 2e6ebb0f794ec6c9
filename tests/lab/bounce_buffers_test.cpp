// Bounces in the buffers the lab renders on Mesa (GL rasterization, the
// depth and normal formats an engine would use), not analytic ones: a
// right-angle prism and a glass slab, each a convex glass prism whose textbook
// path is computed here in double precision from its planes (glm::refract /
// glm::reflect and ray-plane intersections, independent of snell): enter the
// face towards the camera, total internal reflection at a face seen from
// behind (the prism's hypotenuse, the slab's side), leave through another.
// snellTwoInterfaceTrace with one bounce, on the read-back buffers, must land
// within half a texel of that exit and leave along its direction.
#include "gpu_lab.hpp"

#include "lab/scene.hpp"

#include "lab_test_util.hpp"
#include "support/convex_prism.hpp"

#include <snell/snell.hpp>

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <cmath>
#include <string>

namespace {

using namespace snell;
using glm::dvec2;
using glm::dvec3;
using snell_test::Prism;

// Renders the prism's back- and front-face passes with the lab's GL pipeline at 256x256, then follows
// pixel rays through both: the analytic TIR path against snellTwoInterfaceTrace with one bounce.
// Returns how many paths were compared.
int checkBounces(const Prism& prism, const dvec3& enterNormal, const dvec3& tirNormal) {
  labtest::TempDir dir;
  const std::string mesh = dir.write("prism.obj", prism.obj());
  const std::string scene = dir.write(
      "prism.json", R"({"camera": {"position": [0, 0, 0], "target": [0, 0, -1], "fov": 60, "near": 0.5, "far": 20,
      "resolution": [256, 256]}, "object": {"ior": 1.5, "mesh": {"type": "obj", "path": ")" + mesh + R"("}}})");
  const snell::lab::SceneFrame frame = snell::lab::buildFrame(snell::lab::loadScene(scene));
  const snell::lab::ShadeConstants k = snell::lab::shadeConstants(frame, 0);
  snell::lab::GpuLab gpu("auto", frame, {}, {snell::lab::LabShader{SNELL_TECHNIQUE_SINGLE, false, -1}},
                         {SNELL_LAB_GLSL_DIR, SNELL_GLSL_DIR}, {k});
  gpu.renderStatic();
  const snell::lab::StaticBuffers sb = gpu.readStatic(0);
  const snell::Texture2D backDepth(sb.backDepth, snell::Filter::Nearest), backNormal(sb.backNormal, snell::Filter::Linear);
  const snell::Texture2D frontDepth(sb.frontDepth, snell::Filter::Nearest),
      frontNormal(sb.frontNormal, snell::Filter::Linear);
  const snell::Texture2D backPyramid = snellBuildDepthPyramid(
      backDepth, snellDepthSurface(k.params.clipFromView, k.params.zNear, k.params.zFar, SNELL_DEPTH_GL, 0.0f));
  // Bilinear depth reads: a plane between texel centres is read exactly, as the analytic path needs.
  SnellDepthSurface back = snellDepthSurface(k.params.clipFromView, k.params.zNear, k.params.zFar, SNELL_DEPTH_GL, 0.0f);
  SnellDepthSurface front = snellDepthSurface(k.params.clipFromView, k.params.zNear, k.params.zFar, SNELL_DEPTH_GL, 1.0f);
  back.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
  front.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
  SnellTechnique t = snellPresetLinearMarch();
  for (SnellSlot* s : {&t.back, &t.inside}) {
    s->intersect.marchSteps = 256;
    s->intersect.marchBisections = 16;
    s->intersect.marchMaxDistance = k.params.backRange;
    s->intersect.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
  }
  t.bounces = 1;
  // The normal plane inside after a march of 16 steps: exact on planar faces too.
  SnellTechnique tp = t;
  tp.inside.intersect.strategy = SNELL_STRATEGY_PLANE_NORMAL;
  tp.inside.intersect.marchSteps = 16;
  tp.inside.intersect.planeIterations = 2;
  const double eta = 1.0 / 1.5, px = 1.0 / 256.0;
  const glm::dmat4 clip(k.params.clipFromView), viewFromClip = glm::inverse(clip);
  const auto uvOf = [&](dvec3 p) {
    const glm::dvec4 c = clip * glm::dvec4(p, 1.0);
    return dvec2(0.5 * (c.x / c.w + 1.0), 0.5 * (c.y / c.w + 1.0));
  };
  int n = 0;
  for (int j = 4; j < 256; j += 6)
    for (int i = 4; i < 256; i += 6) {
      // The pixel centre's ray.
      const glm::dvec4 ndc((i + 0.5) / 128.0 - 1.0, (j + 0.5) / 128.0 - 1.0, -1.0, 1.0);
      glm::dvec4 v = viewFromClip * ndc;
      const dvec3 q = glm::normalize(dvec3(v) / v.w);
      const auto f = prism.entry(q);
      if (!f || glm::length(f->second - enterNormal) > 1e-9) continue;
      const dvec3 p1 = f->first * q;
      const dvec3 t1 = glm::refract(q, f->second, eta);
      const auto h1 = prism.exit(p1 + 1e-9 * t1, t1);
      if (!h1 || glm::length(h1->second - tirNormal) > 1e-9) continue;
      if (glm::length(glm::refract(t1, -h1->second, 1.0 / eta)) > 0.0) continue;  // not TIR there
      const dvec3 r = glm::reflect(t1, h1->second);
      const auto h2 = prism.exit(h1->first + 1e-9 * r, r);
      if (!h2) continue;
      const dvec3 t2 = glm::refract(r, -h2->second, 1.0 / eta);
      if (glm::length(t2) == 0.0) continue;  // a second TIR: not this test's path
      // Where a bilinear read of the back layer's normals blends two faces (a texel of another face within
      // one texel, in the image), the buffers do not hold the geometry's normal: not this test's path.
      const dvec2 u1 = uvOf(h1->first), u2 = uvOf(h2->first);
      const auto blended = [&](dvec2 uv, dvec3 faceNormal) {
        if (!(uv.x > px && uv.x < 1.0 - px && uv.y > px && uv.y < 1.0 - px)) return true;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const glm::dvec4 c(2.0 * (uv.x + dx * px) - 1.0, 2.0 * (uv.y + dy * px) - 1.0, -1.0, 1.0);
            const glm::dvec4 w = viewFromClip * c;
            const auto b = prism.entry(dvec3(w) / w.w, true);
            if (b && glm::length(b->second - faceNormal) > 1e-9) return true;
          }
        return false;
      };
      if (blended(u1, h1->second) || (h2->second.z <= 0.0 && blended(u2, h2->second))) continue;
      SCOPED_TRACE(testing::Message() << "pixel " << i << " " << j);
      for (const SnellTechnique* with : {&t, &tp}) {
        SCOPED_TRACE(with == &t ? "inside march" : "inside plane");
        const SnellTwoInterfacePath path =
            snellTwoInterfaceTrace(glm::vec3(p1), glm::vec3(f->second), float(eta), 0.0f, backDepth, backNormal,
                                   backPyramid, back, frontDepth, frontNormal, front, *with, SNELL_TIR_CRITICAL);
        EXPECT_TRUE(path.valid);
        EXPECT_EQ(path.bounces, 1);
        EXPECT_FALSE(path.fellBack);
        EXPECT_FALSE(path.tir);
        EXPECT_EQ(path.exitFront, h2->second.z > 0.0);
        EXPECT_LT(glm::length(uvOf(dvec3(path.exitPoint)) - u2), 0.5 * px);
        EXPECT_GT(glm::dot(glm::normalize(dvec3(path.exitDirection)), t2), std::cos(0.01));
        EXPECT_NEAR(path.pathLength, glm::length(h1->first - p1) + glm::length(h2->first - h1->first), 0.02);
      }
      ++n;
    }
  return n;
}

// Enter the top leg (facing the camera), TIR at the hypotenuse, leave through the side leg.
TEST(LabBounceBuffers, RightAnglePrismInTheLabsBuffers) {
  Prism p;
  p.polygon = {{-1.5, -4.0}, {-0.5, -4.0}, {-1.5, -5.0}};
  const int n = checkBounces(p, dvec3(0, 0, 1), glm::normalize(dvec3(1, 0, -1)));
  std::printf("[bounce buffers] right-angle prism: %d paths\n", n);
  EXPECT_GT(n, 20);
}

// A thick glass slab (1 wide, 2.5 deep) right of the view axis: enter its face towards the camera, TIR at
// its side (a ray that meets a side of the slab from inside does: it meets it beyond the critical angle),
// leave through its back face.
TEST(LabBounceBuffers, GlassSlabInTheLabsBuffers) {
  Prism p;
  p.polygon = {{0.2, -3.5}, {1.2, -3.5}, {1.2, -6.0}, {0.2, -6.0}};
  const int n = checkBounces(p, dvec3(0, 0, 1), dvec3(1, 0, 0));
  std::printf("[bounce buffers] glass slab: %d paths\n", n);
  EXPECT_GT(n, 20);
}

}  // namespace
