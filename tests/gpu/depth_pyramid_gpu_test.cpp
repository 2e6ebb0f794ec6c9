// On the GL driver (llvmpipe, both backends):
//  1. the analytic depth scenes rendered by a fragment shader
//     (tests/support/depth_scenes.frag) agree with the CPU buffers computed in
//     double (tests/support/depth_scenes.hpp);
//  2. the depth min/max pyramid built by the GL pass glsl/passes/depth_pyramid.frag
//     (snellDepthPyramidBase / snellDepthMinMaxReduce on the GPU) equals the one
//     snell::snellBuildDepthPyramid builds in C++, bit for bit, on every level.
#include <gtest/gtest.h>

#include <snell/gpu/depth_pyramid_pass.hpp>

#include <snell/depth_pyramid.hpp>
#include <snell/gpu/context.hpp>
#include <snell/gpu/include_flattener.hpp>
#include <snell/gpu/program.hpp>
#include <snell/gpu/resources.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include "support/depth_scenes.hpp"
#include "support/depth_scenes_gpu.hpp"

namespace {

namespace fs = std::filesystem;
using namespace snell::gpu;
using snell_test::DepthScene;

const fs::path kRoot = SNELL_SOURCE_DIR;

std::vector<DepthScene> scenes(int w, int h, int conv) {
  return {snell_test::slantedPlane(w, h, conv), snell_test::sphereBack(w, h, conv), snell_test::stepEdge(w, h, conv),
          snell_test::silhouette(w, h, conv), snell_test::thinSpike(w, h, conv)};
}

class DepthPyramidGpu : public ::testing::TestWithParam<Backend> {};

TEST_P(DepthPyramidGpu, AnalyticScenesRenderTheSameOnGpuAndCpu) {
  Context ctx(GetParam());
  for (int conv : {SNELL_DEPTH_GL, SNELL_DEPTH_REVERSED, SNELL_DEPTH_INFINITE_REVERSED}) {
    for (const DepthScene& sc : scenes(200, 150, conv)) {
      const snell_test::GpuSceneBuffers g = snell_test::renderDepthSceneGpu(ctx, sc);
      const snell::Image& c = sc.depth.level(0);
      const snell::Image& cn = sc.normals.level(0);
      int coverageDiff = 0, covered = 0;
      double maxDepth = 0.0, maxNormal = 0.0;
      for (std::size_t i = 0; i < c.texels.size(); ++i) {
        const bool cv = c.texels[i].x != sc.emptyDepth, gv = g.depth.texels[i].x != sc.emptyDepth;
        covered += cv;
        if (cv != gv) {
          ++coverageDiff;
          continue;
        }
        if (!cv) continue;
        maxDepth = std::max(maxDepth, double(std::fabs(c.texels[i].x - g.depth.texels[i].x)));
        maxNormal = std::max(maxNormal, double(glm::length(glm::vec3(cn.texels[i]) - glm::vec3(g.normals.texels[i]))));
      }
      std::printf("[scene] %s conv %d covered %d coverage differences %d max |depth diff| %.3g max |normal diff| %.3g\n",
                  sc.name.c_str(), conv, covered, coverageDiff, maxDepth, maxNormal);
      SCOPED_TRACE(sc.name + " convention " + std::to_string(conv));
      EXPECT_GT(covered, 1000);
      // Float (GPU) against double (CPU) evaluation: texel centres within a float
      // rounding of a silhouette edge may fall either way; allow 0.2% of them.
      EXPECT_LE(coverageDiff, covered / 500 + 2);
      EXPECT_LT(maxDepth, 2e-5);
      // Box faces: a texel centre within rounding of an edge may take the other face's normal.
      if (sc.kind != snell_test::kSceneSpike) {
        EXPECT_LT(maxNormal, 1e-4);
      }
    }
  }
}

TEST_P(DepthPyramidGpu, GlPassEqualsCppBuilderOnEveryLevel) {
  Context ctx(GetParam());
  const GlApi& gl = ctx.gl();
  // The library's pass (include/snell/gpu/depth_pyramid_pass.hpp), as snell-lab uses it.
  const DepthPyramidPass pass(gl, kRoot / "glsl");
  for (int conv : {SNELL_DEPTH_GL, SNELL_DEPTH_REVERSED}) {
    for (const DepthScene& sc : {snell_test::sphereBack(203, 117, conv), snell_test::silhouette(128, 64, conv),
                                 snell_test::thinSpike(97, 160, conv)}) {
      const snell::Texture2D cpu = snell::snellBuildDepthPyramid(sc.depth, sc.surface());
      const Texture depth(gl, sc.depth);
      const DepthPyramid pyramid(gl, sc.width, sc.height);
      ASSERT_EQ(pyramid.levels(), cpu.levelCount());
      pass.build(pyramid, depth.id(), sc.zNear, sc.zFar, sc.convention, sc.emptyDepth);
      int mismatches = 0, texels = 0;
      for (int lod = 0; lod < cpu.levelCount(); ++lod) {
        const snell::Image got = pyramid.readLevel(lod);
        const snell::Image& want = cpu.level(lod);
        ASSERT_EQ(got.width, want.width);
        ASSERT_EQ(got.height, want.height);
        for (std::size_t i = 0; i < want.texels.size(); ++i) {
          ++texels;
          if (std::memcmp(&got.texels[i], &want.texels[i], sizeof(glm::vec4)) != 0) {
            if (mismatches == 0)
              ADD_FAILURE() << sc.name << " level " << lod << " texel " << i << ": gpu (" << got.texels[i].x << ", "
                            << got.texels[i].y << ", " << got.texels[i].z << ", " << got.texels[i].w << ") cpu ("
                            << want.texels[i].x << ", " << want.texels[i].y << ", " << want.texels[i].z << ", "
                            << want.texels[i].w << ")";
            ++mismatches;
          }
        }
      }
      std::printf("[pyramid] %s conv %d levels %d texels %d mismatches %d\n", sc.name.c_str(), conv, cpu.levelCount(),
                  texels, mismatches);
      EXPECT_EQ(mismatches, 0) << sc.name;
    }
  }
}

// A region build (an object's screen rectangle) after a whole build: the depth changes only inside the
// rectangle (the scene there, empty elsewhere), the region build rewrites only what the rectangle reduces
// into, and every level must then equal snellBuildDepthPyramid of the whole new depth texture, bit for bit.
// The rectangles touch odd edges (203 x 117: every level has an odd size somewhere), and the object moves:
// the second rectangle is rebuilt over the union of both.
TEST_P(DepthPyramidGpu, RegionBuildEqualsTheWholeBuild) {
  Context ctx(GetParam());
  const GlApi& gl = ctx.gl();
  const DepthPyramidPass pass(gl, kRoot / "glsl");
  const DepthScene sc = snell_test::sphereBack(203, 117, SNELL_DEPTH_GL);
  const auto inside = [&](glm::ivec4 r) {
    snell::Image d = sc.depth.level(0);
    for (int y = 0; y < d.height; ++y)
      for (int x = 0; x < d.width; ++x)
        if (x < r.x || x >= r.z || y < r.y || y >= r.w) d.at(x, y) = glm::vec4(sc.emptyDepth);
    return d;
  };
  const DepthPyramid pyramid(gl, sc.width, sc.height);
  const Texture empty(gl, snell::Texture2D(inside(glm::ivec4(0))));
  pass.build(pyramid, empty.id(), sc.zNear, sc.zFar, sc.convention, sc.emptyDepth);
  int checked = 0;
  glm::ivec4 before(0);
  for (const glm::ivec4 rect : {glm::ivec4(37, 11, 120, 90), glm::ivec4(150, 60, 203, 117), glm::ivec4(1, 0, 202, 3),
                                glm::ivec4(90, 40, 91, 41)}) {
    SCOPED_TRACE(::testing::Message() << "rect " << rect.x << " " << rect.y << " " << rect.z << " " << rect.w);
    const snell::Image depthNow = inside(rect);
    const Texture depth(gl, snell::Texture2D(depthNow));
    const glm::ivec4 region(glm::min(glm::ivec2(rect), glm::ivec2(before)), glm::max(glm::ivec2(rect.z, rect.w), glm::ivec2(before.z, before.w)));
    pass.build(pyramid, depth.id(), sc.zNear, sc.zFar, sc.convention, sc.emptyDepth,
               before == glm::ivec4(0) ? rect : region);
    const snell::Texture2D cpu = snell::snellBuildDepthPyramid(snell::Texture2D(depthNow), sc.surface());
    int mismatches = 0;
    for (int lod = 0; lod < cpu.levelCount(); ++lod) {
      const snell::Image got = pyramid.readLevel(lod);
      for (std::size_t i = 0; i < got.texels.size(); ++i)
        mismatches += std::memcmp(&got.texels[i], &cpu.level(lod).texels[i], sizeof(glm::vec4)) != 0;
    }
    EXPECT_EQ(mismatches, 0);
    ++checked;
    before = rect;
  }
  EXPECT_EQ(checked, 4);
}

// The library's pass from a folder without its shaders: an error naming the
// file it looked for, before anything reaches GL.
TEST(DepthPyramidPass, MissingShaderFolderNamesTheFile) {
  Context ctx;
  try {
    const DepthPyramidPass pass(ctx.gl(), "/nonexistent/snell/glsl");
    ADD_FAILURE() << "a pass was built without its shaders";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("cannot open GLSL file /nonexistent/snell/glsl/passes/", 0), 0u) << what;
    EXPECT_NE(what.find(" (no such file)"), std::string::npos) << what;
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, DepthPyramidGpu, ::testing::ValuesIn(snell::gpu::kGlBackends),
                         snell::gpu::BackendParamName());

}  // namespace
