// The per-pixel call shared with the GPU: examples/glsl/lab_technique.glsl
// compiled as C++ inside namespace snell (the same body lab_refract.frag runs
// on the GPU). The rows are the library's tables: the techniques
// (snellTechniqueTable(), include/snell/technique_table.hpp) and the engines'
// refraction models (snellEngineModelTable(), include/snell/engine_model_table.hpp).
#pragma once
#include <snell/engine_model_table.hpp>
#include <snell/snell.hpp>
#include <snell/technique_table.hpp>

namespace snell {
#include "lab_technique.glsl"
}  // namespace snell

#include <string>
#include <vector>

namespace snell::lab {

// One row of the lab: a technique of the table or an engine model, never both.
struct LabRowSpec {
  const SnellTechniqueInfo* technique = nullptr;
  const SnellEngineModelInfo* engine = nullptr;

  std::string name() const { return technique ? technique->name : engine->name; }
  std::string label() const { return technique ? technique->label : engine->label; }
  // A Reference row (the image-space bounds) is measured against, not a contender.
  bool reference() const { return technique && technique->kind == SnellTechniqueKind::Reference; }
  bool costUnit() const { return technique && technique->costUnit; }
  int bounces() const { return technique ? snellTechniqueBounces(*technique) : 0; }
  bool needsDn() const { return technique && snellTechniqueNeedsDn(*technique); }
  int techniqueId() const { return technique ? technique->id : -1; }
  int engineModel() const { return engine ? engine->id : -1; }
};

// "single, plane-normal-0, ..., engine-godot" for messages.
std::string techniqueNames();

// The row of that command-line name (a technique or an engine model), or a spec with neither.
LabRowSpec findRow(const std::string& name);

}  // namespace snell::lab
