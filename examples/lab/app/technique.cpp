#include "technique.hpp"

namespace snell::lab {

std::string techniqueNames() {
  std::string s;
  for (const SnellTechniqueInfo& t : snellTechniqueTable()) s += std::string(s.empty() ? "" : ", ") + t.name;
  for (const SnellEngineModelInfo& m : snellEngineModelTable()) s += std::string(", ") + m.name;
  return s;
}

LabRowSpec findRow(const std::string& name) {
  LabRowSpec r;
  r.technique = snellFindTechnique(name);
  if (!r.technique) r.engine = snellFindEngineModel(name);
  return r;
}

}  // namespace snell::lab
