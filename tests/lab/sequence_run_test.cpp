// snell-lab's animated run (--sequence, app/sequence.hpp) end to end at 32x32: the flicker column is there and
// finite, rows differ, a still scene reads 0, the truth's noise floor is measured on rough glass, and a scene
// with one frame is refused.
#include "lab_run.hpp"
#include "report.hpp"

#include "lab_run_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <string>

namespace {

using snell::lab::LabOptions;
using snell::lab::LabResult;

LabOptions sequenceOptions(const std::string& scene, int frames) {
  LabOptions o = labtest::labRunOptions(scene, 32);
  o.techniques = {"plane-normal-2", "engine-godot"};
  o.sequenceFrames = frames;
  o.threads = 1;
  return o;
}

double flickerOf(const LabResult& r, const std::string& row) {
  for (std::size_t i = 0; i < r.rows.size(); ++i)
    if (r.rows[i].name == row) return r.sequence.flicker.at(i);
  ADD_FAILURE() << "no row " << row;
  return -1.0;
}

}  // namespace

TEST(LabSequence, RoughBlobReportsAFlickerPerRowAndTheNoiseFloor) {
  LabOptions o = sequenceOptions("sequences/blob_rough_030", 3);
  o.truthSamples = 8;
  const LabResult r = snell::lab::runLab(o);
  EXPECT_EQ(r.sequence.frames, 3);
  ASSERT_EQ(r.sequence.flicker.size(), r.rows.size());
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    SCOPED_TRACE(r.rows[i].name);
    EXPECT_TRUE(std::isfinite(r.sequence.flicker[i]));
    EXPECT_GT(r.sequence.flicker[i], 0.0);
  }
  // A technique and an engine model follow the blob differently.
  EXPECT_NE(flickerOf(r, "plane-normal-2"), flickerOf(r, "engine-godot"));
  EXPECT_GT(r.sequence.truthChange, 0.0);
  EXPECT_GT(r.sequence.pixelsPerPair, 100.0);
  // 8 paths per pixel leave noise; its floor is measured and printed under the table.
  EXPECT_GT(r.sequence.noiseFloor, 0.0);
  EXPECT_GT(r.sequence.noiseFloorIndependent, 0.0);
  EXPECT_NE(r.markdown.find("Flicker over frames 0 to 2"), std::string::npos);
  EXPECT_NE(r.markdown.find("Noise floor: the truth's own noise"), std::string::npos);
  labtest::TempDir dir;
  snell::lab::writeJson(dir.file("table.json"), r);
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(dir.file("table.json")));
  ASSERT_TRUE(j.contains("sequence"));
  EXPECT_EQ(j["sequence"]["frames"], 3);
  for (const nlohmann::json& row : j["techniques"]) EXPECT_TRUE(row.contains("flicker")) << row["technique"];
}

TEST(LabSequence, AStillSceneReadsZeroAndARunWithoutTheOptionHasNoFlicker) {
  // sphere_painting does not move: every row draws the same picture each frame, as the smooth truth does.
  const LabResult still = snell::lab::runLab(sequenceOptions("sphere_painting", 2));
  ASSERT_EQ(still.sequence.flicker.size(), still.rows.size());
  for (double f : still.sequence.flicker) EXPECT_EQ(f, 0.0);
  EXPECT_EQ(still.sequence.noiseFloor, 0.0);
  EXPECT_NE(still.markdown.find("Noise floor: 0 (smooth glass"), std::string::npos);

  const LabResult plain = snell::lab::runLab(sequenceOptions("sphere_painting", 0));
  EXPECT_EQ(plain.sequence.frames, 0);
  EXPECT_EQ(plain.markdown.find("Flicker"), std::string::npos);
  labtest::TempDir dir;
  snell::lab::writeJson(dir.file("table.json"), plain);
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(dir.file("table.json")));
  EXPECT_FALSE(j.contains("sequence"));
  for (const nlohmann::json& row : j["techniques"]) EXPECT_FALSE(row.contains("flicker"));
}

TEST(LabSequence, AOneFrameSceneIsRefused) {
  const std::string message = labtest::errorOf([] { snell::lab::runLab(sequenceOptions("sphere_painting", -1)); },
                                               snell::lab::ErrorKind::Usage);
  EXPECT_NE(message.find("--sequence: the scene's animation has 1 frame (animation.frames)"), std::string::npos)
      << message;
}
