// three.js's own renderer on a glTF asset: tools/browser/threejs_render.mjs
// loads the file with three's GLTFLoader (glass as MeshPhysicalMaterial
// transmission, the other materials drawn unlit as the lab draws them) in
// headless Chromium and returns its linear float image, from the lab's camera
// and environment. The lab scores it as a row ("three.js (its renderer)"):
// the real renderer, where the engine-threejs row is a model of its shader.
#pragma once
#include <lab/scene.hpp>

#include <filesystem>
#include <string>

namespace snell::lab {

struct ThreeJsRender {
  Image image;            // the camera's width x height, linear RGB, row 0 at the bottom
  double msPerFrame = 0;  // a second frame's time in the page (SwiftShader: not a GPU's)
  std::string renderer;   // three.js's revision and the WebGL renderer it ran on
};

// Renders `gltf` as `frame`'s camera sees it under its environment, in `workDir` (the job's files).
// Error(Render) naming the cause (no Node.js, no three.js, no Chromium, a page error) when it cannot.
ThreeJsRender renderWithThreeJs(const std::string& gltf, const Scene& scene, const SceneFrame& frame,
                                const std::filesystem::path& workDir);

}  // namespace snell::lab
