// Hostile input to the lab's loaders: truncated and malformed
// files, enormous counts and indices, deep nesting, file names that are not
// UTF-8, directories where files belong, writes that fail. Each must end in a
// snell::lab::Error of the documented kind whose message names the file (and
// the line, where the file has lines); never a crash, a hang or a wrong mesh.
// No GL and no ray tracing: scripts/test.sh runs these under ASan/UBSan too.
#include "lab/image_io.hpp"
#include "lab/obj_loader.hpp"
#include "lab/scene.hpp"

#include "lab_test_util.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

using snell::lab::ErrorKind;
using snell::lab::Mesh;
using snell::lab::loadObj;
using snell::lab::loadScene;
using snell::lab::parseObj;
using snell::lab::parseScene;
using snell::lab::readImage;
using snell::lab::writePng;

namespace {

const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

const char* kScene = R"({
  "camera": { "position": [0, 0, 5] },
  "object": { "mesh": { "type": "icosphere", "subdivisions": 1 } }
})";

std::string meshError(const std::string& text, ErrorKind kind, const std::string& name = "m.obj") {
  return labtest::errorOf([&] { parseObj(text, name); }, kind);
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

// tinyobjloader parses indices with atoi: 4e9 wrapped to -294967296 and the
// message blamed "vertex -294967292"; 1e20 happened to wrap into range and
// loaded as a wrong mesh. Now every index is checked against the counts of
// the file, with the line.
TEST(LabLoaderErrors, ObjEnormousIndicesNameTheLine) {
  EXPECT_EQ(meshError(std::string(kTriangle) + "f 1 2 4000000000\n", ErrorKind::Mesh),
            "m.obj:4: face vertex index 4000000000 is out of range: the file has 3 vertices");
  EXPECT_EQ(meshError(std::string(kTriangle) + "f 1 2 99999999999999999999\n", ErrorKind::Mesh),
            "m.obj:4: face vertex index 99999999999999999999 is out of range: the file has 3 vertices");
  EXPECT_EQ(meshError(std::string(kTriangle) + "f 1 2 2147483648\n", ErrorKind::Mesh),
            "m.obj:4: face vertex index 2147483648 is out of range: the file has 3 vertices");
  // Negative indices count back from the vertices defined so far, not the file's total.
  EXPECT_EQ(meshError("v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n", ErrorKind::Mesh),
            "m.obj:3: face vertex index -3 is out of range: the file has 2 vertices before this line");
  EXPECT_EQ(meshError(std::string(kTriangle) + "vn 0 0 1\nf 1//1 2//1 3//4000000000\n", ErrorKind::Mesh),
            "m.obj:5: face normal index 4000000000 is out of range: the file has 1 normal");
  EXPECT_EQ(meshError("f 1 2 3\n", ErrorKind::Mesh),
            "m.obj:1: face vertex index 1 is out of range: the file has 0 vertices");
}

TEST(LabLoaderErrors, ObjTruncatedAndMalformedLinesNameTheLine) {
  // A file cut mid-line: tinyobjloader filled the missing z with 0, silently.
  EXPECT_EQ(meshError("v 0 0 0\nv 1 0 0\nv 0 1", ErrorKind::Parse),
            "m.obj:3: vertex has 2 coordinates, expected 3 (truncated file?)");
  EXPECT_EQ(meshError(std::string(kTriangle) + "f 1 2", ErrorKind::Parse),
            "m.obj:4: face has 2 vertices, expected at least 3");
  EXPECT_EQ(meshError(std::string(kTriangle) + "vn 0 0\nf 1//1 2//1 3//1\n", ErrorKind::Parse),
            "m.obj:4: normal has 2 coordinates, expected 3 (truncated file?)");
  // Read as 0 by tinyobjloader.
  EXPECT_EQ(meshError("v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", ErrorKind::Parse),
            "m.obj:1: vertex coordinate 'nan' is not a number");
  EXPECT_EQ(meshError("v 0 0 0\nv 1 0x10 0\nv 0 1 0\nf 1 2 3\n", ErrorKind::Parse),
            "m.obj:2: vertex coordinate '0x10' is not a number");
  EXPECT_EQ(meshError("v 0 0 0\nv 1 0 0\nv 0 1e39 0\nf 1 2 3\n", ErrorKind::Mesh),
            "m.obj:3: vertex coordinate '1e39' is not a finite float");
  EXPECT_EQ(meshError(std::string(kTriangle) + "f 0 1 2\n", ErrorKind::Parse),
            "m.obj:4: face vertex index 0 in '0' (OBJ indices start at 1)");
  EXPECT_EQ(meshError(std::string(kTriangle) + "\n\nf a b c\n", ErrorKind::Parse),
            "m.obj:6: malformed face vertex 'a'");
  EXPECT_EQ(meshError(std::string(kTriangle) + "f 1/1/1/1 2 3\n", ErrorKind::Parse),
            "m.obj:4: malformed face vertex '1/1/1/1'");
  EXPECT_EQ(meshError(std::string(kTriangle) + "f /1 2 3\n", ErrorKind::Parse), "m.obj:4: malformed face vertex '/1'");
  // Binary junk (an image renamed .obj) is no OBJ: no v/vn/f line, so no faces.
  EXPECT_EQ(meshError(std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16), ErrorKind::Mesh),
            "m.obj: the OBJ file has no faces (empty mesh)");
}

