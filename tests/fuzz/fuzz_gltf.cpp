// libFuzzer target: snell::lab::parseGltf on the input bytes (a .glb when they
// start with glTF's binary magic, else glTF JSON), with no folder, so every
// external file is refused; then a framing camera over what it loaded. The
// documented failure is snell::lab::Error; any other exception escaping, a
// crash, a hang or a sanitizer report is a bug (in snell's reader or in
// tinygltf, which is compiled here with the same instrumentation).
#include "lab/error.hpp"
#include "lab/gltf_loader.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    const snell::lab::GltfScene g = snell::lab::parseGltf(bytes, "");
    std::vector<snell::lab::Mesh> meshes;
    for (const snell::lab::RefractiveObject& o : g.objects) meshes.push_back(*o.mesh.loaded);
    std::vector<snell::lab::Painting> paintings;
    for (const snell::lab::PaintingSpec& p : g.paintings) paintings.push_back(*p.loaded);
    (void)snell::lab::framingCamera(meshes, paintings);
  } catch (const snell::lab::Error&) {
  }
  return 0;
}
