// The engine model table for C++ callers: the name, label, engine and free
// parameter of every SNELL_ENGINE_* id of
// glsl/snell/shade/engine_models/engine_models.glsl (GLSL has no strings, so
// they live here; the ids and the models live there, once). snell-lab's engine
// rows iterate this table.
#pragma once
#include "shade.hpp"

#include <array>
#include <string>

namespace snell {

// What a model's one free value measures, so a host knows how to sweep it.
enum class SnellEngineParameterKind {
  Length,   // a thickness in view-space units: a constant per material, not the object's chord
  UvScale,  // a screen-uv shift per unit of normal (Godot's "refraction")
};

struct SnellEngineModelInfo {
  int id;                  // SNELL_ENGINE_*
  const char* name;        // command-line and file name (snell-lab --technique, table.json "technique")
  const char* label;       // table and picture label
  const char* engine;      // the engine, version and file the model re-derives
  const char* parameter;   // the engine's name for the free value
  SnellEngineParameterKind kind;
};

// Every engine model, in id order.
inline const std::array<SnellEngineModelInfo, SNELL_ENGINE_MODEL_COUNT>& snellEngineModelTable() {
  static const std::array<SnellEngineModelInfo, SNELL_ENGINE_MODEL_COUNT> table = {{
      {SNELL_ENGINE_THREEJS, "engine-threejs", "three.js / Bevy",
       "three.js r187 transmission_pars_fragment (Bevy 0.20 transmission.wesl: the same point)", "thickness",
       SnellEngineParameterKind::Length},
      {SNELL_ENGINE_FILAMENT_SOLID, "engine-filament-solid", "Filament solid (sphere)",
       "Filament surface_light_indirect.fs refractionSolidSphere, screen space", "thickness",
       SnellEngineParameterKind::Length},
      {SNELL_ENGINE_FILAMENT_THIN, "engine-filament-thin", "Filament thin",
       "Filament surface_light_indirect.fs refractionThinSphere, screen space", "microThickness",
       SnellEngineParameterKind::Length},
      {SNELL_ENGINE_HDRP_SPHERE, "engine-hdrp-sphere", "HDRP sphere + proxy",
       "Unity HDRP Refraction.hlsl RefractionModelSphere, Lit.hlsl screen-space refraction", "thickness",
       SnellEngineParameterKind::Length},
      {SNELL_ENGINE_HDRP_BOX, "engine-hdrp-box", "HDRP box + proxy",
       "Unity HDRP Refraction.hlsl RefractionModelBox, Lit.hlsl screen-space refraction", "thickness",
       SnellEngineParameterKind::Length},
      {SNELL_ENGINE_GODOT, "engine-godot", "Godot screen-uv offset",
       "Godot 4 material.cpp BaseMaterial3D refraction", "refraction", SnellEngineParameterKind::UvScale},
  }};
  return table;
}

// The row of that command-line name, or nullptr.
inline const SnellEngineModelInfo* snellFindEngineModel(const std::string& name) {
  for (const SnellEngineModelInfo& m : snellEngineModelTable())
    if (name == m.name) return &m;
  return nullptr;
}

}  // namespace snell
