#include "report.hpp"
#include "sequence.hpp"
#include "cpu_mirror.hpp"

#include "technique.hpp"

#include "lab/error.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>

namespace snell::lab {

namespace fs = std::filesystem;

namespace {

// A surface of the lab's surface ids (StaticBuffers::sceneSurface): k + 1 painting k, -(o + 1) object o.
std::string surfaceName(int id) {
  return id > 0 ? "painting " + std::to_string(id - 1) : id < 0 ? "object " + std::to_string(-id - 1) : "environment";
}

// The leaks column: the count and, where there are any, the surfaces they come from.
std::string leaksText(const TechniqueRow& t) {
  std::string s = std::to_string(t.leakPixels);
  if (t.leakSurfaces.empty()) return s;
  std::string from;
  for (const auto& [surface, pixels] : t.leakSurfaces)
    from += (from.empty() ? "" : ", ") + surfaceName(surface) +
            (t.leakSurfaces.size() > 1 ? ": " + std::to_string(pixels) : std::string());
  return s + " (" + from + ")";
}

}  // namespace

// Several objects: each as the lab drew it (back to front), and what each row's passes cost per object.
std::string objectsTable(const LabResult& r) {
  if (r.objects.size() < 2) return "";
  std::string s = "\nObjects, in the order they are drawn (back to front; each object's exit and reflect slots read "
                  "the ones drawn before it, as this row drew them):\n\n"
                  "| object | IOR | searched inside | pixels | scene layer (ms) | own buffers (MB) |\n"
                  "|---|---:|---|---:|---:|---:|\n";
  for (const ObjectReport& o : r.objects)
    s += "| " + std::to_string(o.index) + " | " + fmt("%.3g", static_cast<double>(o.ior)) +
         (o.abbe > 0.0f ? ", V_d " + fmt("%.3g", static_cast<double>(o.abbe)) : std::string()) +
         (o.enclosing >= 0 ? " (inside object " + std::to_string(o.enclosing) + ")" : std::string()) + " | " +
         (o.insideScene ? "yes" : "-") + " | " + std::to_string(o.pixels) + " | " + fmt("%.2f", o.layerMs) +
         " | " + fmt("%.1f", static_cast<double>(o.bytes) / 1048576.0) + " |\n";
  s += "\nShared by every object: " + fmt("%.1f", static_cast<double>(r.sharedBytes) / 1048576.0) +
       " MB (the scene layers, the refraction pass's targets). Refraction pass per object (ms, draw order) and the "
       "whole frame against the sum of each object drawn alone; each row's MSE vs the ray tracer over the composited "
       "model's (its floor):\n\n| technique | ms per object | total | x alone | x composited floor |\n"
       "|---|---|---:|---:|---:|\n";
  for (const TechniqueRow& t : r.rows) {
    std::string per;
    for (double ms : t.objectMs) per += (per.empty() ? "" : " + ") + fmt("%.2f", ms);
    s += "| " + t.label + " | " + per + " | " + fmt("%.2f", t.medianMs) + " | " +
         fmt("%.2fx", t.aloneMs > 0.0 ? t.medianMs / t.aloneMs : 0.0) + " | " +
         fmt("%.2fx", r.mseCompositedVsFull > 0.0 ? t.mseFull / r.mseCompositedVsFull : 0.0) + " |\n";
  }
  return s;
}

// snell's best constant-time row against the full ray tracer (nullptr when none ran).
const TechniqueRow* bestConstantTime(const LabResult& r) {
  const TechniqueRow* best = nullptr;
  for (const TechniqueRow& t : r.rows) {
    const SnellTechniqueInfo* info = snellFindTechnique(t.name);
    if (info && info->kind == SnellTechniqueKind::ConstantTime && (!best || t.mseFull < best->mseFull)) best = &t;
  }
  return best;
}

// The real renderers (a glTF scene: three.js's own), beside snell's best constant-time row.
std::string renderersTable(const LabResult& r) {
  if (r.renderers.empty()) return "";
  const TechniqueRow* best = bestConstantTime(r);
  std::string s = "\nReal renderers on the same file, camera and environment (their own images, scored as the rows; "
                  "the other columns do not apply):\n\n| renderer | MSE vs ray traced | MSE vs two-interface ref. | "
                  "snell's best constant-time row | its MSE, x the renderer's | frame (ms) | ran on |\n"
                  "|---|---:|---:|---|---:|---:|---|\n";
  for (const RendererRow& x : r.renderers)
    s += "| " + x.label + " | " + fmt("%.3g", x.mseFull) + " | " + fmt("%.3g", x.mseTwo) + " | " +
         (best ? best->label : std::string("none ran")) + " | " +
         (best && x.mseFull > 0.0 ? fmt("%.2fx", best->mseFull / x.mseFull) : std::string("-")) + " | " +
         fmt("%.1f", x.msPerFrame) + " | " + x.renderer + " |\n";
  return s;
}

std::string markdownTable(const LabResult& r) {
  std::string s;
  s += "| technique | MSE vs ray traced | on TIR | MSE vs two-interface ref. | x bound | own error (MSE vs bound) | unshaded | "
       "invalid | leaks | fetches/px | time ratio | time (ms) | CPU-GPU max | CPU-GPU > 1/255 | CPU-GPU > 4/255 (ties) |\n";
  s += "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const TechniqueRow& t : r.rows) {
    s += "| " + t.label + " | " + fmt("%.3g", t.mseFull) + " | " + fmt("%.3g", t.mseFullTir) + " | " +
         fmt("%.3g", t.mseTwo) + " | " +
         fmt("%.2fx", t.boundRatio) + " | " + fmt("%.3g", t.mseBound) + " | " + fmt("%.2f %%", 100.0 * t.unshadedShare) +
         " | " + fmt("%.2f %%", 100.0 * t.invalidShare) + " | " + leaksText(t) + " | " +
         fmt("%.1f", t.fetchesPerPixel) + " | " +
         fmt("%.2fx", t.costRatio) + " | " + fmt("%.2f", t.medianMs) + " | " + fmt("%.1f/255", 255.0 * t.cpuGpuMaxAbs) +
         " | " + fmt("%.3f %%", 100.0 * t.cpuGpuBeyond1) + " | " + std::to_string(t.cpuGpuBeyond4Pixels) + " (" +
         std::to_string(t.cpuGpuBeyond4Ties) + ") |\n";
  }
  s += renderersTable(r);
  const TechniqueRow* bound = r.boundRow();
  const TechniqueRow* unit = r.costUnitRow();
  s += objectsTable(r);
  s += "\n" + r.scene + ", " + std::to_string(r.width) + "x" + std::to_string(r.height) + ", " +
       std::to_string(r.objectPixels) + " object pixels, scene and back-face buffers " +
       std::to_string(r.width + 2 * r.guardBand) + "x" + std::to_string(r.height + 2 * r.guardBand) + " (a guard band of " +
       std::to_string(r.guardBand) + " texels around the viewport). MSE: linear RGB clamped to [0, 1], over the "
       "object's pixels (Mayer & Assarsson's measure).\n";
  if (r.truthSamples > 0) {
    double smallest = 0.0;
    for (const TechniqueRow& t : r.rows)
      if (smallest == 0.0 || t.mseFull < smallest) smallest = t.mseFull;
    s += "\nThe glass is rough: the ray tracer samples its microfacets (GGX, Walter et al. 2007) with " +
         std::to_string(r.truthSamples) + " paths per pixel, which leaves noise of " + fmt("%.3g", r.truthNoise) +
         " (MSE of the truth against its own mean) in every MSE against it: " +
         fmt("%.3f", smallest > 0.0 ? r.truthNoise / smallest : 0.0) + " of the smallest row's" +
         (smallest > 0.0 && r.truthNoise > 0.1 * smallest ? " (above a tenth: raise --truth-samples)" : "") + ".\n";
  }
  s += "\nWhere the error comes from:\n";
  s += "- model: the two-interface reference (two refractions, Fresnel reflection of the scene at the first "
       "surface, no internal bounces) is " + fmt("%.3g", r.mseTwoVsFull) + " from the full ray tracer; no technique "
       "that models two interfaces can get closer to the ray tracer than that.\n";
  if (r.mseCompositedVsFull >= 0.0)
    s += "- compositing: the objects drawn one after the other, back to front, each with its exact two-interface "
         "path, reading the paintings and the objects drawn before it as the frame shows them (a picture: what "
         "any image-space method that composites objects can see of them) is " + fmt("%.3g", r.mseCompositedVsFull) +
         " from the full ray tracer: the floor of the rows here (\"x composited\" below each row's MSE over it). The "
         "two-interface reference above follows each object's two interfaces through the others instead, as no "
         "picture can.\n";
  s += "- total internal reflection: " + fmt("%.1f %%", 100.0 * r.tirShare) + " of the object pixels meet TIR at "
       "their second interface (every two-interface technique clamps there to the critical angle)" +
       (r.tirShare > 0.0 ? "; on them the two-interface reference is " + fmt("%.3g", r.mseTwoVsFullTir) +
                               " from the full ray tracer (\"on TIR\" in the table: each technique's)"
                         : std::string(" (\"on TIR\" in the table is 0)")) +
       ". Following the principal path inside (refract where Snell allows, reflect on TIR, the ray tracer):";
  for (const ModelFloor& f : r.modelFloors)
    s += " " + std::to_string(f.events) + " events " + fmt("%.3g", f.mseFull) + " (on TIR " + fmt("%.3g", f.mseFullTir) +
         ")" + (&f == &r.modelFloors.back() ? "." : ",");
  s += " That is the floor of a technique that follows that many interface events in image space.\n";
  if (bound) {
    s += "- information: the image-space bound (the same buffers, intersected as exhaustively as a march can: " +
         std::to_string(snellPresetImageSpaceBound().back.intersect.marchSteps) + " march steps + " +
         std::to_string(snellPresetImageSpaceBound().back.intersect.marchBisections) + " bisections per slot over the object's "
         "and the scene's extent) is " + fmt("%.3g", bound->mseTwo) +
         " from the two-interface reference: " + fmt("%.3g", r.boundInformationMse) + " on the " +
         fmt("%.1f %%", 100.0 * r.boundInformationShare) + " of object pixels whose exact path the buffers do not hold "
         "(its exit point or its hit on the scene outside the buffers or hidden behind a nearer surface), " + fmt("%.3g", r.boundBufferMse) +
         " elsewhere (buffer resolution, depth and normal reads). Of the former, " +
         fmt("%.1f %%", 100.0 * r.boundMiddleLayerShare) + " of object pixels (" + fmt("%.3g", r.boundMiddleLayerMse) +
         ") leave through a back face in front of the farthest one at their pixel (a middle layer of a concave object): "
         "at most what a second, depth-peeled back-face layer would buy the bound.\n";
    s += "- the technique itself: \"own error\" is its MSE against the bound's image; \"x bound\" is its MSE vs the "
         "two-interface reference over the bound's (1.00x: as good as any image-space method with these buffers; "
         "a plane method, which also reads the normals, can land slightly below). A technique that follows B bounces "
         "inside is measured against the image-space bound with B bounces (its inside march as exhaustive), and its "
         "\"x bound\" compares the two on the model they both follow: the principal path of 2 + B interface events "
         "(the ray tracer's, above).\n";
  }
  bool engineRows = false;
  for (const TechniqueRow& t : r.rows) {
    const SnellEngineModelInfo* m = t.engine;
    if (!m) continue;
    if (!engineRows)
      s += "- the engines' models (shade/engine_models/: where three.js, Bevy, Filament, HDRP and Godot read their "
           "scene colour; the same Fresnel reflection as the techniques, no back-face pass): each one's free value "
           "swept on this scene, the best kept (lengths as shares of the object's bounding-box diagonal " +
           fmt("%.3g", static_cast<double>(r.objectDiagonal)) + "):";
    s += std::string(engineRows ? "," : "") + " " + t.label + " " + m->parameter + " " +
         (m->kind == SnellEngineParameterKind::Length ? fmt("%.3g", static_cast<double>(t.engineParameter / r.objectDiagonal)) + " d"
                                                      : fmt("%.3g", static_cast<double>(t.engineParameter)));
    if (!t.engineSweep.empty()) {
      double worst = 0.0;
      for (const auto& tried : t.engineSweep) worst = std::max(worst, tried.second);
      s += " (MSE " + fmt("%.3g", t.mseFull) + ", the sweep's worst " + fmt("%.3g", worst) + ")";
    }
    engineRows = true;
  }
  if (engineRows) s += ".\n";
  s += "\nunshaded: object pixels the technique's front-face pass did not cover (they show the scene behind). "
       "invalid: pixels that fell back (no back-face or exit hit: environment along the ray), but not those whose "
       "exit ray found no scene where the ray tracer's exact path also meets nothing after the object (the "
       "environment is right there). leaks: pixels whose "
       "refracted colour comes from an opaque surface nearer the camera than the object's own front face there (a "
       "foreground shown inside the glass; snell's rows read " +
       std::string(r.sceneLayer == SceneLayer::Behind   ? "the scene layer behind the object's nearest point"
                   : r.sceneLayer == SceneLayer::Peeled ? "the scene layer behind the object's back faces"
                                                        : "the whole opaque scene") +
       ", the engines' the whole scene, as their colour copy holds it; in brackets, the surfaces they come from: a "
       "painting or an object drawn before, numbered in the scene file's order)." +
       std::string(r.insideScene ? " An opaque surface reaches inside the object: snell's rows also search the scene "
                                   "along the refracted ray and stop on it where it is nearer than the back faces "
                                   "(SnellTechnique.insideScene)."
                                 : "") +
       " Time: the refraction "
       "pass alone, glFinish + steady clock, median of " + std::to_string(r.frames) + " frames (the bound: 1), all "
       "techniques interleaved, on " + r.gpu + "; ratios are to " + (unit ? unit->label : std::string("the first row")) +
       "; a software rasterizer's milliseconds say little about a GPU. CPU-GPU: the same technique function run in "
       "C++ on the read-back buffers against the GL image; (ties): how many of the pixels beyond 4/255 the C++ "
       "build reproduces within 1/255 when P1 or N1 moves by at most " + std::to_string(kTieUlps) +
       " ulps per component (a texel or TIR boundary that last-bit differences put on opposite sides, not a "
       "disagreement between the builds).\n";
  s += sequenceMarkdown(r);
  return s;
}

