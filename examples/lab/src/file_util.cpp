#include "lab/file_util.hpp"

#include "lab/error.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace snell::lab {

std::string readTextFile(const std::string& path, const std::string& what) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw Error(ErrorKind::Io, what + " file not found: " + path);
  if (std::filesystem::is_directory(path, ec))
    throw Error(ErrorKind::Io, what + " file is a directory: " + path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorKind::Io, "cannot open " + what + " file " + path);
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) throw Error(ErrorKind::Io, "cannot read " + what + " file " + path);
  return s.str();
}

std::string resolvePath(const std::string& path, const std::string& relativeTo) {
  const std::filesystem::path p(path);
  if (p.is_absolute() || relativeTo.empty()) return path;
  return (std::filesystem::path(relativeTo).parent_path() / p).lexically_normal().string();
}

}  // namespace snell::lab
