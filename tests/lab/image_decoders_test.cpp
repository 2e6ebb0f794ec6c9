// The lab's image decoders (libspng, libjpeg-turbo, OpenEXR, stb_image's HDR
// reader) against independent decoders and known texels: stb_image's PNG and
// JPEG readers (what the lab used before) on the committed pictures and test
// images, OpenEXR files written here from known halves, JPEGs encoded here.
#include "lab/error.hpp"
#include "lab/image_io.hpp"

#include "lab_test_util.hpp"

#include <gtest/gtest.h>

// A reference only, on files known to be good (the committed pictures, the
// hand-made seeds, JPEGs encoded here): static, so it cannot clash with the
// lab's own stb_image (compiled for HDR alone).
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_NO_STDIO
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#include <stb/stb_image.h>

#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfRgbaFile.h>
#include <OpenEXR/ImfTiledRgbaFile.h>

#include <csetjmp>
#include <cstdio>
#include <jpeglib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using snell::Image;
using snell::vec4;
using snell::lab::decodeImage;
using snell::lab::ErrorKind;
using snell::lab::readImage;

namespace {

namespace fs = std::filesystem;

const std::string kSource = SNELL_SOURCE_DIR;

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> filesIn(const std::vector<std::string>& dirs, const std::string& extension) {
  std::vector<std::string> out;
  for (const std::string& d : dirs)
    for (const auto& e : fs::directory_iterator(kSource + "/" + d))
      if (e.is_regular_file() && (extension.empty() || e.path().extension() == extension)) out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

// stb_image's 8-bit RGB of a file (rows top to bottom), empty when it refuses it.
std::vector<std::uint8_t> stbDecode(const std::string& bytes, int& w, int& h) {
  int n = 0;
  stbi_uc* p = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), static_cast<int>(bytes.size()), &w,
                                     &h, &n, 3);
  if (p == nullptr) return {};
  std::vector<std::uint8_t> out(p, p + static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3);
  stbi_image_free(p);
  return out;
}

// The largest difference, in 8-bit steps, between the lab's linear decode and
// stb_image's bytes; -1 when the sizes differ. `same`: the share of equal samples.
int largestStep(const Image& lab, const std::vector<std::uint8_t>& stb, int w, int h, double* same = nullptr) {
  if (lab.width != w || lab.height != h) return -1;
  int worst = 0;
  long long equal = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        const int a = static_cast<int>(std::lround(lab.at(x, h - 1 - y)[c] * 255.0f));
        const int b = stb[(static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) * 3 + c];
        worst = std::max(worst, std::abs(a - b));
        equal += a == b;
      }
  if (same != nullptr) *same = static_cast<double>(equal) / (3.0 * w * h);
  return worst;
}

// A JPEG of `rgb` (w x h, rows top to bottom) from libjpeg-turbo's encoder;
// `scans` replaces the scan script when not empty (progressive).
std::string encodeJpeg(const std::vector<std::uint8_t>& rgb, int w, int h, int quality, bool progressive,
                       std::vector<jpeg_scan_info> scans = {}, bool fullChroma = false) {
  jpeg_compress_struct c{};
  jpeg_error_mgr errors{};
  c.err = jpeg_std_error(&errors);
  jpeg_create_compress(&c);
  unsigned char* out = nullptr;
  unsigned long size = 0;
  jpeg_mem_dest(&c, &out, &size);
  c.image_width = static_cast<JDIMENSION>(w);
  c.image_height = static_cast<JDIMENSION>(h);
  c.input_components = 3;
  c.in_color_space = JCS_RGB;
  jpeg_set_defaults(&c);
  jpeg_set_quality(&c, quality, TRUE);
  if (fullChroma) c.comp_info[0].h_samp_factor = c.comp_info[0].v_samp_factor = 1;  // 4:4:4
  if (progressive) jpeg_simple_progression(&c);
  if (!scans.empty()) {
    c.scan_info = scans.data();
    c.num_scans = static_cast<int>(scans.size());
  }
  jpeg_start_compress(&c, TRUE);
  while (c.next_scanline < c.image_height) {
    JSAMPROW row = const_cast<std::uint8_t*>(rgb.data()) + static_cast<std::size_t>(c.next_scanline) * static_cast<std::size_t>(w) * 3;
    jpeg_write_scanlines(&c, &row, 1);
  }
  jpeg_finish_compress(&c);
  jpeg_destroy_compress(&c);
  std::string bytes(reinterpret_cast<const char*>(out), size);
  std::free(out);
  return bytes;
}

