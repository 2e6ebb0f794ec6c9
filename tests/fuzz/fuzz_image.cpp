// libFuzzer target: snell::lab::decodeImage (PNG through libspng, JPEG through
// libjpeg-turbo, OpenEXR, Radiance HDR through stb_image) on the input bytes,
// 8-bit formats decoded as sRGB or as linear. run_fuzzers.sh builds it once per
// format (image_png, image_jpeg, image_exr, image_hdr), each fuzzed from that
// format's corpus, so every campaign minute goes to one decoder. The
// documented failure is snell::lab::Error (Parse: not a decodable image, or
// more than kMaxImagePixels texels); any other exception escaping, a crash or
// a sanitizer report is a bug.
#include "lab/error.hpp"
#include "lab/image_io.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    // At most 2^20 texels: the decoders run the same code on larger images,
    // and 32M-texel decodes would slow the fuzzer to a few runs a second.
    const snell::Image image = snell::lab::decodeImage(bytes, "fuzz.img", (size & 1u) != 0, 1LL << 20);
    // Every texel is read, so a short buffer shows under ASan here.
    float sum = 0.0f;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) sum += image.at(x, y).x;
    (void)sum;
  } catch (const snell::lab::Error&) {
  }
  return 0;
}
