// The lab's report (stage 6 of a run): the table and its notes in Markdown, the Mayer-Assarsson comparison
// and which row to pick, and table.json.
#pragma once
#include "lab_run.hpp"

#include <cstdio>
#include <filesystem>
#include <string>

namespace snell::lab {

inline std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// The table with the notes under it (where the error comes from, the columns, the timing).
std::string markdownTable(const LabResult& r);
// Mayer & Assarsson's figures beside this scene's.
std::string targetsText(const LabResult& r);
// Which row to pick on this scene, by tier.
std::string whichToPick(const LabResult& r);

// Writes a text file; Error(Io) when it cannot (a full disk included).
void writeText(const std::filesystem::path& path, const std::string& text);
void writeJson(const std::filesystem::path& path, const LabResult& r);

}  // namespace snell::lab