std::vector<std::uint8_t> testPattern(int w, int h) {
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = &rgb[(static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) * 3];
      p[0] = static_cast<std::uint8_t>(x * 255 / (w - 1));
      p[1] = static_cast<std::uint8_t>(y * 255 / (h - 1));
      p[2] = static_cast<std::uint8_t>(((x / 8 + y / 8) % 2) * 200 + 20);
    }
  return rgb;
}

std::uint32_t crc32(const std::string& bytes) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (const char ch : bytes) {
    crc ^= static_cast<std::uint8_t>(ch);
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

// `png` with its IHDR claiming w x h, the chunk's CRC recomputed (libspng checks it).
std::string withPngSize(std::string png, std::uint32_t w, std::uint32_t h) {
  for (int k = 0; k < 4; ++k) {
    png[16 + k] = static_cast<char>(w >> (24 - 8 * k));
    png[20 + k] = static_cast<char>(h >> (24 - 8 * k));
  }
  const std::uint32_t crc = crc32(png.substr(12, 17));  // type and 13 data bytes
  for (int k = 0; k < 4; ++k) png[29 + k] = static_cast<char>(crc >> (24 - 8 * k));
  return png;
}

}  // namespace

// Every committed picture (the lab's and the gallery's, animated PNGs among
// them) and the hand-made PNG seeds: the same bytes from libspng. stb_image is
// only handed files known to be good: the mutated fuzz seeds beside them once
// broke it (tests/fuzz/README.md).
TEST(LabImageDecoders, PngGivesTheTexelsStbImageGave) {
  std::vector<std::string> files =
      filesIn({"docs/lab/bunny", "docs/lab/sphere_painting", "docs/lab/sphere_edge", "docs/gallery"}, ".png");
  for (const char* seed : {"gray.png", "rgb.png", "rgba.png"}) files.push_back(kSource + "/tests/fuzz/corpus/image_png/" + seed);
  int compared = 0;
  for (const std::string& path : files) {
    const std::string bytes = readBytes(path);
    int w = 0, h = 0;
    const std::vector<std::uint8_t> stb = stbDecode(bytes, w, h);
    ASSERT_FALSE(stb.empty()) << path << ": stb_image refuses a committed picture";
    const Image lab = decodeImage(bytes, path, /*linear=*/true);
    EXPECT_EQ(largestStep(lab, stb, w, h), 0) << path;
    ++compared;
  }
  EXPECT_GE(compared, 15);
  std::printf("%d PNGs identical\n", compared);
}

