// The files of a parity job that runs in another process (Vulkan, WebGPU, WebGL 2): the case file's text
// and the results the device side wrote, read back with the checks every such runtime makes.
#pragma once

#include "error.hpp"
#include "parity.hpp"
#include "process.hpp"

#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace snell::gpu::detail {

// The results a parity job's device side wrote to `file`: 16 floats per case, `count` cases; `who` names
// the runtime in the error when the file holds another amount.
inline std::vector<ParityIO> readParityResults(const std::filesystem::path& file, std::size_t count,
                                               const std::string& who) {
  const std::string bytes = readTextFile(file);
  if (bytes.size() != count * sizeof(ParityIO))
    throw Error(who + " wrote " + std::to_string(bytes.size()) + " bytes of results for " + std::to_string(count) +
                " cases: " + file.string());
  std::vector<ParityIO> out(count);
  if (!bytes.empty()) std::memcpy(out.data(), bytes.data(), bytes.size());
  return out;
}

// The text of the parity case file `caseFile`, from the first of `includeDirs` that has it; `who` names
// the caller in the error when none does.
inline std::string readCaseFile(const std::vector<std::filesystem::path>& includeDirs, const std::string& caseFile,
                                const std::string& who) {
  for (const std::filesystem::path& d : includeDirs)
    if (std::filesystem::exists(d / caseFile)) return readTextFile(d / caseFile);
  throw Error(who + ": case file " + caseFile + " not found in the include directories");
}

}  // namespace snell::gpu::detail
