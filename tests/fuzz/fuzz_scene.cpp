// libFuzzer target: snell::lab::parseScene on the input text. Parsing only (no
// mesh, image or Embree work): the documented failure is snell::lab::Error
// (Parse for malformed JSON, Schema for a bad field); any other exception
// escaping, a crash or a sanitizer report is a bug.
#include "lab/error.hpp"
#include "lab/scene.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const snell::lab::Scene scene = snell::lab::parseScene(text, "/nonexistent/fuzz/scene.json");
    (void)scene.frameTime(scene.animation.frames - 1);
  } catch (const snell::lab::Error&) {
  }
  return 0;
}
