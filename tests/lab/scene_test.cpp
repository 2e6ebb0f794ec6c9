// Scene files: the bundled scenes load; each bad field is named, with the
// reason, the file and the line; unknown fields, missing files and malformed
// JSON are errors.
#include "lab/scene.hpp"

#include "lab_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using snell::lab::ErrorKind;
using snell::lab::Scene;
using snell::lab::loadScene;
using snell::lab::parseScene;

namespace {

const char* kMinimal = R"({
  "camera": { "position": [0, 0, 5] },
  "object": { "mesh": { "type": "icosphere", "subdivisions": 2 } }
})";

// A valid scene with one field replaced: `field` is the JSON text of the camera block etc.
std::string withCamera(const std::string& camera) {
  return "{\n  \"camera\": " + camera + ",\n  \"object\": { \"mesh\": { \"type\": \"icosphere\" } }\n}";
}

std::string schemaError(const std::string& text, const std::string& file = "test.json") {
  return labtest::errorOf([&] { parseScene(text, file); }, ErrorKind::Schema);
}

}  // namespace

TEST(LabScene, BundledScenesLoadAndBuild) {
  for (const char* name : {"bunny", "bunny_pillar", "paperweight", "sphere_painting", "torus", "blob", "two_spheres",
                           "cube_sphere", "panes", "snow_globe"}) {
    SCOPED_TRACE(name);
    const Scene s = loadScene(labtest::scenesDir() + "/" + name + ".json");
    EXPECT_EQ(s.name, name);
    EXPECT_FALSE(s.description.empty());
    EXPECT_EQ(s.camera.width, 512);
    EXPECT_GE(s.paintings.size(), 1u);
    const snell::lab::SceneFrame f = snell::lab::buildFrame(s, 0.0f);
    ASSERT_EQ(f.objects.size(), s.objects.size());
    for (const snell::lab::FrameObject& o : f.objects) {
      EXPECT_GE(o.mesh.triangleCount(), 12u);
      EXPECT_GT(snell::lab::signedVolume(o.mesh), 0.0);  // outward winding
    }
    EXPECT_GT(f.environment.image().width, 1);
  }
}

TEST(LabScene, DefaultsForOptionalFields) {
  const Scene s = parseScene(kMinimal, "min.json");
  EXPECT_EQ(s.name, "min");
  EXPECT_FLOAT_EQ(s.camera.fovYDegrees, 45.0f);
  EXPECT_EQ(s.camera.width, 512);
  EXPECT_EQ(s.camera.height, 512);
  EXPECT_FLOAT_EQ(s.camera.zNear, 0.1f);
  EXPECT_FLOAT_EQ(s.camera.zFar, 100.0f);
  EXPECT_EQ(s.camera.target, snell::vec3(0.0f));
  EXPECT_EQ(s.camera.up, snell::vec3(0.0f, 1.0f, 0.0f));
  EXPECT_FLOAT_EQ(s.objects.front().ior, 1.5f);
  EXPECT_EQ(s.objects.front().absorption, snell::vec3(0.0f));
  EXPECT_EQ(s.objects.front().abbe, 0.0f);  // no dispersion
  EXPECT_EQ(s.objects.front().mesh.kind, snell::lab::MeshKind::Icosphere);
  EXPECT_EQ(s.objects.front().mesh.subdivisions, 2);
  EXPECT_FLOAT_EQ(s.objects.front().mesh.radius, 1.0f);
  EXPECT_EQ(s.environment.kind, snell::lab::EnvironmentKind::Sky);
  EXPECT_TRUE(s.paintings.empty());
  EXPECT_EQ(s.animation.frames, 1);
}