TEST(LabLoaderErrors, ObjZeroTriangles) {
  for (const char* text : {"", "# only a comment\n", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "\n\n\r\n"}) {
    SCOPED_TRACE(text);
    EXPECT_EQ(meshError(text, ErrorKind::Mesh), "m.obj: the OBJ file has no faces (empty mesh)");
  }
}

// What the line check must still accept: the same tetrahedron written with
// every index form and line ending the format allows.
TEST(LabLoaderErrors, ObjLineCheckAcceptsEveryValidForm) {
  const std::string lf =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
      "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  const Mesh reference = parseObj(lf, "lf.obj");
  ASSERT_EQ(reference.triangleCount(), 4u);
  // The unit-corner tetrahedron: volume 1/6, independent of how the file spells it.
  EXPECT_NEAR(snell::lab::signedVolume(reference), 1.0 / 6.0, 1e-7);
  const std::string variants[] = {
      // CRLF line ends
      "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nv 0 0 1\r\nf 1 3 2\r\nf 1 2 4\r\nf 1 4 3\r\nf 2 3 4\r\n",
      // lone CR line ends, none after the last line
      "v 0 0 0\rv 1 0 0\rv 0 1 0\rv 0 0 1\rf 1 3 2\rf 1 2 4\rf 1 4 3\rf 2 3 4",
      // w, exponents, signs, a trailing comment; every corner form, relative indices, blanks and tabs
      "v 0 0 0 1.0\nv 1e0 0 0\nv 0 +1 0\nv 0 0 1. # a comment\n"
      "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 -1\nvn 0 -1 0\nvn -1 0 0\nvn 1 1 1\n"
      "f 1/1/1 3/3/1 2/2/1\nf -4//2 -3//2 -1//2\nf 1/1 4/3 3/2\n\tf  2//4 3//4   4//4  \n",
      // vertices after the faces that use them
      "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n",
  };
  for (const std::string& text : variants) {
    SCOPED_TRACE(text);
    const Mesh m = parseObj(text, "variant.obj");
    EXPECT_EQ(m.triangleCount(), 4u);
    EXPECT_NEAR(snell::lab::signedVolume(m), 1.0 / 6.0, 1e-7);
  }
}

