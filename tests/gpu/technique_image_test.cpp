// A full 128x128 frame of the glass-sphere-in-front-of-a-painting scene
// (tests/support/technique_scene.hpp) rendered by a fragment pass on llvmpipe
// (both backends) with every two-interface preset, compared pixel by pixel
// with the C++ build of the same function (techImagePixel in
// tests/parity/cases/technique.glsl, which calls snellTwoInterfaceRefraction).
// Criterion: at least 99.9% of pixels within 1/255 in every
// channel, none beyond 4/255.
#include <gtest/gtest.h>

#include <snell/depth_pyramid.hpp>
#include <snell/gpu/context.hpp>
#include <snell/gpu/frame_compare.hpp>
#include <snell/gpu/include_flattener.hpp>
#include <snell/gpu/parity.hpp>
#include <snell/gpu/program.hpp>
#include <snell/gpu/resources.hpp>
#include <snell/snell.hpp>
#include <snell/technique_table.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "support/technique_scene.hpp"

namespace technique_image {
using namespace snell;
using snell::gpu::SnellParityOut;
Texture2D techBackDepth, techBackNormal, techBackPyramid, techSceneDepth, techSceneNormal, techScenePyramid,
    techSceneColor, techEnv, techFrontDepth, techFrontNormal;
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wunused-function"
#include "parity/cases/technique.glsl"
#pragma GCC diagnostic pop
}  // namespace technique_image

namespace {

namespace fs = std::filesystem;
using namespace snell::gpu;
using namespace technique_image;

constexpr int kSize = 128;

void buildTextures() {
  static bool built = false;
  if (built) return;
  built = true;
  const technique_test::Scene s = technique_test::makeScene(kSize, kSize);
  techBackDepth = s.back.depth;
  techBackNormal = s.backNormalMips;
  techBackPyramid = s.backPyramid;
  techSceneDepth = s.plane.depth;
  techSceneNormal = s.sceneNormalMips;
  techScenePyramid = s.scenePyramid;
  techSceneColor = s.sceneColor;
  techEnv = s.env;
  techFrontDepth = s.front.depth;
  techFrontNormal = s.front.normals;
}

glm::vec4 matrixEntries() {
  const glm::mat4 m = technique_test::makeScene(8, 8).back.clipFromView;  // square: same matrix at any size
  return glm::vec4(m[0][0], m[1][1], m[2][2], m[3][2]);
}

class TechniqueImage : public ::testing::TestWithParam<Backend> {};

TEST_P(TechniqueImage, FullFrameMatchesTheCxxBuild) {
  buildTextures();
  Context ctx(GetParam());
  ctx.makeCurrent();
  const GlApi& gl = ctx.gl();
  const fs::path root = SNELL_SOURCE_DIR;
  const std::vector<fs::path> paths = {root / "glsl", root / "tests"};
  // One program per preset, with the preset a compile-time constant and only the
  // strategies its options call compiled in (snellStrategiesUsed): the full
  // dispatcher inlined into three dispersion traces takes llvmpipe minutes to compile.
  auto makeProgram = [&](int preset) {
    const std::string fsSrc = "#version 450 core\n#define SNELL_INTERSECT_STRATEGIES " +
                              std::to_string(snellStrategiesUsed(techImageTechnique(preset), techImageMaterial(preset))) +
                              "\n#define TECH_PRESET " + std::to_string(preset) + R"(
struct SnellParityOut { vec4 a; vec4 b; vec4 c; vec4 d; };
#include "parity/cases/technique.glsl"
uniform vec4 matrixEntries;
layout(location = 0) out vec4 fragColor;
void main() { fragColor = techImagePixel(ivec2(gl_FragCoord.xy), TECH_PRESET, matrixEntries); }
)";
    return Program::graphics(gl, flattenGlslFile(root / "glsl" / "passes" / "fullscreen.vert", {}), flattenGlslSource(fsSrc, "technique_image.frag", paths));
  };
  const std::pair<const char*, const Texture2D*> texs[] = {
      {"techBackDepth", &techBackDepth},     {"techBackNormal", &techBackNormal},   {"techBackPyramid", &techBackPyramid},
      {"techSceneDepth", &techSceneDepth},   {"techSceneNormal", &techSceneNormal}, {"techScenePyramid", &techScenePyramid},
      {"techSceneColor", &techSceneColor},   {"techEnv", &techEnv},                 {"techFrontDepth", &techFrontDepth},
      {"techFrontNormal", &techFrontNormal}};
  std::vector<Texture> uploaded;
  uploaded.reserve(10);
  for (int t = 0; t < 10; ++t) {
    uploaded.emplace_back(gl, *texs[t].second);
    uploaded.back().bind(t);
  }
  const glm::vec4 m = matrixEntries();
  VertexArray vao(gl);
  const char* names[] = {"DIR -> painting",
                         "Plane normal N=2 -> painting",
                         "ISR -> environment",
                         "DIR + dispersion + Beer + edge fade",
                         "Plane depth N=3 -> painting",
                         "Single sample -> painting",
                         "Linear march -> painting",
                         "DDA march -> painting",
                         "DIR bounding box -> painting"};
  constexpr int kPresets = int(sizeof(names) / sizeof(names[0]));
  static_assert(kPresets == TECH_IMAGE_PRESETS, "one name per preset of techImageTechnique");
  for (int preset = 0; preset < kPresets; ++preset) {
    const auto t0 = std::chrono::steady_clock::now();
    const Program program = makeProgram(preset);
    const double compileSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    for (int t = 0; t < 10; ++t)
      if (program.hasUniform(texs[t].first)) program.setSampler(texs[t].first, t);
    Framebuffer fb(gl, kSize, kSize, 1, false);
    fb.clearColor(0, glm::vec4(0.0f));
    fb.bind();
    program.use();
    program.set("matrixEntries", m);
    vao.bind();
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
    checkGl(gl, "technique image draw");
    const snell::Image gpu = fb.readColor(0);
    snell::Image cpu(kSize, kSize);
    int object = 0, fellBackGpu = 0, fellBackCpu = 0, flagDiff = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const glm::vec4 c = cpu.at(x, y) = techImagePixel(glm::ivec2(x, y), preset, m);
        const glm::vec4 g = gpu.at(x, y);
        object += c.w > 0.5f;
        fellBackCpu += c.w > 1.5f;
        fellBackGpu += g.w > 1.5f;
        flagDiff += c.w != g.w;
      }
    const snell::gpu::FrameComparison cmp = snell::gpu::compareFrames(gpu, cpu, [](int, int) { return true; });
    const int n = kSize * kSize, within1 = int(cmp.within1), beyond4 = int(cmp.beyond4);
    const double maxDiff = cmp.maxAbs;
    std::printf("[image] %-38s backend %s: %d px (%d object), within 1/255 %.3f%%, beyond 4/255 %d, max %.3g (x255 "
                "%.3f) | fell back cpu %d gpu %d, flag differences %d | compile %.1f s\n",
                names[preset], backendName(GetParam()), n, object, 100.0 * within1 / n,
                beyond4, maxDiff, maxDiff * 255.0, fellBackCpu, fellBackGpu, flagDiff, compileSeconds);
    EXPECT_GE(within1, int(std::ceil(0.999 * n))) << names[preset];
    EXPECT_EQ(beyond4, 0) << names[preset];
    EXPECT_GT(object, n / 8);
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, TechniqueImage, ::testing::ValuesIn(snell::gpu::kGlBackends),
                         snell::gpu::BackendParamName());

}  // namespace
