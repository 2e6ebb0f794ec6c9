// The environment hook: the techniques reading a cube map instead of an
// equirectangular texture in C++ (include <snell/texture_cube.hpp> first, then
// define SNELL_ENVIRONMENT_TEX / SNELL_SAMPLE_ENVIRONMENT before <snell/snell.hpp>).
// The overloads this translation unit gets take a snell::TextureCube; the
// other translation units keep the equirectangular ones.
#include <snell/texture_cube.hpp>
#define SNELL_ENVIRONMENT_TEX SNELL_TEXCUBE
#define SNELL_SAMPLE_ENVIRONMENT(tex, dir, lod) SNELL_SAMPLE_CUBE_LOD(tex, dir, lod)
#include <snell/snell.hpp>

#include <gtest/gtest.h>

#include "support/technique_scene.hpp"

namespace {

using namespace snell;

TEST(TechniqueCubeEnvironment, ExitRayReadsTheCubeFace) {
  const technique_test::Scene s = technique_test::makeScene(96, 96);
  std::array<Texture2D, 6> faces;
  for (int k = 0; k < 6; ++k) faces[size_t(k)] = Texture2D(Image(8, 8, glm::vec4(0.1f * float(k + 1))));
  const TextureCube cube(faces);
  const SnellTechnique t = snellPresetDir();
  SnellMaterial m = snellMaterial();
  m.reflection = false;
  int n = 0;
  for (int j = 0; j < 96; j += 4)
    for (int i = 0; i < 96; i += 4) {
      const technique_test::Exact e = technique_test::exactTrace(s.front, glm::dvec2((i + 0.5) / 96.0, (j + 0.5) / 96.0), 1.5);
      if (!e.hitsSphere) continue;
      const SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(
          glm::vec3(e.p1), glm::vec3(e.n1), 0.0f, TECH_OBJECT_ARGS(s),
          s.plane.depth, s.sceneNormalMips, s.scenePyramid, s.sceneColor, s.sceneSurface(), cube, t, m, snellView());
      const SnellCubeFace f = snellCubeFaceUv(r.exitDirection);
      ASSERT_TRUE(f.valid);
      EXPECT_EQ(r.color.x, 0.1f * float(f.face + 1));
      ++n;
    }
  EXPECT_GT(n, 50);
}

}  // namespace
