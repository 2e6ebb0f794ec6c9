#include "lab/image_io.hpp"

#include "lab/error.hpp"
#include "lab/file_util.hpp"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

// Only the formats the lab documents: stb_image's other decoders (GIF, PSD,
// PIC, PNM) are never handed a file (issue 16: less third-party code that sees
// hostile bytes). stb_image reads from memory only: the lab opens the file.
#define STB_IMAGE_IMPLEMENTATION
#define STBI_FAILURE_USERMSG
#define STBI_NO_STDIO
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_BMP
#define STBI_ONLY_TGA
#define STBI_ONLY_HDR
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

namespace {

// Byte i of a file as stb_image's memory reader returns it: 0 past the end.
unsigned byteAt(const std::string& b, std::size_t i) {
  return i < b.size() ? static_cast<unsigned>(static_cast<unsigned char>(b[i])) : 0u;
}

// stb_image 2.27 (Debian 12's libstb) does not bound the code count of a JPEG
// Huffman table: a DHT segment whose 16 counts sum past 256 writes past its
// 257-entry arrays (found by fuzz_image, issue 16). Every DHT segment stb_image
// could read is checked here first, the way stb_image reads it (bytes past the
// end read as 0, the table loop bounded by the segment length only). Up to the
// first scan, markers are walked as stb_image walks them; after it, every
// FF C4 is taken for a DHT marker (in entropy-coded data FF is always followed
// by 00 or a marker, so no valid file is refused for it).
void checkJpegHuffmanTables(const std::string& b, const std::string& name) {
  const std::size_t n = b.size();
  const auto byte = [&](std::size_t i) { return byteAt(b, i); };
  const auto checkDht = [&](std::size_t at) {  // `at`: the first byte after FF C4
    long remaining = static_cast<long>(byte(at) << 8 | byte(at + 1)) - 2;
    std::size_t t = at + 2;
    while (remaining > 0) {
      unsigned codes = 0;
      for (std::size_t k = 1; k <= 16; ++k) codes += byte(t + k);
      if (codes > 256)
        throw Error(ErrorKind::Parse, name + ": cannot decode image: a JPEG Huffman table defines " +
                                          std::to_string(codes) + " codes, at most 256 are allowed (corrupt JPEG)");
      t += 17 + codes;
      remaining -= 17 + static_cast<long>(codes);
    }
  };
  // The start-of-image marker, after any fill bytes (FF FF ... FF D8), as stb_image reads it.
  std::size_t i = 0;
  if (byte(i) != 0xFF) return;
  while (i < n && byte(i) == 0xFF) ++i;
  if (byte(i) != 0xD8) return;
  ++i;
  while (i + 1 < n) {
    if (byte(i) != 0xFF) { ++i; continue; }  // stb_image skips to the next FF
    const unsigned marker = byte(i + 1);
    if (marker == 0xFF) { ++i; continue; }  // fill byte
    i += 2;
    if (marker == 0xDA) break;  // the first scan
    if (marker == 0xD9) return;
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) continue;
    if (marker == 0xC4) checkDht(i);
    i += byte(i) << 8 | byte(i + 1);
  }
  for (; i + 1 < n; ++i)
    if (byte(i) == 0xFF && byte(i + 1) == 0xC4) checkDht(i + 2);
}

// stb_image 2.27 loops forever on a run-length Radiance scanline with a
// count of 0 (also what it reads past the end of a truncated file): a "dump"
// of 0 bytes never advances (found by fuzz_image, issue 16). The scanlines are
// walked here as stb_image walks them, from the data after the header.
void checkHdrRunLengths(const std::string& b, int width, int height, const std::string& name) {
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
          throw Error(ErrorKind::Parse, name + ": cannot decode image: scanline " + std::to_string(j) +
                                            " of the Radiance file has a run of length 0 " +
                                            (p > n ? "(the file is truncated)" : "(corrupt HDR)"));
        } else {
          p += count;
        }
        if (static_cast<int>(count) > width - i) return;  // stb_image reports it
        i += static_cast<int>(count);
      }
  }
}

