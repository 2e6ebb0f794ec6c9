// libFuzzer target: snell::lab::decodeImage (PNG through libspng, JPEG through
// libjpeg-turbo, OpenEXR through OpenEXRCore, Radiance HDR through stb_image)
// on the input bytes, 8-bit formats decoded as sRGB or as linear.
// run_fuzzers.sh builds it once per format (image_png, image_jpeg, image_exr,
// image_hdr, with SNELL_FUZZ_IMAGE_<FORMAT> defined), and each target feeds
// its own decoder only: an input that does not start with the format's
// signature gets it in front, so no execution goes to another decoder (the
// lab chooses the decoder by signature). The documented failure is
// snell::lab::Error (Parse: not a decodable image, or more than
// kMaxImagePixels texels); any other exception escaping, a crash or a
// sanitizer report is a bug.
#include "lab/error.hpp"
#include "lab/image_io.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

namespace {

#if defined(SNELL_FUZZ_IMAGE_PNG)
const std::string kSignature("\x89PNG\r\n\x1a\n", 8);
#elif defined(SNELL_FUZZ_IMAGE_JPEG)
const std::string kSignature("\xFF\xD8", 2);
#elif defined(SNELL_FUZZ_IMAGE_EXR)
const std::string kSignature("\x76\x2F\x31\x01", 4);
#elif defined(SNELL_FUZZ_IMAGE_HDR)
const std::string kSignature("#?RADIANCE\n", 11);
#else
#  error "define SNELL_FUZZ_IMAGE_PNG, _JPEG, _EXR or _HDR (run_fuzzers.sh does)"
#endif

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string bytes(reinterpret_cast<const char*>(data), size);
#if defined(SNELL_FUZZ_IMAGE_HDR)
  const bool signed_ = bytes.compare(0, 11, kSignature) == 0 || bytes.compare(0, 7, "#?RGBE\n", 7) == 0;
#else
  const bool signed_ = bytes.compare(0, kSignature.size(), kSignature) == 0;
#endif
  if (!signed_) bytes.insert(0, kSignature);
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
