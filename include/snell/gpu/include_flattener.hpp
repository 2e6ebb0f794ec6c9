// GLSL has no #include: the host splices included files into one source
// before glShaderSource, the way glslang's GL_GOOGLE_include_directive does
// offline, so the very files under glsl/ compile unchanged on both paths.
//
// The output keeps compiler messages pointing at the right file and line:
//   #version 450 core           <- hoisted: must be the first directive
//   #line 1 0                   <- root file: source-string number 0
//   ...body of the root...
//   #line 1000001 1             <- include number 1, its line 1
//   ...body of an include...
//   #line 8 0                   <- back in the root after the #include
// FlatSource::files[i] is the path of file number i. The number is put in the
// #line *source-string* field, as GLSL intends, and also in the line number
// itself (i * kFlatLineStride + line): Mesa's parser resets the source number
// to 0 for every error located on an expression (YYLLOC_DEFAULT), so
// "`x' undeclared" in an include would otherwise be blamed on the root file at
// the include's line number. mapInfoLog() decodes both into
// "path/to/file.glsl:12(5): error". (__LINE__ in an included file carries the
// offset too.)
//
// Rules:
//  - `#include "x"` looks next to the including file, then in searchPaths;
//    `#include <x>` only in searchPaths.
//  - include-once: a file already spliced in is skipped (like #pragma once).
//    Conditionals are not evaluated, so an #include inside an inactive #if
//    still counts as the file's one inclusion; guard files with #ifndef (all
//    of glsl/snell does) if that matters.
//  - a file that includes one still being expanded up the stack is a cycle
//    and an Error naming the chain; nesting deeper than kMaxIncludeDepth, more
//    than kMaxFlatFiles files and a file of kFlatLineStride lines or more are
//    Errors too, each naming the file and line where the limit was crossed.
//  - #version and #extension lines that come before any code, outside #if,
//    move to the top; `#extension GL_GOOGLE_include_directive` (and its
//    companion GL_GOOGLE_cpp_style_line_directive) are dropped: they exist for
//    glslang and Mesa rejects them.
//  - #include inside // or /* */ comments is left alone.
#pragma once

#include "error.hpp"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace snell::gpu {

struct FlatSource {
  std::string text;                // the flattened source, ready for glShaderSource
  std::vector<std::string> files;  // files[i]: path of source-string number i used in #line
};

constexpr int kMaxIncludeDepth = 64;
// Lines of file i > 0 are numbered i * kFlatLineStride + line (see above).
constexpr long kFlatLineStride = 1000000;
// Keeps i * kFlatLineStride + line inside a GLSL int.
constexpr std::size_t kMaxFlatFiles = 2000;

namespace detail {

// The whole file; false if it is not a regular file or a read fails
// (std::ifstream opens a directory, and reading it then gives "" silently).
inline bool readGlslFile(const std::filesystem::path& p, std::string& out) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(p, ec)) return false;
  std::ifstream in(p, std::ios::binary);
  if (!in) return false;
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return false;
  out = text.str();
  return true;
}

class IncludeFlattener {
 public:
  explicit IncludeFlattener(const std::vector<std::filesystem::path>& searchPaths) : searchPaths_(searchPaths) {}

  FlatSource run(const std::string& source, const std::string& name, const std::filesystem::path& dir,
                 const std::string& key, const std::vector<std::string>& defines) {
    std::string defineLines;
    for (const std::string& d : defines) {
      if (d.empty() || d.find_first_of("\r\n") != std::string::npos || d.find('\\') != std::string::npos ||
          !(std::isalpha(static_cast<unsigned char>(d[0])) || d[0] == '_'))
        throw Error(name + ": define '" + d + "' is not one line \"NAME\" or \"NAME VALUE\"");
      defineLines += "#define " + d + "\n";
    }
    expand(source, name, dir, key, 0);
    FlatSource out;
    // The defines come before the first #line, so every line number stays the file's own.
    out.text = version_ + extensions_ + defineLines + body_;
    out.files = files_;
    return out;
  }

