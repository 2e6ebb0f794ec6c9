// Internal: one decoder per image format the lab reads (PNG, JPEG, OpenEXR,
// Radiance HDR), each behind a library made for hostile input. Every decoder
// checks the size its header claims before it allocates texels and reports
// every failure as Error(Parse) naming the file; none exits, aborts or leaks
// on a corrupt file. The table of what each library is trusted with is in
// tests/fuzz/README.md.
#pragma once
#include <snell/bridge.hpp>

#include <cstdint>
#include <string>

namespace snell::lab::detail {

// The texel budget of one decode, with the file name for messages.
struct ImageLimit {
  const std::string& name;
  long long maxPixels;
  // Error(Parse) unless 0 < width, 0 < height and width * height <= maxPixels.
  void check(long long width, long long height) const;
  // Error(Parse) "<name>: cannot decode <format>: <reason>".
  [[noreturn]] void fail(const char* format, const std::string& reason) const;
};

// 8-bit PNG and JPEG texels: rows top to bottom, `channels` bytes per texel
// (the first three RGB), decoded from sRGB unless `linear`.
Image imageFromBytes(const std::uint8_t* texels, int width, int height, int channels, bool linear);

Image decodePng(const std::string& bytes, const ImageLimit& limit, bool linear);   // libspng
Image decodeJpeg(const std::string& bytes, const ImageLimit& limit, bool linear);  // libjpeg-turbo
Image decodeExr(const std::string& bytes, const ImageLimit& limit);                // OpenEXR
Image decodeRadiance(const std::string& bytes, const ImageLimit& limit);          // stb_image's HDR reader

}  // namespace snell::lab::detail
