#include "technique.hpp"

namespace snell::lab {

std::string techniqueNames() {
  std::string s;
  for (const SnellTechniqueInfo& t : snellTechniqueTable()) s += std::string(s.empty() ? "" : ", ") + t.name;
  for (const SnellEngineModelInfo& m : snellEngineModelTable()) s += std::string(", ") + m.name;
  for (const LabRowSpec& r : multiObjectRows()) s += ", " + r.name();
  for (const LabRowSpec& r : roughRows()) s += ", " + r.name();
  return s;
}

std::vector<LabRowSpec> multiObjectRows() {
  std::vector<LabRowSpec> rows;
  for (int steps : kBevySteps) {
    LabRowSpec r;
    r.engine = &snellEngineModelTable()[SNELL_ENGINE_THREEJS];
    r.steps = steps;
    rows.push_back(r);
  }
  LabRowSpec webgpu;
  webgpu.engine = &snellEngineModelTable()[SNELL_ENGINE_THREEJS];
  webgpu.backSidesFirst = true;
  rows.push_back(webgpu);
  return rows;
}

std::vector<LabRowSpec> roughRows() {
  LabRowSpec bevy;
  bevy.engine = &snellEngineModelTable()[SNELL_ENGINE_THREEJS];
  bevy.bevyBlur = true;
  return {bevy};
}

LabRowSpec findRow(const std::string& name) {
  LabRowSpec r;
  r.technique = snellFindTechnique(name);
  if (!r.technique) r.engine = snellFindEngineModel(name);
  if (!r.technique && !r.engine)
    for (const LabRowSpec& row : multiObjectRows())
      if (row.name() == name) return row;
  if (!r.technique && !r.engine)
    for (const LabRowSpec& row : roughRows())
      if (row.name() == name) return row;
  return r;
}

}  // namespace snell::lab