// Every proper prefix of a scene file is malformed JSON: a Parse error naming
// the file and the line, never a Schema error about a half-read field.
TEST(LabLoaderErrors, TruncatedSceneIsAParseErrorWithLine) {
  const std::string text = kScene;
  for (std::size_t n = 0; n < text.size(); ++n) {
    const std::string msg = labtest::errorOf([&] { parseScene(text.substr(0, n), "cut.json"); }, ErrorKind::Parse);
    ASSERT_EQ(msg.rfind("cut.json: malformed JSON: parse error at line ", 0), 0u) << n << ": " << msg;
  }
  EXPECT_EQ(labtest::errorOf([&] { parseScene(text.substr(0, text.size() - 1), "cut.json"); }, ErrorKind::Parse)
                .rfind("cut.json: malformed JSON: parse error at line 4, column ", 0),
            0u);
  EXPECT_NO_THROW(parseScene(text, "cut.json"));
}

TEST(LabLoaderErrors, SceneNotUtf8IsAParseError) {
  const std::string msg =
      labtest::errorOf([] { parseScene("{\n\"name\": \"a\xff\"}", "latin1.json"); }, ErrorKind::Parse);
  EXPECT_EQ(msg.rfind("latin1.json: malformed JSON: parse error at line 2, column ", 0), 0u) << msg;
  EXPECT_NE(msg.find("ill-formed UTF-8 byte"), std::string::npos) << msg;
}

// The line map (json_lines.cpp) stopped recording at depth 256 but did not
// consume the deeper value, so the enclosing array's loop spun forever on a
// scene 258 arrays deep; and the message's preview of the value (json::dump)
// recursed once per level, a stack overflow (SIGSEGV) at 100,000 levels.
TEST(LabLoaderErrors, DeeplyNestedSceneValuesAreSchemaErrors) {
  const std::size_t depth = 100000;
  const std::string deep = std::string(depth, '[') + std::string(depth, ']');
  EXPECT_EQ(labtest::errorOf([&] { parseScene("{\n\"camera\": " + deep + "}", "deep.json"); }, ErrorKind::Schema),
            "deep.json:2: camera: expected an object, got [[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[...");
  const std::string scene = std::string(kScene).insert(1, "\n  \"description\": " + deep + ",");
  EXPECT_EQ(labtest::errorOf([&] { parseScene(scene, "deep.json"); }, ErrorKind::Schema).substr(0, 45),
            "deep.json:2: description: expected a string, ");
  // Past the line map's depth limit the fields after the deep value keep their
  // lines (unknown fields are reported in key order: "fovy" before "zz").
  const std::string typo = std::string(kScene).insert(1, "\n  \"zz\": [" + deep + ", {\"a\": 1}],\n  \"fovy\": 1,");
  EXPECT_EQ(labtest::errorOf([&] { parseScene(typo, "deep.json"); }, ErrorKind::Schema).substr(0, 32),
            "deep.json:3: fovy: unknown field");
  const std::string nestedObjects = [&] {
    std::string s;
    for (int i = 0; i < 300; ++i) s += "{\"k\": ";
    return s + "1" + std::string(300, '}');
  }();
  const std::string nestedScene = "{\n\"camera\": {\"position\": [0, 0, 5]},\n\"object\": " + nestedObjects + "}";
  EXPECT_EQ(labtest::errorOf([&] { parseScene(nestedScene, "deep.json"); }, ErrorKind::Schema),
            "deep.json:3: object.mesh: missing (required: an object)");
}

// An array of 100,000 paintings ran out of memory building their textures
// (4 MB each); the count is checked before any element is read.
TEST(LabLoaderErrors, EnormousPaintingCountIsASchemaError) {
  auto withPaintings = [](int n, const std::string& painting) {
    std::string list;
    for (int i = 0; i < n; ++i) list += (i ? "," : "") + painting;
    return std::string(kScene).insert(1, "\n  \"opaque\": [" + list + "],");
  };
  EXPECT_EQ(labtest::errorOf([&] { parseScene(withPaintings(100000, "{}"), "many.json"); }, ErrorKind::Schema),
            "many.json:2: opaque: expected at most 64 objects, got 100000");
  EXPECT_EQ(labtest::errorOf([&] { parseScene(withPaintings(65, "{}"), "many.json"); }, ErrorKind::Schema),
            "many.json:2: opaque: expected at most 64 objects, got 65");
  const std::string painting = "{\"type\": \"painting\", \"center\": [0, 0, -2]}";
  EXPECT_EQ(parseScene(withPaintings(64, painting), "many.json").paintings.size(), 64u);
}

