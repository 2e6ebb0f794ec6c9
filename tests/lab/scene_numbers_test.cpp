// Scene numbers as the floats they become: a value that is a valid double but
// not a usable float (1e39 is inf, 1e-50 is 0, 179.9999999999 is 180) or one
// whose derived quantities overflow in float (target - position of 1e20) is
// refused naming the file and the field; a value that loads gives a camera
// whose corner rays are finite, and a mesh whose vertices are.
#include "lab/camera.hpp"
#include "lab/scene.hpp"

#include "lab_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

using namespace snell::lab;

namespace {

const char* kFile = "numbers.json";

struct Fields {
  std::string camera = R"("position": [0, 0, 5])";
  std::string object = R"("mesh": { "type": "icosphere", "subdivisions": 1 })";
  std::string extra;  // further top-level fields, each followed by a comma
};

std::string sceneText(const Fields& f) {
  return "{\n" + f.extra + "\n\"camera\": {" + f.camera + "},\n\"object\": {" + f.object + "}\n}";
}

Fields camera(const std::string& fields) {
  Fields f;
  f.camera = fields;
  return f;
}

Fields object(const std::string& fields) {
  Fields f;
  f.object = fields;
  return f;
}

Fields top(const std::string& fields) {
  Fields f;
  f.extra = fields + ",";
  return f;
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The camera a scene gives, with a ray through each corner pixel: finite.
void expectFiniteCornerRays(const Camera& c) {
  EXPECT_EQ(cameraProblem(c), "");
  for (int py : {0, c.height - 1})
    for (int px : {0, c.width - 1}) {
      const Ray r = primaryRay(c, px, py);
      EXPECT_TRUE(finite(r.origin)) << px << "," << py;
      EXPECT_TRUE(finite(r.direction)) << px << "," << py;
      EXPECT_NEAR(glm::length(r.direction), 1.0, 1e-9);
      EXPECT_TRUE(std::isfinite(r.tNear) && std::isfinite(r.tFar) && r.tNear > 0.0 && r.tFar > r.tNear);
    }
  const snell::mat4 view = c.viewFromWorld(), clip = c.clipFromView();
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 4; ++k) EXPECT_TRUE(std::isfinite(view[i][k]) && std::isfinite(clip[i][k]));
}

struct Refusal {
  Fields fields;
  const char* field;   // the path named, e.g. "camera.position[0]"
  const char* reason;  // a piece of the reason
};

void expectRefused(const Refusal& r) {
  const std::string text = sceneText(r.fields);
  SCOPED_TRACE(text);
  std::string message;
  try {
    parseScene(text, kFile);
    ADD_FAILURE() << "loaded; expected an error naming " << r.field;
    return;
  } catch (const Error& e) {
    EXPECT_EQ(static_cast<int>(e.kind()), static_cast<int>(ErrorKind::Schema));
    message = e.what();
  }
  EXPECT_EQ(message.rfind(std::string(kFile) + ":", 0), 0u) << message;
  EXPECT_NE(message.find(std::string(": ") + r.field + ": "), std::string::npos) << message;
  EXPECT_NE(message.find(r.reason), std::string::npos) << message;
}

}  // namespace