// The poster's figures next to this run's, as ratios (absolute MSE depends on the scene and its
// textures; absolute time on the GPU).
std::string targetsText(const LabResult& r) {
  const TechniqueRow* single = r.costUnitRow();
  const TechniqueRow* plane = r.posterRow();
  std::string s = "Mayer & Assarsson (their scene, RTX 3070): normal plane MSE 0.16x single sample's at 1.12x its "
                  "time; depth plane 0.16x at 1.58x; ray marching 1.38x the plane's time.\n";
  s += "Here (" + r.scene + ", vs the two-interface reference):";
  if (single && plane && single->mseTwo > 0.0)
    s += " normal plane (1 it.) " + fmt("%.2fx", plane->mseTwo / single->mseTwo) + " single sample's MSE at " +
         fmt("%.2fx", plane->costRatio) + " its time;";
  const TechniqueRow* best = nullptr;
  for (const TechniqueRow& t : r.rows) {
    const SnellTechniqueInfo* info = snellFindTechnique(t.name);
    if (info && info->kind == SnellTechniqueKind::ConstantTime && (!best || t.mseTwo < best->mseTwo)) best = &t;
  }
  if (best) s += " best constant-time technique: " + best->label + ", " + fmt("%.2fx", best->boundRatio) + " the bound's MSE.";
  return s + "\n";
}

