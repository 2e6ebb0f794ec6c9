// Errors of the lab core. Every failure the user can cause (a missing file, a
// malformed scene, a bad mesh) is a snell::lab::Error whose message names the
// file and, for scene files, the field and the line. The kind maps to the
// command-line exit code, so scripts can tell "file not found" from "bad file".
#pragma once
#include <stdexcept>
#include <string>

namespace snell::lab {

enum class ErrorKind {
  Io,      // a file is missing or cannot be read/written (exit code 3)
  Parse,   // a file is not well-formed JSON/OBJ/image (exit code 4)
  Schema,  // a scene file is well-formed but a field is wrong (exit code 4)
  Mesh,    // a mesh is empty or degenerate (exit code 4)
  Render,  // the tracer failed (Embree error) (exit code 5)
  Usage,   // what was asked cannot be done as asked (a frame larger than the memory budget) (exit code 2)
};

class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  ErrorKind kind() const { return kind_; }

 private:
  ErrorKind kind_;
};

// The process exit code the lab uses for an error of this kind.
inline int exitCode(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::Io: return 3;
    case ErrorKind::Parse:
    case ErrorKind::Schema:
    case ErrorKind::Mesh: return 4;
    case ErrorKind::Render: return 5;
    case ErrorKind::Usage: return 2;
  }
  return 1;
}

}  // namespace snell::lab