// stb_image 2.27 grows its buffer to a PNG chunk's declared length before it
// checks that the file holds that many bytes: 106 bytes asked for 2 GiB
// (an IDAT claiming 1.5 GB, rounded up to a power of two): every chunk up to
// IEND must fit in the file. And it copies a first IDAT of length 0 to a null
// buffer (undefined behaviour, found by the campaign): empty IDAT chunks, which
// add nothing to the image data, are left out of what it is given. Returns
// whether `out` holds such a copy.
bool checkPngChunks(const std::string& b, const std::string& name, std::string& out) {
  static const char kSignature[] = "\x89PNG\r\n\x1a\n";
  if (b.compare(0, 8, kSignature, 8) != 0) return false;
  const auto byte = [&](std::size_t i) { return static_cast<std::uint32_t>(byteAt(b, i)); };
  std::vector<std::size_t> emptyIdat;
  for (std::size_t p = 8; p + 8 <= b.size();) {
    const std::uint64_t length = byte(p) << 24 | byte(p + 1) << 16 | byte(p + 2) << 8 | byte(p + 3);
    const std::string type = b.substr(p + 4, 4);
    const std::uint64_t left = b.size() - (p + 8);
    if (length + 4 > left)
      throw Error(ErrorKind::Parse, name + ": cannot decode image: PNG chunk '" + type + "' claims " +
                                        std::to_string(length) + " bytes, the file has " +
                                        std::to_string(left < 4 ? 0 : left - 4) + " left (truncated or corrupt)");
    if (type == "IEND") break;
    if (type == "IDAT" && length == 0) emptyIdat.push_back(p);
    p += 8 + static_cast<std::size_t>(length) + 4;
  }
  if (emptyIdat.empty()) return false;
  out.clear();
  std::size_t from = 0;
  for (const std::size_t p : emptyIdat) {
    out.append(b, from, p - from);
    from = p + 12;  // length, type, no data, CRC
  }
  out.append(b, from, std::string::npos);
  return true;
}

}  // namespace

Image decodeImage(const std::string& bytes, const std::string& name, bool linear, long long maxPixels) {
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw Error(ErrorKind::Parse, name + ": cannot decode image: the file is larger than 2 GiB");
  checkJpegHuffmanTables(bytes, name);
  std::string withoutEmptyIdat;
  const std::string& input = checkPngChunks(bytes, name, withoutEmptyIdat) ? withoutEmptyIdat : bytes;
  const auto* data = reinterpret_cast<const stbi_uc*>(input.data());
  const int size = static_cast<int>(input.size());
  int w = 0, h = 0, n = 0;
  // Checked on the header, before stb_image allocates for it: a few bytes can
  // claim 16384 x 16384 texels, which stb_image accepts (1 GiB of bytes, 4 GiB
  // as the lab's floats). When stb_image cannot read the header, decoding
  // below fails on it too, with the reason (stbi_info's is always "not of any
  // known type").
  const auto checkSize = [&] {
    // stb_image "decodes" a Radiance file whose header says +X 0 to no texels.
    if (w <= 0 || h <= 0)
      throw Error(ErrorKind::Parse, name + ": cannot decode image: its header says " + std::to_string(w) + " x " +
                                        std::to_string(h) + " pixels");
    if (static_cast<long long>(w) * h > maxPixels)
      throw Error(ErrorKind::Parse, name + ": image is " + std::to_string(w) + " x " + std::to_string(h) +
                                        " pixels; the lab reads at most " + std::to_string(maxPixels) +
                                        (maxPixels == kMaxImagePixels ? " (8192 x 4096)" : ""));
  };
  if (stbi_info_from_memory(data, size, &w, &h, &n)) checkSize();
  const bool hdr = stbi_is_hdr_from_memory(data, size) != 0;
  Image img;
  if (hdr) {
    if (w > 0 && h > 0) checkHdrRunLengths(input, w, h, name);
    float* texels = stbi_loadf_from_memory(data, size, &w, &h, &n, 4);
    if (!texels) throw Error(ErrorKind::Parse, name + ": cannot decode image: " + stbi_failure_reason());
    const std::unique_ptr<float, void (*)(void*)> owner(texels, stbi_image_free);
    checkSize();
    img = Image(w, h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const float* p = texels + (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) * 4;
        img.at(x, h - 1 - y) = vec4(p[0], p[1], p[2], 1.0f);
      }
    return img;
  }
  unsigned char* texels = stbi_load_from_memory(data, size, &w, &h, &n, 4);
  if (!texels) throw Error(ErrorKind::Parse, name + ": cannot decode image: " + stbi_failure_reason());
  const std::unique_ptr<unsigned char, void (*)(void*)> owner(texels, stbi_image_free);
  checkSize();
  float table[256];
  for (int i = 0; i < 256; ++i) {
    const float v = static_cast<float>(i) / 255.0f;
    table[i] = linear ? v : srgbDecode(v);
  }
  img = Image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const unsigned char* p = texels + (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) * 4;
      img.at(x, h - 1 - y) = vec4(table[p[0]], table[p[1]], table[p[2]], 1.0f);
    }
  return img;
}

Image readImage(const std::string& path, bool linear) {
  return decodeImage(readTextFile(path, "image"), path, linear);
}

}  // namespace snell::lab
