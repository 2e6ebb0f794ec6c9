// glTF 2.0 assets (.gltf with its files beside it, or .glb) as lab scenes,
// read with tinygltf (Debian's libtinygltf-dev) compiled without stb_image and
// without its file-system defaults. What the lab takes from a file is listed
// in examples/scenes/README.md ("glTF assets"); in short:
// - every mesh node of the file's scene, with its world transform;
// - a primitive whose material has KHR_materials_transmission (factor > 0)
//   becomes a refractive object: IOR from KHR_materials_ior (default 1.5),
//   absorption from KHR_materials_volume, sigma = -ln(attenuationColor) /
//   attenuationDistance per channel. A transmissive material without
//   KHR_materials_volume (or with thicknessFactor 0) is thin-walled in glTF,
//   a model snell does not render: it is refused, naming the material;
// - every other triangle primitive becomes an opaque painting, unlit: its
//   base colour factor times its base colour texture;
// - the first perspective camera met walking the scene's nodes, else none.
// Untrusted files are safe: the file and every external buffer or image at
// most kMaxGltfBytes, checked before reading; URIs only name files in the
// asset's folder or below it (no absolute path, no "..", no symbolic link
// out of it; nothing is expanded); every accessor and buffer view is checked
// against its buffer before it is read; images go through the lab's decoders
// (image_io.hpp). Every error is Error(Io) for an unreadable file, else
// Error(Parse) or Error(Schema) naming the file and the node, mesh,
// primitive, material, accessor or image at fault.
#pragma once
#include "lab/camera.hpp"
#include "lab/scene.hpp"

#include <string>
#include <vector>

namespace snell::lab {

// The largest .gltf/.glb file, external buffer or image file the lab reads.
inline constexpr long long kMaxGltfBytes = 256LL << 20;
// The most vertices (and indices) one primitive may have.
inline constexpr long long kMaxGltfElements = 1LL << 24;

struct GltfScene {
  std::vector<RefractiveObject> objects;  // mesh kind Loaded, world space
  std::vector<PaintingSpec> paintings;    // each holding its loaded painting
  bool hasCamera = false;
  Camera camera;  // the file's camera when hasCamera (resolution 512 high, the file's aspect ratio)
  std::vector<std::string> warnings;  // what the lab reads differently from the file, each a sentence
};

// Reads `path`: a .glb when it starts with glTF's binary magic, else JSON.
GltfScene loadGltf(const std::string& path);

// The same on a file's bytes; `path` names it in messages and its folder is
// where external files resolve ("" refuses every external file).
GltfScene parseGltf(const std::string& bytes, const std::string& path);

// A camera that frames `objects` (their bounding sphere fills 80 % of a 40
// degree view, seen from the front and a little above) with near and far
// planes around everything in `paintings` too.
Camera framingCamera(const std::vector<Mesh>& objects, const std::vector<Painting>& paintings);

}  // namespace snell::lab
