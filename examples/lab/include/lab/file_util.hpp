// Small file helpers with errors that name the path.
#pragma once
#include <string>

namespace snell::lab {

// Whole file as a string; Error(Io) "<what> file not found: <path>" or
// "cannot read <what> file <path>".
std::string readTextFile(const std::string& path, const std::string& what);

// `path` if absolute, else resolved against the directory of `relativeTo`
// (a file path): scene files refer to meshes and images relative to themselves.
std::string resolvePath(const std::string& path, const std::string& relativeTo);

}  // namespace snell::lab
