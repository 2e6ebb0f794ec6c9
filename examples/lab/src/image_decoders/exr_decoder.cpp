// OpenEXR through the OpenEXR library (Debian's 3.1, fuzzed in OSS-Fuzz) from
// memory: its limits on image and tile sizes are set before the header is
// read, the data window is checked against the lab's budget before pixels are
// allocated, and every Iex exception becomes Error(Parse). RgbaInputFile
// gives RGB(A), luminance and chroma files as RGBA halves.
#include "image_decoders.hpp"

#include "lab/error.hpp"

#include <OpenEXR/Iex.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfRgbaFile.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <new>
#include <vector>

namespace snell::lab::detail {

namespace {

// A read past the end throws, as OpenEXR's own file stream does.
class MemoryStream final : public OPENEXR_IMF_NAMESPACE::IStream {
 public:
  explicit MemoryStream(const std::string& bytes) : IStream("memory"), bytes_(bytes) {}
  bool read(char c[], int n) override {
    if (n < 0 || pos_ > bytes_.size() || static_cast<std::size_t>(n) > bytes_.size() - pos_)
      throw IEX_NAMESPACE::InputExc("unexpected end of file");
    std::memcpy(c, bytes_.data() + pos_, static_cast<std::size_t>(n));
    pos_ += static_cast<std::size_t>(n);
    return pos_ < bytes_.size();
  }
  std::uint64_t tellg() override { return pos_; }
  void seekg(std::uint64_t pos) override { pos_ = static_cast<std::size_t>(std::min<std::uint64_t>(pos, bytes_.size() + 1)); }

 private:
  const std::string& bytes_;
  std::size_t pos_ = 0;
};

}  // namespace

Image decodeExr(const std::string& bytes, const ImageLimit& limit) {
  // Process-wide in OpenEXR: the header's sanity check refuses larger sizes
  // before any line-offset table or tile buffer is sized from them.
  const int side = static_cast<int>(std::min<long long>(limit.maxPixels, 1 << 16));
  OPENEXR_IMF_NAMESPACE::Header::setMaxImageSize(side, side);
  OPENEXR_IMF_NAMESPACE::Header::setMaxTileSize(std::min(side, 4096), std::min(side, 4096));
  std::vector<OPENEXR_IMF_NAMESPACE::Rgba> texels;
  long long width = 0, height = 0;
  try {
    MemoryStream stream(bytes);
    OPENEXR_IMF_NAMESPACE::RgbaInputFile file(stream, /*numThreads=*/0);
    const IMATH_NAMESPACE::Box2i window = file.dataWindow();
    width = static_cast<long long>(window.max.x) - window.min.x + 1;
    height = static_cast<long long>(window.max.y) - window.min.y + 1;
    limit.check(width, height);
    texels.resize(static_cast<std::size_t>(width * height));
    file.setFrameBuffer(OPENEXR_IMF_NAMESPACE::ComputeBasePointer(texels.data(), window), 1,
                        static_cast<std::size_t>(width));
    file.readPixels(window.min.y, window.max.y);
  } catch (const Error&) {
    throw;
  } catch (const std::bad_alloc&) {
    limit.fail("OpenEXR", "out of memory");
  } catch (const std::exception& e) {
    limit.fail("OpenEXR", e.what());
  }
  Image img(static_cast<int>(width), static_cast<int>(height));
  for (long long y = 0; y < height; ++y)
    for (long long x = 0; x < width; ++x) {
      const OPENEXR_IMF_NAMESPACE::Rgba& t = texels[static_cast<std::size_t>(y * width + x)];
      const vec3 c(static_cast<float>(t.r), static_cast<float>(t.g), static_cast<float>(t.b));
      // Radiance cannot be NaN or infinite and an environment of it would
      // turn every pixel that sees it into NaN: such a file is refused.
      if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z))
        limit.fail("OpenEXR", "texel (" + std::to_string(x) + ", " + std::to_string(y) + ") is not finite");
      // Negative values (left by some filters) are read as 0: the lab's colours are never negative.
      img.at(static_cast<int>(x), static_cast<int>(height - 1 - y)) = vec4(max(c, vec3(0.0f)), 1.0f);
    }
  return img;
}

}  // namespace snell::lab::detail