 private:
  struct Frame {
    std::string key;   // identity: canonical path (or the name of an in-memory source)
    std::string name;  // what messages show
  };

  std::vector<std::filesystem::path> searchPaths_;
  std::vector<std::string> files_;
  std::set<std::string> done_;
  std::vector<Frame> stack_;
  std::string version_, extensions_, body_;  // output: #version first, then #extension, then the rest
  bool codeSeen_ = false;
  bool versionSeen_ = false;
  int conditionalDepth_ = 0;

  // One line, split into what the flattener cares about.
  struct LineInfo {
    bool directive = false;  // starts (outside comments) with '#'
    std::string keyword;     // include, version, extension, if, ...
    std::string rest;        // text after the keyword
    bool code = false;       // has non-comment, non-directive text
  };

  // Classifies `line` and advances the /* */ state across lines.
  static LineInfo scan(const std::string& line, bool& inBlockComment) {
    LineInfo info;
    std::size_t i = 0;
    const std::size_t n = line.size();
    bool sawToken = false;
    while (i < n) {
      if (inBlockComment) {
        std::size_t end = line.find("*/", i);
        if (end == std::string::npos) return info;
        inBlockComment = false;
        i = end + 2;
        continue;
      }
      if (line.compare(i, 2, "//") == 0) break;
      if (line.compare(i, 2, "/*") == 0) {
        inBlockComment = true;
        i += 2;
        continue;
      }
      const char c = line[i];
      if (std::isspace(static_cast<unsigned char>(c))) {
        ++i;
        continue;
      }
      if (!sawToken && c == '#') {
        info.directive = true;
        std::size_t k = i + 1;
        while (k < n && (line[k] == ' ' || line[k] == '\t')) ++k;
        std::size_t start = k;
        while (k < n && std::isalpha(static_cast<unsigned char>(line[k]))) ++k;
        info.keyword = line.substr(start, k - start);
        info.rest = line.substr(k);
        // Comments after a directive may open a block comment; keep tracking.
        for (std::size_t j = k; j < n; ++j) {
          if (line.compare(j, 2, "//") == 0) break;
          if (line.compare(j, 2, "/*") == 0) {
            std::size_t end = line.find("*/", j + 2);
            if (end == std::string::npos) {
              inBlockComment = true;
              break;
            }
            j = end + 1;
          }
        }
        return info;
      }
      sawToken = true;
      info.code = true;
      // Past the first token only comment openers matter: jump to the next '/'
      // (stepping character by character made a 50 MB file take 1.3 s).
      i = line.find('/', i + 1);
      if (i == std::string::npos) break;
    }
    return info;
  }

  static std::string lineDirective(int line, int index) {
    return "#line " + std::to_string(index * kFlatLineStride + line) + " " + std::to_string(index) + "\n";
  }

  std::string where(const std::string& file, int line) const { return file + ":" + std::to_string(line); }

  std::string chain(const std::string& last) const {
    std::string s;
    for (const Frame& f : stack_) s += f.name + " -> ";
    return s + last;
  }

  static std::string canonicalKey(const std::filesystem::path& p) {
    std::error_code ec;
    std::filesystem::path c = std::filesystem::weakly_canonical(p, ec);
    return (ec ? p.lexically_normal() : c).string();
  }

  static bool isFile(const std::filesystem::path& p) {
    std::error_code ec;
    return std::filesystem::is_regular_file(p, ec);
  }

  std::filesystem::path resolve(const std::string& target, bool quoted, const std::filesystem::path& dir,
                                const std::string& includer, int line) const {
    std::vector<std::filesystem::path> tried;
    if (quoted && !dir.empty()) tried.push_back(dir);
    for (const auto& s : searchPaths_) tried.push_back(s);
    for (const auto& base : tried) {
      std::filesystem::path p = (base / target).lexically_normal();
      if (isFile(p)) return p;
    }
    std::string looked, notFiles;
    for (const auto& base : tried) {
      looked += (looked.empty() ? "" : ", ") + base.string();
      std::error_code ec;
      const std::filesystem::path p = (base / target).lexically_normal();
      if (std::filesystem::exists(p, ec)) notFiles += "; " + p.string() + " is not a regular file";
    }
    throw Error(where(includer, line) + ": cannot find #include " + (quoted ? "\"" : "<") + target +
                (quoted ? "\"" : ">") + " (looked in: " + (looked.empty() ? "no directories" : looked) + notFiles +
                "); add its directory to the search paths");
  }

