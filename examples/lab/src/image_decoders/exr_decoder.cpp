// OpenEXR through the OpenEXR library (Debian's 3.1, fuzzed in OSS-Fuzz) from
// memory, in two passes of the same library. First its C core (OpenEXRCore,
// written for hostile files) parses every header against the file's size and
// the lab's limits; only a file it accepts reaches the C++ reader, whose 3.1
// header parser allocates an unknown attribute's declared size before reading
// it (fuzz_image_exr: 12 bytes asked for 1.8 GB). Then RgbaInputFile gives
// RGB(A), luminance and chroma files as RGBA halves: the data window is
// checked against the lab's budget before pixels are allocated, and every Iex
// exception becomes Error(Parse).
#include "image_decoders.hpp"

#include "lab/error.hpp"

#include <OpenEXR/Iex.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfRgbaFile.h>
#include <OpenEXR/openexr.h>

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

// The bytes and the first message of the core's parse.
struct CoreRead {
  const std::string& bytes;
  std::string message;
};

std::int64_t coreReadAt(exr_const_context_t, void* user, void* buffer, std::uint64_t size, std::uint64_t offset,
                        exr_stream_error_func_ptr_t) {
  const std::string& b = static_cast<CoreRead*>(user)->bytes;
  if (offset >= b.size()) return 0;
  const std::uint64_t n = std::min<std::uint64_t>(size, b.size() - offset);
  std::memcpy(buffer, b.data() + offset, static_cast<std::size_t>(n));
  return static_cast<std::int64_t>(n);
}

std::int64_t coreSize(exr_const_context_t, void* user) {
  return static_cast<std::int64_t>(static_cast<CoreRead*>(user)->bytes.size());
}

void coreError(exr_const_context_t context, exr_result_t, const char* message) {
  void* user = nullptr;
  if (exr_get_user_data(context, &user) == EXR_ERR_SUCCESS && user != nullptr) {
    std::string& kept = static_cast<CoreRead*>(user)->message;
    if (kept.empty() && message != nullptr) kept = message;
  }
}

// Error(Parse) unless OpenEXRCore parses every header of the file within the sizes.
void checkHeadersWithCore(const std::string& bytes, const ImageLimit& limit, int side, int tile) {
  CoreRead read{bytes, {}};
  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  init.user_data = &read;
  init.read_fn = coreReadAt;
  init.size_fn = coreSize;
  init.error_handler_fn = coreError;
  init.max_image_width = init.max_image_height = side;
  init.max_tile_width = init.max_tile_height = tile;
  exr_context_t context = nullptr;
  const exr_result_t status = exr_start_read(&context, limit.name.c_str(), &init);
  exr_finish(&context);
  if (status != EXR_ERR_SUCCESS)
    limit.fail("OpenEXR", read.message.empty() ? exr_get_error_code_as_string(status) : read.message);
}

}  // namespace

Image decodeExr(const std::string& bytes, const ImageLimit& limit) {
  // Process-wide in OpenEXR: the header's sanity check refuses larger sizes
  // before any line-offset table or tile buffer is sized from them.
  const int side = static_cast<int>(std::min<long long>(limit.maxPixels, 1 << 16));
  const int tile = std::min(side, 4096);
  checkHeadersWithCore(bytes, limit, side, tile);
  OPENEXR_IMF_NAMESPACE::Header::setMaxImageSize(side, side);
  OPENEXR_IMF_NAMESPACE::Header::setMaxTileSize(tile, tile);
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
