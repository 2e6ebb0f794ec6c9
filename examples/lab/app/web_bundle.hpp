// The web page's bundle (examples/web): what snell-lab renders, written so
// that the three.js page renders the same frame, and the lab's own image of
// each technique it ran, so a test can compare the page's pixels with the
// lab's. snell-lab --web-bundle DIR writes it.
#pragma once
#include "gpu_lab.hpp"
#include "technique.hpp"

#include "lab/mask.hpp"
#include "lab/scene.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace snell::lab {

// One technique the lab ran on the frame: its row and its picture (the objects' colour over the scene, linear
// RGB, GL row order: row 0 at the bottom).
struct WebBundleImage {
  LabRowSpec row;
  const Image* image = nullptr;
};

// The lab's own GL buffers of one row, per object in draw order: what each object read (its scene layer, back
// and front faces: passes 1b and 2) and its front-face pass's fragment inputs, so the page can run a technique
// on exactly the lab's buffers and tell snell's code apart from the two rasterizers. With several objects a
// scene layer holds the objects drawn before, coloured as `row` drew them: the page matches the lab on these
// buffers with that row's technique only.
struct WebBundleLabBuffers {
  std::string row;                       // the name of the row they come from
  std::vector<StaticBuffers> objects;    // in draw order
  std::vector<TechniqueBuffers> fronts;  // in draw order
};

// Writes DIR/bundle.json and its binary files (little-endian float32, uint32 indices, a uint8 mask; GL
// row order); DIR is created. dN[i] and k[i]: frame.objects[i]'s d_N (empty: none) and constants; `order`:
// the draw order (back to front). `objectMask`: the ray tracer's object pixels (the lab's measure). Throws
// lab::Error (Io) when a file cannot be written, (Render) when the inputs do not match the frame's objects.
// A glTF scene: `asset` (the .glb or .gltf) is copied in as the page's "asset" (three.js's own renderer
// loads it), with `threejsImage`, the lab's render of it with three.js (nullptr: none ran).
struct WebBundleAsset {
  std::string path;                      // "": the scene is not a glTF asset
  const Image* threejsImage = nullptr;
};
void writeWebBundle(const std::filesystem::path& dir, const std::string& sceneName, const SceneFrame& frame,
                    const std::vector<std::vector<float>>& dN, const std::vector<ShadeConstants>& k,
                    const std::vector<std::size_t>& order, const std::vector<WebBundleImage>& images,
                    const Mask& objectMask, const WebBundleLabBuffers& lab, const WebBundleAsset& asset = {});

}  // namespace snell::lab