// Linux file names are bytes. Loading works through them; messages carry the
// bytes as they are; the scene's default name (which goes into table.json,
// where nlohmann::json rejects bytes that are not UTF-8) escapes them.
TEST(LabLoaderErrors, FileNamesThatAreNotUtf8) {
  const labtest::TempDir dir;
  const std::string scenePath = dir.write("sc\xff\xfe.json", kScene);
  const snell::lab::Scene s = loadScene(scenePath);
  EXPECT_EQ(s.name, "sc\\xFF\\xFE");
  EXPECT_EQ(loadScene(dir.write("szen\xc3\xab.json", kScene)).name, "szen\xc3\xab");       // UTF-8 stays as it is
  EXPECT_EQ(loadScene(dir.write("o\xc0\xaf.json", kScene)).name, "o\\xC0\\xAF");           // overlong '/'
  EXPECT_EQ(loadScene(dir.write("s\xed\xa0\x80.json", kScene)).name, "s\\xED\\xA0\\x80");  // a UTF-16 surrogate
  EXPECT_EQ(loadScene(dir.write("t\xe2\x82.json", kScene)).name, "t\\xE2\\x82");           // cut sequence

  const std::string objPath = dir.write("m\xff.obj", std::string(kTriangle) + "f 1 2 3\n");
  EXPECT_EQ(loadObj(objPath).triangleCount(), 1u);
  const std::string pngPath = dir.file("i\xff.png");
  writePng(pngPath, snell::Image(3, 2, snell::vec4(1.0f)));
  EXPECT_EQ(readImage(pngPath).width, 3);

  const std::string missing = dir.file("nope\xff.json");
  EXPECT_EQ(labtest::errorOf([&] { loadScene(missing); }, ErrorKind::Io), "scene file not found: " + missing);
  const std::string missingObj = dir.file("nope\xff.obj");
  EXPECT_EQ(labtest::errorOf([&] { loadObj(missingObj); }, ErrorKind::Io), "mesh file not found: " + missingObj);
  const std::string badObj = dir.write("bad\xff.obj", std::string(kTriangle) + "f 1 2 7\n");
  EXPECT_EQ(labtest::errorOf([&] { loadObj(badObj); }, ErrorKind::Mesh),
            badObj + ":4: face vertex index 7 is out of range: the file has 3 vertices");
}

TEST(LabLoaderErrors, DirectoryInsteadOfAFile) {
  const labtest::TempDir dir;
  const std::string d = dir.file("a_directory.json");
  std::filesystem::create_directories(d);
  EXPECT_EQ(labtest::errorOf([&] { loadScene(d); }, ErrorKind::Io), "scene file is a directory: " + d);
  EXPECT_EQ(labtest::errorOf([&] { loadObj(d); }, ErrorKind::Io), "mesh file is a directory: " + d);
  EXPECT_EQ(labtest::errorOf([&] { readImage(d); }, ErrorKind::Io), "image file is a directory: " + d);
  EXPECT_EQ(labtest::errorOf([&] { writePng(d, snell::Image(2, 2)); }, ErrorKind::Io),
            "cannot write PNG file " + d + ": Is a directory");
}

// stbi_write_png ignored fwrite/fclose failures: writing to a full disk
// "succeeded" and left a truncated file.
TEST(LabLoaderErrors, PngWriteFailuresSayWhy) {
  EXPECT_EQ(labtest::errorOf([] { writePng("/dev/full", snell::Image(64, 64)); }, ErrorKind::Io),
            "cannot write PNG file /dev/full: No space left on device");
  EXPECT_EQ(labtest::errorOf([] { writePng("/nonexistent/dir/out.png", snell::Image(2, 2)); }, ErrorKind::Io),
            "cannot write PNG file /nonexistent/dir/out.png: No such file or directory");
}