  // Parses `"x"` or `<x>` after #include.
  std::string includeTarget(const std::string& rest, bool& quoted, const std::string& file, int line) const {
    std::size_t i = rest.find_first_not_of(" \t");
    if (i != std::string::npos && (rest[i] == '"' || rest[i] == '<')) {
      const char close = rest[i] == '"' ? '"' : '>';
      std::size_t end = rest.find(close, i + 1);
      if (end != std::string::npos && end > i + 1) {
        quoted = close == '"';
        return rest.substr(i + 1, end - i - 1);
      }
    }
    throw Error(where(file, line) + ": malformed #include (expected #include \"file\" or #include <file>)");
  }

  static std::string firstWord(const std::string& s) {
    std::size_t b = s.find_first_not_of(" \t");
    if (b == std::string::npos) return {};
    std::size_t e = s.find_first_of(" \t:", b);
    return s.substr(b, e == std::string::npos ? std::string::npos : e - b);
  }

  void expand(const std::string& source, const std::string& name, const std::filesystem::path& dir,
              const std::string& key, int depth) {
    const int index = static_cast<int>(files_.size());
    files_.push_back(name);
    done_.insert(key);
    stack_.push_back(Frame{key, name});
    body_ += lineDirective(1, index);

    std::istringstream in(source);
    std::string line;
    int lineNo = 0;
    bool inBlockComment = false;
    while (std::getline(in, line)) {
      if (++lineNo >= kFlatLineStride)
        throw Error(where(name, lineNo) + ": more than " + std::to_string(kFlatLineStride - 1) +
                    " lines; #line mapping cannot number it");
      if (!line.empty() && line.back() == '\r') line.pop_back();
      const LineInfo info = scan(line, inBlockComment);
      if (info.code) codeSeen_ = true;
      if (!info.directive) {
        body_ += line;
        body_ += '\n';
        continue;
      }
      const std::string& kw = info.keyword;
      if (kw == "if" || kw == "ifdef" || kw == "ifndef") ++conditionalDepth_;
      if (kw == "endif" && conditionalDepth_ > 0) --conditionalDepth_;
      const bool hoistable = !codeSeen_ && conditionalDepth_ == 0;

      if (kw == "extension") {
        const std::string ext = firstWord(info.rest);
        if (ext == "GL_GOOGLE_include_directive" || ext == "GL_GOOGLE_cpp_style_line_directive") {
          body_ += "\n";  // dropped; the blank line keeps the numbering
          continue;
        }
      }
      // A second #version stays in place so the compiler reports it at its own line.
      if ((kw == "extension" || (kw == "version" && !versionSeen_)) && hoistable) {
        if (kw == "version") {
          versionSeen_ = true;
          version_ = line + "\n";
        } else {
          extensions_ += line + "\n";
        }
        body_ += "\n";
        continue;
      }
      if (kw != "include") {
        body_ += line + "\n";
        continue;
      }

      bool quoted = false;
      const std::string target = includeTarget(info.rest, quoted, name, lineNo);
      const std::filesystem::path path = resolve(target, quoted, dir, name, lineNo);
      const std::string childKey = canonicalKey(path);
      for (const Frame& f : stack_)
        if (f.key == childKey)
          throw Error("#include cycle: " + chain(path.string()) + " (at " + where(name, lineNo) + ")");
      if (done_.count(childKey)) {
        body_ += "\n";  // include-once
        continue;
      }
      if (depth + 1 >= kMaxIncludeDepth)
        throw Error(where(name, lineNo) + ": #include nesting deeper than " + std::to_string(kMaxIncludeDepth) +
                    " files (" + chain(path.string()) + ")");
      if (files_.size() >= kMaxFlatFiles)
        throw Error(where(name, lineNo) + ": #include \"" + target + "\" would be file number " +
                    std::to_string(files_.size() + 1) + "; the flattener numbers at most " +
                    std::to_string(kMaxFlatFiles) + " files");
      std::string text;
      if (!readGlslFile(path, text))
        throw Error(where(name, lineNo) + ": cannot read #include \"" + target + "\" (" + path.string() + ")");
      expand(text, path.string(), path.parent_path(), childKey, depth + 1);
      body_ += lineDirective(lineNo + 1, index);
    }
    stack_.pop_back();
  }
};

}  // namespace detail

