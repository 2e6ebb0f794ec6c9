// OpenEXR through OpenEXRCore, the C core of Debian's OpenEXR 3.1, which was
// written for hostile files (OSS-Fuzz runs it): every header is parsed
// against the file's size and the lab's size limits, the chunk table is
// validated (no reconstruction of a damaged one), and each chunk is unpacked
// into buffers the lab sized from the checked data window. The library's C++
// reader is not used: its 3.1 header parser allocates an unknown attribute's
// declared size before reading it (fuzz_image_exr: 1.8 GB from a 470-byte
// file, which the core refuses).
//
// Read: the first part of a file, scan lines or tiles (the full-resolution
// level), half or float channels R, G, B (missing ones read as 0) or Y alone
// (grey). Refused with a reason: deep data, integer R, G, B or Y, any
// subsampled (luminance-chroma) channel, files with none of R, G, B, Y.
#include "image_decoders.hpp"

#include <OpenEXR/openexr.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace snell::lab::detail {

namespace {

struct Source {
  const std::string& bytes;
  std::string message;  // the core's first error message
};

std::int64_t readAt(exr_const_context_t, void* user, void* buffer, std::uint64_t size, std::uint64_t offset,
                    exr_stream_error_func_ptr_t) {
  const std::string& b = static_cast<Source*>(user)->bytes;
  if (offset >= b.size()) return 0;
  const std::uint64_t n = std::min<std::uint64_t>(size, b.size() - offset);
  std::memcpy(buffer, b.data() + offset, static_cast<std::size_t>(n));
  return static_cast<std::int64_t>(n);
}

std::int64_t sizeOf(exr_const_context_t, void* user) {
  return static_cast<std::int64_t>(static_cast<Source*>(user)->bytes.size());
}

void keepMessage(exr_const_context_t context, exr_result_t, const char* message) {
  void* user = nullptr;
  if (exr_get_user_data(context, &user) == EXR_ERR_SUCCESS && user != nullptr && message != nullptr) {
    std::string& kept = static_cast<Source*>(user)->message;
    if (kept.empty()) kept = message;
  }
}

// Owns the context and the decoding pipeline: both are released on every path.
struct Reader {
  Source source;
  exr_context_t context = nullptr;
  exr_decode_pipeline_t pipeline{};
  bool pipelineLive = false;
  const ImageLimit& limit;

  Reader(const std::string& bytes, const ImageLimit& l) : source{bytes, {}}, limit(l) {}
  ~Reader() {
    if (pipelineLive) exr_decoding_destroy(context, &pipeline);
    exr_finish(&context);
  }
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  void check(exr_result_t status) {
    if (status != EXR_ERR_SUCCESS)
      limit.fail("OpenEXR", source.message.empty() ? exr_get_error_code_as_string(status) : source.message);
  }
};

// The lab's plane of a channel (0, 1, 2 for R, G, B; 3 for Y), -1 for others.
int planeOf(const char* name) {
  if (std::strcmp(name, "R") == 0) return 0;
  if (std::strcmp(name, "G") == 0) return 1;
  if (std::strcmp(name, "B") == 0) return 2;
  if (std::strcmp(name, "Y") == 0) return 3;
  return -1;
}

}  // namespace

