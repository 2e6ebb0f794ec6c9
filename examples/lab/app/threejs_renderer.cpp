#include "threejs_renderer.hpp"

#include "gpu_lab.hpp"

#include <lab/error.hpp>
#include <nlohmann/json.hpp>
#include <snell/gpu/process.hpp>

#include <fstream>
#include <iterator>

namespace snell::lab {

namespace fs = std::filesystem;

namespace {

void writeFloats(const fs::path& path, const Image& image) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(image.texels.data()),
            static_cast<std::streamsize>(image.texels.size() * sizeof(vec4)));
  if (!out) throw Error(ErrorKind::Io, "cannot write " + path.string());
}

nlohmann::json vec(vec3 v) { return {v.x, v.y, v.z}; }

}  // namespace

ThreeJsRender renderWithThreeJs(const std::string& gltf, const Scene& scene, const SceneFrame& frame,
                                const fs::path& workDir) {
  std::error_code ec;
  fs::create_directories(workDir, ec);
  if (ec) throw Error(ErrorKind::Io, "cannot create " + workDir.string() + ": " + ec.message());
  const Camera& c = frame.camera;
  const Image environment = environmentImage(frame);
  writeFloats(workDir / "environment.f32", environment);
  const nlohmann::json camera = {{"position", vec(c.position)},  {"target", vec(c.target)}, {"up", vec(c.up)},
                                 {"fovYDegrees", c.fovYDegrees}, {"near", c.zNear},         {"far", c.zFar},
                                 {"environmentRotationDegrees", frame.environment.rotationDegrees()}};
  std::ofstream(workDir / "camera.json") << camera.dump(1) << "\n";
  const fs::path out = workDir / "threejs.f32", info = workDir / "threejs_info.json";
  fs::remove(out, ec);
  const std::vector<std::string> args = {
      std::string(SNELL_TOOLS_DIR) + "/browser/threejs_render.mjs",
      "--gltf", gltf,
      "--environment", (workDir / "environment.f32").string(),
      "--env-size", std::to_string(environment.width) + "x" + std::to_string(environment.height),
      "--camera", (workDir / "camera.json").string(),
      "--size", std::to_string(c.width) + "x" + std::to_string(c.height),
      "--out", out.string(),
      "--info", info.string(),
      "--quiet"};
  gpu::ToolResult t;
  try {
    t = gpu::runTool("node", args, "nodejs");
  } catch (const gpu::Error& e) {
    throw Error(ErrorKind::Render, std::string("three.js (its renderer): ") + e.what());
  }
  if (t.exitCode != 0)
    throw Error(ErrorKind::Render, "three.js (its renderer) on " + scene.name + " failed (exit " +
                                       std::to_string(t.exitCode) + "): " + t.output +
                                       "(install what it names with scripts/install-deps.sh, or run without it: "
                                       "--no-threejs)");
  std::ifstream in(out, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ThreeJsRender r;
  r.image = Image(c.width, c.height);
  if (bytes.size() != r.image.texels.size() * sizeof(vec4))
    throw Error(ErrorKind::Render, "three.js (its renderer): " + out.string() + " holds " + std::to_string(bytes.size()) +
                                       " bytes, not the " + std::to_string(c.width) + "x" + std::to_string(c.height) +
                                       " RGBA floats asked for");
  std::memcpy(r.image.texels.data(), bytes.data(), bytes.size());
  for (vec4& p : r.image.texels)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw Error(ErrorKind::Render, "three.js (its renderer): its image holds a non-finite value");
  try {
    const nlohmann::json j = nlohmann::json::parse(std::ifstream(info));
    r.msPerFrame = j.at("ms").value("secondFrame", 0.0);
    r.renderer = "three.js r" + j.value("three", std::string("?")) + " on " + j.value("renderer", std::string("?"));
  } catch (const nlohmann::json::exception& e) {
    throw Error(ErrorKind::Render, "three.js (its renderer): cannot read " + info.string() + ": " + e.what());
  }
  return r;
}

}  // namespace snell::lab
