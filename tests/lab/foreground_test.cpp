// snell-lab on a scene with an opaque pillar between the camera and the glass
// (examples/scenes/bunny_pillar.json at 128x128): the glass is not drawn over
// the pillar, and no snell row shows the pillar inside the glass, with either
// scene layer; an engine row that reads the whole scene does (the measure can
// tell a leak when there is one).
#include "lab_run.hpp"

#include "lab_test_util.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using snell::lab::LabOptions;
using snell::lab::LabResult;
using snell::lab::SceneLayer;
using snell::lab::TechniqueRow;

LabResult runPillar(SceneLayer layer) {
  LabOptions o;
  o.scenePath = labtest::scenesDir() + "/bunny_pillar.json";
  o.width = 128;
  o.height = 128;
  o.frames = 1;
  o.outDir = "";
  o.quiet = true;
  o.sceneLayer = layer;
  o.techniques = {"single", "plane-normal-2", "dir", "linear-march", "plane-normal-2-bounces", "engine-threejs"};
  o.dirs.labGlsl = SNELL_LAB_GLSL_DIR;
  o.dirs.snellGlsl = SNELL_GLSL_DIR;
  return snell::lab::runLab(o);
}

TEST(LabForeground, NoSnellRowShowsThePillarInsideTheGlass) {
  for (SceneLayer layer : {SceneLayer::Behind, SceneLayer::Full}) {
    const LabResult r = runPillar(layer);
    SCOPED_TRACE(layer == SceneLayer::Behind ? "behind" : "full");
    bool sawEngine = false;
    for (const TechniqueRow& t : r.rows) {
      SCOPED_TRACE(t.name);
      // The glass is depth-tested against the opaque scene: it covers (almost) no pixel where the ray tracer
      // sees the pillar first (rasterization and the tracer's pixel-centre ray differ along silhouettes).
      EXPECT_LT(t.overdrawnShare, 0.01);
      if (t.name.rfind("engine-", 0) == 0) {
        sawEngine = true;
        // three.js's model reads its colour copy with the pillar in it wherever its offset lands there.
        EXPECT_GT(t.leakPixels, 50);
      } else {
        EXPECT_EQ(t.leakPixels, 0);
      }
    }
    EXPECT_TRUE(sawEngine);
  }
}

// The layer behind the object holds what the pillar hides: every snell row is closer to the ray tracer with it
// than with the whole scene, where the rule can only fall back to the environment.
TEST(LabForeground, TheLayerBehindTheObjectBeatsTheRuleAlone) {
  const LabResult behind = runPillar(SceneLayer::Behind);
  const LabResult full = runPillar(SceneLayer::Full);
  for (const TechniqueRow& t : behind.rows) {
    if (t.name.rfind("engine-", 0) == 0) continue;
    SCOPED_TRACE(t.name);
    const TechniqueRow* f = full.row(t.name);
    ASSERT_NE(f, nullptr);
    EXPECT_LT(t.mseFull, f->mseFull);
  }
}

}  // namespace