Image decodeExr(const std::string& bytes, const ImageLimit& limit) {
  Reader r(bytes, limit);
  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  init.user_data = &r.source;
  init.read_fn = readAt;
  init.size_fn = sizeOf;
  init.error_handler_fn = keepMessage;
  init.max_image_width = init.max_image_height = static_cast<int>(std::min<long long>(limit.maxPixels, 1 << 16));
  init.max_tile_width = init.max_tile_height = 4096;
  init.flags = EXR_CONTEXT_FLAG_DISABLE_CHUNK_RECONSTRUCTION;
  r.check(exr_start_read(&r.context, limit.name.c_str(), &init));

  exr_storage_t storage{};
  r.check(exr_get_storage(r.context, 0, &storage));
  if (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED)
    limit.fail("OpenEXR", "deep data is not an image the lab can read");
  exr_attr_box2i_t window{};
  r.check(exr_get_data_window(r.context, 0, &window));
  const long long width = static_cast<long long>(window.max.x) - window.min.x + 1;
  const long long height = static_cast<long long>(window.max.y) - window.min.y + 1;
  limit.check(width, height);
  const exr_attr_chlist_t* channels = nullptr;
  r.check(exr_get_channels(r.context, 0, &channels));
  bool present[4] = {false, false, false, false};
  for (int i = 0; i < channels->num_channels; ++i) {
    const exr_attr_chlist_entry_t& c = channels->entries[i];
    // Any subsampled channel: its chroma would be lost or misplaced.
    if (c.x_sampling != 1 || c.y_sampling != 1)
      limit.fail("OpenEXR", std::string("channel ") + c.name.str + " is subsampled (luminance-chroma); save the image as RGB");
    const int plane = planeOf(c.name.str);
    if (plane < 0) continue;
    if (c.pixel_type == EXR_PIXEL_UINT)
      limit.fail("OpenEXR", std::string("channel ") + c.name.str + " holds integers, not radiance");
    present[plane] = true;
  }
  const bool grey = !present[0] && !present[1] && !present[2];
  if (grey && !present[3]) limit.fail("OpenEXR", "no R, G, B or Y channel");

  // One float plane per channel read, rows top to bottom as in the file.
  const std::size_t texels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  std::vector<float> planes[4];
  // Every other channel is decoded into one scratch plane: OpenEXR 3.1.5's
  // core crashes in exr_decoding_run on a channel whose output pointer is
  // left null, which its documentation says skips the channel.
  std::vector<float> scratch;
  for (int p = 0; p < 4; ++p)
    if (present[p] && (grey == (p == 3))) planes[p].assign(texels, 0.0f);

  // Decodes one chunk whose top-left texel is (x0, y0) in the data window.
  const auto decode = [&](const exr_chunk_info_t& chunk, long long x0, long long y0) {
    if (chunk.width <= 0 || chunk.height <= 0 || x0 < 0 || y0 < 0 || x0 + chunk.width > width || y0 + chunk.height > height)
      limit.fail("OpenEXR", "a chunk lies outside the data window");
    if (!r.pipelineLive) {
      r.check(exr_decoding_initialize(r.context, 0, &chunk, &r.pipeline));
      r.pipelineLive = true;
    } else {
      r.check(exr_decoding_update(r.context, 0, &chunk, &r.pipeline));
    }
    for (int i = 0; i < r.pipeline.channel_count; ++i) {
      exr_coding_channel_info_t& c = r.pipeline.channels[i];
      const int plane = planeOf(c.channel_name);
      std::vector<float>& target = plane < 0 || planes[plane].empty() ? scratch : planes[plane];
      if (target.empty()) target.assign(texels, 0.0f);
      c.decode_to_ptr = reinterpret_cast<std::uint8_t*>(target.data() + static_cast<std::size_t>(y0 * width + x0));
      c.user_pixel_stride = static_cast<std::int32_t>(sizeof(float));
      c.user_line_stride = static_cast<std::int32_t>(width * static_cast<long long>(sizeof(float)));
      c.user_bytes_per_element = static_cast<std::int16_t>(sizeof(float));
      c.user_data_type = EXR_PIXEL_FLOAT;
    }
    r.check(exr_decoding_choose_default_routines(r.context, 0, &r.pipeline));
    r.check(exr_decoding_run(r.context, 0, &r.pipeline));
  };

  if (storage == EXR_STORAGE_SCANLINE) {
    std::int32_t lines = 0;
    r.check(exr_get_scanlines_per_chunk(r.context, 0, &lines));
    if (lines <= 0) limit.fail("OpenEXR", "no scan lines per chunk");
    for (long long y = window.min.y; y <= window.max.y; y += lines) {
      exr_chunk_info_t chunk{};
      r.check(exr_read_scanline_chunk_info(r.context, 0, static_cast<int>(y), &chunk));
      decode(chunk, 0, static_cast<long long>(chunk.start_y) - window.min.y);
    }
  } else {
    std::uint32_t tileW = 0, tileH = 0;
    exr_tile_level_mode_t levels{};
    exr_tile_round_mode_t rounding{};
    r.check(exr_get_tile_descriptor(r.context, 0, &tileW, &tileH, &levels, &rounding));
    if (tileW == 0 || tileH == 0) limit.fail("OpenEXR", "tiles of size 0");
    const long long across = (width + tileW - 1) / tileW, down = (height + tileH - 1) / tileH;
    for (long long ty = 0; ty < down; ++ty)
      for (long long tx = 0; tx < across; ++tx) {
        exr_chunk_info_t chunk{};
        r.check(exr_read_tile_chunk_info(r.context, 0, static_cast<int>(tx), static_cast<int>(ty), 0, 0, &chunk));
        decode(chunk, tx * tileW, ty * tileH);
      }
  }

  Image img(static_cast<int>(width), static_cast<int>(height));
  for (long long y = 0; y < height; ++y)
    for (long long x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * width + x);
      vec3 c = grey ? vec3(planes[3][i])
                    : vec3(planes[0].empty() ? 0.0f : planes[0][i], planes[1].empty() ? 0.0f : planes[1][i],
                           planes[2].empty() ? 0.0f : planes[2][i]);
      // Radiance cannot be NaN or infinite, and an environment of it would
      // turn every pixel that sees it into NaN: such a file is refused.
      if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z))
        limit.fail("OpenEXR", "texel (" + std::to_string(x) + ", " + std::to_string(y) + ") is not finite");
      // Negative values (left by some filters) are read as 0: the lab's colours are never negative.
      img.at(static_cast<int>(x), static_cast<int>(height - 1 - y)) = vec4(max(c, vec3(0.0f)), 1.0f);
    }
  return img;
}

}  // namespace snell::lab::detail
