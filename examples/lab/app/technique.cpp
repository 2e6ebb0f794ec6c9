#include "technique.hpp"

namespace snell::lab {

std::string techniqueNames() {
  std::string s;
  for (const SnellTechniqueInfo& t : snellTechniqueTable()) s += std::string(s.empty() ? "" : ", ") + t.name;
  return s;
}

}  // namespace snell::lab
