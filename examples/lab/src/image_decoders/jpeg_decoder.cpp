// JPEG through libjpeg-turbo (Debian's libjpeg62-turbo 2.1, fuzzed in
// OSS-Fuzz). Its errors leave through longjmp from the library's error manager
// back into decodeJpeg, never through exit(); corrupt-data warnings are errors
// too (djpeg's -strict), so a damaged file is refused rather than shown with
// grey blocks. The size is checked on the header, before the decompressor
// allocates, and a progressive file may not have more scans than a real
// encoder writes (each scan re-runs the entropy decoder over the image: a few
// kilobytes of scans cost minutes otherwise).
#include "image_decoders.hpp"

#include <csetjmp>
#include <cstdio>
// jpeglib.h needs size_t and FILE declared before it.
#include <jpeglib.h>

#include <memory>
#include <vector>

namespace snell::lab::detail {

namespace {

// libjpeg-turbo's own example limit for djpeg -maxscans is 500; real
// progressive encoders write about 10.
constexpr int kMaxScans = 100;
// The decompressor's working memory beyond the output rows (a progressive
// image keeps its coefficients: 6 bytes per texel at 4:4:4).
constexpr long kMaxWorkingMemory = 1L << 30;

// Everything setjmp must find unchanged after longjmp lives behind one
// pointer taken before setjmp: no local of decodeJpeg changes between the two.
struct JpegState {
  jpeg_decompress_struct info{};
  jpeg_error_mgr errors{};
  jpeg_progress_mgr progress{};
  std::jmp_buf jump{};
  char message[JMSG_LENGTH_MAX] = {};
  std::vector<std::uint8_t> texels;
};

JpegState& stateOf(j_common_ptr info) { return *static_cast<JpegState*>(info->client_data); }

[[noreturn]] void leave(j_common_ptr info) {
  JpegState& s = stateOf(info);
  info->err->format_message(info, s.message);
  std::longjmp(s.jump, 1);
}

void onMessage(j_common_ptr info, int level) {
  if (level < 0) leave(info);  // a warning: corrupt data the library would paper over
}

void onProgress(j_common_ptr info) {
  if (info->is_decompressor == 0) return;
  const auto* d = reinterpret_cast<j_decompress_ptr>(info);
  if (d->input_scan_number > kMaxScans) {
    JpegState& s = stateOf(info);
    std::snprintf(s.message, sizeof s.message, "more than %d scans (a real encoder writes about 10)", kMaxScans);
    std::longjmp(s.jump, 1);
  }
}

}  // namespace

Image decodeJpeg(const std::string& bytes, const ImageLimit& limit, bool linear) {
  const auto state = std::make_unique<JpegState>();
  jpeg_decompress_struct& info = state->info;
  info.err = jpeg_std_error(&state->errors);
  state->errors.error_exit = leave;
  state->errors.emit_message = onMessage;
  state->errors.output_message = [](j_common_ptr) {};  // nothing goes to stderr
  info.client_data = state.get();
  if (setjmp(state->jump) != 0) {
    jpeg_destroy_decompress(&info);  // frees every pool the library allocated
    limit.fail("JPEG", state->message);
  }
  jpeg_create_decompress(&info);
  info.mem->max_memory_to_use = kMaxWorkingMemory;
  state->progress.progress_monitor = onProgress;
  info.progress = &state->progress;
  jpeg_mem_src(&info, reinterpret_cast<const unsigned char*>(bytes.data()), static_cast<unsigned long>(bytes.size()));
  jpeg_read_header(&info, TRUE);
  // From here on snell's own code may throw (the size check, out of memory):
  // the decompressor's pools are freed on that path too.
  try {
    // Checked before jpeg_start_decompress, which allocates for the size.
    limit.check(info.image_width, info.image_height);
    info.out_color_space = JCS_RGB;  // grey is widened; CMYK and YCCK are refused by the library
    info.dct_method = JDCT_ISLOW;
    jpeg_start_decompress(&info);
    const std::size_t row = static_cast<std::size_t>(info.output_width) * 3;
    state->texels.resize(row * info.output_height);
    while (info.output_scanline < info.output_height) {
      JSAMPROW rows[1] = {state->texels.data() + row * info.output_scanline};
      jpeg_read_scanlines(&info, rows, 1);
    }
    jpeg_finish_decompress(&info);
  } catch (...) {
    jpeg_destroy_decompress(&info);
    throw;
  }
  const int width = static_cast<int>(info.output_width), height = static_cast<int>(info.output_height);
  jpeg_destroy_decompress(&info);
  return imageFromBytes(state->texels.data(), width, height, 3, linear);
}

}  // namespace snell::lab::detail
