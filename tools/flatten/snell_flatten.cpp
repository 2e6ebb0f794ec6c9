// snell-flatten: one self-contained GLSL file from a shader that #includes
// snell (or anything else), for engines that cannot resolve includes
// (three.js ShaderMaterial, Godot, Unity ShaderLab, plain glShaderSource).
//
//   snell-flatten [-I DIR]... [--no-line] [--strip-comments] [-o OUT] FILE
//
// The includes are spliced by snell::gpu::flattenGlslFile (the same code the
// GPU runner and the tests use): include-once, cycles and missing files are
// errors naming the file and line, #version and #extension lines move to the
// top, and the GL_GOOGLE_include_directive line is dropped (Mesa rejects it).
// The GLSL tree snell-flatten was installed with (or built from) is always on
// the include path, after any -I.
#include <snell/gpu/include_flattener.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

const char* kUsage =
    "usage: snell-flatten [-I DIR]... [--no-line] [--strip-comments] [-o OUT] FILE\n"
    "  Writes FILE with every #include spliced in (to OUT, or to standard output).\n"
    "  -I DIR            search DIR for #include \"...\" and <...> (in order; snell's own\n"
    "                    GLSL tree is searched last)\n"
    "  --no-line         leave out the #line directives (they map compiler messages back\n"
    "                    to the original files, but some engines renumber lines)\n"
    "  --strip-comments  leave out // and /* */ comments and blank runs (about 60% of snell)\n"
    "  -o OUT            write to OUT instead of standard output\n";

// snell's GLSL tree: share/snell/glsl next to an installed binary, else the
// source tree this binary was built from.
std::filesystem::path snellGlslDir(const char* argv0) {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::canonical("/proc/self/exe", ec);
  const std::filesystem::path base = ec ? std::filesystem::path(argv0).parent_path() : exe.parent_path();
  const std::filesystem::path installed = base.parent_path() / "share" / "snell" / "glsl";
  if (std::filesystem::is_directory(installed / "snell", ec)) return installed;
  return SNELL_FLATTEN_SOURCE_GLSL_DIR;
}

// Drops comments (GLSL has no string literals, so // and /* always start one),
// trailing blanks and runs of blank lines; a line that held only a comment goes too.
std::string stripComments(const std::string& text) {
  std::string out, line;
  bool inBlock = false;
  bool lastBlank = true;
  std::istringstream in(text);
  while (std::getline(in, line)) {
    std::string kept;
    bool hadComment = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
      if (inBlock) {
        if (line.compare(i, 2, "*/") == 0) {
          inBlock = false;
          ++i;
          kept += ' ';
        }
        continue;
      }
      if (line.compare(i, 2, "//") == 0) {
        hadComment = true;
        break;
      }
      if (line.compare(i, 2, "/*") == 0) {
        inBlock = hadComment = true;
        ++i;
        continue;
      }
      kept += line[i];
    }
    if (inBlock) hadComment = true;
    while (!kept.empty() && (kept.back() == ' ' || kept.back() == '\t' || kept.back() == '\r')) kept.pop_back();
    const bool blank = kept.find_first_not_of(" \t") == std::string::npos;
    if (blank && (hadComment || lastBlank)) continue;
    out += kept;
    out += '\n';
    lastBlank = blank;
  }
  return out;
}

std::string dropLineDirectives(const std::string& text) {
  std::string out, line;
  std::istringstream in(text);
  while (std::getline(in, line))
    if (line.rfind("#line ", 0) != 0) out += line + '\n';
  return out;
}

int fail(const std::string& message) {
  std::cerr << "snell-flatten: " << message << '\n';
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::filesystem::path> searchPaths;
  std::string input, output;
  bool noLine = false, strip = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-h" || a == "--help") {
      std::cout << kUsage;
      return 0;
    } else if (a == "--no-line") {
      noLine = true;
    } else if (a == "--strip-comments") {
      strip = true;
    } else if (a == "-I" || a == "-o") {
      if (i + 1 >= argc) return fail(a + " needs a value\n" + kUsage);
      if (a == "-I") {
        searchPaths.emplace_back(argv[++i]);
      } else {
        output = argv[++i];
      }
    } else if (a.rfind("-I", 0) == 0) {
      searchPaths.emplace_back(a.substr(2));
    } else if (!a.empty() && a[0] == '-') {
      return fail("unknown option '" + a + "'\n" + kUsage);
    } else if (!input.empty()) {
      return fail("one input file only (got '" + input + "' and '" + a + "')\n" + kUsage);
    } else {
      input = a;
    }
  }
  if (input.empty()) return fail(std::string("no input file\n") + kUsage);
  searchPaths.push_back(snellGlslDir(argv[0]));
  std::string text;
  try {
    text = snell::gpu::flattenGlslFile(input, searchPaths).text;
  } catch (const snell::gpu::Error& e) {
    return fail(e.what());
  }
  if (noLine) text = dropLineDirectives(text);
  if (strip) text = stripComments(text);
  if (output.empty()) {
    std::cout << text;
    return std::cout.good() ? 0 : fail("cannot write to standard output");
  }
  std::ofstream out(output, std::ios::binary);
  out << text;
  out.close();
  if (!out) return fail("cannot write " + output + ": " + std::strerror(errno));
  return 0;
}