// JPEGs encoded here from the committed pictures and the JPEG seeds, decoded
// by libjpeg-turbo and by stb_image. The two differ where the standard lets
// decoders differ, in rounding: stb_image's SSE2 inverse DCT and colour
// conversion round differently from libjpeg-turbo's accurate integer ones
// (about 2 % of samples, by at most 3 steps of 255, even without chroma
// subsampling), and its triangle upsampler rounds every output with +8 where
// libjpeg-turbo alternates +8 and +7 (about 6 % with 4:2:0).
TEST(LabImageDecoders, JpegGivesTheTexelsStbImageGave) {
  int compared = 0;
  const auto compare = [&](const std::string& bytes, const std::string& name, int allowed) {
    int w = 0, h = 0;
    const std::vector<std::uint8_t> stb = stbDecode(bytes, w, h);
    ASSERT_FALSE(stb.empty()) << name;
    const Image lab = decodeImage(bytes, name, /*linear=*/true);
    double same = 0.0;
    const int step = largestStep(lab, stb, w, h, &same);
    EXPECT_GE(step, 0) << name;
    EXPECT_LE(step, allowed) << name;
    EXPECT_GE(same, 0.9) << name;
    std::printf("%s: largest difference %d/255, %.2f %% of samples identical\n", name.c_str(), step, 100.0 * same);
    ++compared;
  };
  for (const char* picture : {"docs/lab/bunny/overview.png", "docs/gallery/water_masks.png"}) {
    int w = 0, h = 0;
    const std::vector<std::uint8_t> rgb = stbDecode(readBytes(kSource + "/" + picture), w, h);
    ASSERT_FALSE(rgb.empty()) << picture;
    compare(encodeJpeg(rgb, w, h, 95, false, {}, true), std::string(picture) + " 4:4:4 q95", 3);
    compare(encodeJpeg(rgb, w, h, 85, true, {}, true), std::string(picture) + " 4:4:4 progressive", 3);
    compare(encodeJpeg(rgb, w, h, 75, false), std::string(picture) + " 4:2:0 q75", 3);
    compare(encodeJpeg(rgb, w, h, 85, true), std::string(picture) + " 4:2:0 progressive", 3);
  }
  EXPECT_EQ(compared, 8);
  // The hand-made seed (the mutated seeds beside it are not for stb_image).
  compare(readBytes(kSource + "/tests/fuzz/corpus/image_jpeg/rgb.jpg"), "rgb.jpg", 3);
  EXPECT_EQ(compared, 9);
}

// A JPEG with more scans than any encoder writes would make the decoder run
// over the image once per scan: refused. 190 scans are legal JPEG (one DC
// scan, then each AC coefficient of each component on its own).
TEST(LabImageDecoders, JpegWithTooManyScansIsRefused) {
  const int w = 64, h = 48;
  const std::vector<std::uint8_t> rgb = testPattern(w, h);
  std::vector<jpeg_scan_info> scans;
  scans.push_back(jpeg_scan_info{3, {0, 1, 2, 0}, 0, 0, 0, 0});
  for (int component = 0; component < 3; ++component)
    for (int k = 1; k <= 63; ++k) scans.push_back(jpeg_scan_info{1, {component, 0, 0, 0}, k, k, 0, 0});
  const std::string many = encodeJpeg(rgb, w, h, 90, true, scans);
  const std::string msg = labtest::errorOf([&] { decodeImage(many, "many.jpg"); }, ErrorKind::Parse);
  EXPECT_EQ(msg, "many.jpg: cannot decode JPEG: more than 100 scans (a real encoder writes about 10)");
  // The standard progressive script (10 scans) decodes, and as stb_image does.
  const Image ok = decodeImage(encodeJpeg(rgb, w, h, 90, true), "progressive.jpg", true);
  EXPECT_EQ(ok.width, w);
  EXPECT_EQ(ok.height, h);
}

// Damaged JPEGs are refused with libjpeg-turbo's reason, never shown with
// the grey blocks the library would fill in; sizes past the budget are
// refused on the header.
TEST(LabImageDecoders, JpegErrorsNameTheFileAndTheReason) {
  const int w = 64, h = 48;
  const std::string good = encodeJpeg(testPattern(w, h), w, h, 90, false);
  EXPECT_EQ(decodeImage(good, "good.jpg").width, w);
  const std::string cut = labtest::errorOf([&] { decodeImage(good.substr(0, good.size() / 2), "cut.jpg"); }, ErrorKind::Parse);
  EXPECT_EQ(cut, "cut.jpg: cannot decode JPEG: Premature end of JPEG file");
  // The frame header (SOF0) claiming 20000 x 30000.
  std::string big = good;
  const std::size_t sof = big.find("\xFF\xC0");
  ASSERT_NE(sof, std::string::npos);
  big.replace(sof + 5, 4, std::string("\x75\x30\x4E\x20", 4));
  EXPECT_EQ(labtest::errorOf([&] { decodeImage(big, "big.jpg"); }, ErrorKind::Parse),
            "big.jpg: image is 20000 x 30000 pixels; the lab reads at most 33554432 (8192 x 4096)");
  const std::string noSoi = labtest::errorOf([&] { decodeImage(std::string("\xFF\xD8\xFF\xD9", 4), "eoi.jpg"); }, ErrorKind::Parse);
  EXPECT_EQ(noSoi.rfind("eoi.jpg: cannot decode JPEG: ", 0), 0u) << noSoi;
}

