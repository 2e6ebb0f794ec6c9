// The GLSL include flattener against hostile file trees: huge files,
// deep and cyclic nesting, missing files, directories, too many files or
// lines, names that are not UTF-8. Each ends in a snell::gpu::Error whose text
// names the file and line where it went wrong. No GL is involved, so this runs
// in the ASan/UBSan build of scripts/test.sh too; the compiler-message mapping
// is checked against Mesa in tests/gpu/include_flattener_test.cpp.
#include <snell/gpu/include_flattener.hpp>

#include "support/gpu_error_of.hpp"
#include "support/temp_dir.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using snell::gpu::Error;
using snell::gpu::FlatSource;
using snell::gpu::flattenGlslFile;
using snell::gpu::flattenGlslSource;
using snell_test::TempDir;

using snell_test::gpuErrorOf;

std::string str(const fs::path& p) { return p.lexically_normal().string(); }

// 50 MB in 400,000 lines: flattened in one linear pass (about 0.3 s in a
// Release build), with the root's numbering resumed after it.
TEST(IncludeFlattenerLimits, HugeFile) {
  TempDir dir("snell_flatten");
  const std::string line = "float pad(float x) { return x; } // " + std::string(88, '.') + "\n";  // 125 bytes
  std::string big;
  big.reserve(line.size() * 400000 + 64);
  for (int i = 0; i < 400000; ++i) big += line;
  big += "float lastLineOfBig() { return 2.0; }\n";
  ASSERT_GT(big.size(), 50u * 1000 * 1000);
  dir.write("big.glsl", big);
  const fs::path root = dir.write("root.comp", "#version 450 core\n#include \"big.glsl\"\nvoid main() {}\n");
  const FlatSource flat = flattenGlslFile(root, {});
  ASSERT_EQ(flat.files.size(), 2u);
  EXPECT_EQ(flat.files[1], str(dir.path() / "big.glsl"));
  // Everything of big.glsl, then the root resumes at its line 3.
  EXPECT_NE(flat.text.find("#line 1000001 1\n" + line), std::string::npos);
  EXPECT_NE(flat.text.find("float lastLineOfBig() { return 2.0; }\n#line 3 0\nvoid main() {}\n"), std::string::npos);
  EXPECT_LT(flat.text.size(), big.size() + 200);
}

// Lines of include i are numbered i * 1,000,000 + line, so a file cannot
// have a millionth line.
TEST(IncludeFlattenerLimits, MillionLinesNameTheFileAndLine) {
  TempDir dir("snell_flatten");
  const fs::path tall = dir.write("tall.glsl", std::string(999999, '\n'));
  EXPECT_EQ(flattenGlslFile(tall, {}).files.size(), 1u);  // 999,999 lines: the most that can be numbered
  const fs::path taller = dir.write("taller.glsl", std::string(1000000, '\n'));
  EXPECT_EQ(gpuErrorOf([&] { flattenGlslFile(taller, {}); }),
            taller.string() + ":1000000: more than 999999 lines; #line mapping cannot number it");
}

TEST(IncludeFlattenerLimits, DeepNestingNamesTheChain) {
  TempDir dir("snell_flatten");
  const int files = snell::gpu::kMaxIncludeDepth + 6;
  for (int i = 0; i < files; ++i)
    dir.write("f" + std::to_string(i) + ".glsl",
              "// file " + std::to_string(i) + "\n#include \"f" + std::to_string(i + 1) + ".glsl\"\n");
  // f63 is the 64th file of the chain; its include of f64 is one too many.
  std::string chain;
  for (int i = 0; i <= 64; ++i) chain += (i ? " -> " : "") + str(dir.path() / ("f" + std::to_string(i) + ".glsl"));
  EXPECT_EQ(gpuErrorOf([&] { flattenGlslFile(dir.path() / "f0.glsl", {}); }),
            str(dir.path() / "f63.glsl") + ":2: #include nesting deeper than 64 files (" + chain + ")");
}

TEST(IncludeFlattenerLimits, CyclesNameTheChainAndTheLine) {
  TempDir dir("snell_flatten");
  const fs::path a = dir.write("a.glsl", "#include \"b.glsl\"\n");
  const fs::path b = dir.write("b.glsl", "// b\n#include \"sub/../c.glsl\"\n");
  const fs::path c = dir.write("c.glsl", "\n\n#include \"a.glsl\"\n");
  EXPECT_EQ(gpuErrorOf([&] { flattenGlslFile(a, {}); }),
            "#include cycle: " + a.string() + " -> " + str(b) + " -> " + str(c) + " -> " + str(a) + " (at " + str(c) +
                ":3)");
  const fs::path self = dir.write("self.glsl", "float x;\n#include \"./self.glsl\"\n");
  EXPECT_EQ(gpuErrorOf([&] { flattenGlslFile(self, {}); }),
            "#include cycle: " + self.string() + " -> " + str(self) + " (at " + self.string() + ":2)");
}

