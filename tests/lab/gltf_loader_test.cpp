// glTF assets as lab scenes (lab/gltf_loader.hpp): node transforms, the
// Khronos glass extensions and the camera against values worked out by hand
// from the glTF 2.0 specification, the bundled assets against their own JSON
// read independently, and hostile files (truncated, wrong offsets, huge
// counts, missing or escaping files, cycles) each ending in a named error.
// No GL and no ray tracing: scripts/test.sh runs these under ASan/UBSan too.
#include "lab/gltf_loader.hpp"
#include "lab/scene.hpp"

#include "lab_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

using snell::lab::ErrorKind;
using snell::lab::GltfScene;
using snell::lab::parseGltf;
using Json = nlohmann::json;

namespace {

std::string base64(const std::string& bytes) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += {k[(v >> 18) & 63], k[(v >> 12) & 63], k[(v >> 6) & 63], k[v & 63]};
  }
  if (i + 1 == bytes.size()) {
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    out += {k[(v >> 18) & 63], k[(v >> 12) & 63], '=', '='};
  } else if (i + 2 == bytes.size()) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8);
    out += {k[(v >> 18) & 63], k[(v >> 12) & 63], k[(v >> 6) & 63], '='};
  }
  return out;
}

// A closed tetrahedron, wound counter-clockwise seen from outside: 4 float positions (48 bytes), then 12
// unsigned-short indices (24 bytes).
const float kTetra[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const std::uint16_t kTetraIndices[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};

std::string tetraBuffer() {
  std::string b(72, '\0');
  std::memcpy(b.data(), kTetra, 48);
  std::memcpy(b.data() + 48, kTetraIndices, 24);
  return b;
}

// One glass tetrahedron under a turned and scaled parent node, an opaque one beside it, and a camera.
Json tetra() {
  Json j = Json::parse(R"({
    "asset": {"version": "2.0"},
    "scene": 0,
    "scenes": [{"nodes": [0, 3]}],
    "nodes": [
      {"name": "parent", "translation": [1, 2, 3], "scale": [2, 2, 2], "children": [1, 2]},
      {"name": "glass", "mesh": 0, "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,1,1]},
      {"name": "stone", "mesh": 1, "translation": [5, 0, 0]},
      {"name": "eye", "camera": 0, "translation": [0, 0, 10]}
    ],
    "cameras": [{"type": "perspective", "perspective": {"yfov": 0.5, "znear": 0.25, "zfar": 80, "aspectRatio": 1.5}}],
    "meshes": [
      {"name": "tetra", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]},
      {"name": "rock", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 1}]}
    ],
    "materials": [
      {"name": "Glass", "extensions": {
        "KHR_materials_transmission": {"transmissionFactor": 1},
        "KHR_materials_volume": {"thicknessFactor": 1, "attenuationColor": [0.5, 0.25, 1], "attenuationDistance": 2},
        "KHR_materials_ior": {"ior": 1.7}},
       "pbrMetallicRoughness": {"roughnessFactor": 0, "metallicFactor": 0}},
      {"name": "Stone", "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.6, 1]}}
    ],
    "accessors": [
      {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0,0,0], "max": [1,1,1]},
      {"bufferView": 1, "componentType": 5123, "count": 12, "type": "SCALAR"}
    ],
    "bufferViews": [
      {"buffer": 0, "byteOffset": 0, "byteLength": 48},
      {"buffer": 0, "byteOffset": 48, "byteLength": 24}
    ],
    "buffers": [{"byteLength": 72}]
  })");
  // The parent turns 90 degrees about +Y: quaternion (x, y, z, w) = (0, sin 45, 0, cos 45).
  j["nodes"][0]["rotation"] = {0.0, std::sqrt(0.5), 0.0, std::sqrt(0.5)};
  j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(tetraBuffer());
  return j;
}

GltfScene load(const Json& j, const std::string& name = "asset.gltf") { return parseGltf(j.dump(), name); }

std::string gltfError(const Json& j, ErrorKind kind, const std::string& name = "asset.gltf") {
  return labtest::errorOf([&] { load(j, name); }, kind);
}

