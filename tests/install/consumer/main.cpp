// A user's tool built against the installed package: calls a snell function in
// C++ and finds the shader sources through the exported SNELL_GLSL_DIR.
#include <snell/snell.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>

int main() {
  // Straight through at normal incidence: the direction is unchanged.
  snell::SnellRefraction r = snell::snellRefract(snell::vec3(0, 0, -1), snell::vec3(0, 0, 1), 1.0f / 1.5f,
                                                 SNELL_TIR_CRITICAL);
  if (!r.valid || r.tir || std::fabs(r.direction.z + 1.0f) > 1e-6f) {
    std::fprintf(stderr, "snellRefract gave an unexpected result\n");
    return 1;
  }
  for (const char* f : {SNELL_GLSL_DIR "/snell/snell.glsl", SNELL_GLSL_DIR "/snell/prelude.glsl",
                        SNELL_HLSL_DIR "/snell/bridge.hlsl"}) {
    if (!std::filesystem::exists(f)) {
      std::fprintf(stderr, "installed shader source missing: %s\n", f);
      return 1;
    }
  }
  std::puts("snell consumer: ok");
  return 0;
}
