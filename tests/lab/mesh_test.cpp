// Mesh loading (OBJ through tinyobjloader) and the built-in generators.
#include "lab/mesh.hpp"
#include "lab/mesh_generators.hpp"
#include "lab/obj_loader.hpp"

#include "lab_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace snell::lab;

namespace {
constexpr double kPi = 3.14159265358979323846;

// A unit cube as six quads, counter-clockwise from outside.
const char* kCubeObj = R"(# cube
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 2 3 7 6
f 3 4 8 7
f 4 1 5 8
)";

void expectUnitNormals(const Mesh& m) {
  ASSERT_EQ(m.normals.size(), m.positions.size());
  for (const snell::vec3& n : m.normals) EXPECT_NEAR(snell::length(n), 1.0f, 1e-5f);
}
}  // namespace

TEST(LabMesh, ObjQuadsAreTriangulatedWithSmoothNormals) {
  const Mesh m = parseObj(kCubeObj, "cube.obj");
  EXPECT_EQ(m.triangleCount(), 12u);
  EXPECT_EQ(m.vertexCount(), 8u);
  EXPECT_NEAR(signedVolume(m), 1.0, 1e-6);
  expectUnitNormals(m);
  // A corner's smooth normal points out of the cube, along the diagonal.
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const snell::vec3 out = snell::normalize(m.positions[i] - snell::vec3(0.5f));
    EXPECT_GT(snell::dot(m.normals[i], out), 0.9f);
  }
}

TEST(LabMesh, InwardWindingIsFlippedOutward) {
  std::string inward = kCubeObj;
  // Reverse every face: "f a b c d" -> "f d c b a".
  std::string out;
  std::size_t pos = 0;
  while (pos < inward.size()) {
    std::size_t end = inward.find('\n', pos);
    std::string line = inward.substr(pos, end - pos);
    if (line.rfind("f ", 0) == 0) {
      char a[8], b[8], c[8], d[8];
      std::sscanf(line.c_str(), "f %7s %7s %7s %7s", a, b, c, d);
      line = std::string("f ") + d + " " + c + " " + b + " " + a;
    }
    out += line + "\n";
    pos = end + 1;
  }
  const Mesh m = parseObj(out, "inward.obj");
  EXPECT_NEAR(signedVolume(m), 1.0, 1e-6);
  for (std::size_t i = 0; i < m.positions.size(); ++i)
    EXPECT_GT(snell::dot(m.normals[i], m.positions[i] - snell::vec3(0.5f)), 0.0f);
}

TEST(LabMesh, ObjNormalsFromTheFileAreKept) {
  const Mesh m = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nf 1//1 2//1 3//1\n", "tri.obj");
  ASSERT_EQ(m.triangleCount(), 1u);
  for (const snell::vec3& n : m.normals) EXPECT_EQ(n, snell::vec3(0.0f, 0.0f, 1.0f));
}

TEST(LabMesh, EmptyObjIsAnError) {
  const std::string msg = labtest::errorOf([] { parseObj("# nothing here\nv 0 0 0\n", "empty.obj"); }, ErrorKind::Mesh);
  EXPECT_NE(msg.find("empty.obj: the OBJ file has no faces"), std::string::npos) << msg;
}

TEST(LabMesh, OutOfRangeIndexIsAnError) {
  const std::string msg =
      labtest::errorOf([] { parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "bad.obj"); }, ErrorKind::Mesh);
  EXPECT_NE(msg.find("bad.obj"), std::string::npos) << msg;
  EXPECT_NE(msg.find("vertex"), std::string::npos) << msg;
}

TEST(LabMesh, DegenerateObjIsAnError) {
  const std::string msg =
      labtest::errorOf([] { parseObj("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n", "flat.obj"); }, ErrorKind::Mesh);
  EXPECT_NE(msg.find("flat.obj"), std::string::npos) << msg;
  EXPECT_NE(msg.find("degenerate"), std::string::npos) << msg;
}

TEST(LabMesh, MissingObjNamesThePath) {
  const std::string msg = labtest::errorOf([] { loadObj("/nonexistent/bunny.obj"); }, ErrorKind::Io);
  EXPECT_NE(msg.find("mesh file not found: /nonexistent/bunny.obj"), std::string::npos) << msg;
}

TEST(LabMesh, BundledBunnyIsClosedAndOutward) {
  const Mesh m = loadObj(labtest::scenesDir() + "/bunny.obj");
  EXPECT_EQ(m.triangleCount(), 3674u);
  EXPECT_EQ(m.vertexCount(), 1839u);
  EXPECT_GT(signedVolume(m), 0.0);
  expectUnitNormals(m);
}