TEST(LabScene, CommentsAndAllFieldKinds) {
  const Scene s = parseScene(R"({
    // comments are allowed
    "name": "all", "description": "every kind",
    "camera": { "position": [1, 2, 3], "target": [0, 1, 0], "up": [0, 1, 0], "fov": 60,
                "resolution": [320, 200], "near": 0.5, "far": 20 },
    "object": { "mesh": { "type": "torus", "major_radius": 2, "minor_radius": 0.5, "major_segments": 8, "minor_segments": 6 },
                "transform": { "translate": [1, 0, 0], "rotate": [0, 90, 0], "scale": [1, 2, 1] },
                "ior": 1.33, "absorption": [0.1, 0.2, 0.3], "abbe": 55.5 },
    "environment": { "type": "color", "color": [0.2, 0.3, 0.4], "intensity": 2 },
    "opaque": [ { "type": "painting", "center": [0, 0, -3], "size": [2, 1], "rotate": [0, 0, 10],
                  "texture": { "type": "gradient", "colors": [[1, 0, 0], [0, 0, 1]], "direction": "vertical" } },
                { "type": "painting", "center": [0, -1, 0],
                  "texture": { "type": "checker", "squares": [4, 4], "resolution": [64, 64] } } ],
    "animation": { "frames": 10, "time_start": 1, "time_step": 0.5 }
  })", "all.json");
  EXPECT_EQ(s.camera.width, 320);
  EXPECT_EQ(s.camera.height, 200);
  EXPECT_EQ(s.objects.front().mesh.kind, snell::lab::MeshKind::Torus);
  EXPECT_FLOAT_EQ(s.objects.front().transform.scale.y, 2.0f);
  EXPECT_FLOAT_EQ(s.objects.front().abbe, 55.5f);
  EXPECT_EQ(s.environment.kind, snell::lab::EnvironmentKind::Color);
  ASSERT_EQ(s.paintings.size(), 2u);
  EXPECT_EQ(s.paintings[0].texture.direction, 1);
  EXPECT_FLOAT_EQ(s.frameTime(4), 3.0f);
  const snell::lab::SceneFrame f = snell::lab::buildFrame(s, 0.0f);
  EXPECT_EQ(f.objects.front().mesh.triangleCount(), 8u * 6u * 2u);
  EXPECT_FLOAT_EQ(f.objects.front().abbe, 55.5f);
  EXPECT_NEAR(f.environment.lookup(snell::vec3(0, 1, 0)).z, 0.8f, 1e-6f);
}

TEST(LabScene, BadFovNamesFieldReasonValueAndLine) {
  const std::string msg = schemaError(withCamera("{\n    \"position\": [0, 0, 5],\n    \"fov\": \"wide\"\n  }"));
  EXPECT_NE(msg.find("test.json:4: camera.fov: expected a number in (0, 180), got \"wide\""), std::string::npos) << msg;
  const std::string big = schemaError(withCamera(R"({ "position": [0, 0, 5], "fov": 180 })"));
  EXPECT_NE(big.find("camera.fov: expected a number in (0, 180), got 180"), std::string::npos) << big;
}

TEST(LabScene, UnknownFieldIsATypo) {
  const std::string msg = schemaError(withCamera(R"({ "position": [0, 0, 5], "fovy": 50 })"));
  EXPECT_NE(msg.find("camera.fovy: unknown field"), std::string::npos) << msg;
  EXPECT_NE(msg.find("fov"), std::string::npos) << msg;
  const std::string top = schemaError(std::string(kMinimal).insert(1, "\"enviroment\": {},"));
  EXPECT_NE(top.find("enviroment: unknown field"), std::string::npos) << top;
}

// nlohmann::json keeps the last of two equal keys; the scene reader refuses them (a second "object" used to
// replace the first silently), naming both lines; an escaped spelling of the same key is the same key.
TEST(LabScene, AKeyGivenTwiceIsAnError) {
  const std::string twice = "{\n"
                            "  \"camera\": { \"position\": [0, 0, 5] },\n"
                            "  \"object\": { \"mesh\": { \"type\": \"icosphere\" } },\n"
                            "  \"object\": { \"mesh\": { \"type\": \"torus\" } }\n"
                            "}\n";
  const std::string msg = schemaError(twice, "twice.json");
  EXPECT_EQ(msg.rfind("twice.json:4: object: given twice (first on line 3)", 0), 0u) << msg;
  const std::string nested = schemaError(withCamera(R"({ "position": [0, 0, 5], "fov": 40, "fov": 50 })"));
  EXPECT_NE(nested.find("camera.fov: given twice"), std::string::npos) << nested;
  const std::string escaped = schemaError(withCamera(R"({ "position": [0, 0, 5], "f\u006Fv": 40, "fov": 50 })"));
  EXPECT_NE(escaped.find("camera.fov: given twice"), std::string::npos) << escaped;
  // Equal values in an array are no duplicate keys.
  EXPECT_NO_THROW(parseScene(withCamera(R"({ "position": [5, 5, 5] })"), "array.json"));
}

// A misspelt required field is reported as the unknown field it is, with the name it was meant to be; a
// missing one that nothing resembles stays "missing".
TEST(LabScene, AMisspeltRequiredFieldIsUnknownNotMissing) {
  const std::string objet = schemaError(R"({ "camera": { "position": [0, 0, 5] }, "objet": { "mesh": { "type": "icosphere" } } })");
  EXPECT_NE(objet.find("objet: unknown field (did you mean \"object\"?"), std::string::npos) << objet;
  const std::string mesh = schemaError(R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "tpye": "icosphere" } } })");
  EXPECT_NE(mesh.find("object.mesh.tpye: unknown field (did you mean \"type\"?"), std::string::npos) << mesh;
  const std::string absent = schemaError(R"({ "camera": { "position": [0, 0, 5] }, "colour": 1 })");
  EXPECT_NE(absent.find("object: missing (required: an object)"), std::string::npos) << absent;
}

