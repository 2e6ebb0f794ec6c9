#include "web_bundle.hpp"

#include "lab/error.hpp"

#include <snell/technique_table.hpp>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <fstream>

namespace snell::lab {

namespace fs = std::filesystem;

namespace {

void writeBytes(const fs::path& file, const void* data, std::size_t bytes) {
  std::ofstream out(file, std::ios::binary);
  out.write(static_cast<const char*>(data), static_cast<std::streamsize>(bytes));
  out.close();
  if (!out) throw Error(ErrorKind::Io, "cannot write " + file.string());
}

// RGBA float32 texels, row 0 first (the bottom row, as GL uploads and reads them); `channels` 1 keeps only x
// (a depth buffer: the page widens it to RGBA when it loads it, a quarter of the bytes on disk).
nlohmann::json writeImage(const fs::path& dir, const std::string& file, const Image& img, int channels = 4) {
  if (channels == 4) {
    writeBytes(dir / file, img.texels.data(), img.texels.size() * sizeof(vec4));
  } else {
    std::vector<float> x(img.texels.size());
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = img.texels[i].x;
    writeBytes(dir / file, x.data(), x.size() * sizeof(float));
  }
  return {{"width", img.width}, {"height", img.height}, {"channels", channels}, {"texels", file}};
}

nlohmann::json vec(const vec3& v) { return {v.x, v.y, v.z}; }

// Column-major, as GLSL and three.js's Matrix4.fromArray take it.
nlohmann::json matrix(const mat4& m) {
  nlohmann::json a = nlohmann::json::array();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) a.push_back(m[c][r]);
  return a;
}

const char* layerName(SceneLayer layer) {
  switch (layer) {
    case SceneLayer::Full: return "full";
    case SceneLayer::Peeled: return "peeled";
    case SceneLayer::Behind: break;
  }
  return "behind";
}

// The mesh as the lab's GL pass pulls it: positions with Wyman's d_N in w (0 where the lab computed none),
// normals, triangle indices.
nlohmann::json writeMesh(const fs::path& dir, const std::string& prefix, const Mesh& m, const std::vector<float>& dN) {
  std::vector<glm::vec4> positions(m.vertexCount()), normals(m.vertexCount());
  for (std::size_t i = 0; i < m.vertexCount(); ++i) {
    positions[i] = glm::vec4(m.positions[i], i < dN.size() ? dN[i] : 0.0f);
    normals[i] = glm::vec4(m.normals[i], 0.0f);
  }
  writeBytes(dir / (prefix + "positions.f32"), positions.data(), positions.size() * sizeof(glm::vec4));
  writeBytes(dir / (prefix + "normals.f32"), normals.data(), normals.size() * sizeof(glm::vec4));
  writeBytes(dir / (prefix + "indices.u32"), m.indices.data(), m.indices.size() * sizeof(std::uint32_t));
  return {{"vertices", m.vertexCount()},
          {"indices", m.indices.size()},
          {"positions", prefix + "positions.f32"},
          {"normals", prefix + "normals.f32"},
          {"triangles", prefix + "indices.u32"},
          {"hasDn", !dN.empty()}};
}

// A painting's mesh: positions and normals (w 0), uvs, indices.
nlohmann::json writePaintingMesh(const fs::path& dir, const std::string& prefix, const Painting& p) {
  std::vector<glm::vec4> positions(p.positions.size()), normals(p.positions.size());
  for (std::size_t i = 0; i < p.positions.size(); ++i) {
    positions[i] = glm::vec4(p.positions[i], 0.0f);
    normals[i] = glm::vec4(p.normals[i], 0.0f);
  }
  writeBytes(dir / (prefix + "positions.f32"), positions.data(), positions.size() * sizeof(glm::vec4));
  writeBytes(dir / (prefix + "normals.f32"), normals.data(), normals.size() * sizeof(glm::vec4));
  writeBytes(dir / (prefix + "uvs.f32"), p.uvs.data(), p.uvs.size() * sizeof(glm::vec2));
  writeBytes(dir / (prefix + "indices.u32"), p.indices.data(), p.indices.size() * sizeof(std::uint32_t));
  return {{"vertices", p.positions.size()},
          {"indices", p.indices.size()},
          {"positions", prefix + "positions.f32"},
          {"normals", prefix + "normals.f32"},
          {"uvs", prefix + "uvs.f32"},
          {"triangles", prefix + "indices.u32"}};
}

// What one object read in the lab's row: its scene layer, back and front faces (depth as one channel), and its
// front pass's fragment inputs.
nlohmann::json writeLabBuffers(const fs::path& dir, const std::string& prefix, const StaticBuffers& b,
                               const TechniqueBuffers& front) {
  return {{"sceneColor", writeImage(dir, prefix + "scene_color.f32", b.sceneColor)},
          {"sceneDepth", writeImage(dir, prefix + "scene_depth.f32", b.sceneDepth, 1)},
          {"sceneNormal", writeImage(dir, prefix + "scene_normal.f32", b.sceneNormal)},
          {"backDepth", writeImage(dir, prefix + "back_depth.f32", b.backDepth, 1)},
          {"backNormal", writeImage(dir, prefix + "back_normal.f32", b.backNormal)},
          {"frontLayerDepth", writeImage(dir, prefix + "front_layer_depth.f32", b.frontDepth, 1)},
          {"frontLayerNormal", writeImage(dir, prefix + "front_layer_normal.f32", b.frontNormal)},
          {"frontPosition", writeImage(dir, prefix + "front_position.f32", front.position)},
          {"frontNormal", writeImage(dir, prefix + "front_normal.f32", front.normal)}};
}

}  // namespace