// One plain paragraph from this table's own numbers (vs the full ray tracer): which row to pick for a budget,
// with and without a back-face pass, and what following the bounces inside buys on this object.
std::string whichToPick(const LabResult& r) {
  const TechniqueRow *best = nullptr, *cheap = nullptr, *search = nullptr, *bounce = nullptr, *engine = nullptr;
  for (const TechniqueRow& t : r.rows) {
    const SnellTechniqueInfo* info = snellFindTechnique(t.name);
    if (!info) {
      if (t.engine && (!engine || t.mseFull < engine->mseFull)) engine = &t;
      continue;
    }
    const bool bounces = snellTechniqueBounces(*info) > 0;
    if (info->kind == SnellTechniqueKind::ConstantTime && (!best || t.mseFull < best->mseFull)) best = &t;
    if (info->kind == SnellTechniqueKind::Search && !bounces && (!search || t.mseFull < search->mseFull)) search = &t;
    if (info->kind != SnellTechniqueKind::Reference && bounces && (!bounce || t.mseFull < bounce->mseFull)) bounce = &t;
  }
  if (!best) return "";
  // The cheapest constant-time row within a quarter of the best one's error.
  for (const TechniqueRow& t : r.rows) {
    const SnellTechniqueInfo* info = snellFindTechnique(t.name);
    if (info && info->kind == SnellTechniqueKind::ConstantTime && t.mseFull <= 1.25 * best->mseFull &&
        (!cheap || t.costRatio < cheap->costRatio))
      cheap = &t;
  }
  const auto at = [](const TechniqueRow& t) {
    return t.label + " (MSE " + fmt("%.3g", t.mseFull) + ", " + fmt("%.2fx", t.costRatio) + " single sample's time)";
  };
  std::string s = "\nWhich to pick on " + r.scene + " (MSE vs the ray tracer): with a back-face pass, " + at(*best);
  if (cheap && cheap != best) s += "; within a quarter of its error and cheaper, " + at(*cheap);
  s += ".";
  if (search && best->mseFull > 0.0)
    s += (search->mseFull >= best->mseFull ? std::string(" The searches do not buy more here: the best, ")
                                           : std::string(" A search does better here: ")) +
         at(*search) + ", " + fmt("%.2fx", search->mseFull / best->mseFull) + " that error.";
  if (bounce && best->mseFull > 0.0)
    s += " Following total internal reflection inside (" + fmt("%.1f %%", 100.0 * r.tirShare) + " of the object's "
         "pixels meet it): " + at(*bounce) + ", " + fmt("%.2fx", bounce->mseFull / best->mseFull) +
         " the error without" + (bounce->mseFull < 0.9 * best->mseFull ? "; worth it on this object." : ": not worth it on this object.");
  if (engine && engine->mseFull > 0.0)
    s += " Without a back-face pass (the engines' tier, their free value at its best for this scene): " + at(*engine) +
         "; " + best->label + " has " + fmt("%.2fx", best->mseFull / engine->mseFull) + " its error at " +
         fmt("%.2fx", engine->costRatio > 0.0 ? best->costRatio / engine->costRatio : 0.0) + " its time.";
  return s + "\n";
}

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  if (!out) throw Error(ErrorKind::Io, "cannot write " + path.string() + ": " + std::strerror(errno));
  out << text;
  // A full disk shows only when the buffer is flushed.
  if (!out.flush()) throw Error(ErrorKind::Io, "cannot write " + path.string() + ": " + std::strerror(errno));
}

