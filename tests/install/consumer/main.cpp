// A user's tool built against snell (tests/install/run_consumer.cmake builds it
// in every consumption mode): calls a snell function in C++, flattens the
// shader sources it was pointed at with the GPU layer's flattener, lists the
// GPU layer's runtimes (an install has the four that need no source tree: its
// headers compile without the ones it leaves out), and checks the version
// macros.
#include <snell/gpu/include_flattener.hpp>
#include <snell/gpu/runtime_list.hpp>
#include <snell/snell.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>

#if !defined(SNELL_VERSION_MAJOR) || SNELL_VERSION != SNELL_VERSION_MAJOR * 10000 + SNELL_VERSION_MINOR * 100 + SNELL_VERSION_PATCH
#error "SNELL_VERSION_* missing or inconsistent"
#endif

int main() {
  // Straight through at normal incidence: the direction is unchanged.
  snell::SnellRefraction r = snell::snellRefract(snell::vec3(0, 0, -1), snell::vec3(0, 0, 1), 1.0f / 1.5f,
                                                 SNELL_TIR_CRITICAL);
  if (!r.valid || r.tir || std::fabs(r.direction.z + 1.0f) > 1e-6f) {
    std::fprintf(stderr, "snellRefract gave an unexpected result\n");
    return 1;
  }
  for (const char* f : {SNELL_GLSL_DIR "/snell/snell.glsl", SNELL_HLSL_DIR "/snell/bridge.hlsl",
                        SNELL_SINGLE_FILE_DIR "/snell.glsl"}) {
    if (!std::filesystem::exists(f)) {
      std::fprintf(stderr, "shader source missing: %s\n", f);
      return 1;
    }
  }
  const snell::gpu::FlatSource flat = snell::gpu::flattenGlslFile(SNELL_GLSL_DIR "/snell/optics.glsl", {SNELL_GLSL_DIR});
  if (flat.text.find("SnellRefraction snellRefract(") == std::string::npos) {
    std::fprintf(stderr, "the flattened optics.glsl has no snellRefract\n");
    return 1;
  }
  if (snell::gpu::runtimeList().size() < 4) {
    std::fprintf(stderr, "snell::gpu lists %zu runtimes: %s\n", snell::gpu::runtimeList().size(),
                 snell::gpu::runtimeNames().c_str());
    return 1;
  }
  std::printf("snell consumer: ok (snell %d.%d.%d; runtimes %s)\n", SNELL_VERSION_MAJOR, SNELL_VERSION_MINOR,
              SNELL_VERSION_PATCH, snell::gpu::runtimeNames().c_str());
  return 0;
}