TEST(LabLoaderErrors, CorruptImagesNameThePathAndTheReason) {
  const labtest::TempDir dir;
  const std::string good = dir.file("good.png");
  writePng(good, snell::Image(64, 64, snell::vec4(0.5f)));
  const std::string png = readFile(good);
  const std::string cut = dir.write("cut.png", png.substr(0, png.size() / 2));
  const std::string cutMsg = labtest::errorOf([&] { readImage(cut); }, ErrorKind::Parse);
  EXPECT_EQ(cutMsg.rfind(cut + ": cannot decode PNG: ", 0), 0u) << cutMsg;
  const std::string empty = dir.write("empty.png", "");
  EXPECT_EQ(labtest::errorOf([&] { readImage(empty); }, ErrorKind::Parse),
            empty + ": cannot decode image: not a PNG, JPEG, OpenEXR or Radiance HDR file (the formats the lab reads)");
  // A Radiance header that promises 100000 x 100000 texels and ends.
  const std::string hdr = dir.write("sky.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000 +X 100000\n\x02\x02");
  EXPECT_EQ(labtest::errorOf([&] { readImage(hdr); }, ErrorKind::Parse),
            hdr + ": image is 100000 x 100000 pixels; the lab reads at most 33554432 (8192 x 4096)");
}

// Found by fuzz_image inside Debian 12's stb_image 2.27, which decoded PNG
// and JPEG then: each input is now refused by libspng or libjpeg-turbo with
// its own reason. The Radiance ones still reach stb_image's HDR reader and
// are refused by the lab's checks in front of it: a header of width 0, and
// a run of length 0, on which stb_image loops forever.
TEST(LabLoaderErrors, ImageFuzzFindingsAreParseErrors) {
  const std::string fuzz = std::string(SNELL_SOURCE_DIR) + "/tests/fuzz/regressions/";
  const auto reason = [&](const std::string& file) {
    const std::string msg = labtest::errorOf([&] { readImage(fuzz + file); }, ErrorKind::Parse);
    EXPECT_EQ(msg.rfind(fuzz + file + ": ", 0), 0u) << msg;
    return msg.substr(fuzz.size() + file.size() + 2);
  };
  // A Huffman table (DHT) whose counts sum past 256.
  EXPECT_EQ(reason("image_jpeg/jpeg_dht_overflow.jpg"), "cannot decode JPEG: Bogus Huffman table definition");
  // Fill bytes before the start-of-image marker, which stb_image skipped.
  EXPECT_EQ(reason("image_jpeg/jpeg_fill_bytes_before_soi.jpg"),
            "cannot decode image: not a PNG, JPEG, OpenEXR or Radiance HDR file (the formats the lab reads)");
  // An IDAT claiming 1.5 GB, and a first IDAT of length 0 (with a bad CRC).
  EXPECT_EQ(reason("image_png/png_idat_length_past_end.png").rfind("cannot decode PNG: ", 0), 0u);
  EXPECT_EQ(reason("image_png/png_empty_first_idat.png").rfind("cannot decode PNG: ", 0), 0u);
  EXPECT_EQ(reason("image_hdr/hdr_zero_width.hdr"), "cannot decode image: its header says 0 x 6 pixels");
  EXPECT_EQ(reason("image_hdr/hdr_zero_run_hang.hdr"),
            "cannot decode Radiance HDR: scanline 3 has a run of length 0 (the file is truncated)");
  // stb_image takes a header line that starts with NUL for the empty line that ends the header.
  EXPECT_EQ(reason("image_hdr/hdr_nul_header_line_hang.hdr").rfind("cannot decode Radiance HDR: scanline ", 0), 0u);
  // The same on a file cut inside its first scanline: stb_image read zeros past the end and hung.
  const std::string sky = readFile(std::string(SNELL_SOURCE_DIR) + "/tests/fuzz/corpus/image_hdr/sky.hdr");
  const std::string::size_type data = sky.find("+X 8\n") + 5;
  ASSERT_NE(data, std::string::npos + 5);
  const labtest::TempDir tmp;
  const std::string cut = tmp.write("cut.hdr", sky.substr(0, data + 10));
  EXPECT_EQ(labtest::errorOf([&] { readImage(cut); }, ErrorKind::Parse),
            cut + ": cannot decode Radiance HDR: scanline 0 has a run of length 0 (the file is truncated)");
  EXPECT_EQ(readImage(std::string(SNELL_SOURCE_DIR) + "/tests/fuzz/corpus/image_hdr/sky.hdr").width, 8);
  {
    // An empty IDAT is legal PNG: a good file with one inserted before its data decodes the same.
    const labtest::TempDir pngDir;
    snell::Image ramp(4, 3);
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 4; ++x) ramp.at(x, y) = snell::vec4(0.25f * static_cast<float>(x), 0.3f * static_cast<float>(y), 0.5f, 1.0f);
    const std::string goodPath = pngDir.file("ramp.png");
    writePng(goodPath, ramp);
    std::string png = readFile(goodPath);
    const std::size_t idat = png.find("IDAT");
    ASSERT_NE(idat, std::string::npos);
    png.insert(idat - 4, std::string("\0\0\0\0IDAT\x35\xaf\x06\x1e", 12));  // length 0, type, CRC-32 of "IDAT"
    const snell::Image a = readImage(goodPath);
    const snell::Image b = readImage(pngDir.write("empty_idat.png", png));
    ASSERT_EQ(b.width, 4);
    EXPECT_EQ(a.texels, b.texels);
  }
  const snell::Image good = readImage(std::string(SNELL_SOURCE_DIR) + "/tests/fuzz/corpus/image_jpeg/rgb.jpg");
  EXPECT_EQ(good.width, 8);
  EXPECT_EQ(good.height, 6);
}