TEST(LabSceneNumbers, ValuesThatAreNotFloatsAreRefusedNamingTheField) {
  const char* kInf = "is beyond the float range";
  const char* kZero = "rounds to 0 as a float";
  const Refusal cases[] = {
      {camera(R"("position": [1e39, 0, 5])"), "camera.position[0]", kInf},
      {camera(R"("position": [0, 0, 5], "target": [0, -1e39, 0])"), "camera.target[1]", kInf},
      {camera(R"("position": [0, 0, 5], "up": [0, 1, 1e39])"), "camera.up[2]", kInf},
      {camera(R"("position": [0, 0, 5], "fov": 1e-50)"), "camera.fov", kZero},
      {camera(R"("position": [0, 0, 5], "fov": 179.99999999999)"), "camera.fov", "rounds to 180 as a float"},
      {camera(R"("position": [0, 0, 5], "near": 1e-50)"), "camera.near", kZero},
      {camera(R"("position": [0, 0, 5], "far": 1e39)"), "camera.far", kInf},
      {object(R"("mesh": { "type": "icosphere" }, "transform": { "rotate": [1e39, 0, 0] })"),
       "object.transform.rotate[0]", kInf},
      {object(R"("mesh": { "type": "icosphere" }, "transform": { "translate": [0, 1e39, 0] })"),
       "object.transform.translate[1]", kInf},
      {object(R"("mesh": { "type": "icosphere" }, "transform": { "scale": 1e39 })"), "object.transform.scale", kInf},
      {object(R"("mesh": { "type": "icosphere" }, "transform": { "scale": 1e-50 })"), "object.transform.scale", kZero},
      {object(R"("mesh": { "type": "icosphere" }, "transform": { "scale": [1, 1e-40, 1] })"),
       "object.transform.scale[1]", kZero},
      {object(R"("mesh": { "type": "obj", "path": "x.obj", "fit_size": 1e39 })"), "object.mesh.fit_size", kInf},
      {object(R"("mesh": { "type": "icosphere", "radius": 1e-50 })"), "object.mesh.radius", kZero},
      {object(R"("mesh": { "type": "blob", "speed": -1e39 })"), "object.mesh.speed", kInf},
      {object(R"("mesh": { "type": "blob", "frequency": 1e39 })"), "object.mesh.frequency", kInf},
      {object(R"("mesh": { "type": "icosphere" }, "ior": 1e-50)"), "object.ior", kZero},
      {object(R"("mesh": { "type": "icosphere" }, "absorption": [0, 1e39, 0])"), "object.absorption[1]", kInf},
      {top(R"("animation": { "frames": 2, "time_start": 1e39 })"), "animation.time_start", kInf},
      {top(R"("animation": { "frames": 2, "time_step": -1e39 })"), "animation.time_step", kInf},
      {top(R"("environment": { "type": "sky", "rotation": 1e39 })"), "environment.rotation", kInf},
      {top(R"("environment": { "type": "sky", "intensity": 1e39 })"), "environment.intensity", kInf},
      {top(R"("environment": { "type": "sky", "sun_azimuth": -1e39 })"), "environment.sun_azimuth", kInf},
      {top(R"("environment": { "type": "sky", "grid_width": 1e-50 })"), "environment.grid_width", kZero},
      {top(R"("environment": { "type": "color", "color": [1e39, 0, 0] })"), "environment.color[0]", kInf},
      {top(R"("opaque": [{ "type": "painting", "center": [0, 0, 1e39] }])"), "opaque[0].center[2]", kInf},
      {top(R"("opaque": [{ "type": "painting", "center": [0, 0, -2], "size": [1e39, 1] }])"), "opaque[0].size[0]",
       kInf},
      {top(R"("opaque": [{ "type": "painting", "center": [0, 0, -2], "size": [1, 1e-50] }])"), "opaque[0].size[1]",
       kZero},
      {top(R"("opaque": [{ "type": "painting", "center": [0, 0, -2], "rotate": [0, 1e39, 0] }])"),
       "opaque[0].rotate[1]", kInf},
      {top(R"("opaque": [{ "type": "painting", "center": [0, 0, -2],
                           "texture": { "type": "gradient", "colors": [[0, 0, 0], [0, 1e39, 0]] } }])"),
       "opaque[0].texture.colors[1]", kInf},
  };
  for (const Refusal& r : cases) expectRefused(r);
}

TEST(LabSceneNumbers, DerivedValuesThatOverflowAFloatAreRefusedNamingTheField) {
  const Refusal cases[] = {
      // |target - position|^2 = 1e40 overflows a float: glm::lookAt's basis was NaN.
      {camera(R"("position": [0, 0, 1e20])"), "camera.position", "too long for float arithmetic"},
      {camera(R"("position": [0, 0, 5], "target": [1e20, 0, 0])"), "camera.target", "too long for float arithmetic"},
      {camera(R"("position": [3e38, 0, 0], "target": [-3e38, 0, 0])"), "camera.position",
       "too long for float arithmetic"},
      // Distinct doubles, the same float.
      {camera(R"("position": [0, 0, 1e10], "target": [0, 0, 1.0000000001e10])"), "camera.target",
       "must differ from camera.position"},
      // Every depth past 2^24 x near rounds to the cleared 1 in a float depth buffer.
      {camera(R"("position": [0, 0, 5], "near": 1e-30)"), "camera.near", "far / near is 1e+32"},
      {camera(R"("position": [0, 0, 5], "near": 1e-6, "far": 1e6)"), "camera.near", "far / near"},
      // tan(fov / 2) is denormal: snellPerspective gives its zero matrix.
      {camera(R"("position": [0, 0, 5], "fov": 1e-37)"), "camera.fov", "the projection"},
      {top(R"("animation": { "frames": 3, "time_start": 3e38, "time_step": 1e38 })"), "animation.time_step",
       "overflows a float"},
      {top(R"("animation": { "frames": 100000, "time_step": 1e34 })"), "animation.time_step", "overflows a float"},
      {top(R"("opaque": [{ "type": "painting", "center": [3e38, 0, 0], "size": [2e38, 1] }])"), "opaque[0].size",
       "overflows a float"},
  };
  for (const Refusal& r : cases) expectRefused(r);
}

