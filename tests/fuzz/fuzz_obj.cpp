// libFuzzer target: snell::lab::parseObj on the input text. The documented
// failures are snell::lab::Error (Parse: tinyobjloader rejects the text; Mesh:
// no triangles, bad indices, degenerate or non-finite geometry); any other
// exception escaping, a crash or a sanitizer report is a bug.
#include "lab/error.hpp"
#include "lab/obj_loader.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const snell::lab::Mesh mesh = snell::lab::parseObj(text, "fuzz.obj");
    (void)mesh;
  } catch (const snell::lab::Error&) {
  }
  return 0;
}
