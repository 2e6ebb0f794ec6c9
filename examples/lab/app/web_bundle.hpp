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

// One technique the lab ran on the frame: its row and its picture (the object's colour over the scene, linear
// RGB, GL row order: row 0 at the bottom).
struct WebBundleImage {
  LabRowSpec row;
  const Image* image = nullptr;
};

// Writes DIR/bundle.json and its binary files (little-endian float32, uint32 indices, a uint8 mask; GL
// row order); DIR is
// created. `objectMask`: the ray tracer's object pixels (the lab's measure). `buffers` and `front`: the
// lab's own GL buffers (passes 1-2) and the front-face pass's fragment inputs, so the page can run a
// technique on exactly the lab's buffers and tell snell's code apart from the two rasterizers. Throws
// lab::Error (Io) when a file cannot be written.
void writeWebBundle(const std::filesystem::path& dir, const std::string& sceneName, const SceneFrame& frame,
                    const std::vector<float>& dN, const ShadeConstants& k, const std::vector<WebBundleImage>& images,
                    const Mask& objectMask, const StaticBuffers& buffers, const TechniqueBuffers& front);

}  // namespace snell::lab