// Flattens a shader held in memory. `name` labels it in messages (files[0]);
// if it has a directory part, quoted includes look there first. `defines`
// ("NAME" or "NAME VALUE", one line each) become #define lines right after the
// hoisted #version and #extension lines, before any code: the way to compile
// one file as several programs (SNELL_INTERSECT_STRATEGIES, a technique id).
inline FlatSource flattenGlslSource(const std::string& source, const std::string& name,
                                    const std::vector<std::filesystem::path>& searchPaths,
                                    const std::vector<std::string>& defines = {}) {
  const std::filesystem::path asPath(name);
  detail::IncludeFlattener f(searchPaths);
  return f.run(source, name, asPath.parent_path(), "<source> " + name, defines);
}

inline FlatSource flattenGlslFile(const std::filesystem::path& file,
                                  const std::vector<std::filesystem::path>& searchPaths,
                                  const std::vector<std::string>& defines = {}) {
  std::string text;
  if (!detail::readGlslFile(file, text)) {
    std::error_code ec;
    const char* why = !std::filesystem::exists(file, ec)        ? " (no such file)"
                      : std::filesystem::is_directory(file, ec) ? " (a directory)"
                                                                : " (unreadable)";
    throw Error("cannot open GLSL file " + file.string() + why);
  }
  std::error_code ec;
  std::filesystem::path key = std::filesystem::weakly_canonical(file, ec);
  detail::IncludeFlattener f(searchPaths);
  return f.run(text, file.string(), file.parent_path(), (ec ? file.lexically_normal() : key).string(), defines);
}

namespace detail {
// The three log location prefixes, matched by hand: std::regex costs every
// translation unit that includes this header about ten seconds of compile
// time, and matches recursively (a long run of blanks or digits overflowed
// the stack: tests/fuzz/fuzz_include_flattener). Each returns false or sets
// the parts and `end`, the index just past the prefix.
struct LogLocation {
  std::string lead, number, line, column;
  std::size_t end = 0;
};
inline std::size_t skipLogSpace(const std::string& s, std::size_t i) {
  while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
  return i;
}
// One or more digits from i: the index past them, or npos when there is none.
inline std::size_t logDigits(const std::string& s, std::size_t i) {
  std::size_t j = i;
  while (j < s.size() && s[j] >= '0' && s[j] <= '9') ++j;
  return j > i ? j : std::string::npos;
}
inline bool logCharAt(const std::string& s, std::size_t i, char c) { return i < s.size() && s[i] == c; }
// Mesa: ^(\s*)(\d+):(\d+)\((\d+)\)
inline bool matchMesa(const std::string& s, LogLocation& m) {
  const std::size_t ws = skipLogSpace(s, 0), a = logDigits(s, ws);
  if (a == std::string::npos || !logCharAt(s, a, ':')) return false;
  const std::size_t b = logDigits(s, a + 1);
  if (b == std::string::npos || !logCharAt(s, b, '(')) return false;
  const std::size_t c = logDigits(s, b + 1);
  if (c == std::string::npos || !logCharAt(s, c, ')')) return false;
  m = {s.substr(0, ws), s.substr(ws, a - ws), s.substr(a + 1, b - a - 1), s.substr(b + 1, c - b - 1), c + 1};
  return true;
}
// glslang: ^(\s*(?:ERROR|WARNING|INFO|NOTE): )(\d+):(\d+):
inline bool matchGlslang(const std::string& s, LogLocation& m) {
  const std::size_t ws = skipLogSpace(s, 0);
  for (const char* word : {"ERROR: ", "WARNING: ", "INFO: ", "NOTE: "}) {
    const std::string w(word);
    if (s.compare(ws, w.size(), w) != 0) continue;
    const std::size_t n0 = ws + w.size(), a = logDigits(s, n0);
    if (a == std::string::npos || !logCharAt(s, a, ':')) return false;
    const std::size_t b = logDigits(s, a + 1);
    if (b == std::string::npos || !logCharAt(s, b, ':')) return false;
    m = {s.substr(0, n0), s.substr(n0, a - n0), s.substr(a + 1, b - a - 1), "", b + 1};
    return true;
  }
  return false;
}
// NVIDIA: ^(\s*)(\d+)\((\d+)\) :
inline bool matchNvidia(const std::string& s, LogLocation& m) {
  const std::size_t ws = skipLogSpace(s, 0), a = logDigits(s, ws);
  if (a == std::string::npos || !logCharAt(s, a, '(')) return false;
  const std::size_t b = logDigits(s, a + 1);
  if (b == std::string::npos || s.compare(b, 3, ") :") != 0) return false;
  m = {s.substr(0, ws), s.substr(ws, a - ws), s.substr(a + 1, b - a - 1), "", b + 3};
  return true;
}
}  // namespace detail