void writeWebBundle(const fs::path& dir, const std::string& sceneName, const SceneFrame& frame,
                    const std::vector<std::vector<float>>& dN, const std::vector<ShadeConstants>& k,
                    const std::vector<std::size_t>& order, const std::vector<WebBundleImage>& images,
                    const Mask& objectMask, const WebBundleLabBuffers& lab, const WebBundleAsset& asset) {
  const std::size_t n = frame.objects.size();
  if (n == 0 || k.size() != n || dN.size() != n || order.size() != n)
    throw Error(ErrorKind::Render, "web bundle: " + std::to_string(n) + " objects but " + std::to_string(k.size()) +
                                       " sets of constants, " + std::to_string(dN.size()) + " d_N lists and a draw "
                                       "order of " + std::to_string(order.size()));
  if (!lab.objects.empty() && (lab.objects.size() != n || lab.fronts.size() != n))
    throw Error(ErrorKind::Render, "web bundle: the lab's buffers of " + std::to_string(lab.objects.size()) + " and " +
                                       std::to_string(lab.fronts.size()) + " objects for " + std::to_string(n));
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw Error(ErrorKind::Io, "cannot create the web bundle's directory " + dir.string() + ": " + ec.message());
  // What every object shares (camera, guard band, read modes) is the same in each object's constants.
  const ShadeConstants& shared = k.front();
  const LabParams& p = shared.params;
  nlohmann::json j;
  j["scene"] = sceneName;
  j["width"] = frame.camera.width;
  j["height"] = frame.camera.height;
  j["margin"] = shared.margin;
  j["viewFromWorld"] = matrix(shared.viewFromWorld);
  j["clipFromView"] = matrix(shared.clipFromView);
  j["bufferClipFromView"] = matrix(p.clipFromView);
  j["bufferViewFromClip"] = matrix(glm::inverse(p.clipFromView));  // as the lab inverts it (float)
  j["zNear"] = p.zNear;
  j["zFar"] = p.zFar;
  j["envX"] = vec(p.envX);
  j["envY"] = vec(p.envY);
  j["envZ"] = vec(p.envZ);
  j["depthFilter"] = p.depthFilter;
  j["reflectSource"] = p.reflectSource;
  j["normalFilter"] = shared.normalFilter == NormalFilter::Linear ? "linear" : "nearest";
  j["sceneLayer"] = layerName(shared.sceneLayer);

  // Every refractive object in the file's order, with its own constants; the lab draws them in drawOrder.
  nlohmann::json objects = nlohmann::json::array();
  for (std::size_t i = 0; i < n; ++i) {
    const LabParams& q = k[i].params;
    const std::string prefix = "object" + std::to_string(i) + "_";
    nlohmann::json oj = {{"ior", q.ior},
                         {"iors", vec(q.iors)},
                         {"dispersion", q.dispersion},
                         {"absorption", vec(q.absorption)},
                         {"backRange", q.backRange},
                         {"exitRange", q.exitRange},
                         {"insideScene", q.insideScene},
                         {"objectNearDistance", k[i].objectNearDistance},
                         {"enclosing", k[i].enclosing},
                         {"mesh", writeMesh(dir, prefix + "mesh_", frame.objects[i].mesh, dN[i])}};
    for (std::size_t position = 0; position < lab.objects.size(); ++position)
      if (order[position] == i)
        oj["labBuffers"] = writeLabBuffers(dir, prefix + "lab_", lab.objects[position], lab.fronts[position]);
    objects.push_back(oj);
  }
  j["objects"] = objects;
  j["drawOrder"] = order;

  nlohmann::json paintings = nlohmann::json::array();
  for (std::size_t i = 0; i < frame.paintings.size(); ++i) {
    const Painting& painting = frame.paintings[i];
    const std::string prefix = "painting_" + std::to_string(i) + "_";
    nlohmann::json pj = writeImage(dir, prefix + "texture.f32", painting.texture.level(0));
    pj["mesh"] = writePaintingMesh(dir, prefix, painting);
    paintings.push_back(pj);
  }
  j["paintings"] = paintings;
  j["environment"] = writeImage(dir, "environment.f32", environmentImage(frame));

  // Every technique a page can run (the table's contenders), with the strategies its slots call on any object
  // as the lab configures them (one program shades every object, as the lab's); and the lab's picture of each
  // it ran.
  nlohmann::json techniques = nlohmann::json::array();
  for (const SnellTechniqueInfo& t : snellTechniqueTable()) {
    if (t.kind == SnellTechniqueKind::Reference) continue;
    int strategies = 0;
    for (const ShadeConstants& c : k)
      strategies |= snellStrategiesUsed(labTechnique(t.id, false, c.params), labMaterial(c.params));
    nlohmann::json tj = {{"name", t.name}, {"label", t.label}, {"id", t.id}, {"strategies", strategies}};
    for (const WebBundleImage& image : images)
      if (image.row.technique == &t && image.image)
        tj["labImage"] = writeImage(dir, std::string("lab_") + t.name + ".f32", *image.image);
    techniques.push_back(tj);
  }
  j["techniques"] = techniques;
  if (!lab.objects.empty()) {
    j["labBuffersRow"] = lab.row;
    // The lab's frame before any object: what its picture shows where no pass shaded an object pixel.
    j["labOpaqueColor"] = writeImage(dir, "lab_opaque_color.f32", lab.objects.front().fullColor);
  }
  if (!asset.path.empty()) {
    const std::string name = "asset" + fs::path(asset.path).extension().string();
    fs::copy_file(asset.path, dir / name, fs::copy_options::overwrite_existing, ec);
    if (ec) throw Error(ErrorKind::Io, "cannot copy " + asset.path + " into the web bundle: " + ec.message());
    j["asset"] = {{"file", name}, {"environmentRotationDegrees", frame.environment.rotationDegrees()}};
    if (asset.threejsImage) j["asset"]["labThreejsImage"] = writeImage(dir, "lab_threejs.f32", *asset.threejsImage);
  }
  writeBytes(dir / "object_mask.u8", objectMask.bits.data(), objectMask.bits.size());
  j["objectMask"] = {{"width", objectMask.width}, {"height", objectMask.height}, {"bits", "object_mask.u8"}};

  std::ofstream out(dir / "bundle.json");
  out << j.dump(1) << "\n";
  out.close();
  if (!out) throw Error(ErrorKind::Io, "cannot write " + (dir / "bundle.json").string());
}

}  // namespace snell::lab