TEST(LabMesh, GeneratorsEncloseTheAnalyticVolume) {
  const double r = 1.3;
  EXPECT_NEAR(signedVolume(makeIcosphere(1.3f, 5)) / (4.0 / 3.0 * kPi * r * r * r), 1.0, 2e-3);
  EXPECT_NEAR(signedVolume(makeUvSphere(1.3f, 128, 64)) / (4.0 / 3.0 * kPi * r * r * r), 1.0, 2e-3);
  // Inscribed polygons in both directions: (2 pi / 64)^2 / 6 + (2 pi / 128)^2 / 6 = 0.002 short.
  EXPECT_NEAR(signedVolume(makeTorus(1.0f, 0.3f, 128, 64)) / (2.0 * kPi * kPi * 1.0 * 0.09), 1.0, 3e-3);
  const Mesh blob = makeBlob(BlobParams{}, 0.7f);
  EXPECT_GT(signedVolume(blob), 0.0);
  expectUnitNormals(blob);
  EXPECT_EQ(makeIcosphere(1.0f, 3).triangleCount(), 20u * 64u);
  // The box: its volume, its faces' normals along the axes, points inside and out by parity.
  const Mesh box = makeBox(snell::vec3(0.5f, 1.2f, 2.0f));
  EXPECT_NEAR(signedVolume(box), 0.5 * 1.2 * 2.0, 1e-6);
  EXPECT_EQ(box.triangleCount(), 12u);
  for (std::size_t t = 0; t < box.indices.size(); t += 3) {
    const snell::vec3 a = box.positions[box.indices[t]], b = box.positions[box.indices[t + 1]], c = box.positions[box.indices[t + 2]];
    const snell::vec3 n = snell::normalize(snell::cross(b - a, c - a));
    EXPECT_NEAR(snell::dot(n, box.normals[box.indices[t]]), 1.0f, 1e-6f);  // outward winding, flat normals
    EXPECT_NEAR(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1.0f, 1e-6f);
  }
  EXPECT_TRUE(pointInsideMesh(box, glm::dvec3(0.24, -0.59, 0.99)));
  EXPECT_FALSE(pointInsideMesh(box, glm::dvec3(0.26, 0.0, 0.0)));
  EXPECT_FALSE(pointInsideMesh(box, glm::dvec3(0.0, 0.0, 1.01)));
  for (const Mesh& m : {makeIcosphere(2.0f, 3), makeUvSphere(2.0f, 16, 8)})
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      EXPECT_NEAR(snell::length(m.positions[i]), 2.0f, 1e-5f);
      EXPECT_NEAR(snell::dot(m.normals[i], m.positions[i] / 2.0f), 1.0f, 1e-5f);
    }
}

TEST(LabMesh, GeneratorArgumentsAreChecked) {
  EXPECT_THROW(makeTorus(0.5f, 1.0f, 8, 8), Error);
  EXPECT_THROW(makeUvSphere(1.0f, 2, 8), Error);
  EXPECT_THROW(makeIcosphere(-1.0f, 2), Error);
  EXPECT_THROW(makeBox(snell::vec3(1.0f, 0.0f, 1.0f)), Error);
}

TEST(LabMesh, TransformScalesRotatesTranslatesAndKeepsWinding) {
  Mesh m = makeIcosphere(1.0f, 2);
  Transform t;
  t.scale = snell::vec3(2.0f, 2.0f, -2.0f);  // mirrors: winding must be fixed
  t.rotateDegrees = snell::vec3(0.0f, 90.0f, 0.0f);
  t.translate = snell::vec3(5.0f, 0.0f, 0.0f);
  applyTransform(m, t);
  EXPECT_NEAR(signedVolume(m), 8.0 * signedVolume(makeIcosphere(1.0f, 2)), 1e-3);
  const Bounds b = meshBounds(m);
  EXPECT_NEAR(b.center().x, 5.0f, 1e-4f);
  for (std::size_t i = 0; i < m.positions.size(); ++i)
    EXPECT_GT(snell::dot(m.normals[i], m.positions[i] - snell::vec3(5.0f, 0.0f, 0.0f)), 0.0f);
  // Rotation order: X, then Y, then Z (about fixed axes).
  Transform r;
  r.rotateDegrees = snell::vec3(90.0f, 90.0f, 0.0f);
  const snell::vec3 y = snell::vec3(r.matrix() * snell::vec4(0.0f, 1.0f, 0.0f, 0.0f));
  // X by 90 takes +Y to +Z; Y by 90 takes +Z to +X.
  EXPECT_NEAR(y.x, 1.0f, 1e-6f);
  EXPECT_NEAR(y.y, 0.0f, 1e-6f);
}
