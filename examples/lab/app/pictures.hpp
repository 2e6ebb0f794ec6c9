// The lab's pictures (stage 6 of a run): the panels, the overview.
#pragma once
#include "lab_run.hpp"
#include "references.hpp"

#include <snell/bridge.hpp>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace snell::lab {

// Stage 6: the pictures (ground truth, model error, a panel per technique, the overview) and the tables.
void writeOutputs(const std::filesystem::path& out, const References& refs, const std::vector<Image>& images,
                  const std::vector<Image>& rendererImages,
                  const std::string& gpuDescription, LabResult& result,
                  std::chrono::steady_clock::time_point start);

}  // namespace snell::lab