TEST(LabScene, EachBadFieldIsNamed) {
  struct Case {
    const char* text;
    const char* expected;
  };
  const Case cases[] = {
      {R"({ "object": { "mesh": { "type": "icosphere" } } })", "camera: missing"},
      {R"({ "camera": { "position": [0, 0, 5] } })", "object: missing"},
      {R"({ "camera": { "target": [0, 0, 0] }, "object": { "mesh": { "type": "icosphere" } } })", "camera.position: missing"},
      {R"({ "camera": { "position": [0, 0] }, "object": { "mesh": { "type": "icosphere" } } })",
       "camera.position: expected an array of 3 numbers, got [0,0]"},
      {R"({ "camera": { "position": [0, 0, 5], "resolution": [0, 10] }, "object": { "mesh": { "type": "icosphere" } } })",
       "camera.resolution[0]: expected an array of 2 integers each in [8, 8192]"},
      // --size allows no less than 8 either: one limit for both.
      {R"({ "camera": { "position": [0, 0, 5], "resolution": [4, 4] }, "object": { "mesh": { "type": "icosphere" } } })",
       "camera.resolution[0]: expected an array of 2 integers each in [8, 8192]"},
      {R"({ "camera": { "position": [0, 0, 5], "resolution": [64.5, 10] }, "object": { "mesh": { "type": "icosphere" } } })",
       "camera.resolution[0]: expected an array of 2 integers"},
      {R"({ "camera": { "position": [0, 0, 5], "near": 0 }, "object": { "mesh": { "type": "icosphere" } } })",
       "camera.near: expected a number > 0, got 0"},
      {R"({ "camera": { "position": [0, 0, 5], "near": 2, "far": 1 }, "object": { "mesh": { "type": "icosphere" } } })",
       "camera.far: expected a number > near"},
      {R"({ "camera": { "position": [0, 0, 5], "target": [0, 0, 5] }, "object": { "mesh": { "type": "icosphere" } } })",
       "camera.target: must differ from camera.position"},
      {R"({ "camera": { "position": [0, 0, 5], "up": [0, 0, 1] }, "object": { "mesh": { "type": "icosphere" } } })",
       "camera.up: must be non-zero and not parallel"},
      {R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "type": "cube" } } })",
       "object.mesh.type: expected one of \"obj\", \"sphere\", \"icosphere\", \"torus\", \"blob\", \"box\", got \"cube\""},
      {R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "radius": 1 } } })", "object.mesh.type: missing"},
      {R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "type": "obj" } } })", "object.mesh.path: missing"},
      {R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "type": "icosphere", "subdivisions": 9 } } })",
       "object.mesh.subdivisions: expected an integer in [0, 8], got 9"},
      {R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "type": "sphere", "segments": 16, "subdivisions": 2 } } })",
       "object.mesh.subdivisions: unknown field"},
      {R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "type": "torus", "major_radius": 1, "minor_radius": 2 } } })",
       "object.mesh.minor_radius: expected a number < major_radius"},
      {R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "type": "blob", "amplitude": 1 } } })",
       "object.mesh.amplitude: expected a number in [0, 1), got 1"},
      {R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "type": "icosphere" }, "ior": "glass" } })",
       "object.ior: expected a number in (0, 10], got \"glass\""},
      {R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "type": "icosphere" }, "abbe": 0.5 } })",
       "object.abbe: expected a number in [1, 10000], got 0.5"},
      {R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "type": "icosphere" }, "absorption": [0, -1, 0] } })",
       "object.absorption[1]: expected an array of 3 numbers each >= 0, got [0,-1,0]"},
      {R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "type": "icosphere" }, "transform": { "scale": 0 } } })",
       "object.transform.scale: expected a number > 0 or an array of 3 such numbers, got 0"},
      {R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "type": "icosphere" }, "transform": { "rotation": [0, 0, 0] } } })",
       "object.transform.rotation: unknown field (expected one of: translate, rotate, scale)"},
      {R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "type": "icosphere" } }, "environment": { "type": "sky", "sun_elevation": 100 } })",
       "environment.sun_elevation: expected a number in [-90, 90], got 100"},
      {R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "type": "icosphere" } }, "environment": { "type": "color" } })",
       "environment.color: missing"},
      {R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "type": "icosphere" } }, "opaque": {} })",
       "opaque: expected an array of objects, got {}"},
      {R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "type": "icosphere" } }, "opaque": [ { "type": "painting" } ] })",
       "opaque[0].center: missing"},
      {R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "type": "icosphere" } }, "opaque": [ { "type": "painting", "center": [0,0,0], "texture": { "type": "gradient", "colors": [[1,0,0]] } } ] })",
       "opaque[0].texture.colors: expected an array of at least 2 colours"},
      {R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "type": "icosphere" } }, "opaque": [ { "type": "painting", "center": [0,0,0], "texture": { "type": "checker", "direction": "vertical" } } ] })",
       "opaque[0].texture.direction: unknown field"},
      {R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "type": "icosphere" } }, "animation": { "frames": 0 } })",
       "animation.frames: expected an integer in [1, 100000], got 0"},
      {R"([1, 2, 3])", "(top level): expected an object, got [1,2,3]"},
      // Several objects: a list of the same fields, named by position.
      {R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "type": "icosphere" } }, "objects": [ { "mesh": { "type": "icosphere" } } ] })",
       "give either \"object\" (one refractive object) or \"objects\" (a list), not both"},
      {R"({ "camera": { "position": [0, 0, 5] }, "objects": [] })", "objects: the list is empty"},
      {R"({ "camera": { "position": [0, 0, 5] }, "objects": { "mesh": { "type": "icosphere" } } })",
       "objects: expected an array of objects, got {"},
      {R"({ "camera": { "position": [0, 0, 5] }, "objects": [ { "mesh": { "type": "icosphere" } }, { "mesh": { "type": "icosphere" }, "ior": 0 } ] })",
       "objects[1].ior: expected a number in (0, 10], got 0"},
      {R"({ "camera": { "position": [0, 0, 5] }, "objects": [ { "mesh": { "type": "icosphere" } }, { "mesh": { "type": "icosphere" }, "iro": 1.3 } ] })",
       "objects[1].iro: unknown field"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    const std::string msg = schemaError(c.text);
    EXPECT_NE(msg.find(c.expected), std::string::npos) << "message: " << msg;
    EXPECT_EQ(msg.rfind("test.json", 0), 0u) << msg;  // names the file first
  }
}

