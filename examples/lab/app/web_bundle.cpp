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

// RGBA float32 texels, row 0 first (the bottom row, as GL uploads and reads them).
nlohmann::json writeImage(const fs::path& dir, const std::string& file, const Image& img) {
  writeBytes(dir / file, img.texels.data(), img.texels.size() * sizeof(vec4));
  return {{"width", img.width}, {"height", img.height}, {"texels", file}};
}

nlohmann::json vec(const vec3& v) { return {v.x, v.y, v.z}; }

// Column-major, as GLSL and three.js's Matrix4.fromArray take it.
nlohmann::json matrix(const mat4& m) {
  nlohmann::json a = nlohmann::json::array();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) a.push_back(m[c][r]);
  return a;
}

}  // namespace

void writeWebBundle(const fs::path& dir, const std::string& sceneName, const SceneFrame& frame,
                    const std::vector<float>& dN, const ShadeConstants& k, const std::vector<WebBundleImage>& images,
                    const Mask& objectMask, const StaticBuffers& buffers, const TechniqueBuffers& front) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw Error(ErrorKind::Io, "cannot create the web bundle's directory " + dir.string() + ": " + ec.message());
  const LabParams& p = k.params;
  nlohmann::json j;
  j["scene"] = sceneName;
  j["width"] = frame.camera.width;
  j["height"] = frame.camera.height;
  j["margin"] = k.margin;
  j["viewFromWorld"] = matrix(k.viewFromWorld);
  j["clipFromView"] = matrix(k.clipFromView);
  j["bufferClipFromView"] = matrix(p.clipFromView);
  j["bufferViewFromClip"] = matrix(glm::inverse(p.clipFromView));  // as the lab inverts it (float)
  j["zNear"] = p.zNear;
  j["zFar"] = p.zFar;
  j["ior"] = p.ior;
  j["absorption"] = vec(p.absorption);
  j["envX"] = vec(p.envX);
  j["envY"] = vec(p.envY);
  j["envZ"] = vec(p.envZ);
  j["backRange"] = p.backRange;
  j["exitRange"] = p.exitRange;
  j["depthFilter"] = p.depthFilter;
  j["reflectSource"] = p.reflectSource;
  j["normalFilter"] = k.normalFilter == NormalFilter::Linear ? "linear" : "nearest";

  // The mesh as the lab's GL pass pulls it: positions with Wyman's d_N in w (0 where the lab computed none),
  // normals, triangle indices.
  const Mesh& m = frame.objects.front().mesh;
  std::vector<glm::vec4> positions(m.vertexCount()), normals(m.vertexCount());
  for (std::size_t i = 0; i < m.vertexCount(); ++i) {
    positions[i] = glm::vec4(m.positions[i], i < dN.size() ? dN[i] : 0.0f);
    normals[i] = glm::vec4(m.normals[i], 0.0f);
  }
  writeBytes(dir / "mesh_positions.f32", positions.data(), positions.size() * sizeof(glm::vec4));
  writeBytes(dir / "mesh_normals.f32", normals.data(), normals.size() * sizeof(glm::vec4));
  writeBytes(dir / "mesh_indices.u32", m.indices.data(), m.indices.size() * sizeof(std::uint32_t));
  j["mesh"] = {{"vertices", m.vertexCount()},
               {"indices", m.indices.size()},
               {"positions", "mesh_positions.f32"},
               {"normals", "mesh_normals.f32"},
               {"triangles", "mesh_indices.u32"},
               {"hasDn", !dN.empty()}};

  nlohmann::json paintings = nlohmann::json::array();
  for (std::size_t i = 0; i < frame.paintings.size(); ++i) {
    const Painting& painting = frame.paintings[i];
    nlohmann::json pj = writeImage(dir, "painting_" + std::to_string(i) + ".f32", painting.texture.level(0));
    pj["corners"] = nlohmann::json::array();
    for (const vec3& c : painting.corners()) pj["corners"].push_back(vec(c));
    paintings.push_back(pj);
  }
  j["paintings"] = paintings;
  j["environment"] = writeImage(dir, "environment.f32", environmentTexture(frame).level(0));

  // Every technique a page can run (the table's contenders), with the strategies its slots call as the lab
  // configures them; and the lab's picture of each it ran.
  nlohmann::json techniques = nlohmann::json::array();
  for (const SnellTechniqueInfo& t : snellTechniqueTable()) {
    if (t.kind == SnellTechniqueKind::Reference) continue;
    nlohmann::json tj = {{"name", t.name},
                         {"label", t.label},
                         {"id", t.id},
                         {"strategies", snellStrategiesUsed(labTechnique(t.id, false, p), labMaterial(p))}};
    for (const WebBundleImage& image : images)
      if (image.row.technique == &t && image.image)
        tj["labImage"] = writeImage(dir, std::string("lab_") + t.name + ".f32", *image.image);
    techniques.push_back(tj);
  }
  j["techniques"] = techniques;
  j["labBuffers"] = {{"sceneColor", writeImage(dir, "lab_scene_color.f32", buffers.sceneColor)},
                     {"sceneDepth", writeImage(dir, "lab_scene_depth.f32", buffers.sceneDepth)},
                     {"sceneNormal", writeImage(dir, "lab_scene_normal.f32", buffers.sceneNormal)},
                     {"backDepth", writeImage(dir, "lab_back_depth.f32", buffers.backDepth)},
                     {"backNormal", writeImage(dir, "lab_back_normal.f32", buffers.backNormal)},
                     {"frontLayerDepth", writeImage(dir, "lab_front_layer_depth.f32", buffers.frontDepth)},
                     {"frontLayerNormal", writeImage(dir, "lab_front_layer_normal.f32", buffers.frontNormal)},
                     {"frontPosition", writeImage(dir, "lab_front_position.f32", front.position)},
                     {"frontNormal", writeImage(dir, "lab_front_normal.f32", front.normal)}};
  writeBytes(dir / "object_mask.u8", objectMask.bits.data(), objectMask.bits.size());
  j["objectMask"] = {{"width", objectMask.width}, {"height", objectMask.height}, {"bits", "object_mask.u8"}};

  std::ofstream out(dir / "bundle.json");
  out << j.dump(1) << "\n";
  out.close();
  if (!out) throw Error(ErrorKind::Io, "cannot write " + (dir / "bundle.json").string());
}

}  // namespace snell::lab
