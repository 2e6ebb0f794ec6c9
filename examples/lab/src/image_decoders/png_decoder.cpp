// PNG through libspng (Debian's libspng 0.7, fuzzed in OSS-Fuzz): every
// critical chunk's CRC checked, every error a return code, limits on the image
// size and on the memory ancillary chunks may take set before anything is read.
#include "image_decoders.hpp"

#include <spng.h>

#include <algorithm>
#include <memory>
#include <vector>

namespace snell::lab::detail {

Image decodePng(const std::string& bytes, const ImageLimit& limit, bool linear) {
  const std::unique_ptr<spng_ctx, void (*)(spng_ctx*)> ctx(spng_ctx_new(0), spng_ctx_free);
  if (!ctx) limit.fail("PNG", "out of memory");
  const auto check = [&](int status) {
    if (status != 0) limit.fail("PNG", spng_strerror(status));
  };
  // A side may be as long as the texel budget (a 1-texel-high strip); the
  // product is checked on the header below, before decoding allocates.
  const auto side = static_cast<std::uint32_t>(std::min<long long>(limit.maxPixels, 0x7FFFFFFF));
  check(spng_set_image_limits(ctx.get(), side, side));
  // Text, ICC profiles and other ancillary chunks are kept in memory, some
  // of them inflated: at most 16 MiB of them, none larger than the file.
  check(spng_set_chunk_limits(ctx.get(), std::max<std::size_t>(bytes.size(), 1), std::size_t{16} << 20));
  check(spng_set_png_buffer(ctx.get(), bytes.data(), bytes.size()));
  spng_ihdr ihdr{};
  check(spng_get_ihdr(ctx.get(), &ihdr));
  limit.check(ihdr.width, ihdr.height);
  std::size_t size = 0;
  check(spng_decoded_image_size(ctx.get(), SPNG_FMT_RGBA8, &size));
  std::vector<std::uint8_t> texels(size);
  // No SPNG_DECODE_GAMMA: the bytes are taken as sRGB (or as data when
  // `linear`) whatever a gAMA chunk says, as the lab always read them;
  // 16-bit samples keep their high byte.
  check(spng_decode_image(ctx.get(), texels.data(), texels.size(), SPNG_FMT_RGBA8, 0));
  return imageFromBytes(texels.data(), static_cast<int>(ihdr.width), static_cast<int>(ihdr.height), 4, linear);
}

}  // namespace snell::lab::detail