TEST(LabImageDecoders, PngErrorsNameTheFileAndTheReason) {
  const labtest::TempDir dir;
  const std::string path = dir.file("good.png");
  snell::lab::writePng(path, Image(64, 64, vec4(0.5f)));
  const std::string png = readBytes(path);
  ASSERT_EQ(png.substr(12, 4), "IHDR");
  EXPECT_EQ(decodeImage(withPngSize(png, 64, 64), "same.png").width, 64);  // the CRC helper is right
  EXPECT_EQ(labtest::errorOf([&] { decodeImage(withPngSize(png, 16384, 16384), "wide.png"); }, ErrorKind::Parse),
            "wide.png: image is 16384 x 16384 pixels; the lab reads at most 33554432 (8192 x 4096)");
  const std::string huge = labtest::errorOf([&] { decodeImage(withPngSize(png, 0x7FFFFFFF, 0x7FFFFFFF), "huge.png"); }, ErrorKind::Parse);
  EXPECT_EQ(huge.rfind("huge.png: cannot decode PNG: ", 0), 0u) << huge;
  std::string badCrc = png;
  badCrc[29] = static_cast<char>(badCrc[29] ^ 1);
  EXPECT_EQ(labtest::errorOf([&] { decodeImage(badCrc, "crc.png"); }, ErrorKind::Parse),
            "crc.png: cannot decode PNG: invalid chunk checksum");
  const std::string cut = labtest::errorOf([&] { decodeImage(png.substr(0, png.size() / 2), "cut.png"); }, ErrorKind::Parse);
  EXPECT_EQ(cut.rfind("cut.png: cannot decode PNG: ", 0), 0u) << cut;
}

namespace {

void writeExr(const std::string& path, const std::vector<Imf::Rgba>& texels, const Imath::Box2i& data,
              Imf::RgbaChannels channels = Imf::WRITE_RGBA, Imf::Compression compression = Imf::ZIP_COMPRESSION) {
  Imf::Header header(Imath::Box2i({0, 0}, {7, 7}), data);
  header.compression() = compression;
  Imf::RgbaOutputFile file(path.c_str(), header, channels);
  file.setFrameBuffer(Imf::ComputeBasePointer(texels.data(), data), 1, static_cast<std::size_t>(data.max.x - data.min.x + 1));
  file.writePixels(data.max.y - data.min.y + 1);
}

}  // namespace

