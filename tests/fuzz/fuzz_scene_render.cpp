// libFuzzer target: for each input that parseScene accepts, builds the frame
// (buildFrame, at the first and the last animation time) and traces a 16x16
// ground-truth frame with the Embree reference tracer, both trace modes and,
// with several objects, the composited model in the file's order. The
// documented failure is snell::lab::Error (a missing mesh or image, a mesh or
// transform the loader names, a tracer refusal); any other exception, a crash,
// an Embree assertion or a sanitizer report is a bug: no scene file may make
// the lab abort.
//
// Sizes are capped before building (sky bake, tessellation, texture size) so
// that an input costs milliseconds; the numbers themselves are untouched.
#include "lab/error.hpp"
#include "lab/scene.hpp"
#include "lab/tracer.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace {

void capSizes(snell::lab::Scene& s) {
  using snell::ivec2;
  s.camera.width = 16;
  s.camera.height = 16;
  for (snell::lab::RefractiveObject& o : s.objects) {
    snell::lab::MeshSpec& m = o.mesh;
    m.segments = std::min(m.segments, 24);
    m.rings = std::min(m.rings, 12);
    m.subdivisions = std::min(m.subdivisions, 3);
    m.blob.subdivisions = std::min(m.blob.subdivisions, 3);
    m.majorSegments = std::min(m.majorSegments, 24);
    m.minorSegments = std::min(m.minorSegments, 12);
  }
  s.environment.bakeSize = glm::min(s.environment.bakeSize, ivec2(32, 16));
  for (snell::lab::PaintingSpec& p : s.paintings) p.texture.resolution = glm::min(p.texture.resolution, ivec2(16, 16));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    snell::lab::Scene scene = snell::lab::parseScene(text, "/nonexistent/fuzz/scene.json");
    capSizes(scene);
    for (int frame : {0, scene.animation.frames - 1}) {
      const snell::lab::SceneFrame f = snell::lab::buildFrame(scene, scene.frameTime(frame));
      const snell::lab::ReferenceTracer tracer(f);
      snell::lab::TraceOptions options;
      options.threads = 1;
      options.progress = false;
      options.maxDepth = 6;
      (void)tracer.render(f.camera, options);
      options.mode = snell::lab::TraceMode::TwoInterfaces;
      (void)tracer.render(f.camera, options);
      if (f.objects.size() > 1) {
        std::vector<std::size_t> order;
        std::vector<glm::dvec3> index;
        for (std::size_t i = 0; i < f.objects.size(); ++i) {
          order.push_back(i);
          index.push_back(glm::dvec3(snell::lab::channelIors(f.objects[i])));
        }
        (void)tracer.renderComposited(f.camera, order, index, options);
      }
      if (scene.animation.frames == 1) break;
    }
  } catch (const snell::lab::Error&) {
  }
  return 0;
}