// Every line kind the lab does not use (skin weights, lines, points,
// smoothing groups, tags, materials, groups) is blanked before tinyobjloader
// sees the text, which converted a `vw` joint id of 1e30 to int (undefined
// behaviour). They change nothing, and later lines keep their numbers.
TEST(LabLoaderErrors, ObjUnusedLinesNeverReachTheParser) {
  const std::string tetra = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  const std::string hostile =
      "vw 0 1e30 0.5 6.4e11 0.5\nvw 99999999999999999999\nl 1 99999999999\np -99999999999\ns 1e99\n"
      "t a 99999999999/1/0 1 2\nusemtl x\nmtllib nowhere.mtl\no obj\ng grp\nvp 0 0\nvt 1e99 nan\n";
  const Mesh reference = parseObj(tetra, "tetra.obj");
  const Mesh m = parseObj(hostile + tetra, "hostile.obj");
  EXPECT_EQ(m.positions, reference.positions);
  EXPECT_EQ(m.indices, reference.indices);
  EXPECT_EQ(meshError(hostile + kTriangle + "f 1 2 9\n", ErrorKind::Mesh),
            "m.obj:16: face vertex index 9 is out of range: the file has 3 vertices");
  // The fuzzer's input: nothing in it is a face, and no line of it reaches tinyobjloader unchecked.
  const std::string finding = std::string(SNELL_SOURCE_DIR) + "/tests/fuzz/regressions/obj/vw_joint_id_overflow.obj";
  EXPECT_EQ(labtest::errorOf([&] { loadObj(finding); }, ErrorKind::Mesh),
            finding + ": the OBJ file has no faces (empty mesh)");
  EXPECT_EQ(meshError(readFile(finding) + "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 x\n", ErrorKind::Parse),
            "m.obj:23: malformed face vertex 'x'");
}