TEST(LabSceneNumbers, LargeButUsableValuesLoadWithFiniteCornerRays) {
  const Fields cases[] = {
      camera(R"("position": [0, 0, 5], "up": [0, 1e20, 0])"),  // was "up must be non-zero"
      camera(R"("position": [0, 0, 5], "up": [0, 1e-30, 0])"),
      camera(R"("position": [0, 0, 5], "up": [0, 3e38, 3e38])"),
      camera(R"("position": [0, 0, 1e15], "near": 1e10, "far": 1e16)"),
      camera(R"("position": [0, 0, 5], "fov": 1e-3)"),
      camera(R"("position": [0, 0, 5], "fov": 179.999)"),
      camera(R"("position": [0, 0, 5], "near": 1e-4, "far": 100)"),
      object(R"("mesh": { "type": "icosphere" }, "transform": { "rotate": [1e30, -1e30, 3e38] })"),
      top(R"("animation": { "frames": 3, "time_start": 1e30, "time_step": 1e30 })"),
      top(R"("environment": { "type": "sky", "rotation": 3e38 })"),
  };
  for (const Fields& f : cases) {
    const std::string text = sceneText(f);
    SCOPED_TRACE(text);
    try {
      const Scene s = parseScene(text, kFile);
      expectFiniteCornerRays(s.camera);
      const Mesh m = buildObjectMesh(s, 0, s.frameTime(s.animation.frames - 1));
      EXPECT_FALSE(m.positions.empty());
    } catch (const Error& e) {
      ADD_FAILURE() << e.what();
    }
  }
  // up [0, 1e20, 0] is the default up: the top-centre ray leans to +Y.
  const Scene s = parseScene(sceneText(camera(R"("position": [0, 0, 5], "up": [0, 1e20, 0])")), kFile);
  EXPECT_GT(primaryRayAtUv(s.camera, glm::dvec2(0.5, 1.0)).direction.y, 0.1);
  EXPECT_NEAR(primaryRayAtUv(s.camera, glm::dvec2(0.5, 1.0)).direction.x, 0.0, 1e-12);
}

TEST(LabSceneNumbers, TransformsThatOverflowTheMeshNameTheField) {
  struct Case {
    const char* transform;
    const char* field;
  } cases[] = {
      {R"("scale": 3e38)", "object.transform.scale"},
      {R"("scale": 1e38, "translate": [3.4e38, 0, 0])", "object.transform.translate"},
  };
  for (const Case& c : cases) {
    const std::string text = sceneText(object(std::string(R"("mesh": { "type": "icosphere", "radius": 2 }, "transform": {)") +
                                              c.transform + "}"));
    SCOPED_TRACE(text);
    const Scene s = parseScene(text, kFile);
    const std::string message = labtest::errorOf([&] { buildObjectMesh(s, 0); }, ErrorKind::Schema);
    EXPECT_EQ(message.rfind(std::string(kFile) + ": " + c.field + ": the transformed mesh has non-finite vertex", 0), 0u)
        << message;
  }
  // A tiny scale (a finite float) keeps finite unit normals: its float inverse overflowed.
  const Scene s = parseScene(sceneText(object(R"("mesh": { "type": "icosphere" }, "transform": { "scale": 1e-20 })")), kFile);
  const Mesh m = buildObjectMesh(s, 0);
  for (const glm::vec3& n : m.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-5f);
}

TEST(LabSceneNumbers, CameraProblemRefusesNonFiniteCameras) {
  Camera c;
  EXPECT_EQ(cameraProblem(c), "");
  Camera inf = c;
  inf.position.x = std::numeric_limits<float>::infinity();
  EXPECT_NE(cameraProblem(inf).find("view matrix"), std::string::npos);
  Camera far = c;
  far.zFar = std::numeric_limits<float>::infinity();
  EXPECT_NE(cameraProblem(far).find("projection"), std::string::npos);
  Camera zeroNear = c;
  zeroNear.zNear = 0.0f;
  EXPECT_NE(cameraProblem(zeroNear), "");
}