TEST(IncludeFlattenerLimits, MissingIncludeNamesTheIncludingFileAndLine) {
  TempDir dir("snell_flatten");
  const fs::path inc = dir.path() / "inc";
  fs::create_directories(inc);
  const fs::path a = dir.write("lib/a.glsl", "// a\n\n#include \"missing.glsl\"\n");
  const fs::path root = dir.write("root.comp", "#version 450 core\n#include \"lib/a.glsl\"\n");
  EXPECT_EQ(gpuErrorOf([&] { flattenGlslFile(root, {inc}); }),
            str(a) + ":3: cannot find #include \"missing.glsl\" (looked in: " + str(dir.path() / "lib") + ", " +
                inc.string() + "); add its directory to the search paths");
  // An in-memory root without a directory looks in the search paths only.
  EXPECT_EQ(gpuErrorOf([&] { flattenGlslSource("\n#include <gone.glsl>\n", "mem.comp", {}); }),
            "mem.comp:2: cannot find #include <gone.glsl> (looked in: no directories); add its directory to the "
            "search paths");
  EXPECT_EQ(gpuErrorOf([&] { flattenGlslSource("#include \"unterminated\n", "mem.comp", {}); }),
            "mem.comp:1: malformed #include (expected #include \"file\" or #include <file>)");
  EXPECT_EQ(gpuErrorOf([&] { flattenGlslSource("#include \"\"\n", "mem.comp", {}); }),
            "mem.comp:1: malformed #include (expected #include \"file\" or #include <file>)");
}

// std::ifstream opens a directory, and reading it gave "": a directory passed
// as the shader flattened to an empty source without a word.
TEST(IncludeFlattenerLimits, DirectoriesAndMissingRoots) {
  TempDir dir("snell_flatten");
  fs::create_directories(dir.path() / "shaders.glsl");
  EXPECT_EQ(gpuErrorOf([&] { flattenGlslFile(dir.path() / "shaders.glsl", {}); }),
            "cannot open GLSL file " + (dir.path() / "shaders.glsl").string() + " (a directory)");
  EXPECT_EQ(gpuErrorOf([&] { flattenGlslFile(dir.path() / "absent.comp", {}); }),
            "cannot open GLSL file " + (dir.path() / "absent.comp").string() + " (no such file)");
  const fs::path root = dir.write("root.comp", "#include \"shaders.glsl\"\n");
  EXPECT_EQ(gpuErrorOf([&] { flattenGlslFile(root, {}); }),
            root.string() + ":1: cannot find #include \"shaders.glsl\" (looked in: " + dir.path().string() + "; " +
                str(dir.path() / "shaders.glsl") + " is not a regular file); add its directory to the search paths");
}

// Source-string numbers times 1,000,000 must stay inside a GLSL int.
TEST(IncludeFlattenerLimits, TooManyFilesNamesTheIncludeThatCrossesTheLimit) {
  TempDir dir("snell_flatten");
  std::string root;
  for (int i = 0; i < 2000; ++i) {
    const std::string name = "f" + std::to_string(i) + ".glsl";
    dir.write(name, "float f" + std::to_string(i) + ";\n");
    root += "#include \"" + name + "\"\n";
  }
  const fs::path rootPath = dir.write("root.glsl", root);
  // The root is file 1, so f1998.glsl (line 1999) is file 2000 and f1999.glsl file 2001.
  EXPECT_EQ(gpuErrorOf([&] { flattenGlslFile(rootPath, {}); }),
            rootPath.string() + ":2000: #include \"f1999.glsl\" would be file number 2001; the flattener numbers at "
                                "most 2000 files");
  dir.write("root.glsl", root.substr(0, root.rfind("#include")));
  EXPECT_EQ(flattenGlslFile(rootPath, {}).files.size(), 2000u);
}

// Linux file names are bytes: they resolve, and messages carry them unchanged.
TEST(IncludeFlattenerLimits, NamesThatAreNotUtf8) {
  TempDir dir("snell_flatten");
  const fs::path latin1 = dir.write("caf\xe9.glsl", "float cafe;\n");
  const FlatSource flat = flattenGlslSource("#include \"caf\xe9.glsl\"\n", (dir.path() / "r.comp").string(), {});
  ASSERT_EQ(flat.files.size(), 2u);
  EXPECT_EQ(flat.files[1], str(latin1));
  EXPECT_NE(flat.text.find("float cafe;"), std::string::npos);
  const fs::path root = dir.write("r\xff.comp", "\n#include \"nope\xfe.glsl\"\n");
  EXPECT_EQ(gpuErrorOf([&] { flattenGlslFile(root, {}); }),
            root.string() + ":2: cannot find #include \"nope\xfe.glsl\" (looked in: " + dir.path().string() +
                "); add its directory to the search paths");
}

}  // namespace