// Rewrites the file numbers in a compiler log into paths:
//   Mesa     "0:12(5): error: ..."   -> "a/b.glsl:12(5): error: ..."
//   glslang  "ERROR: 0:12: '...'"    -> "ERROR: a/b.glsl:12: '...'"
//   NVIDIA   "0(12) : error C0000"   -> "a/b.glsl(12) : error C0000"
// A line number >= kFlatLineStride names its file itself (Mesa may report
// source 0 for it); otherwise the source number does. Locations that name no
// file of `source` are left as they are.
inline std::string mapInfoLog(const std::string& log, const FlatSource& source) {
  // (source number, line) -> "path:line" parts; false if it names no known file.
  auto locate = [&](const std::string& number, const std::string& lineText, std::string& path, std::string& line) {
    unsigned long long index = 0, n = 0;
    try {
      index = std::stoull(number);
      n = std::stoull(lineText);
    } catch (...) {
      return false;
    }
    const auto stride = static_cast<unsigned long long>(kFlatLineStride);
    if (n >= stride) {
      index = n / stride;
      n %= stride;
    }
    if (index >= source.files.size()) return false;
    path = source.files[static_cast<std::size_t>(index)];
    line = std::to_string(n);
    return true;
  };
  // The location is at the start of a line and is looked for in its first
  // kHead characters only; a line whose location prefix is longer is left as it is.
  constexpr std::size_t kHead = 256;
  std::istringstream in(log);
  std::string text, result, path, line;
  bool first = true;
  while (std::getline(in, text)) {
    detail::LogLocation m;
    std::string mapped = text;
    const std::string head = text.substr(0, kHead);
    const std::string tail = text.size() > kHead ? text.substr(kHead) : std::string();
    if (detail::matchMesa(head, m) && locate(m.number, m.line, path, line))
      mapped = m.lead + path + ":" + line + "(" + m.column + ")" + head.substr(m.end) + tail;
    else if (detail::matchGlslang(head, m) && locate(m.number, m.line, path, line))
      mapped = m.lead + path + ":" + line + ":" + head.substr(m.end) + tail;
    else if (detail::matchNvidia(head, m) && locate(m.number, m.line, path, line))
      mapped = m.lead + path + "(" + line + ") :" + head.substr(m.end) + tail;
    result += (first ? "" : "\n") + mapped;
    first = false;
  }
  if (!log.empty() && log.back() == '\n') result += "\n";
  return result;
}

}  // namespace snell::gpu
