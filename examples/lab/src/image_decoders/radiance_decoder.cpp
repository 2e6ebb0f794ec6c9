// Radiance RGBE (.hdr) through stb_image's HDR reader, the only stb decoder
// the lab still compiles (STBI_ONLY_HDR): no Debian library more trusted reads
// the format (OpenEXR does not; OpenImageIO would bring a dozen decoders for
// one), and this one is small enough for the fuzzer to cover every branch.
// Its two known defects are walked around here: a run-length scanline with a
// run of 0 (also what a truncated file reads as) loops forever, and a header
// of width 0 "decodes" to no texels.
#include "image_decoders.hpp"

#include <memory>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_FAILURE_USERMSG
#define STBI_NO_STDIO
#define STBI_ONLY_HDR
#include <stb/stb_image.h>

namespace snell::lab::detail {

namespace {

unsigned byteAt(const std::string& b, std::size_t i) {
  return i < b.size() ? static_cast<unsigned>(static_cast<unsigned char>(b[i])) : 0u;
}

// The scanlines walked as stb_image 2.27 walks them, from the data after the
// header (bytes past the end read as 0, as its memory reader returns them);
// a run of 0 is refused before stb_image would loop on it.
void checkRunLengths(const std::string& b, int width, int height, const ImageLimit& limit) {
  if (width < 8 || width >= 32768) return;  // stb_image reads these flat: no runs
  const std::size_t n = b.size();
  std::size_t p = 0;
  const auto get8 = [&] { return byteAt(b, p++); };
  const auto skipLine = [&] {  // returns whether stb_image takes the line for empty
    // stb_image keeps a line in a C string: one that starts with NUL is empty to it.
    const bool empty = p >= n || b[p] == '\n' || b[p] == '\0';
    while (p < n && b[p] != '\n') ++p;
    ++p;
    return empty;
  };
  skipLine();                // #?RADIANCE
  while (p < n && !skipLine()) {
  }                          // header lines up to the empty one
  skipLine();                // -Y height +X width
  for (int j = 0; j < height; ++j) {
    const unsigned c1 = get8(), c2 = get8(), high = get8();
    if (c1 != 2 || c2 != 2 || (high & 0x80)) return;  // not run-length encoded: read flat from here on
    if (static_cast<int>(high << 8 | get8()) != width) return;  // stb_image reports it
    for (int k = 0; k < 4; ++k)
      for (int i = 0; i < width;) {
        unsigned count = get8();
        if (count > 128) {
          count -= 128;
          get8();
        } else if (count == 0) {
          limit.fail("Radiance HDR", "scanline " + std::to_string(j) + " has a run of length 0 " +
                                         (p > n ? "(the file is truncated)" : "(corrupt HDR)"));
        } else {
          p += count;
        }
        if (static_cast<int>(count) > width - i) return;  // stb_image reports it
        i += static_cast<int>(count);
      }
  }
}

}  // namespace

Image decodeRadiance(const std::string& bytes, const ImageLimit& limit) {
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int size = static_cast<int>(bytes.size());  // the caller refuses files over 2 GiB
  int w = 0, h = 0, n = 0;
  // The header, before stb_image allocates for it. When stb_image cannot read
  // it, decoding below fails on it with the reason.
  if (stbi_info_from_memory(data, size, &w, &h, &n)) {
    limit.check(w, h);
    checkRunLengths(bytes, w, h, limit);
  }
  float* texels = stbi_loadf_from_memory(data, size, &w, &h, &n, 3);
  if (texels == nullptr) limit.fail("Radiance HDR", stbi_failure_reason());
  const std::unique_ptr<float, void (*)(void*)> owner(texels, stbi_image_free);
  limit.check(w, h);
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float* p = texels + (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) * 3;
      img.at(x, h - 1 - y) = vec4(p[0], p[1], p[2], 1.0f);
    }
  return img;
}

}  // namespace snell::lab::detail