// Halves written by OpenEXR's own writer come back exactly, rows flipped to
// the lab's bottom-up order, whatever the compression and data window.
TEST(LabImageDecoders, ExrGivesTheHalvesItWasWritten) {
  const labtest::TempDir dir;
  const Imath::Box2i window({-2, 1}, {4, 3});  // 7 x 3, off the origin
  const int w = 7, h = 3;
  std::vector<Imf::Rgba> texels(static_cast<std::size_t>(w * h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float fx = static_cast<float>(x), fy = static_cast<float>(y);
      texels[static_cast<std::size_t>(y * w + x)] = Imf::Rgba(0.125f * fx, 1000.0f + fy, 0.0009765625f * (fx + 1.0f), 0.5f);
    }
  for (const Imf::Compression c : {Imf::NO_COMPRESSION, Imf::ZIP_COMPRESSION, Imf::PIZ_COMPRESSION, Imf::RLE_COMPRESSION}) {
    const std::string path = dir.file("t" + std::to_string(static_cast<int>(c)) + ".exr");
    writeExr(path, texels, window, Imf::WRITE_RGBA, c);
    const Image img = readImage(path);
    ASSERT_EQ(img.width, w);
    ASSERT_EQ(img.height, h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const Imf::Rgba& t = texels[static_cast<std::size_t>(y * w + x)];
        EXPECT_EQ(img.at(x, h - 1 - y), vec4(float(t.r), float(t.g), float(t.b), 1.0f)) << x << "," << y << " c" << c;
      }
  }
  {
    // Tiles of 4 x 2 over the 7 x 3 window: partial tiles at the right and bottom.
    const std::string tiled = dir.file("tiled.exr");
    Imf::Header header(Imath::Box2i({0, 0}, {7, 7}), window);
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::TiledRgbaOutputFile file(tiled.c_str(), header, Imf::WRITE_RGB, 4, 2, Imf::ONE_LEVEL);
    file.setFrameBuffer(Imf::ComputeBasePointer(texels.data(), window), 1, static_cast<std::size_t>(w));
    file.writeTiles(0, file.numXTiles() - 1, 0, file.numYTiles() - 1);
  }
  const Image tiles = readImage(dir.file("tiled.exr"));
  ASSERT_EQ(tiles.width, w);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Imf::Rgba& t = texels[static_cast<std::size_t>(y * w + x)];
      EXPECT_EQ(tiles.at(x, h - 1 - y), vec4(float(t.r), float(t.g), float(t.b), 1.0f)) << x << "," << y << " tiled";
    }
  // A luminance-only file reads as grey; luminance-chroma is refused with the reason.
  const std::string yc = dir.file("yc.exr");
  writeExr(yc, std::vector<Imf::Rgba>(64, Imf::Rgba(0.5f, 0.25f, 0.125f, 1.0f)), Imath::Box2i({0, 0}, {7, 7}), Imf::WRITE_YC);
  EXPECT_EQ(labtest::errorOf([&] { readImage(yc); }, ErrorKind::Parse),
            yc + ": cannot decode OpenEXR: channel BY is subsampled (luminance-chroma); save the image as RGB");
  const std::string grey = dir.file("y.exr");
  writeExr(grey, texels, window, Imf::WRITE_Y);
  const Image g = readImage(grey);
  EXPECT_EQ(g.at(3, 0).x, g.at(3, 0).y);
  EXPECT_EQ(g.at(3, 0).y, g.at(3, 0).z);
  EXPECT_GT(g.at(3, 0).x, 0.0f);
  // Alpha and any other channel are read past, not stored: an RGBA file with
  // more channels than the lab reads gives the same texels (above: RGBA).
  // Negative radiance reads as 0; a NaN or infinite texel is refused, named.
  std::vector<Imf::Rgba> odd = texels;
  odd[0] = Imf::Rgba(-1.0f, 0.5f, -0.0f, 1.0f);
  const std::string negative = dir.file("neg.exr");
  writeExr(negative, odd, window);
  EXPECT_EQ(readImage(negative).at(0, h - 1), vec4(0.0f, 0.5f, 0.0f, 1.0f));
  odd[w + 2].g = std::numeric_limits<float>::infinity();
  const std::string inf = dir.file("inf.exr");
  writeExr(inf, odd, window);
  EXPECT_EQ(labtest::errorOf([&] { readImage(inf); }, ErrorKind::Parse), inf + ": cannot decode OpenEXR: texel (2, 1) is not finite");
  odd[w + 2].g = std::numeric_limits<float>::quiet_NaN();
  writeExr(inf, odd, window);
  EXPECT_EQ(labtest::errorOf([&] { readImage(inf); }, ErrorKind::Parse), inf + ": cannot decode OpenEXR: texel (2, 1) is not finite");
}

TEST(LabImageDecoders, ExrErrorsNameTheFileAndTheReason) {
  const labtest::TempDir dir;
  std::vector<Imf::Rgba> texels(64, Imf::Rgba(0.5f, 0.5f, 0.5f, 1.0f));
  const std::string path = dir.file("good.exr");
  writeExr(path, texels, Imath::Box2i({0, 0}, {7, 7}));
  const std::string exr = readBytes(path);
  ASSERT_EQ(decodeImage(exr, "good.exr").width, 8);
  const std::string cut = labtest::errorOf([&] { decodeImage(exr.substr(0, exr.size() - 20), "cut.exr"); }, ErrorKind::Parse);
  EXPECT_EQ(cut.rfind("cut.exr: cannot decode OpenEXR: ", 0), 0u) << cut;
  const std::string header = labtest::errorOf([&] { decodeImage(exr.substr(0, 40), "head.exr"); }, ErrorKind::Parse);
  EXPECT_EQ(header.rfind("head.exr: cannot decode OpenEXR: ", 0), 0u) << header;
  // A data window of 40000 x 40000 is refused before any pixel is allocated.
  const std::string bigPath = dir.file("big.exr");
  {
    Imf::Header h(40000, 40000);
    Imf::RgbaOutputFile file(bigPath.c_str(), h, Imf::WRITE_RGB);  // header only: no pixels written
  }
  EXPECT_EQ(labtest::errorOf([&] { readImage(bigPath); }, ErrorKind::Parse),
            bigPath + ": image is 40000 x 40000 pixels; the lab reads at most 33554432 (8192 x 4096)");
}

