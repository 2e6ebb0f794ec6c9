#include "lab/image_io.hpp"

#include "lab/error.hpp"
#include "lab/file_util.hpp"
#include "image_decoders/image_decoders.hpp"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

// Writing sees only the lab's own buffers: stb_image_write is kept for it.
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

namespace detail {

void ImageLimit::check(long long width, long long height) const {
  if (width <= 0 || height <= 0)
    throw Error(ErrorKind::Parse, name + ": cannot decode image: its header says " + std::to_string(width) + " x " +
                                      std::to_string(height) + " pixels");
  // Both sides are below 2^31 here (each library's own limit), so the product cannot overflow.
  if (width > maxPixels || height > maxPixels || width * height > maxPixels)
    throw Error(ErrorKind::Parse, name + ": image is " + std::to_string(width) + " x " + std::to_string(height) +
                                      " pixels; the lab reads at most " + std::to_string(maxPixels) +
                                      (maxPixels == kMaxImagePixels ? " (8192 x 4096)" : ""));
}

void ImageLimit::fail(const char* format, const std::string& reason) const {
  throw Error(ErrorKind::Parse, name + ": cannot decode " + format + ": " + reason);
}

Image imageFromBytes(const std::uint8_t* texels, int width, int height, int channels, bool linear) {
  float table[256];
  for (int i = 0; i < 256; ++i) {
    const float v = static_cast<float>(i) / 255.0f;
    table[i] = linear ? v : srgbDecode(v);
  }
  Image img(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::uint8_t* p =
          texels + (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) *
                       static_cast<std::size_t>(channels);
      img.at(x, height - 1 - y) = vec4(table[p[0]], table[p[1]], table[p[2]], 1.0f);
    }
  return img;
}

}  // namespace detail

namespace {

bool startsWith(const std::string& bytes, const char* magic, std::size_t length) {
  return bytes.compare(0, length, magic, length) == 0;
}

}  // namespace

Image decodeImage(const std::string& bytes, const std::string& name, bool linear, long long maxPixels) {
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw Error(ErrorKind::Parse, name + ": cannot decode image: the file is larger than 2 GiB");
  const detail::ImageLimit limit{name, maxPixels};
  // Chosen by the file's signature, never by its name.
  if (startsWith(bytes, "\x89PNG\r\n\x1a\n", 8)) return detail::decodePng(bytes, limit, linear);
  if (startsWith(bytes, "\xFF\xD8", 2)) return detail::decodeJpeg(bytes, limit, linear);
  if (startsWith(bytes, "\x76\x2F\x31\x01", 4)) return detail::decodeExr(bytes, limit);
  if (startsWith(bytes, "#?RADIANCE\n", 11) || startsWith(bytes, "#?RGBE\n", 7))
    return detail::decodeRadiance(bytes, limit);
  throw Error(ErrorKind::Parse, name + ": cannot decode image: not a PNG, JPEG, OpenEXR or Radiance HDR file "
                                       "(the formats the lab reads)");
}

Image readImage(const std::string& path, bool linear) {
  return decodeImage(readTextFile(path, "image"), path, linear);
}

}  // namespace snell::lab