// A list of objects loads each with its own fields, in order; one object given as a one-element list is
// the same scene as one given as "object".
TEST(LabScene, ObjectsListLoadsEveryObject) {
  const Scene list = parseScene(R"({ "camera": { "position": [0, 0, 5] }, "objects": [
      { "mesh": { "type": "icosphere", "subdivisions": 2 }, "ior": 1.33, "transform": { "translate": [1, 0, 0] } },
      { "mesh": { "type": "sphere", "segments": 8, "rings": 4 }, "ior": 2.4, "absorption": [0.1, 0.2, 0.3] } ] })",
                                "list.json");
  ASSERT_EQ(list.objects.size(), 2u);
  EXPECT_EQ(list.objects[0].field, "objects[0]");
  EXPECT_FLOAT_EQ(list.objects[0].ior, 1.33f);
  EXPECT_FLOAT_EQ(list.objects[1].ior, 2.4f);
  EXPECT_FLOAT_EQ(list.objects[1].absorption.z, 0.3f);
  const snell::lab::SceneFrame f = snell::lab::buildFrame(list);
  ASSERT_EQ(f.objects.size(), 2u);
  EXPECT_EQ(f.objects[0].mesh.triangleCount(), 20u * 16u);
  EXPECT_NEAR(snell::lab::meshBounds(f.objects[0].mesh).center().x, 1.0f, 1e-5f);
  EXPECT_EQ(f.objects[1].mesh.triangleCount(), 8u * (2u * 4u - 2u));  // single triangles at the poles
  const Scene one = parseScene(R"({ "camera": { "position": [0, 0, 5] }, "object": { "mesh": { "type": "icosphere" }, "ior": 1.7 } })", "one.json");
  const Scene oneList = parseScene(R"({ "camera": { "position": [0, 0, 5] }, "objects": [ { "mesh": { "type": "icosphere" }, "ior": 1.7 } ] })", "one.json");
  ASSERT_EQ(one.objects.size(), 1u);
  ASSERT_EQ(oneList.objects.size(), 1u);
  EXPECT_EQ(one.objects[0].field, "object");
  EXPECT_EQ(snell::lab::buildFrame(one).objects[0].mesh.positions, snell::lab::buildFrame(oneList).objects[0].mesh.positions);
  EXPECT_EQ(one.objects[0].ior, oneList.objects[0].ior);
}