// Only the four documented formats are decoded, chosen by signature: BMP,
// TGA, GIF and PNM (which the lab's stb_image once read or knew) are refused.
TEST(LabImageDecoders, OtherFormatsAreRefusedBySignature) {
  const std::string expected = ": cannot decode image: not a PNG, JPEG, OpenEXR or Radiance HDR file (the formats the lab reads)";
  for (const auto& [name, bytes] : std::vector<std::pair<std::string, std::string>>{
           {"a.gif", std::string("GIF89a\x01\x00\x01\x00\x80\x00\x00", 13)},
           {"a.ppm", "P6\n1 1\n255\n\x01\x02\x03"},
           {"a.bmp", std::string("BM\x3a\0\0\0\0\0\0\0\x36\0\0\0", 14)},
           {"a.png", "this is not a png"},
           {"empty.png", ""}})
    EXPECT_EQ(labtest::errorOf([&] { decodeImage(bytes, name); }, ErrorKind::Parse), name + expected);
}

// Every committed image regression input gives a clear parse error naming
// the file, under the new decoders too: each is a file the decoders must
// refuse, so one that decodes is a failure (a decoder that stopped checking).
TEST(LabImageDecoders, CommittedRegressionInputsGiveClearErrors) {
  int inputs = 0;
  for (const std::string& path : filesIn({"tests/fuzz/regressions/image_png", "tests/fuzz/regressions/image_jpeg",
                                          "tests/fuzz/regressions/image_exr", "tests/fuzz/regressions/image_hdr"},
                                         "")) {
    ++inputs;
    try {
      const Image img = readImage(path);
      ADD_FAILURE() << path << " decodes (" << img.width << " x " << img.height << ") instead of giving a parse error";
    } catch (const snell::lab::Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::Parse) << path;
      EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
    }
  }
  EXPECT_GE(inputs, 8);
}

// Found by fuzz_image_exr: an attribute of a type OpenEXR does not know,
// declaring 1.8 GB in a 470-byte file. OpenEXR 3.1's C++ reader allocated
// that much before reading; its C core, which the lab reads with, refuses it.
TEST(LabImageDecoders, ExrAttributeLargerThanTheFileIsRefusedBeforeAllocation) {
  const std::string path = kSource + "/tests/fuzz/regressions/image_exr/exr_opaque_attribute_size_oom.exr";
  const std::string msg = labtest::errorOf([&] { readImage(path); }, ErrorKind::Parse);
  EXPECT_EQ(msg.rfind(path + ": cannot decode OpenEXR: ", 0), 0u) << msg;
  // The same in a good file: an attribute of an unknown type declaring 1.8 GB.
  const labtest::TempDir dir;
  std::vector<Imf::Rgba> texels(64, Imf::Rgba(0.5f, 0.5f, 0.5f, 1.0f));
  writeExr(dir.file("good.exr"), texels, Imath::Box2i({0, 0}, {7, 7}));
  std::string exr = readBytes(dir.file("good.exr"));
  exr.insert(8, std::string("big\0opaque\0\x00\x00\x00\x70" "abcd", 18));
  EXPECT_EQ(labtest::errorOf([&] { decodeImage(exr, "big.exr"); }, ErrorKind::Parse),
            "big.exr: cannot decode OpenEXR: Attribute 'big', type 'opaque': Invalid size 1879048192");
}
