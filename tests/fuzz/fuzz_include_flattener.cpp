// libFuzzer target: snell::gpu::flattenGlslSource and mapInfoLog.
//
// The input is split into "files" by lines that read exactly "@@@": part 0 is
// the root source (in memory, named <tmp>/root.glsl so quoted includes look
// next to it), parts 1..8 are written to a per-process temp dir as
//   a.glsl b.glsl c.glsl d.glsl sub/e.glsl sub/f.glsl sub/g.glsl sub/h.glsl
// (a slot without a part is deleted). The search paths are <tmp> and <tmp>/sub.
// The only exception allowed out of the flattener is snell::gpu::Error;
// anything else (another exception type, a crash, a sanitizer report) is a bug.
// The flattened result is then fed to mapInfoLog as a compiler log, with the
// root text as the log too (hostile "0:12(3):" lines), and the result must be
// what the std::regex version that mapInfoLog replaced (to save every GPU
// translation unit its compile time) gives: an oracle, here only.
#include <snell/gpu/include_flattener.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// mapInfoLog as it was written with std::regex (patterns on the first 256
// characters of each line).
std::string regexMapInfoLog(const std::string& log, const snell::gpu::FlatSource& source) {
  static const std::regex mesa(R"(^(\s*)(\d+):(\d+)\((\d+)\))");
  static const std::regex glslang(R"(^(\s*(?:ERROR|WARNING|INFO|NOTE): )(\d+):(\d+):)");
  static const std::regex nvidia(R"(^(\s*)(\d+)\((\d+)\) :)");
  auto locate = [&](const std::string& number, const std::string& lineText, std::string& path, std::string& line) {
    unsigned long long index = 0, n = 0;
    try {
      index = std::stoull(number);
      n = std::stoull(lineText);
    } catch (...) {
      return false;
    }
    const auto stride = static_cast<unsigned long long>(snell::gpu::kFlatLineStride);
    if (n >= stride) {
      index = n / stride;
      n %= stride;
    }
    if (index >= source.files.size()) return false;
    path = source.files[static_cast<std::size_t>(index)];
    line = std::to_string(n);
    return true;
  };
  std::istringstream in(log);
  std::string text, result, path, line;
  bool first = true;
  while (std::getline(in, text)) {
    std::smatch m;
    std::string mapped = text;
    const std::string head = text.substr(0, 256);
    const std::string tail = text.size() > 256 ? text.substr(256) : std::string();
    if (std::regex_search(head, m, mesa) && locate(m[2].str(), m[3].str(), path, line))
      mapped = m[1].str() + path + ":" + line + "(" + m[4].str() + ")" + m.suffix().str() + tail;
    else if (std::regex_search(head, m, glslang) && locate(m[2].str(), m[3].str(), path, line))
      mapped = m[1].str() + path + ":" + line + ":" + m.suffix().str() + tail;
    else if (std::regex_search(head, m, nvidia) && locate(m[2].str(), m[3].str(), path, line))
      mapped = m[1].str() + path + "(" + line + ") :" + m.suffix().str() + tail;
    result += (first ? "" : "\n") + mapped;
    first = false;
  }
  if (!log.empty() && log.back() == '\n') result += "\n";
  return result;
}

const char* const kSlots[] = {"a.glsl", "b.glsl", "c.glsl", "d.glsl",
                              "sub/e.glsl", "sub/f.glsl", "sub/g.glsl", "sub/h.glsl"};
constexpr std::size_t kSlotCount = sizeof(kSlots) / sizeof(kSlots[0]);

const fs::path& tempDir() {
  static const fs::path dir = [] {
    std::string templ = (fs::temp_directory_path() / "snell-fuzz-flatten-XXXXXX").string();
    if (!mkdtemp(templ.data())) std::abort();
    fs::create_directories(fs::path(templ) / "sub");
    return fs::path(templ);
  }();
  return dir;
}

// Holds its own copy of the path: made after tempDir()'s static, it is
// destroyed before it (the first version read the destroyed path at exit,
// which libFuzzer's fork mode reported as a crash of every job).
struct Cleanup {
  fs::path dir;
  ~Cleanup() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

std::vector<std::string> split(const std::string& data) {
  std::vector<std::string> parts(1);
  std::size_t pos = 0;
  while (pos <= data.size()) {
    std::size_t eol = data.find('\n', pos);
    const std::size_t end = eol == std::string::npos ? data.size() : eol;
    const std::string line = data.substr(pos, end - pos);
    if (line == "@@@") {
      parts.emplace_back();
    } else {
      parts.back() += line;
      if (eol != std::string::npos) parts.back() += '\n';
    }
    if (eol == std::string::npos) break;
    pos = eol + 1;
  }
  return parts;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const fs::path& dir = tempDir();
  static const Cleanup cleanup{dir};
  const std::vector<std::string> parts = split(std::string(reinterpret_cast<const char*>(data), size));
  // Last contents per slot (-1 char: absent): files are rewritten only when they change.
  static std::vector<std::string> last(kSlotCount, std::string(1, '\xff') + "absent");
  for (std::size_t i = 0; i < kSlotCount; ++i) {
    const fs::path p = dir / kSlots[i];
    const std::string want = i + 1 < parts.size() ? parts[i + 1] : std::string(1, '\xff') + "absent";
    if (want == last[i]) continue;
    last[i] = want;
    if (i + 1 < parts.size()) {
      std::ofstream out(p, std::ios::binary | std::ios::trunc);
      out << parts[i + 1];
    } else {
      std::error_code ec;
      fs::remove(p, ec);
    }
  }
  const std::vector<fs::path> search = {dir, dir / "sub"};
  snell::gpu::FlatSource flat;
  try {
    flat = snell::gpu::flattenGlslSource(parts[0], (dir / "root.glsl").string(), search);
  } catch (const snell::gpu::Error&) {
    flat.files = {"root.glsl", "a.glsl"};
  }
  // A compiler log is not adversarial in practice, but mapInfoLog must not
  // crash on any text, and must agree with the regex oracle.
  if (snell::gpu::mapInfoLog(parts[0], flat) != regexMapInfoLog(parts[0], flat)) std::abort();
  return 0;
}
