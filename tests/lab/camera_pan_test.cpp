// The camera's pan over an animation (animation.camera_pan_pixels, lab::pannedCamera): the target shows the asked
// pixels away in frame f, by the camera's own projection (glm::lookAt and snellPerspective, not the pan's basis);
// the scene reader's errors name the field; the bundled sequences load.
#include "lab/camera.hpp"
#include "lab/scene.hpp"

#include "lab_test_util.hpp"

#include <gtest/gtest.h>

#include <string>

using snell::vec2;
using snell::vec3;
using snell::vec4;
using snell::lab::Camera;
using snell::lab::ErrorKind;

namespace {

// Where a world point lands in the picture, in pixels (x right, y up, (0, 0) the bottom-left corner).
vec2 pixelOf(const Camera& c, vec3 world) {
  const vec4 clip = c.clipFromView() * c.viewFromWorld() * vec4(world, 1.0f);
  return vec2((clip.x / clip.w * 0.5f + 0.5f) * static_cast<float>(c.width),
              (clip.y / clip.w * 0.5f + 0.5f) * static_cast<float>(c.height));
}

std::string sceneWithAnimation(const std::string& animation) {
  return R"({ "camera": { "position": [1, 2, 5], "target": [0, 0.5, 0], "fov": 40, "resolution": [300, 200] },
              "object": { "mesh": { "type": "icosphere", "subdivisions": 2 } },
              "animation": )" + animation + " }";
}

}  // namespace

TEST(LabCameraPan, TheTargetMovesByTheAskedPixelsPerFrame) {
  // A tilted, non-square view: the pan is along the picture's axes, not the world's.
  const snell::lab::Scene s =
      snell::lab::parseScene(sceneWithAnimation(R"({ "frames": 9, "camera_pan_pixels": [0.25, -1.5] })"), "pan.json");
  const vec3 target = s.camera.target;
  const vec2 centre = pixelOf(s.camera, target);
  EXPECT_NEAR(centre.x, 150.0f, 1e-3f);
  EXPECT_NEAR(centre.y, 100.0f, 1e-3f);
  for (int f : {0, 1, 8}) {
    SCOPED_TRACE(f);
    const Camera c = s.frameCamera(f);
    // The camera moves, the picture pans the other way: the target shows f * pan pixels back.
    const vec2 at = pixelOf(c, target);
    EXPECT_NEAR(at.x, 150.0f - 0.25f * static_cast<float>(f), 2e-3f);
    EXPECT_NEAR(at.y, 100.0f + 1.5f * static_cast<float>(f), 2e-3f);
    // Position and target move together: the view direction does not turn.
    const vec3 before = s.camera.target - s.camera.position, after = c.target - c.position;
    EXPECT_NEAR(snell::length(after - before), 0.0f, 1e-5f);
  }
  // The frame the lab and the reference renderer build carries that camera.
  const snell::lab::SceneFrame frame = snell::lab::buildAnimationFrame(s, 8);
  EXPECT_EQ(frame.camera.position, s.frameCamera(8).position);
}

TEST(LabCameraPan, WithoutAPanEveryFrameKeepsTheCamera) {
  const snell::lab::Scene s = snell::lab::parseScene(sceneWithAnimation(R"({ "frames": 4 })"), "still.json");
  EXPECT_EQ(s.animation.cameraPanPixels, vec2(0.0f));
  EXPECT_EQ(s.frameCamera(3).position, s.camera.position);
  EXPECT_EQ(s.frameCamera(3).target, s.camera.target);
}

TEST(LabCameraPan, BadPansAreNamed) {
  struct Case {
    const char* animation;
    const char* expected;
  };
  const Case cases[] = {
      {R"({ "camera_pan_pixels": [1] })", "pan.json:3: animation.camera_pan_pixels: expected an array of 2 numbers, got [1]"},
      {R"({ "camera_pan_pixels": "left" })", "animation.camera_pan_pixels: expected an array of 2 numbers, got \"left\""},
      {R"({ "camera_pan_pixels": [1e39, 0] })", "animation.camera_pan_pixels[0]"},
      // Each frame moves the camera by about 1e30 of its own pixels: the last frame's camera is beyond float.
      {R"({ "frames": 100000, "camera_pan_pixels": [3e38, 0] })",
       "animation.camera_pan_pixels: the last frame's camera (panned by (frames - 1) times it): "},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.animation);
    const std::string message = labtest::errorOf(
        [&] { snell::lab::parseScene(sceneWithAnimation(c.animation), "pan.json"); }, ErrorKind::Schema);
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
  }
}

TEST(LabCameraPan, TheBundledSequencesLoad) {
  const snell::lab::Scene blob = snell::lab::loadScene(labtest::scenesDir() + "/sequences/blob_rough_030.json");
  EXPECT_EQ(blob.animation.frames, 8);
  EXPECT_EQ(blob.animation.cameraPanPixels, vec2(0.0f));
  EXPECT_EQ(blob.objects.at(0).roughness, 0.3f);
  const snell::lab::Scene bunny = snell::lab::loadScene(labtest::scenesDir() + "/sequences/bunny_rough_030_pan.json");
  EXPECT_EQ(bunny.animation.frames, 8);
  EXPECT_EQ(bunny.animation.cameraPanPixels, vec2(0.25f, 0.0f));
  EXPECT_EQ(bunny.objects.at(0).roughness, 0.3f);
  EXPECT_GT(snell::lab::buildAnimationFrame(bunny, 7).objects.at(0).mesh.triangleCount(), 3000u);
}
