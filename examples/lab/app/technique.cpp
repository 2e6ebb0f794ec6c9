#include "technique.hpp"

namespace snell::lab {

std::string techniqueNames() {
  std::string s;
  for (const SnellTechniqueInfo& t : snellTechniqueTable()) s += std::string(s.empty() ? "" : ", ") + t.name;
  for (const SnellEngineModelInfo& m : snellEngineModelTable()) s += std::string(", ") + m.name;
  for (const LabRowSpec& r : bevyStepRows()) s += ", " + r.name();
  return s;
}

std::vector<LabRowSpec> bevyStepRows() {
  std::vector<LabRowSpec> rows;
  for (int steps : kBevySteps) {
    LabRowSpec r;
    r.engine = &snellEngineModelTable()[SNELL_ENGINE_THREEJS];
    r.steps = steps;
    rows.push_back(r);
  }
  return rows;
}

LabRowSpec findRow(const std::string& name) {
  LabRowSpec r;
  r.technique = snellFindTechnique(name);
  if (!r.technique) r.engine = snellFindEngineModel(name);
  if (!r.technique && !r.engine)
    for (const LabRowSpec& steps : bevyStepRows())
      if (steps.name() == name) return steps;
  return r;
}

}  // namespace snell::lab
