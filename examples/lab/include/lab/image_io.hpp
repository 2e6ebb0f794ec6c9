// Image files. snell::Image holds linear RGBA floats with row 0 at the bottom
// (GL order); files store row 0 at the top, so reading and writing flip rows.
#pragma once
#include <snell/bridge.hpp>

#include <string>

namespace snell::lab {

// The sRGB transfer function (IEC 61966-2-1), per channel, input clamped to [0, 1].
float srgbEncode(float linear);
float srgbDecode(float encoded);

enum class PngEncoding {
  Srgb,    // linear values are sRGB-encoded (for viewing)
  Linear,  // values written as they are, clamped to [0, 1] (for data: masks, heat maps)
};

// 8-bit RGB PNG (alpha dropped). Error(Io) naming the path and the system's
// reason ("No space left on device") on failure.
void writePng(const std::string& path, const Image& image, PngEncoding encoding = PngEncoding::Srgb);

// The most texels an image may have (8192 x 4096: 512 MiB as linear RGBA floats).
inline constexpr long long kMaxImagePixels = 8192LL * 4096LL;

// PNG (libspng) or JPEG (libjpeg-turbo), 8-bit, decoded from sRGB to linear
// unless `linear`; OpenEXR (the OpenEXR library) or Radiance HDR (stb_image's
// HDR reader), already linear. The format is chosen by the file's signature.
// Returns linear RGBA with alpha 1. Error(Io) naming the path when it is
// missing or a directory; Error(Parse) naming it when it is in no format
// above, corrupt (the library's reason: "cannot decode JPEG: Bogus Huffman
// table definition"), or larger than kMaxImagePixels texels (checked on the
// header, before anything is allocated). An OpenEXR texel that is NaN or
// infinite is an error; a negative one reads as 0.
Image readImage(const std::string& path, bool linear = false);

// The same on a file's bytes; `name` is the file name used in messages. A
// smaller `maxPixels` keeps the fuzzer fast (tests/fuzz/fuzz_image.cpp).
Image decodeImage(const std::string& bytes, const std::string& name, bool linear = false,
                  long long maxPixels = kMaxImagePixels);

}  // namespace snell::lab
