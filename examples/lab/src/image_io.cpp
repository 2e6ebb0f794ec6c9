#include "lab/image_io.hpp"

#include "lab/error.hpp"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_FAILURE_USERMSG
#include <stb/stb_image.h>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace snell::lab {

float srgbEncode(float linear) {
  const float c = linear > 0.0f ? std::min(linear, 1.0f) : 0.0f;  // NaN -> 0
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

float srgbDecode(float encoded) {
  const float c = encoded > 0.0f ? std::min(encoded, 1.0f) : 0.0f;
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

void writePng(const std::string& path, const Image& image, PngEncoding encoding) {
  if (image.width <= 0 || image.height <= 0) throw Error(ErrorKind::Io, "cannot write an empty image to " + path);
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3);
  std::size_t o = 0;
  for (int y = image.height - 1; y >= 0; --y)
    for (int x = 0; x < image.width; ++x) {
      const vec4& t = image.at(x, y);
      for (int c = 0; c < 3; ++c) {
        float v = t[c];
        v = encoding == PngEncoding::Srgb ? srgbEncode(v) : (v > 0.0f ? std::min(v, 1.0f) : 0.0f);
        bytes[o++] = static_cast<std::uint8_t>(std::lround(v * 255.0f));
      }
    }
  // Encoded in memory and written here: stbi_write_png ignores fwrite and
  // fclose failures, so a full disk left a truncated PNG and no error.
  std::vector<unsigned char> png;
  const auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    const auto* p = static_cast<const unsigned char*>(data);
    out->insert(out->end(), p, p + size);
  };
  if (!stbi_write_png_to_func(append, &png, image.width, image.height, 3, bytes.data(), image.width * 3))
    throw Error(ErrorKind::Io, "cannot encode PNG for " + path);
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) throw Error(ErrorKind::Io, "cannot write PNG file " + path + ": " + std::strerror(errno));
  const bool written = std::fwrite(png.data(), 1, png.size(), f) == png.size();
  const int writeErrno = errno;
  const bool closed = std::fclose(f) == 0;  // a full disk often shows only here, when the buffer is flushed
  if (!written || !closed)
    throw Error(ErrorKind::Io, "cannot write PNG file " + path + ": " + std::strerror(written ? errno : writeErrno));
}

Image readImage(const std::string& path, bool linear) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw Error(ErrorKind::Io, "image file not found: " + path);
  if (std::filesystem::is_directory(path, ec)) throw Error(ErrorKind::Io, "image file is a directory: " + path);
  int w = 0, h = 0, n = 0;
  const bool hdr = stbi_is_hdr(path.c_str()) != 0;
  Image img;
  if (hdr) {
    float* data = stbi_loadf(path.c_str(), &w, &h, &n, 4);
    if (!data) throw Error(ErrorKind::Parse, path + ": cannot decode image: " + stbi_failure_reason());
    img = Image(w, h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const float* p = data + (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) * 4;
        img.at(x, h - 1 - y) = vec4(p[0], p[1], p[2], 1.0f);
      }
    stbi_image_free(data);
    return img;
  }
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 4);
  if (!data) throw Error(ErrorKind::Parse, path + ": cannot decode image: " + stbi_failure_reason());
  float table[256];
  for (int i = 0; i < 256; ++i) {
    const float v = static_cast<float>(i) / 255.0f;
    table[i] = linear ? v : srgbDecode(v);
  }
  img = Image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const unsigned char* p = data + (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) * 4;
      img.at(x, h - 1 - y) = vec4(table[p[0]], table[p[1]], table[p[2]], 1.0f);
    }
  stbi_image_free(data);
  return img;
}

}  // namespace snell::lab