// The world position of a tetra vertex under the parent (T (1,2,3), R 90 deg about Y, S 2) and `child`'s
// translation, worked by hand: R takes (x, y, z) to (z, y, -x).
snell::vec3 world(const float p[3], float cx, float cy, float cz) {
  const float x = 2.0f * (p[0] + cx), y = 2.0f * (p[1] + cy), z = 2.0f * (p[2] + cz);
  return {z + 1.0f, y + 2.0f, -x + 3.0f};
}

std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The JSON chunk of a .glb, read by hand from the container's layout (12-byte header, then chunk length,
// chunk type "JSON", the text).
Json glbJson(const std::string& bytes) {
  std::uint32_t length = 0;
  std::memcpy(&length, bytes.data() + 12, 4);
  return Json::parse(bytes.substr(20, length));
}

}  // namespace

TEST(GltfLoader, NodeTransformsMaterialsAndCameraFollowTheSpecification) {
  const GltfScene g = load(tetra());
  ASSERT_EQ(g.objects.size(), 1u);
  ASSERT_EQ(g.paintings.size(), 1u);
  EXPECT_TRUE(g.warnings.empty()) << g.warnings.front();
  const snell::lab::Mesh& glass = *g.objects[0].mesh.loaded;
  ASSERT_EQ(glass.positions.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    const snell::vec3 want = world(kTetra[i], 0.0f, 0.0f, 1.0f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(glass.positions[static_cast<std::size_t>(i)][c], want[c], 1e-5f) << i;
  }
  EXPECT_GT(snell::lab::signedVolume(glass), 0.0);  // still outward after the transforms
  EXPECT_FLOAT_EQ(g.objects[0].ior, 1.7f);
  // sigma = -ln(attenuationColor) / attenuationDistance per channel.
  EXPECT_NEAR(g.objects[0].absorption.x, std::log(2.0) / 2.0, 1e-6);
  EXPECT_NEAR(g.objects[0].absorption.y, std::log(4.0) / 2.0, 1e-6);
  EXPECT_NEAR(g.objects[0].absorption.z, 0.0, 1e-9);
  const snell::lab::Painting& stone = *g.paintings[0].loaded;
  for (int i = 0; i < 4; ++i) {
    const snell::vec3 want = world(kTetra[i], 5.0f, 0.0f, 0.0f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(stone.positions[static_cast<std::size_t>(i)][c], want[c], 1e-5f) << i;
  }
  const snell::vec3 color = stone.colorAt(snell::vec2(0.5f));
  EXPECT_NEAR(color.x, 0.2f, 1e-6f);  // glTF's baseColorFactor is linear
  EXPECT_NEAR(color.y, 0.4f, 1e-6f);
  EXPECT_NEAR(color.z, 0.6f, 1e-6f);
  ASSERT_TRUE(g.hasCamera);
  EXPECT_EQ(g.camera.position, snell::vec3(0.0f, 0.0f, 10.0f));
  EXPECT_EQ(g.camera.target, snell::vec3(0.0f, 0.0f, 9.0f));  // the node's -Z
  EXPECT_NEAR(g.camera.fovYDegrees, 0.5 * 180.0 / M_PI, 1e-4);
  EXPECT_EQ(g.camera.height, 512);
  EXPECT_EQ(g.camera.width, 768);  // aspectRatio 1.5
  EXPECT_FLOAT_EQ(g.camera.zNear, 0.25f);
  EXPECT_FLOAT_EQ(g.camera.zFar, 80.0f);
}

TEST(GltfLoader, MirroringTransformKeepsTheWindingOutward) {
  Json j = tetra();
  j["nodes"][0]["scale"] = {-2.0, 2.0, 2.0};
  const GltfScene g = load(j);
  EXPECT_GT(snell::lab::signedVolume(*g.objects[0].mesh.loaded), 0.0);
}

TEST(GltfLoader, GlassWithoutVolumeIsRefusedNamingTheMaterial) {
  Json j = tetra();
  j["materials"][0]["extensions"].erase("KHR_materials_volume");
  EXPECT_NE(gltfError(j, ErrorKind::Schema).find("materials[0] 'Glass': transmissive but thin-walled"), std::string::npos);
  j = tetra();
  j["materials"][0]["extensions"]["KHR_materials_volume"]["thicknessFactor"] = 0;
  EXPECT_NE(gltfError(j, ErrorKind::Schema).find("thicknessFactor is 0"), std::string::npos);
}

TEST(GltfLoader, WhatTheLabDoesNotRenderIsAWarning) {
  Json j = tetra();
  j["materials"][0]["pbrMetallicRoughness"]["metallicRoughnessTexture"] = {{"index", 0}};
  j["materials"][0]["extensions"]["KHR_materials_transmission"]["transmissionFactor"] = 0.5;
  const GltfScene g = load(j);
  ASSERT_EQ(g.warnings.size(), 2u);
  for (const std::string& w : g.warnings) EXPECT_NE(w.find("materials[0] 'Glass'"), std::string::npos) << w;
}

// glTF's roughnessFactor is the scene file's roughness (both perceptual, GGX alpha its square); glTF's
// default is 1, and out-of-range values are refused as a scene file's are.
TEST(GltfLoader, RoughnessFactorIsTheObjectsRoughness) {
  Json j = tetra();
  j["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"] = 0.3;
  EXPECT_FLOAT_EQ(load(j).objects.at(0).roughness, 0.3f);
  j["materials"][0]["pbrMetallicRoughness"].erase("roughnessFactor");
  EXPECT_FLOAT_EQ(load(j).objects.at(0).roughness, 1.0f);
  j["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"] = 1.5;
  EXPECT_NE(gltfError(j, ErrorKind::Schema).find("roughnessFactor must be in [0, 1]"), std::string::npos);
}

// KHR_materials_dispersion: V_d = 20 / dispersion, and the IORs per channel its text gives,
// n(lambda) = n_d + (n_d - 1) / V_d * (523655 / lambda^2 - 1.5168) at the C, d and F lines (nm).
TEST(GltfLoader, DispersionBecomesAnIorPerChannel) {
  Json j = tetra();
  j["materials"][0]["extensions"]["KHR_materials_dispersion"] = {{"dispersion", 0.5}};
  const GltfScene g = load(j);
  EXPECT_TRUE(g.warnings.empty());
  ASSERT_EQ(g.objects.size(), 1u);
  EXPECT_FLOAT_EQ(g.objects[0].abbe, 40.0f);
  snell::lab::FrameObject o;
  o.ior = g.objects[0].ior;
  o.abbe = g.objects[0].abbe;
  const snell::vec3 iors = snell::lab::channelIors(o);
  const double lambda[3] = {656.27, 587.56, 486.13};
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(iors[c], 1.7 + 0.7 / 40.0 * (523655.0 / (lambda[c] * lambda[c]) - 1.5168), 2e-6) << "channel " << c;
  j["materials"][0]["extensions"]["KHR_materials_dispersion"]["dispersion"] = 0.0;
  EXPECT_EQ(load(j).objects[0].abbe, 0.0f);  // the extension's default: none
  j["materials"][0]["extensions"]["KHR_materials_dispersion"]["dispersion"] = 25.0;
  EXPECT_NE(gltfError(j, ErrorKind::Schema).find("materials[0] 'Glass': KHR_materials_dispersion.dispersion 25"),
            std::string::npos);
  j["materials"][0]["extensions"]["KHR_materials_dispersion"]["dispersion"] = -1.0;
  EXPECT_NE(gltfError(j, ErrorKind::Schema).find("KHR_materials_dispersion.dispersion -1"), std::string::npos);
}

TEST(GltfLoader, BundledAssetsMatchTheirOwnJson) {
  for (const char* name : {"glass_bunny", "suzanne_paperweight", "ior_grid", "flint_ball"}) {
    SCOPED_TRACE(name);
    const std::string path = labtest::scenesDir() + "/gltf/" + name + ".glb";
    const GltfScene g = snell::lab::loadGltf(path);
    EXPECT_TRUE(g.warnings.empty());
    EXPECT_TRUE(g.hasCamera);
    // Independently: the glass materials' IORs and Abbe numbers (20 / dispersion), one object per node whose
    // mesh uses one.
    const Json j = glbJson(fileBytes(path));
    std::vector<double> want, wantAbbe;
    for (const Json& node : j["nodes"]) {
      if (!node.contains("mesh")) continue;
      for (const Json& p : j["meshes"][node["mesh"].get<std::size_t>()]["primitives"]) {
        const Json& m = j["materials"][p["material"].get<std::size_t>()];
        if (m.contains("extensions") && m["extensions"].contains("KHR_materials_transmission")) {
          want.push_back(m["extensions"].value("KHR_materials_ior", Json::object()).value("ior", 1.5));
          const double dispersion = m["extensions"].value("KHR_materials_dispersion", Json::object()).value("dispersion", 0.0);
          wantAbbe.push_back(dispersion > 0.0 ? 20.0 / dispersion : 0.0);
        }
      }
    }
    ASSERT_EQ(g.objects.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
      EXPECT_FLOAT_EQ(g.objects[i].ior, static_cast<float>(want[i]));
      EXPECT_FLOAT_EQ(g.objects[i].abbe, static_cast<float>(wantAbbe[i]));
    }
    EXPECT_FALSE(g.paintings.empty());  // the backdrop (and Suzanne)
  }
}

TEST(GltfLoader, SceneFileNamesAnAssetAndOverridesItsCamera) {
  const std::string dir = labtest::scenesDir() + "/gltf";
  const snell::lab::Scene s = snell::lab::parseScene(R"({
    "gltf": "ior_grid.glb",
    "camera": { "position": [0, 0, 9], "fov": 30 },
    "environment": { "type": "color", "color": [0.1, 0.2, 0.3] }
  })", dir + "/override.json");
  EXPECT_EQ(s.objects.size(), 9u);
  EXPECT_EQ(s.camera.position, snell::vec3(0.0f, 0.0f, 9.0f));
  EXPECT_EQ(s.environment.kind, snell::lab::EnvironmentKind::Color);
  const std::string both = labtest::errorOf(
      [&] {
        snell::lab::parseScene(R"({"gltf": "ior_grid.glb", "object": {"mesh": {"type": "sphere"}}})", dir + "/o.json");
      },
      ErrorKind::Schema);
  EXPECT_NE(both.find("takes its objects from the asset"), std::string::npos) << both;
}

TEST(GltfLoaderErrors, TruncatedBinaryIsAParseError) {
  const std::string path = labtest::scenesDir() + "/gltf/glass_bunny.glb";
  const std::string bytes = fileBytes(path);
  for (std::size_t keep : {std::size_t{3}, std::size_t{12}, std::size_t{40}, bytes.size() / 2, bytes.size() - 1}) {
    const std::string message =
        labtest::errorOf([&] { parseGltf(bytes.substr(0, keep), "cut.glb"); }, ErrorKind::Parse);
    EXPECT_NE(message.find("cut.glb"), std::string::npos) << message;
  }
}

TEST(GltfLoaderErrors, OffsetsAndCountsPastTheBufferNameTheAccessor) {
  Json j = tetra();
  j["bufferViews"][1]["byteOffset"] = 60;  // 60 + 24 > 72
  EXPECT_NE(gltfError(j, ErrorKind::Schema).find("bufferViews[1]: byteOffset 60 + byteLength 24"), std::string::npos);
  j = tetra();
  j["accessors"][0]["count"] = 5;  // 5 * 12 > 48
  EXPECT_NE(gltfError(j, ErrorKind::Schema).find("accessors[0]"), std::string::npos);
  j = tetra();
  j["accessors"][1]["count"] = 4000000000LL;
  EXPECT_NE(gltfError(j, ErrorKind::Schema).find("count 4000000000 is not in"), std::string::npos);
  j = tetra();
  j["accessors"][0]["byteOffset"] = 1000000;
  EXPECT_NE(gltfError(j, ErrorKind::Schema).find("accessors[0]"), std::string::npos);
  j = tetra();
  j["meshes"][0]["primitives"][0]["indices"] = 7;  // tinygltf checks this one itself
  EXPECT_NE(gltfError(j, ErrorKind::Parse).find("indices accessor out of bounds"), std::string::npos);
}

TEST(GltfLoaderErrors, IndexPastTheVerticesNamesThePrimitive) {
  Json j = tetra();
  std::string b = tetraBuffer();
  const std::uint16_t bad = 9;
  std::memcpy(b.data() + 48 + 2, &bad, 2);
  j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(b);
  const std::string m = gltfError(j, ErrorKind::Schema);
  EXPECT_NE(m.find("nodes[1] 'glass' -> meshes[0] 'tetra' primitives[0]: index 9 is past its 4 vertices"), std::string::npos)
      << m;
}

TEST(GltfLoaderErrors, CyclesAndMissingNodesAreRefused) {
  Json j = tetra();
  j["nodes"][1]["children"] = {0};
  EXPECT_NE(gltfError(j, ErrorKind::Schema).find("reached twice"), std::string::npos);
  j = tetra();
  j["nodes"][2]["children"] = {2};
  EXPECT_NE(gltfError(j, ErrorKind::Schema).find("nodes[2] 'stone': reached twice"), std::string::npos);
}

TEST(GltfLoaderErrors, ExternalFilesStayInTheAssetsFolder) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "snell_gltf_files";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "inner");
  std::ofstream(dir / "tetra.bin", std::ios::binary) << tetraBuffer();
  std::ofstream(dir / "inner" / "tetra.bin", std::ios::binary) << tetraBuffer();
  std::filesystem::create_symlink(dir / "tetra.bin", dir / "inner" / "link.bin");
  const auto withBuffer = [&](const std::string& uri) {
    Json j = tetra();
    j["buffers"][0]["uri"] = uri;
    return j;
  };
  // Allowed: beside it, or below it.
  EXPECT_EQ(load(withBuffer("tetra.bin"), (dir / "a.gltf").string()).objects.size(), 1u);
  EXPECT_EQ(load(withBuffer("tetra.bin"), (dir / "inner" / "..inner.gltf").string()).objects.size(), 1u);
  // Refused: missing, out through "..", absolute, through a link out of the folder, shell expansion.
  for (const std::string uri : {"missing.bin", "../tetra.bin", "/etc/passwd", "link.bin", "~/tetra.bin", "$HOME/x.bin"}) {
    const std::string m = gltfError(withBuffer(uri), ErrorKind::Parse, (dir / "inner" / "a.gltf").string());
    EXPECT_NE(m.find("a.gltf"), std::string::npos) << uri << ": " << m;
  }
  // Parsed from memory without a file: no external file at all.
  const std::string fromMemory = gltfError(withBuffer("tetra.bin"), ErrorKind::Parse, "");
  EXPECT_NE(fromMemory.find("external files are not read"), std::string::npos) << fromMemory;
  std::filesystem::remove_all(dir);
}

