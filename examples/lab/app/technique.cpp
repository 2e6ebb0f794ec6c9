#include "technique.hpp"

namespace snell::lab {

const std::vector<TechniqueInfo>& allTechniques() {
  static const std::vector<TechniqueInfo> list = {
      {LAB_TECHNIQUE_SINGLE, "single", "single sample",
       "one depth sample behind the ray origin (GPU Gems baseline), both interfaces"},
      {LAB_TECHNIQUE_PLANE_NORMAL_0, "plane-normal-0", "normal plane, 0 it.",
       "Mayer & Assarsson normal-based plane, no refinement"},
      {LAB_TECHNIQUE_PLANE_NORMAL_1, "plane-normal-1", "normal plane, 1 it.",
       "Mayer & Assarsson normal-based plane, 1 refinement iteration"},
      {LAB_TECHNIQUE_PLANE_NORMAL_2, "plane-normal-2", "normal plane, 2 it.",
       "Mayer & Assarsson normal-based plane, 2 refinement iterations"},
      {LAB_TECHNIQUE_PLANE_DEPTH_1, "plane-depth", "depth plane, 1 it.",
       "Mayer & Assarsson depth-based plane (depth mips = the min/max pyramid), 1 iteration"},
      {LAB_TECHNIQUE_DIR, "dir", "DIR (CBS 5)",
       "Oliveira & Brauwers: conservative binary search, 5 steps, range from the pyramid"},
      {LAB_TECHNIQUE_ISR, "isr", "ISR (Wyman)",
       "Wyman 2005: distance interpolation between d_V and the per-vertex d_N"},
      {LAB_TECHNIQUE_LINEAR_MARCH, "linear-march", "linear march",
       "screen-space ray march: 32 view-space steps + 4 bisections"},
      {LAB_TECHNIQUE_DDA, "dda", "DDA march",
       "perspective-correct pixel DDA march (McGuire & Mara), up to 256 steps"},
  };
  return list;
}

const TechniqueInfo* findTechnique(const std::string& name) {
  for (const TechniqueInfo& t : allTechniques())
    if (name == t.name) return &t;
  return nullptr;
}

std::string techniqueNames() {
  std::string s;
  for (const TechniqueInfo& t : allTechniques()) s += std::string(s.empty() ? "" : ", ") + t.name;
  return s;
}

}  // namespace snell::lab
