// The technique table for C++ callers: the name, label and source of every
// SNELL_TECHNIQUE_* id of glsl/snell/shade/technique_presets.glsl (GLSL has
// no strings, so they live here; the ids and the presets live there, once).
// snell-lab's --technique list, its table rows, the benchmarks and the tests
// all iterate this table: adding a technique is a preset and an id there plus
// one row here.
#pragma once
#include "shade.hpp"

#include <array>
#include <string>

namespace snell {

// How a technique's cost grows (Mayer & Assarsson's distinction): a fixed handful of lookups per
// pixel whatever the ray's length and the resolution; a search or march whose precision (or step
// count) is tied to the ray's length in pixels; or the image-space bound, a reference for the others.
enum class SnellTechniqueKind { ConstantTime, Search, Reference };

// What a host that compares techniques (snell-lab) reads from a row, never
// from an id or a name: the kind (a Reference row is measured against, not a
// contender; it marches its exit over the whole scene), the cost unit (every
// time ratio is to this row's time), the poster row (the one compared with
// Mayer & Assarsson's published figures, against the cost unit), and, from the
// preset, whether the technique reads Wyman's per-vertex d_N
// (snellTechniqueNeedsDn).
struct SnellTechniqueInfo {
  int id;                   // SNELL_TECHNIQUE_*
  const char* name;         // command-line and file name (snell-lab --technique, table.json "technique")
  const char* label;        // table and picture label
  const char* method;       // the published method, one line (the parameters come from the preset)
  SnellTechniqueKind kind;
  bool costUnit = false;    // the unit of the time ratios (one row)
  bool posterRow = false;   // compared with Mayer & Assarsson's poster figures (one row)
};

// Every technique, in id order (single sample first: the lab's cost unit).
inline const std::array<SnellTechniqueInfo, SNELL_TECHNIQUE_COUNT>& snellTechniqueTable() {
  static const std::array<SnellTechniqueInfo, SNELL_TECHNIQUE_COUNT> table = {{
      {SNELL_TECHNIQUE_SINGLE, "single", "single sample", "one depth sample behind the ray origin (GPU Gems baseline)",
       SnellTechniqueKind::ConstantTime, /*costUnit=*/true},
      {SNELL_TECHNIQUE_PLANE_NORMAL_0, "plane-normal-0", "normal plane, 0 it.", "Mayer & Assarsson normal-based plane",
       SnellTechniqueKind::ConstantTime},
      {SNELL_TECHNIQUE_PLANE_NORMAL_1, "plane-normal-1", "normal plane, 1 it.", "Mayer & Assarsson normal-based plane",
       SnellTechniqueKind::ConstantTime, false, /*posterRow=*/true},
      {SNELL_TECHNIQUE_PLANE_NORMAL_2, "plane-normal-2", "normal plane, 2 it.", "Mayer & Assarsson normal-based plane",
       SnellTechniqueKind::ConstantTime},
      {SNELL_TECHNIQUE_PLANE_DEPTH, "plane-depth", "depth plane, 1 it.", "Mayer & Assarsson depth-based plane",
       SnellTechniqueKind::ConstantTime},
      {SNELL_TECHNIQUE_DIR, "dir", "DIR (CBS 5)", "Oliveira & Brauwers 2007, conservative binary search",
       SnellTechniqueKind::Search},
      {SNELL_TECHNIQUE_ISR, "isr", "ISR (Wyman)", "Wyman 2005, distance interpolation",
       SnellTechniqueKind::ConstantTime},
      {SNELL_TECHNIQUE_LINEAR_MARCH, "linear-march", "linear march", "screen-space ray march",
       SnellTechniqueKind::Search},
      {SNELL_TECHNIQUE_DDA, "dda", "DDA march", "perspective-correct pixel DDA march (McGuire & Mara)",
       SnellTechniqueKind::Search},
      {SNELL_TECHNIQUE_IMAGE_SPACE_BOUND, "image-space-bound", "image-space bound",
       "the best any image-space method can do with these buffers (a reference, not a real-time method)",
       SnellTechniqueKind::Reference},
      {SNELL_TECHNIQUE_PLANE_NORMAL_2_BOUNCES, "plane-normal-2-bounces", "normal plane, 2 it., bounces",
       "normal plane that follows TIR inside (Davis & Wyman 2007: a march between front and back depth)",
       SnellTechniqueKind::Search},
      {SNELL_TECHNIQUE_LINEAR_MARCH_BOUNCES, "linear-march-bounces", "linear march, bounces",
       "linear march that follows TIR inside (Davis & Wyman 2007: a march between front and back depth)",
       SnellTechniqueKind::Search},
      {SNELL_TECHNIQUE_IMAGE_SPACE_BOUND_BOUNCES, "image-space-bound-bounces", "image-space bound, bounces",
       "the image-space bound that follows TIR inside as exhaustively (the reference of the bounce techniques)",
       SnellTechniqueKind::Reference},
  }};
  return table;
}

// The row of that command-line name, or nullptr.
inline const SnellTechniqueInfo* snellFindTechnique(const std::string& name) {
  for (const SnellTechniqueInfo& t : snellTechniqueTable())
    if (name == t.name) return &t;
  return nullptr;
}

// The row of that SNELL_TECHNIQUE_* id, or nullptr.
inline const SnellTechniqueInfo* snellFindTechnique(int id) {
  for (const SnellTechniqueInfo& t : snellTechniqueTable())
    if (id == t.id) return &t;
  return nullptr;
}

// Whether the technique reads Wyman's per-vertex d_N (its preset's back slot source).
inline bool snellTechniqueNeedsDn(const SnellTechniqueInfo& t) {
  return snellTechniquePreset(t.id).back.source == SNELL_SOURCE_WYMAN;
}

// How many total internal reflections the technique follows inside (its preset's bounces, clamped as
// snellTwoInterfaceTrace clamps them): 0 for a two-interface technique. A Reference row with B
// bounces is the image-space bound of the rows with B.
inline int snellTechniqueBounces(const SnellTechniqueInfo& t) {
  const int b = snellTechniquePreset(t.id).bounces;
  return b < 0 ? 0 : (b > SNELL_MAX_BOUNCES ? SNELL_MAX_BOUNCES : b);
}

// The SNELL_INTERSECT_STRATEGIES bits (bit k = strategy k) of the slots this
// technique calls (shade/two_interface*.glsl): every slot whose source runs its
// intersector (not SNELL_SOURCE_ENVIRONMENT; for the back slot not
// SNELL_SOURCE_WYMAN either), the reflect slot only with the material's
// reflection on. A strategy
// outside 0 .. SNELL_STRATEGY_COUNT - 1 adds nothing (it misses either way). A host
// that compiles one program per technique defines the mask before including
// the shaders, so the program holds only those strategies: the dispatcher,
// inlined with every strategy into each slot, is most of a technique shader's
// code. The mask follows the slots' values: a program whose slots come
// from uniforms must be built for every value they can take.
inline int snellStrategiesUsed(const SnellTechnique& t, const SnellMaterial& m) {
  int mask = 0;
  const auto add = [&mask](const SnellSlot& slot) {
    const int strategy = slot.intersect.strategy;
    if (slot.source != SNELL_SOURCE_ENVIRONMENT && strategy >= 0 && strategy < SNELL_STRATEGY_COUNT)
      mask |= 1 << strategy;
  };
  if (t.back.source != SNELL_SOURCE_WYMAN) add(t.back);
  add(t.exit);
  if (m.reflection) add(t.reflect);
  return mask;
}

// One slot's strategy and parameters in words, from the options themselves
// (so no description restates a default): "conservative binary search, 5 steps, range from the pyramid".
inline std::string snellDescribeIntersect(const SnellIntersectOptions& o) {
  const auto count = [](int n, const char* one, const char* many) { return std::to_string(n) + (n == 1 ? one : many); };
  const auto distance = [](float x) {
    std::string d = std::to_string(x);
    d.erase(d.find_last_not_of('0') + 1);
    if (!d.empty() && d.back() == '.') d.pop_back();
    return d;
  };
  const std::string farStart = o.planeFarStart ? ", far start on closed surfaces" : "";
  const std::string range = o.rangeSource == SNELL_RANGE_EXPLICIT ? "range from a bounding box" : "range from the pyramid";
  switch (o.strategy) {
    case SNELL_STRATEGY_SINGLE: return "single sample";
    case SNELL_STRATEGY_PLANE_NORMAL:
      return "normal plane, " + count(o.planeIterations, " iteration", " iterations") + farStart;
    case SNELL_STRATEGY_PLANE_DEPTH:
      return "depth plane (depth mips = the min/max pyramid), " + count(o.planeIterations, " iteration", " iterations") +
             farStart;
    case SNELL_STRATEGY_CBS: return "conservative binary search, " + count(o.cbsSteps, " step", " steps") + ", " + range;
    case SNELL_STRATEGY_BINARY: return "binary search, " + count(o.binarySteps, " step", " steps") + ", " + range;
    case SNELL_STRATEGY_LINEAR_BINARY:
      return "linear search, " + count(o.linearSteps, " step", " steps") + " + " +
             count(o.binarySteps, " binary step", " binary steps") + ", " + range;
    case SNELL_STRATEGY_LINEAR_MARCH:
      return "linear march, " + count(o.marchSteps, " view-space step", " view-space steps") + " + " +
             count(o.marchBisections, " bisection", " bisections") + " over " + distance(o.marchMaxDistance);
    case SNELL_STRATEGY_DDA: return "pixel DDA march, up to " + count(o.ddaSteps, " step", " steps") + " over " + distance(o.ddaMaxDistance);
    default: return "no strategy (every ray misses)";
  }
}

// How one technique finds the back face: its back slot, or Wyman's distance interpolation.
inline std::string snellDescribeBack(const SnellTechnique& t) {
  if (t.back.source == SNELL_SOURCE_WYMAN) return "distance interpolation between d_V and the per-vertex d_N";
  if (t.back.source == SNELL_SOURCE_ENVIRONMENT) return "none (a thin surface: the ray leaves where it enters)";
  return snellDescribeIntersect(t.back.intersect);
}

// How a technique that bounces finds where a reflected ray leaves: its inside slot (the two strategies
// snellTwoInterfaceTrace runs there; the march's bracket of the plane counts as its view-space steps).
inline std::string snellDescribeInside(const SnellTechnique& t) {
  const SnellIntersectOptions& o = t.inside.intersect;
  const std::string bounces = std::to_string(t.bounces) + (t.bounces == 1 ? " bounce" : " bounces");
  if (t.inside.source == SNELL_SOURCE_BUFFERS && o.strategy == SNELL_STRATEGY_PLANE_NORMAL)
    return bounces + ", each a march of " + std::to_string(o.marchSteps) + " steps between the front and back layers, "
           "then the normal plane, " + std::to_string(o.planeIterations) + " iterations";
  if (t.inside.source == SNELL_SOURCE_BUFFERS && o.strategy == SNELL_STRATEGY_LINEAR_MARCH)
    return bounces + ", each a march of " + std::to_string(o.marchSteps) + " steps + " +
           std::to_string(o.marchBisections) + " bisections between the front and back layers";
  return bounces + ", none followed (the inside slot has no strategy that works from inside)";
}

// "method; back faces: ...; exit: ...[; inside: ...]" for --help and the docs, from the preset.
inline std::string snellDescribeTechnique(const SnellTechniqueInfo& t) {
  const SnellTechnique o = snellTechniquePreset(t.id);
  const std::string back = snellDescribeBack(o), exit = snellDescribeIntersect(o.exit.intersect);
  return std::string(t.method) + "; back faces: " + back + "; exit: " + (exit == back ? "the same" : exit) +
         (o.bounces > 0 ? "; inside: " + snellDescribeInside(o) : std::string());
}

}  // namespace snell