TEST(GltfLoaderErrors, WhatCannotBeRenderedIsNamed) {
  Json j = tetra();
  j["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  EXPECT_NE(gltfError(j, ErrorKind::Schema).find("KHR_draco_mesh_compression is not read"), std::string::npos);
  j = tetra();
  j["materials"][0]["extensions"].erase("KHR_materials_transmission");
  EXPECT_NE(gltfError(j, ErrorKind::Schema).find("nothing for snell to refract"), std::string::npos);
  j = tetra();
  j["meshes"][0]["primitives"][0]["attributes"].erase("POSITION");
  EXPECT_NE(gltfError(j, ErrorKind::Schema).find("primitives[0]: no POSITION attribute"), std::string::npos);
  j = tetra();
  j["materials"][0]["extensions"]["KHR_materials_ior"]["ior"] = 0.5;
  EXPECT_NE(gltfError(j, ErrorKind::Schema).find("KHR_materials_ior.ior"), std::string::npos);
  j = tetra();
  j["cameras"][0]["perspective"]["zfar"] = 1e7;  // 4e7 times znear 0.25
  EXPECT_NE(gltfError(j, ErrorKind::Schema).find("cameras[0]: zfar / znear"), std::string::npos);
  j = tetra();
  j["accessors"][0]["sparse"] = {{"count", 1},
                                 {"indices", {{"bufferView", 1}, {"componentType", 5123}}},
                                 {"values", {{"bufferView", 0}}}};
  EXPECT_NE(gltfError(j, ErrorKind::Schema).find("sparse accessors are not read"), std::string::npos);
  EXPECT_NE(labtest::errorOf([] { parseGltf("{ not json", "bad.gltf"); }, ErrorKind::Parse).find("bad.gltf"),
            std::string::npos);
  EXPECT_NE(labtest::errorOf([] { snell::lab::loadGltf("/nonexistent/x.glb"); }, ErrorKind::Io).find("x.glb"),
            std::string::npos);
}