void writeJson(const fs::path& path, const LabResult& r) {
  nlohmann::json j;
  j["scene"] = r.scene;
  j["width"] = r.width;
  j["height"] = r.height;
  j["object_pixels"] = r.objectPixels;
  j["guard_band_texels"] = r.guardBand;
  j["scene_layer"] = r.sceneLayer == SceneLayer::Behind ? "behind" : r.sceneLayer == SceneLayer::Peeled ? "peeled" : "full";
  j["inside_scene"] = r.insideScene;
  j["frames"] = r.frames;
  j["gpu"] = r.gpu;
  j["mse_two_interface_vs_full"] = r.mseTwoVsFull;
  if (r.truthSamples > 0) {
    j["truth_samples"] = r.truthSamples;
    j["truth_noise"] = r.truthNoise;
  }
  if (r.mseCompositedVsFull >= 0.0) j["mse_composited_two_interface_vs_full"] = r.mseCompositedVsFull;
  j["mse_two_interface_vs_full_on_tir"] = r.mseTwoVsFullTir;
  j["tir_share"] = r.tirShare;
  nlohmann::json floors = nlohmann::json::array();
  for (const ModelFloor& f : r.modelFloors)
    floors.push_back({{"events", f.events}, {"mse_vs_full", f.mseFull}, {"mse_vs_full_on_tir", f.mseFullTir}});
  j["principal_path_floors"] = floors;
  j["bound_information_mse"] = r.boundInformationMse;
  j["bound_information_share"] = r.boundInformationShare;
  j["bound_buffer_mse"] = r.boundBufferMse;
  j["bound_middle_layer_mse"] = r.boundMiddleLayerMse;
  j["bound_middle_layer_share"] = r.boundMiddleLayerShare;
  j["trace_seconds"] = r.traceSeconds;
  j["static_passes_ms"] = r.staticPassMs;
  j["object_diagonal"] = r.objectDiagonal;
  nlohmann::json objects = nlohmann::json::array();
  for (const ObjectReport& o : r.objects) {
    nlohmann::json oj = {{"index", o.index},
                         {"ior", o.ior},
                         {"enclosing", o.enclosing},
                         {"inside_scene", o.insideScene},
                         {"pixels", o.pixels},
                         {"scene_layer_ms", o.layerMs},
                         {"own_buffer_bytes", o.bytes}};
    if (o.abbe > 0.0f) oj["abbe"] = o.abbe;  // dispersive only: other scenes' tables keep their keys
    objects.push_back(oj);
  }
  j["objects_back_to_front"] = objects;
  j["shared_buffer_bytes"] = r.sharedBytes;
  nlohmann::json rows = nlohmann::json::array();
  for (const TechniqueRow& t : r.rows) {
    rows.push_back({{"technique", t.name},
                    {"label", t.label},
                    {"mse_vs_ray_traced", t.mseFull},
                    {"mse_vs_ray_traced_on_tir", t.mseFullTir},
                    {"mse_vs_two_interface", t.mseTwo},
                    {"bounces", t.bounces},
                    {"model_events", t.modelEvents},
                    {"mse_vs_model", t.mseModel},
                    {"mse_vs_bound", t.mseBound},
                    {"ratio_to_bound", t.boundRatio},
                    {"unshaded_share", t.unshadedShare},
                    {"invalid_share", t.invalidShare},
                    {"back_miss_share", t.backMissShare},
                    {"exit_miss_share", t.exitMissShare},
                    {"fetches_per_pixel", t.fetchesPerPixel},
                    {"time_ratio_to_single", t.costRatio},
                    {"time_ms_median", t.medianMs},
                    {"cpu_gpu_max_abs", t.cpuGpuMaxAbs},
                    {"cpu_gpu_share_beyond_1_255", t.cpuGpuBeyond1},
                    {"cpu_gpu_share_beyond_4_255", t.cpuGpuBeyond4},
                    {"cpu_gpu_pixels_beyond_4_255", t.cpuGpuBeyond4Pixels},
                    {"cpu_gpu_pixels_beyond_4_255_ties", t.cpuGpuBeyond4Ties},
                    {"cpu_gpu_fetch_count_mismatch_share", t.fetchMismatch},
                    {"leak_pixels", t.leakPixels},
                    {"overdrawn_share", t.overdrawnShare},
                    {"cpu_gpu_worst_pixel", {t.worstX, t.worstY}}});
    if (!t.leakSurfaces.empty()) {
      nlohmann::json surfaces = nlohmann::json::object();
      for (const auto& [surface, pixels] : t.leakSurfaces) surfaces[surfaceName(surface)] = pixels;
      rows.back()["leak_surfaces"] = surfaces;
    }
    if (t.mseComposited >= 0.0) rows.back()["mse_vs_composited"] = t.mseComposited;
    if (!t.objectMs.empty()) {
      rows.back()["time_ms_per_object"] = t.objectMs;
      rows.back()["time_ms_objects_alone"] = t.aloneMs;
    }
    if (const SnellEngineModelInfo* m = t.engine) {
      nlohmann::json sweep = nlohmann::json::array();
      for (const auto& [value, mse] : t.engineSweep) sweep.push_back({{"value", value}, {"mse_vs_ray_traced", mse}});
      rows.back()["engine"] = m->engine;
      if (t.steps > 1) rows.back()["bevy_steps"] = t.steps;
      rows.back()["engine_parameter"] = {{"name", m->parameter}, {"value", t.engineParameter}, {"sweep", sweep}};
    }
  }
  j["techniques"] = rows;
  nlohmann::json renderers = nlohmann::json::array();
  for (const RendererRow& x : r.renderers)
    renderers.push_back({{"renderer", x.name}, {"label", x.label}, {"ran_on", x.renderer}, {"mse_vs_ray_traced", x.mseFull},
                         {"mse_vs_two_interface", x.mseTwo}, {"frame_ms", x.msPerFrame}});
  if (!r.renderers.empty()) j["renderers"] = renderers;
  addSequenceJson(j, r);
  // Scene names come from file names, which need not be UTF-8: replace what JSON cannot hold, don't throw.
  writeText(path, j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}


}  // namespace snell::lab