TEST(LabScene, LineOfTheBadField) {
  const std::string text = "{\n"
                           "  \"camera\": {\n"
                           "    \"position\": [0, 0, 5]\n"
                           "  },\n"
                           "  \"object\": {\n"
                           "    \"mesh\": { \"type\": \"icosphere\" },\n"
                           "    \"ior\": -1\n"
                           "  }\n"
                           "}\n";
  const std::string msg = schemaError(text, "scene.json");
  EXPECT_EQ(msg.rfind("scene.json:7: object.ior:", 0), 0u) << msg;
}

TEST(LabScene, MalformedJsonIsAParseErrorWithLine) {
  const std::string msg = labtest::errorOf(
      [] { parseScene("{\n  \"camera\": { \"position\": [0, 0, 5] },\n  \"object\": \n}", "broken.json"); },
      ErrorKind::Parse);
  EXPECT_NE(msg.find("broken.json: malformed JSON"), std::string::npos) << msg;
  EXPECT_NE(msg.find("line 4"), std::string::npos) << msg;
}

// Found by tests/fuzz/fuzz_scene (regressions/scene/): nlohmann reports a
// number that overflows a double as out_of_range, not parse_error; it escaped.
TEST(LabScene, NumberOverflowIsAParseError) {
  for (const char* text : {"1e400", "{ \"camera\": { \"fov\": -3188029e826 } }", "[1, 2e999]"}) {
    SCOPED_TRACE(text);
    const std::string msg = labtest::errorOf([&] { parseScene(text, "big.json"); }, ErrorKind::Parse);
    EXPECT_NE(msg.find("big.json: malformed JSON"), std::string::npos) << msg;
    EXPECT_NE(msg.find("number overflow"), std::string::npos) << msg;
  }
}

TEST(LabScene, MissingSceneFileNamesThePath) {
  const std::string msg = labtest::errorOf([] { loadScene("/nonexistent/dir/scene.json"); }, ErrorKind::Io);
  EXPECT_NE(msg.find("scene file not found: /nonexistent/dir/scene.json"), std::string::npos) << msg;
}

TEST(LabScene, MissingMeshAndImageFilesNameThePath) {
  const labtest::TempDir dir;
  const std::string scenePath = dir.write("s.json", R"({
    "camera": { "position": [0, 0, 5] },
    "object": { "mesh": { "type": "obj", "path": "meshes/missing.obj" } }
  })");
  const Scene s = loadScene(scenePath);
  EXPECT_EQ(s.objects.front().mesh.path, dir.file("meshes/missing.obj"));  // relative to the scene file
  const std::string msg = labtest::errorOf([&] { snell::lab::buildObjectMesh(s, 0); }, ErrorKind::Io);
  EXPECT_NE(msg.find("mesh file not found: " + dir.file("meshes/missing.obj")), std::string::npos) << msg;

  const Scene env = parseScene(R"({
    "camera": { "position": [0, 0, 5] },
    "object": { "mesh": { "type": "icosphere" } },
    "environment": { "type": "image", "path": "/nonexistent/sky.hdr" },
    "opaque": [ { "type": "painting", "center": [0, 0, -2], "texture": { "type": "image", "path": "/nonexistent/art.png" } } ]
  })", "");
  const std::string envMsg = labtest::errorOf([&] { snell::lab::buildEnvironment(env); }, ErrorKind::Io);
  EXPECT_NE(envMsg.find("/nonexistent/sky.hdr"), std::string::npos) << envMsg;
  const std::string artMsg = labtest::errorOf([&] { snell::lab::buildPaintings(env); }, ErrorKind::Io);
  EXPECT_NE(artMsg.find("/nonexistent/art.png"), std::string::npos) << artMsg;
}

TEST(LabScene, BlobDeformsOverFrames) {
  const Scene s = loadScene(labtest::scenesDir() + "/blob.json");
  EXPECT_EQ(s.animation.frames, 60);
  const snell::lab::Mesh a = snell::lab::buildObjectMesh(s, 0, s.frameTime(0));
  const snell::lab::Mesh b = snell::lab::buildObjectMesh(s, 0, s.frameTime(10));
  ASSERT_EQ(a.positions.size(), b.positions.size());
  EXPECT_EQ(a.indices, b.indices);  // same topology: one deformable mesh
  float moved = 0.0f;
  for (std::size_t i = 0; i < a.positions.size(); ++i) moved = std::max(moved, snell::length(a.positions[i] - b.positions[i]));
  EXPECT_GT(moved, 0.05f);
}
