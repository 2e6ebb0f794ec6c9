// The #include flattener, checked against the real GL compiler: an error in a
// nested include must come back as that file's path and line.
#include <snell/gpu/context.hpp>
#include <snell/gpu/include_flattener.hpp>
#include <snell/gpu/program.hpp>

#include "support/temp_dir.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using snell::gpu::Error;
using snell::gpu::FlatSource;

using snell_test::TempDir;

std::size_t count(const std::string& haystack, const std::string& needle) {
  std::size_t n = 0;
  for (std::size_t p = haystack.find(needle); p != std::string::npos; p = haystack.find(needle, p + 1)) ++n;
  return n;
}

// Compiles `flat` as a compute shader and returns the mapped error (or "").
std::string compileError(const snell::gpu::Context& ctx, const FlatSource& flat) {
  try {
    snell::gpu::Program::compute(ctx.gl(), flat);
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

const char* kMain =
    "layout(local_size_x = 1) in;\n"
    "layout(std430, binding = 0) buffer B { float v[]; };\n";

TEST(IncludeFlattener, NestedIncludesMapCompilerErrorsToFileAndLine) {
  TempDir dir;
  // root -> lib/a.glsl -> lib/sub/b.glsl -> (via search path) common.glsl
  dir.write("inc/common.glsl", "float commonValue() { return 1.0; }\n");
  const fs::path b = dir.write("src/lib/sub/b.glsl",
                               "#include <common.glsl>\n"
                               "float bValue() {\n"
                               "  return commonValue() + 2.0;\n"
                               "}\n");
  dir.write("src/lib/a.glsl",
            "/* a.glsl */\n"
            "#include \"sub/b.glsl\"\n"
            "float aValue() { return bValue() * 2.0; }\n");
  const fs::path root = dir.write("src/main.comp",
                                  "// leading comment\n"
                                  "#version 450 core\n"
                                  "#extension GL_GOOGLE_include_directive : require\n"
                                  "#include \"lib/a.glsl\"\n" +
                                      std::string(kMain) +
                                      "void main() { v[0] = aValue(); }\n");
  const std::vector<fs::path> search = {dir.path() / "inc"};
  FlatSource flat = snell::gpu::flattenGlslFile(root, search);
  ASSERT_EQ(flat.files.size(), 4u);
  EXPECT_EQ(flat.files[0], root.string());
  EXPECT_EQ(flat.files[2], b.lexically_normal().string());

  snell::gpu::Context ctx;
  EXPECT_EQ(compileError(ctx, flat), "") << flat.text;  // the clean version compiles

  // Break line 3 of b.glsl: the message must name b.glsl:3, not "0:..." or "2:3".
  dir.write("src/lib/sub/b.glsl",
            "#include <common.glsl>\n"
            "float bValue() {\n"
            "  return commonValue() + undefinedThing;\n"
            "}\n");
  flat = snell::gpu::flattenGlslFile(root, search);
  std::string err = compileError(ctx, flat);
  EXPECT_NE(err.find(b.lexically_normal().string() + ":3("), std::string::npos) << err << "\n" << flat.text;
  // Every located message must name b.glsl: Mesa reports source number 0 for
  // expression errors, which only the line-number encoding survives.
  std::istringstream lines(err);
  for (std::string l; std::getline(lines, l);)
    if (l.find("error:") != std::string::npos) {
      EXPECT_EQ(l.rfind(b.lexically_normal().string() + ":3(", 0), 0u) << l;
    }
  EXPECT_NE(err.find("compute shader"), std::string::npos) << err;
  EXPECT_NE(err.find("undefinedThing"), std::string::npos) << err;

  // An error in the root after the include: #line must resume the root's numbering.
  dir.write("src/lib/sub/b.glsl", "#include <common.glsl>\nfloat bValue() { return 2.0; }\n");
  dir.write("src/main.comp",
            "#version 450 core\n"
            "#include \"lib/a.glsl\"\n" +
                std::string(kMain) +  // lines 3-4
                "void main() { v[0] = aValue() + nope; }\n");  // line 5
  flat = snell::gpu::flattenGlslFile(root, search);
  err = compileError(ctx, flat);
  EXPECT_NE(err.find(root.string() + ":5("), std::string::npos) << err << "\n" << flat.text;
}

TEST(IncludeFlattener, VersionFirstAndGoogleExtensionDropped) {
  TempDir dir;
  dir.write("x.glsl", "float x() { return 1.0; }\n");
  const std::string src =
      "/* header comment\n"
      "   spanning lines */\n"
      "#version 450 core\n"
      "#extension GL_GOOGLE_include_directive : enable\n"
      "#extension GL_ARB_gpu_shader_int64 : enable\n"
      "#include \"x.glsl\"\n" +
      std::string(kMain) + "void main() { v[0] = x(); }\n";
  const FlatSource flat = snell::gpu::flattenGlslSource(src, (dir.path() / "shader.comp").string(), {});
  EXPECT_EQ(flat.text.rfind("#version 450 core\n#extension GL_ARB_gpu_shader_int64 : enable\n#line 1 0\n", 0), 0u)
      << flat.text;
  EXPECT_EQ(flat.text.find("GL_GOOGLE_include_directive"), std::string::npos) << flat.text;
  snell::gpu::Context ctx;
  EXPECT_EQ(compileError(ctx, flat), "");  // Mesa rejects the GOOGLE extension, so this proves it is gone
}

// Defines go after #version and #extension and before the first #line: the
// shader sees them, and an error keeps its own file's line number.
TEST(IncludeFlattener, DefinesComeAfterVersionWithoutMovingLines) {
  TempDir dir;
  const fs::path root = dir.write("d.comp",
                                  "#version 450 core\n"
                                  "#extension GL_GOOGLE_include_directive : require\n" +
                                      std::string(kMain) +             // lines 3-4
                                      "void main() { v[0] = float(VALUE) + nope; }\n");  // line 5
  const FlatSource flat = snell::gpu::flattenGlslFile(root, {}, {"VALUE 7", "FLAG"});
  EXPECT_EQ(flat.text.rfind("#version 450 core\n#define VALUE 7\n#define FLAG\n#line 1 0\n", 0), 0u) << flat.text;
  snell::gpu::Context ctx;
  const std::string err = compileError(ctx, flat);
  EXPECT_NE(err.find(root.string() + ":5("), std::string::npos) << err << "\n" << flat.text;
  EXPECT_EQ(err.find("VALUE"), std::string::npos) << err;  // VALUE is defined: only `nope` is unknown
  // A define must be one line NAME or NAME VALUE: nothing else reaches the source.
  for (const char* bad : {"", "A\nvoid f() {}", "7UP 1", "A \\"}) {
    try {
      snell::gpu::flattenGlslFile(root, {}, {bad});
      ADD_FAILURE() << "define '" << bad << "' was accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("is not one line"), std::string::npos) << e.what();
    }
  }
}

TEST(IncludeFlattener, IncludeOnce) {
  TempDir dir;
  dir.write("once.glsl", "float onceMarker() { return 1.0; }\n");
  dir.write("other.glsl", "#include \"once.glsl\"\nfloat other() { return onceMarker(); }\n");
  const std::string src = "#version 450 core\n#include \"once.glsl\"\n#include \"other.glsl\"\n#include \"./once.glsl\"\n" +
                          std::string(kMain) + "void main() { v[0] = other(); }\n";
  const FlatSource flat = snell::gpu::flattenGlslSource(src, "root.comp", {dir.path()});
  EXPECT_EQ(count(flat.text, "float onceMarker()"), 1u) << flat.text;
  EXPECT_EQ(flat.files.size(), 3u);
  snell::gpu::Context ctx;
  EXPECT_EQ(compileError(ctx, flat), "");
}

TEST(IncludeFlattener, CycleNamesTheChain) {
  TempDir dir;
  dir.write("a.glsl", "#include \"b.glsl\"\n");
  dir.write("b.glsl", "// b\n#include \"c.glsl\"\n");
  dir.write("c.glsl", "#include \"a.glsl\"\n");
  try {
    snell::gpu::flattenGlslFile(dir.path() / "a.glsl", {});
    FAIL() << "a cycle must throw";
  } catch (const Error& e) {
    const std::string msg = e.what();
    const auto a = (dir.path() / "a.glsl").string(), b = (dir.path() / "b.glsl").string(),
               c = (dir.path() / "c.glsl").string();
    EXPECT_NE(msg.find(a + " -> " + b + " -> " + c + " -> " + a), std::string::npos) << msg;
    EXPECT_NE(msg.find("cycle"), std::string::npos) << msg;
  }
}

TEST(IncludeFlattener, MissingFileNamesIncluderAndLine) {
  TempDir dir;
  const fs::path root = dir.write("root.glsl", "#version 450 core\n\n// fine\n  #  include \"nope/missing.glsl\"\n");
  try {
    snell::gpu::flattenGlslFile(root, {dir.path() / "inc"});
    FAIL() << "a missing include must throw";
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(root.string() + ":4:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("nope/missing.glsl"), std::string::npos) << msg;
    EXPECT_NE(msg.find((dir.path() / "inc").string()), std::string::npos) << msg;  // where it looked
  }
  // <...> does not look next to the includer.
  dir.write("beside.glsl", "float beside() { return 1.0; }\n");
  EXPECT_THROW(snell::gpu::flattenGlslSource("#include <beside.glsl>\n", (dir.path() / "r.glsl").string(), {}), Error);
  EXPECT_NO_THROW(snell::gpu::flattenGlslSource("#include \"beside.glsl\"\n", (dir.path() / "r.glsl").string(), {}));
  EXPECT_THROW(snell::gpu::flattenGlslSource("#include beside.glsl\n", "r.glsl", {dir.path()}), Error);
}

TEST(IncludeFlattener, DepthLimit) {
  TempDir dir;
  auto chain = [&](int files) {
    for (int i = 0; i < files; ++i) {
      const std::string next = i + 1 < files ? "#include \"f" + std::to_string(i + 1) + ".glsl\"\n" : "";
      dir.write("f" + std::to_string(i) + ".glsl", next + "float f" + std::to_string(i) + "() { return 1.0; }\n");
    }
  };
  chain(snell::gpu::kMaxIncludeDepth);  // exactly at the limit: fine
  EXPECT_EQ(snell::gpu::flattenGlslFile(dir.path() / "f0.glsl", {}).files.size(),
            static_cast<std::size_t>(snell::gpu::kMaxIncludeDepth));
  chain(snell::gpu::kMaxIncludeDepth + 6);
  try {
    snell::gpu::flattenGlslFile(dir.path() / "f0.glsl", {});
    FAIL() << "a chain deeper than the limit must throw";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("deeper than 64"), std::string::npos) << e.what();
  }
}

TEST(IncludeFlattener, IncludesInCommentsAreNotExpanded) {
  const std::string src =
      "#version 450 core\n"
      "// #include \"missing1.glsl\"\n"
      "/* a block\n"
      "#include \"missing2.glsl\"\n"
      "*/\n"
      "/* one line */ float y;\n";
  const FlatSource flat = snell::gpu::flattenGlslSource(src, "c.glsl", {});
  EXPECT_EQ(flat.files.size(), 1u);
  EXPECT_NE(flat.text.find("#include \"missing2.glsl\""), std::string::npos);
}

TEST(IncludeFlattener, MapInfoLogFormats) {
  FlatSource flat;
  flat.files = {"root.comp", "lib/a.glsl"};
  EXPECT_EQ(snell::gpu::mapInfoLog("1:12(5): error: `x' undeclared\n0:3(1): warning: w\n", flat),
            "lib/a.glsl:12(5): error: `x' undeclared\nroot.comp:3(1): warning: w\n");
  EXPECT_EQ(snell::gpu::mapInfoLog("ERROR: 1:7: 'y' : undeclared identifier", flat),
            "ERROR: lib/a.glsl:7: 'y' : undeclared identifier");
  EXPECT_EQ(snell::gpu::mapInfoLog("0(4) : error C1008: undefined variable", flat),
            "root.comp(4) : error C1008: undefined variable");
  // Line numbers of include i are offset by i * kFlatLineStride; that wins over a source number of 0.
  EXPECT_EQ(snell::gpu::mapInfoLog("0:1000009(3): error: `q' undeclared", flat), "lib/a.glsl:9(3): error: `q' undeclared");
  EXPECT_EQ(snell::gpu::mapInfoLog("ERROR: 1:1000002: 'r'", flat), "ERROR: lib/a.glsl:2: 'r'");
  // Unknown source numbers and ordinary text pass through.
  EXPECT_EQ(snell::gpu::mapInfoLog("7:1(1): error: z\nlinker error", flat), "7:1(1): error: z\nlinker error");
  EXPECT_EQ(snell::gpu::mapInfoLog("0:5000001(1): error: z", flat), "0:5000001(1): error: z");
}

// Found by tests/fuzz/fuzz_include_flattener (regressions/include_flattener/):
// std::regex recursed once per character of a long run of blanks or digits at
// the start of a log line and overflowed the stack. Now only a line's first
// 256 characters are matched: a long line is kept whole, mapped or not.
TEST(IncludeFlattener, MapInfoLogSurvivesHugeLines) {
  FlatSource flat;
  flat.files = {"root.comp", "lib/a.glsl"};
  const std::string blanks = std::string(1000000, ' ') + "0:1(1): error";
  EXPECT_EQ(snell::gpu::mapInfoLog(blanks, flat), blanks);
  const std::string digits = "0:" + std::string(1000000, '1') + "(1): error";
  EXPECT_EQ(snell::gpu::mapInfoLog(digits, flat), digits);
  const std::string longMessage = "1:12(5): error: " + std::string(1000000, 'x');
  EXPECT_EQ(snell::gpu::mapInfoLog(longMessage, flat), "lib/a.glsl:12(5): error: " + std::string(1000000, 'x'));
}

}  // namespace
