// The lab's row of three.js's own renderer on a glTF asset (threejs_renderer.hpp): the image it scores
// must be three.js's view of the same camera, environment and backdrop. Checked against the Embree ray
// tracer's image of the lab's frame, computed here: away from the glass (where the two renderers draw the
// same unlit backdrop) they must agree closely, which a wrong camera, a flipped row order or a wrong
// environment hand-off breaks; and the row's MSE must be what the written image scores over the tracer's
// mask. Runs Chromium (scripts/install-deps.sh): a missing one fails.
#include "lab/gltf_loader.hpp"
#include "lab/metrics.hpp"
#include "lab/scene.hpp"
#include "lab/tracer.hpp"

#include "lab_run_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace fs = std::filesystem;

TEST(LabThreeJsRow, SeesTheSameFrameAsTheRayTracer) {
  const int size = 64;
  snell::lab::LabOptions o = labtest::labRunOptions("gltf/glass_bunny", size);
  o.scenePath = labtest::scenesDir() + "/gltf/glass_bunny.glb";
  o.techniques = {"single"};
  const labtest::TempDir dir;
  o.outDir = dir.file("out");
  const snell::lab::LabResult r = snell::lab::runLab(o);
  ASSERT_EQ(r.renderers.size(), 1u);

  snell::lab::Scene scene = snell::lab::loadScene(o.scenePath);
  scene.camera.width = scene.camera.height = size;
  const snell::lab::SceneFrame frame = snell::lab::buildFrame(scene);
  snell::lab::TraceOptions full;
  const snell::lab::TraceResult truth = snell::lab::ReferenceTracer(frame).render(frame.camera, full);

  std::ifstream in(dir.file("out/threejs/threejs.f32"), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  snell::Image three(size, size);
  ASSERT_EQ(bytes.size(), three.texels.size() * sizeof(snell::vec4));
  std::memcpy(three.texels.data(), bytes.data(), bytes.size());

  EXPECT_NEAR(r.renderers[0].mseFull, snell::lab::compareImages(truth.color, three, truth.mask).mse, 1e-9);
  // Away from the glass (two pixels clear of the tracer's mask): the backdrop, unlit in both. The mean
  // absolute difference per channel, against three.js's image as written and as a wrong hand-off would
  // give it (upside down, one pixel to the side).
  const auto backdropDifference = [&](int flipY, int shiftX) {
    double sum = 0.0;
    int n = 0;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        bool nearGlass = false;
        for (int dy = -2; dy <= 2; ++dy)
          for (int dx = -2; dx <= 2; ++dx)
            nearGlass = nearGlass || truth.mask.at(std::clamp(x + dx, 0, size - 1), std::clamp(y + dy, 0, size - 1));
        if (nearGlass) continue;
        const snell::vec4 t = three.at(std::clamp(x + shiftX, 0, size - 1), flipY ? size - 1 - y : y);
        for (int c = 0; c < 3; ++c) sum += static_cast<double>(std::fabs(truth.color.at(x, y)[c] - t[c]));
        n += 3;
      }
    EXPECT_GT(n, size * size);  // most of the frame is backdrop
    return sum / n;
  };
  const double asWritten = backdropDifference(0, 0);
  std::printf("backdrop: mean |three.js - ray traced| %.4f; upside down %.4f; a pixel to the side %.4f\n", asWritten,
              backdropDifference(1, 0), backdropDifference(0, 1));
  // SwiftShader snaps vertices to 1/16 pixel and the test card's detail is finer than a pixel at this size.
  EXPECT_LT(asWritten, 0.03);
  EXPECT_GT(backdropDifference(1, 0), 3.0 * asWritten);
  EXPECT_GT(backdropDifference(0, 1), 2.0 * asWritten);
}
