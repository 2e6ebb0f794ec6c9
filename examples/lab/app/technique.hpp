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

// Bevy's transmission steps (bevy_pbr transmission/node.rs): the transmissive objects, sorted back to
// front, are split into `steps` groups (the first groups one object more where the count does not divide),
// and the colour target is copied before each group, whose objects read that copy. One step is the one copy
// of the opaque scene every engine row reads; the lab adds these rows with the three.js / Bevy model when a
// scene has several objects.
constexpr int kBevySteps[] = {2, 3};

// One row of the lab: a technique of the table or an engine model, never both.
struct LabRowSpec {
  const SnellTechniqueInfo* technique = nullptr;
  const SnellEngineModelInfo* engine = nullptr;
  int steps = 1;  // an engine row: Bevy's steps (the colour copies, kBevySteps); 1: the opaque copy only
  // An engine row in three.js's WebGPU order (Renderer._renderTransparents for double-sided transmissive
  // materials): every object's back faces first, back to front, shaded with the model (normal turned to the
  // camera) from the opaque copy and depth-tested; then the front faces, from a copy of the frame that holds
  // those back faces (PhysicalLightingModel's viewportOpaqueMipTexture, copied at its first use).
  bool backSidesFirst = false;
  // An engine row that reads three.js's point through Bevy's spiral blur (LAB_ENGINE_BEVY): on smooth glass it
  // is the three.js row, so the lab adds it when an object is rough.
  bool bevyBlur = false;

  std::string name() const {
    if (technique) return technique->name;
    if (backSidesFirst) return "engine-threejs-webgpu";
    if (bevyBlur) return "engine-bevy";
    return steps > 1 ? "engine-bevy-steps-" + std::to_string(steps) : engine->name;
  }
  std::string label() const {
    if (technique) return technique->label;
    if (backSidesFirst) return "three.js WebGPU order";
    if (bevyBlur) return "Bevy (spiral blur)";
    return steps > 1 ? "Bevy, " + std::to_string(steps) + " steps" : engine->label;
  }
  // A row whose colour copy depends on the objects drawn (Bevy's steps, three.js's WebGPU order): with one
  // object the lab runs it only when named.
  bool multiObject() const { return steps > 1 || backSidesFirst; }
  // A row that differs from another only on rough glass (Bevy's blur): with smooth glass the lab runs it only
  // when named.
  bool roughOnly() const { return bevyBlur; }
  // A Reference row (the image-space bounds) is measured against, not a contender.
  bool reference() const { return technique && technique->kind == SnellTechniqueKind::Reference; }
  bool costUnit() const { return technique && technique->costUnit; }
  int bounces() const { return technique ? snellTechniqueBounces(*technique) : 0; }
  bool needsDn() const { return technique && snellTechniqueNeedsDn(*technique); }
  int techniqueId() const { return technique ? technique->id : -1; }
  int engineModel() const { return bevyBlur ? LAB_ENGINE_BEVY : engine ? engine->id : -1; }
};

// "single, plane-normal-0, ..., engine-godot" for messages.
std::string techniqueNames();

// The row of that command-line name (a technique, an engine model, engine-bevy-steps-N, engine-threejs-webgpu,
// engine-bevy),
// or a spec with neither.
LabRowSpec findRow(const std::string& name);

// The engines' multi-object strategies, with the three.js / Bevy model: Bevy's steps (kBevySteps) and
// three.js's WebGPU order.
std::vector<LabRowSpec> multiObjectRows();

// The engines' rows that differ from another only on rough glass: engine-bevy (three.js's point, Bevy's blur).
std::vector<LabRowSpec> roughRows();

}  // namespace snell::lab
