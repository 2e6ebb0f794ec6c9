#include "lab_run.hpp"
#include "web_bundle.hpp"

#include "technique.hpp"

#include "lab/error.hpp"
#include "lab/figure.hpp"
#include "lab/image_io.hpp"
#include "lab/metrics.hpp"
#include "lab/scene.hpp"
#include "lab/tracer.hpp"

#include <snell/depth_pyramid.hpp>
#include <snell/wyman_dn.hpp>
#include <snell/gpu/frame_compare.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <set>
#include <thread>

namespace snell::lab {

namespace fs = std::filesystem;

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

float clamp01(float v) { return std::min(std::max(v, 0.0f), 1.0f); }

// The largest input nudge (ulps per component of P1 or N1) under which a CPU/GPU difference beyond 4/255
// still counts as a rounding tie in the table: float32 positions read back from the G-buffer and the GPU's
// own arithmetic (fused multiply-adds in llvmpipe) differ from the C++ build by about this much.
constexpr int kTieUlps = 4;

// The read-back buffers as the C++ side samples them (the same filters as GL).
struct CpuBuffers {
  Texture2D backDepth, backNormal, backPyramid;
  Texture2D frontDepth, frontNormal;
  Texture2D sceneDepth, sceneNormal, scenePyramid, sceneColor;  // the layer snell's rows read
  Texture2D fullDepth, fullNormal, fullPyramid, fullColor;      // the whole opaque scene (engine rows)
  Texture2D environment;
};

CpuBuffers cpuBuffers(const StaticBuffers& b, const ShadeConstants& k, const SceneFrame& frame) {
  const Filter normalFilter = k.normalFilter == NormalFilter::Linear ? Filter::Linear : Filter::Nearest;
  CpuBuffers c;
  c.backDepth = Texture2D(b.backDepth);
  c.backNormal = Texture2D(b.backNormal, normalFilter);
  c.frontDepth = Texture2D(b.frontDepth);
  c.frontNormal = Texture2D(b.frontNormal, normalFilter);
  c.sceneDepth = Texture2D(b.sceneDepth);
  c.sceneNormal = Texture2D(b.sceneNormal, normalFilter);
  c.sceneColor = Texture2D(b.sceneColor, Filter::Linear);
  c.fullDepth = Texture2D(b.fullDepth);
  c.fullNormal = Texture2D(b.fullNormal, normalFilter);
  c.fullColor = Texture2D(b.fullColor, Filter::Linear);
  c.fullPyramid =
      snellBuildDepthPyramid(c.fullDepth, snellDepthSurface(k.params.clipFromView, k.params.zNear, k.params.zFar, SNELL_DEPTH_GL, 1.0f));
  c.backPyramid =
      snellBuildDepthPyramid(c.backDepth, snellDepthSurface(k.params.clipFromView, k.params.zNear, k.params.zFar, SNELL_DEPTH_GL, 0.0f));
  c.scenePyramid =
      snellBuildDepthPyramid(c.sceneDepth, snellDepthSurface(k.params.clipFromView, k.params.zNear, k.params.zFar, SNELL_DEPTH_GL, 1.0f));
  c.environment = environmentTexture(frame);
  return c;
}

// Runs f(y) for every row on `threads` threads.
template <class F>
void parallelRows(int height, int threads, F&& f) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::atomic<int> next{0};
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t)
    pool.emplace_back([&] {
      for (int y = next++; y < height; y = next++) f(y);
    });
  for (std::thread& t : pool) t.join();
}

// Composite: the object's pixels from `object` where the front pass covered them, else the scene (whose
// buffer holds `margin` more texels on every side: the guard band).
Image composite(const Image& object, const Image& coverage, const Image& scene, int margin) {
  Image out(object.width, object.height);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      out.at(x, y) = coverage.at(x, y).w > 0.0f ? vec4(vec3(object.at(x, y)), 1.0f) : scene.at(x + margin, y + margin);
  return out;
}

Image downscale(const Image& img, int factor) {
  if (factor <= 1) return img;
  Image out(std::max(1, img.width / factor), std::max(1, img.height / factor));
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      vec4 s(0.0f);
      for (int dy = 0; dy < factor; ++dy)
        for (int dx = 0; dx < factor; ++dx) s += img.at(x * factor + dx, y * factor + dy);
      out.at(x, y) = s / static_cast<float>(factor * factor);
    }
  return out;
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
         " | " + fmt("%.2f %%", 100.0 * t.invalidShare) + " | " + std::to_string(t.leakPixels) + " | " +
         fmt("%.1f", t.fetchesPerPixel) + " | " +
         fmt("%.2fx", t.costRatio) + " | " + fmt("%.2f", t.medianMs) + " | " + fmt("%.1f/255", 255.0 * t.cpuGpuMaxAbs) +
         " | " + fmt("%.3f %%", 100.0 * t.cpuGpuBeyond1) + " | " + std::to_string(t.cpuGpuBeyond4Pixels) + " (" +
         std::to_string(t.cpuGpuBeyond4Ties) + ") |\n";
  }
  const TechniqueRow* bound = r.boundRow();
  const TechniqueRow* unit = r.costUnitRow();
  s += "\n" + r.scene + ", " + std::to_string(r.width) + "x" + std::to_string(r.height) + ", " +
       std::to_string(r.objectPixels) + " object pixels, scene and back-face buffers " +
       std::to_string(r.width + 2 * r.guardBand) + "x" + std::to_string(r.height + 2 * r.guardBand) + " (a guard band of " +
       std::to_string(r.guardBand) + " texels around the viewport). MSE: linear RGB clamped to [0, 1], over the "
       "object's pixels (Mayer & Assarsson's measure).\n\nWhere the error comes from:\n";
  s += "- model: the two-interface reference (two refractions, Fresnel reflection of the scene at the first "
       "surface, no internal bounces) is " + fmt("%.3g", r.mseTwoVsFull) + " from the full ray tracer; no technique "
       "that models two interfaces can get closer to the ray tracer than that.\n";
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
    const SnellEngineModelInfo* m = snellFindEngineModel(t.name);
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
       "invalid: pixels that fell back (no back-face or exit hit: environment along the ray). leaks: pixels whose "
       "refracted colour comes from an opaque surface nearer the camera than the object's own front face there (a "
       "foreground shown inside the glass; snell's rows read " +
       std::string(r.sceneLayer == SceneLayer::Behind ? "the scene layer behind the object's nearest point"
                                                      : "the whole opaque scene") +
       ", the engines' the whole scene, as their colour copy holds it). Time: the refraction "
       "pass alone, glFinish + steady clock, median of " + std::to_string(r.frames) + " frames (the bound: 1), all "
       "techniques interleaved, on " + r.gpu + "; ratios are to " + (unit ? unit->label : std::string("the first row")) +
       "; a software rasterizer's milliseconds say little about a GPU. CPU-GPU: the same technique function run in "
       "C++ on the read-back buffers against the GL image; (ties): how many of the pixels beyond 4/255 the C++ "
       "build reproduces within 1/255 when P1 or N1 moves by at most " + std::to_string(kTieUlps) +
       " ulps per component (a texel or TIR boundary that last-bit differences put on opposite sides, not a "
       "disagreement between the builds).\n";
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
      if (snellFindEngineModel(t.name) && (!engine || t.mseFull < engine->mseFull)) engine = &t;
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
  j["scene_layer"] = r.sceneLayer == SceneLayer::Behind ? "behind" : "full";
  j["frames"] = r.frames;
  j["gpu"] = r.gpu;
  j["mse_two_interface_vs_full"] = r.mseTwoVsFull;
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
    if (const SnellEngineModelInfo* m = snellFindEngineModel(t.name)) {
      nlohmann::json sweep = nlohmann::json::array();
      for (const auto& [value, mse] : t.engineSweep) sweep.push_back({{"value", value}, {"mse_vs_ray_traced", mse}});
      rows.back()["engine"] = m->engine;
      rows.back()["engine_parameter"] = {{"name", m->parameter}, {"value", t.engineParameter}, {"sweep", sweep}};
    }
  }
  j["techniques"] = rows;
  // Scene names come from file names, which need not be UTF-8: replace what JSON cannot hold, don't throw.
  writeText(path, j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

// ---- The stages of one lab run, in order (runLab below). ----

// Stage 1: the requested rows of the technique table, in table order, and the image-space bounds
// they are measured against: always the two-interface one, the one with B bounces when a row with B
// runs. Before the scene loads: a typo should not cost a ray trace.
std::vector<LabRowSpec> selectTechniques(const LabOptions& options) {
  const auto asked = [&](const std::string& name) {
    return options.techniques.empty() ||
           std::find(options.techniques.begin(), options.techniques.end(), name) != options.techniques.end();
  };
  const auto someRowBounces = [&](int bounces) {
    for (const SnellTechniqueInfo& t : snellTechniqueTable())
      if (t.kind != SnellTechniqueKind::Reference && asked(t.name) && snellTechniqueBounces(t) == bounces) return true;
    return false;
  };
  std::vector<LabRowSpec> rows;
  for (const SnellTechniqueInfo& t : snellTechniqueTable()) {
    const bool bound = t.kind == SnellTechniqueKind::Reference &&
                       (snellTechniqueBounces(t) == 0 || someRowBounces(snellTechniqueBounces(t)));
    if (bound || (t.kind != SnellTechniqueKind::Reference && asked(t.name))) rows.push_back(LabRowSpec{&t, nullptr});
  }
  // The engines' models after the techniques: snell's cheapest tier, compared on the same buffers.
  for (const SnellEngineModelInfo& m : snellEngineModelTable())
    if (asked(m.name)) rows.push_back(LabRowSpec{nullptr, &m});
  return rows;
}

// Stage 2: the ground truth, full paths and the two-interface reference.
struct References {
  std::unique_ptr<ReferenceTracer> tracer;
  TraceResult full, two;
  Mask tir;  // object pixels with TIR on the principal path (LabResult::tirShare)
  // The principal path of 2 + B events for each bounce count B > 0 a row follows: the model reference
  // of those rows, as `two` is of the two-interface ones.
  std::map<int, TraceResult> principal;

  const TraceResult& modelOf(int bounces) const { return bounces > 0 ? principal.at(2 + bounces) : two; }
};

// The principal-path lengths whose model floor the lab reports: one bounce inside (3), two (4), four (6).
constexpr int kFloorEvents[] = {3, 4, 6};

Mask both(const Mask& a, const Mask& b) {
  Mask m(a.width, a.height);
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) m.set(x, y, a.at(x, y) && b.at(x, y));
  return m;
}

References traceReferences(const SceneFrame& frame, const std::vector<LabRowSpec>& techniques,
                            const LabOptions& options, LabResult& result) {
  References refs;
  refs.tracer = std::make_unique<ReferenceTracer>(frame);
  TraceOptions to;
  to.threads = options.threads;
  to.progress = !options.quiet;
  to.mode = TraceMode::Full;
  refs.full = refs.tracer->render(frame.camera, to);
  to.mode = TraceMode::TwoInterfaces;
  refs.two = refs.tracer->render(frame.camera, to);
  result.traceSeconds = refs.full.stats.seconds + refs.two.stats.seconds;
  result.objectPixels = refs.full.mask.count();
  if (result.objectPixels == 0)
    throw Error(ErrorKind::Render, "the ray tracer sees no pixel of the refractive object (is it in front of the "
                                   "camera, between the near and far planes?); no error can be measured");
  result.mseTwoVsFull = compareImages(refs.full.color, refs.two.color, refs.full.mask).mse;
  refs.tir = both(refs.two.tir, refs.full.mask);
  result.tirShare = static_cast<double>(refs.tir.count()) / static_cast<double>(result.objectPixels);
  result.mseTwoVsFullTir = compareImages(refs.full.color, refs.two.color, refs.tir).mse;
  to.mode = TraceMode::Principal;
  std::set<int> kept;  // the events of the rows' models
  for (const LabRowSpec& t : techniques)
    if (t.bounces() > 0) kept.insert(2 + t.bounces());
  std::set<int> events(std::begin(kFloorEvents), std::end(kFloorEvents));
  events.insert(kept.begin(), kept.end());
  for (int e : events) {
    to.events = e;
    TraceResult principal = refs.tracer->render(frame.camera, to);
    result.traceSeconds += principal.stats.seconds;
    if (std::find(std::begin(kFloorEvents), std::end(kFloorEvents), e) != std::end(kFloorEvents))
      result.modelFloors.push_back({e, compareImages(refs.full.color, principal.color, refs.full.mask).mse,
                                    compareImages(refs.full.color, principal.color, refs.tir).mse});
    if (kept.count(e)) refs.principal.emplace(e, std::move(principal));
  }
  return refs;
}

// Stage 3a: the object pixels whose two-interface path the buffers cannot show any image-space method:
// the exact exit point P2 (critical-angle TIR, as the techniques) off screen or not the farthest back
// face at its pixel (a middle layer of a concave object), or the exit ray's hit on the opaque scene off
// screen or behind a nearer surface. Rays that leave into the environment lack nothing.
struct MissingInformation {
  Mask any;
  // Of them, the pixels whose P2 is on screen but in front of the farthest back face there: a middle
  // layer of a concave object, what a second (depth-peeled) back-face buffer could hold.
  Mask middleLayer;
};

MissingInformation missingInformation(const References& refs, const SceneFrame& frame, const StaticBuffers& sb,
                                      const ShadeConstants& k) {
  const Mask& object = refs.full.mask;
  MissingInformation info{Mask(object.width, object.height), Mask(object.width, object.height)};
  Mask& missing = info.any;
  // What the buffers hold: the viewport and the guard band around it.
  const int W = sb.backDepth.width, H = sb.backDepth.height;
  const glm::dmat4 clipFromWorld = glm::dmat4(k.params.clipFromView) * glm::dmat4(k.viewFromWorld);
  // The buffer texel a world point projects to, or false when it is off screen / behind the camera.
  const auto texel = [&](const glm::dvec3& p, int* px, int* py) {
    const glm::dvec4 c = clipFromWorld * glm::dvec4(p, 1.0);
    if (!(c.w > 0.0)) return false;
    const double u = 0.5 * (c.x / c.w + 1.0), v = 0.5 * (c.y / c.w + 1.0);
    if (!(u >= 0.0 && u < 1.0 && v >= 0.0 && v < 1.0)) return false;
    *px = std::min(W - 1, static_cast<int>(u * W));
    *py = std::min(H - 1, static_cast<int>(v * H));
    return true;
  };
  const auto viewDistance = [&](const glm::dvec3& p) { return -(glm::dmat4(k.viewFromWorld) * glm::dvec4(p, 1.0)).z; };
  const auto bufferDistance = [&](const Image& depth, int x, int y) {
    return static_cast<double>(snellLinearizeDepth(depth.at(x, y).x, k.params.zNear, k.params.zFar, SNELL_DEPTH_GL));
  };
  const double backTolerance = 0.02 * static_cast<double>(k.params.backRange);
  for (int y = 0; y < object.height; ++y)
    for (int x = 0; x < object.width; ++x) {
      if (!object.at(x, y)) continue;
      const std::vector<PathEvent> in = refs.tracer->principalPath(primaryRay(frame.camera, x, y), 2, TirPolicy::Critical);
      if (in.size() < 2 || in[0].type != PathEventType::Enter ||
          (in[1].type != PathEventType::Exit && in[1].type != PathEventType::CriticalClamp))
        continue;  // not a two-interface path (grazing or open mesh): nothing to classify
      int bx = 0, by = 0;
      const glm::dvec3 p2 = in[1].point;
      // P2's distance in front of (< 0) or behind the back face the buffer holds at its texel.
      const bool hasBack = texel(p2, &bx, &by) && sb.backDepth.at(bx, by).x > 0.0f;
      const double gap = hasBack ? viewDistance(p2) - bufferDistance(sb.backDepth, bx, by) : 0.0;
      if (!hasBack || std::abs(gap) > backTolerance) {
        missing.set(x, y, true);
        if (hasBack && gap < -backTolerance) info.middleLayer.set(x, y, true);
        continue;
      }
      Ray out;
      out.origin = p2 + refs.tracer->offsetEpsilon() * in[1].direction;
      out.direction = in[1].direction;
      const std::vector<PathEvent> ev = refs.tracer->principalPath(out, 1, TirPolicy::Critical);
      if (ev.empty() || ev[0].type != PathEventType::HitOpaque) continue;
      int sx = 0, sy = 0;
      const double d = viewDistance(ev[0].point);
      if (!texel(ev[0].point, &sx, &sy) || bufferDistance(sb.sceneDepth, sx, sy) < d * (1.0 - 1e-2))
        missing.set(x, y, true);
    }
  return info;
}

// Wyman's d_N per vertex, when a technique reads it (else none: the shaders read 0).
std::vector<float> wymanDnIfNeeded(const SceneFrame& frame, const std::vector<LabRowSpec>& techniques) {
  const bool wanted = std::any_of(techniques.begin(), techniques.end(),
                                  [](const LabRowSpec& t) { return t.needsDn(); });
  if (!wanted) return {};
  return computeWymanDn(frame.object.positions, frame.object.normals, frame.object.indices);
}

// Stage 4, per technique: what the C++ build computes for one covered pixel of the GPU's front pass.
struct CpuShader {
  const LabRowSpec& info;
  float engineParameter;  // the engine model's free value (engine rows)
  const CpuBuffers& cb;
  const LabParams& params;
  int margin;  // guard band of the buffers, texels per side

  bool readsFullScene() const { return info.engine != nullptr; }

  SnellTwoInterfaceResult operator()(vec3 p1, vec3 n1, float dN) const {
    const bool full = readsFullScene();
    return labShadeRow(info.techniqueId(), info.engineModel(), engineParameter, info.reference(), p1, n1, dN,
                       cb.backDepth, cb.backNormal, cb.backPyramid, cb.frontDepth, cb.frontNormal,
                       full ? cb.fullDepth : cb.sceneDepth, full ? cb.fullNormal : cb.sceneNormal,
                       full ? cb.fullPyramid : cb.scenePyramid, full ? cb.fullColor : cb.sceneColor, cb.environment,
                       params);
  }

  // A foreground leak: the transmitted colour of the pixel whose front face is at p1 comes from an opaque
  // surface nearer the camera than that front face (the surface at the exit hit's texel of the depth
  // buffer the row read). Counted where the exit ray heads away from the camera: a path that leaves
  // through the front faces after bouncing inside may rightly see what stands in front.
  bool leaks(vec3 p1, const SnellTwoInterfaceResult& r) const {
    if (!r.exitHit.valid || !(r.exitDirection.z <= 0.0f)) return false;
    const Image& depth = (readsFullScene() ? cb.fullDepth : cb.sceneDepth).level(0);
    const vec2 uv = glm::clamp(r.exitHit.uv, vec2(0.0f), vec2(1.0f));
    const int x = std::min(depth.width - 1, static_cast<int>(uv.x * static_cast<float>(depth.width)));
    const int y = std::min(depth.height - 1, static_cast<int>(uv.y * static_cast<float>(depth.height)));
    const double d = static_cast<double>(depth.at(x, y).x);
    if (!(d < 1.0)) return false;  // empty: the environment
    // Window depth to view distance in double (GL convention: d = (f (z - n)) / (z (f - n)) for distance z).
    const double n = static_cast<double>(params.zNear), f = static_cast<double>(params.zFar);
    const double distance = n * f / (f - d * (f - n));
    return distance < -static_cast<double>(p1.z);
  }

  // Is a CPU/GPU difference at (x, y) a rounding tie (a texel or TIR boundary that the two builds'
  // last-bit differences put on opposite sides) rather than a disagreement between the functions?
  // Nudges P1 or N1 by 1..maxUlps ulps per component (every sign pattern) and looks for a C++ result
  // within 1/255 of the GPU colour: returns the smallest nudge that reproduces it, or -1. With
  // `reproduced`, counts every reproducing nudge (and `tried`, every nudge) instead of stopping.
  int tieUlps(const TechniqueBuffers& tb, int x, int y, int maxUlps, int* reproduced, int* tried) const {
    const vec4 pf = tb.position.at(x, y), nf = tb.normal.at(x, y), gf = tb.color.at(x, y);
    int best = -1;
    for (int ulps = 1; ulps <= maxUlps; ulps *= 2)
      for (int which = 0; which < 2; ++which)
        for (int dx = -1; dx <= 1; ++dx)
          for (int dy = -1; dy <= 1; ++dy)
            for (int dz = -1; dz <= 1; ++dz) {
              vec3 q(pf), m(nf);
              vec3& v = which == 0 ? q : m;
              const int d[3] = {dx, dy, dz};
              for (int a = 0; a < 3; ++a)
                for (int s = 0; s < ulps * std::abs(d[a]); ++s) v[a] = std::nextafter(v[a], d[a] > 0 ? 1e30f : -1e30f);
              const SnellTwoInterfaceResult rr = (*this)(q, m, pf.w);
              float e = 0.0f;
              for (int a = 0; a < 3; ++a) e = std::max(e, std::abs(clamp01(rr.color[a]) - clamp01(gf[a])));
              if (tried) ++*tried;
              if (e <= 1.0f / 255.0f) {
                if (reproduced) ++*reproduced;
                if (best < 0) best = ulps;
                if (!reproduced) return best;
              }
            }
    return best;
  }
};

// Stage 4a: the C++ image of one technique: the same labShade per covered pixel of the GPU's front
// pass, on the read-back inputs. rgb colour; stats x = fell back, y = fetches, z = a foreground leak
// (CpuShader::leaks).
void shadeOnCpu(const CpuShader& shade, const TechniqueBuffers& tb, int threads, Image& color, Image& stats) {
  parallelRows(tb.normal.height, threads, [&](int y) {
    for (int x = 0; x < tb.normal.width; ++x) {
      const vec4 n = tb.normal.at(x, y);
      if (!(n.w > 0.0f)) continue;
      const vec4 p = tb.position.at(x, y);
      const SnellTwoInterfaceResult r = shade(vec3(p), vec3(n), p.w);
      color.at(x, y) = vec4(r.color, 1.0f);
      stats.at(x, y) = vec4(r.fellBack ? 1.0f : 0.0f, static_cast<float>(r.fetches),
                            shade.leaks(vec3(p), r) ? 1.0f : 0.0f, 0.0f);
    }
  });
}

// Stage 4b: the row's shares and the CPU-vs-GPU agreement, over the front pass's covered pixels.
void compareCpuGpu(const CpuShader& shade, const TechniqueBuffers& tb, const Image& cpuColor, const Image& cpuStats,
                   TechniqueRow& row) {
  auto covered = [&](int x, int y) { return tb.normal.at(x, y).w > 0.0f; };
  const gpu::FrameComparison c =
      gpu::compareFrames(tb.color, cpuColor, covered, gpu::ClampChannels::ToUnit, [&](int x, int y) {
        row.cpuGpuBeyond4Ties += shade.tieUlps(tb, x, y, kTieUlps, nullptr, nullptr) > 0;
      });
  row.cpuGpuMaxAbs = c.maxAbs;
  row.worstX = c.worstX;
  row.worstY = c.worstY;
  row.cpuGpuBeyond4Pixels = static_cast<int>(c.beyond4);
  std::size_t invalid = 0, backMiss = 0, exitMiss = 0, fetchDiff = 0, leaks = 0;
  double fetches = 0.0;
  for (int y = 0; y < tb.normal.height; ++y)
    for (int x = 0; x < tb.normal.width; ++x) {
      if (!covered(x, y)) continue;
      const vec4 s = tb.stats.at(x, y);
      invalid += s.x > 0.5f;
      backMiss += s.z < 0.5f;
      exitMiss += s.w < 0.5f;
      fetches += static_cast<double>(s.y);
      fetchDiff += s.y != cpuStats.at(x, y).y;
      leaks += cpuStats.at(x, y).z > 0.5f;
    }
  const double n = c.pixels ? static_cast<double>(c.pixels) : 1.0;
  row.invalidShare = static_cast<double>(invalid) / n;
  row.backMissShare = static_cast<double>(backMiss) / n;
  row.exitMissShare = static_cast<double>(exitMiss) / n;
  row.fetchesPerPixel = fetches / n;
  row.cpuGpuBeyond1 = static_cast<double>(c.pixels - c.within1) / n;
  row.cpuGpuBeyond4 = static_cast<double>(c.beyond4) / n;
  row.fetchMismatch = static_cast<double>(fetchDiff) / n;
  row.leakPixels = static_cast<int>(leaks);
}

// SNELL_LAB_DEBUG_PARITY: the worst pixel's inputs and both builds' results, on stderr.
void debugWorstPixel(const CpuShader& shade, const TechniqueBuffers& tb, const Image& cpuColor, const Image& cpuStats,
                     const TechniqueRow& row) {
  if (!std::getenv("SNELL_LAB_DEBUG_PARITY") || row.worstX < 0) return;
  const int x = row.worstX, y = row.worstY;
  const glm::dvec4 p(tb.position.at(x, y)), nn(tb.normal.at(x, y)), g(tb.color.at(x, y)), c(cpuColor.at(x, y));
  const glm::dvec4 gs(tb.stats.at(x, y)), cs(cpuStats.at(x, y));
  std::fprintf(stderr,
               "[parity] %s worst pixel (%d, %d): |d| %.2f/255; P1 (%.9g %.9g %.9g) N1 (%.9g %.9g %.9g) dN %.9g\n"
               "  gpu rgb (%.5f %.5f %.5f) fellBack %g fetches %g backHit %g exitHit %g\n"
               "  cpu rgb (%.5f %.5f %.5f) fellBack %g fetches %g\n",
               shade.info.name().c_str(), x, y, 255.0 * row.cpuGpuMaxAbs, p.x, p.y, p.z, nn.x, nn.y, nn.z, p.w, g.x, g.y, g.z,
               gs.x, gs.y, gs.z, gs.w, c.x, c.y, c.z, cs.x, cs.y);
  int reproduced = 0, tried = 0;
  const int bestUlps = shade.tieUlps(tb, x, y, 32, &reproduced, &tried);
  std::fprintf(stderr, "  input nudges (P1 or N1, 1..32 ulps) reproducing the GPU colour: %d of %d, smallest %d ulps\n",
               reproduced, tried, bestUlps);
}

// Stage 4: one technique on the GPU, the same in C++, compared; its image (the object composited over
// the scene) for the pictures.
TechniqueRow runTechnique(GpuLab& gpu, std::size_t index, const CpuShader& shade, const StaticBuffers& sb,
                          const References& refs, int threads, Image& image) {
  gpu.renderTechnique(index);  // also compiles the shader's JIT code: not timed
  const TechniqueBuffers tb = gpu.readTechnique();
  Image cpuColor(tb.color.width, tb.color.height), cpuStats(tb.color.width, tb.color.height);
  shadeOnCpu(shade, tb, threads, cpuColor, cpuStats);
  TechniqueRow row;
  row.name = shade.info.name();
  row.label = shade.info.label();
  compareCpuGpu(shade, tb, cpuColor, cpuStats, row);
  debugWorstPixel(shade, tb, cpuColor, cpuStats, row);
  // Coverage: the ray tracer's object pixels that the front pass did not shade (near-plane clipping,
  // silhouette rasterization) hold the scene colour in the composite; say how many, and refuse to score
  // a technique that shaded none of them.
  const Mask& object = refs.full.mask;
  std::size_t unshaded = 0, overdrawn = 0;
  for (int y = 0; y < tb.normal.height; ++y)
    for (int x = 0; x < tb.normal.width; ++x) {
      const bool covered = tb.normal.at(x, y).w > 0.0f;
      unshaded += object.at(x, y) && !covered;
      overdrawn += !object.at(x, y) && covered;
    }
  const std::size_t objectPixels = object.count();
  if (unshaded == objectPixels)
    throw Error(ErrorKind::Render,
                "technique " + shade.info.name() + " shaded none of the " + std::to_string(objectPixels) +
                    " pixels where the ray tracer sees the object (does the near plane cut the object, or does the "
                    "camera sit inside it?); no error can be measured");
  row.unshadedShare = objectPixels ? static_cast<double>(unshaded) / static_cast<double>(objectPixels) : 0.0;
  row.overdrawnShare = objectPixels ? static_cast<double>(overdrawn) / static_cast<double>(objectPixels) : 0.0;
  image = composite(tb.color, tb.normal, sb.fullColor, shade.margin);
  row.mseFull = compareImages(refs.full.color, image, refs.full.mask).mse;
  row.mseTwo = compareImages(refs.two.color, image, refs.full.mask).mse;
  row.mseFullTir = compareImages(refs.full.color, image, refs.tir).mse;
  row.bounces = shade.info.bounces();
  row.modelEvents = 2 + row.bounces;
  row.mseModel = compareImages(refs.modelOf(row.bounces).color, image, refs.full.mask).mse;
  return row;
}

// Stage 4, before an engine row runs: its free value (a material's thickness, Godot's uv scale) has no value in
// the scene, so it is swept on this scene and the best value by MSE against the full ray tracer is kept: the
// comparison is as fair to the engine as a user tuning it by eye could be at best. The C++ build of the same
// row shades the GPU front pass's inputs for every value; the GPU then runs the best.
struct EngineSweep {
  float best = 0.0f;
  std::vector<std::pair<float, double>> tried;  // (value, MSE vs the full ray tracer), in the order tried
};

// The sweep: a grid of 41 values (lengths 0 to the object's bounding-box diagonal d, uv scales 0 to 0.3; Godot's
// default is 0.05), on in steps of 1.25x while the grid's last value is the best (to 8 d, or Godot's clamp 1), then
// six halvings of the step on both sides of the best. Each value costs one C++ frame of the cheap model (about
// 20 ms at 512x512 on 2 cores).
std::vector<float> engineGrid(const SnellEngineModelInfo& m, const LabParams& p) {
  const float top = m.kind == SnellEngineParameterKind::UvScale ? 0.3f : p.backRange;
  std::vector<float> v;
  for (int i = 0; i <= 40; ++i) v.push_back(top * static_cast<float>(i) / 40.0f);
  return v;
}

EngineSweep sweepEngineParameter(GpuLab& gpu, std::size_t index, const LabRowSpec& row, const CpuBuffers& cb,
                                 const LabParams& params, const StaticBuffers& sb, const References& refs,
                                 int threads, int margin) {
  gpu.renderTechnique(index);
  const TechniqueBuffers tb = gpu.readTechnique();
  EngineSweep sweep;
  double bestMse = 0.0;
  const auto tryValue = [&](float value) {
    Image color(tb.color.width, tb.color.height), stats(tb.color.width, tb.color.height);
    shadeOnCpu(CpuShader{row, value, cb, params, margin}, tb, threads, color, stats);
    const double mse =
        compareImages(refs.full.color, composite(color, tb.normal, sb.fullColor, margin), refs.full.mask).mse;
    sweep.tried.emplace_back(value, mse);
    if (sweep.tried.size() == 1 || mse < bestMse) {
      bestMse = mse;
      sweep.best = value;
    }
  };
  std::vector<float> grid = engineGrid(*row.engine, params);
  for (float value : grid) tryValue(value);
  const bool uv = row.engine->kind == SnellEngineParameterKind::UvScale;
  const float cap = uv ? 1.0f : 8.0f * params.backRange;
  float step = grid[1] - grid[0];
  while (sweep.best == grid.back() && grid.back() > 0.0f && grid.back() < cap) {
    step = std::min(cap, 1.25f * grid.back()) - grid.back();
    grid.push_back(grid.back() + step);
    tryValue(grid.back());
  }
  for (int halving = 0; halving < 6; ++halving) {
    step *= 0.5f;
    const float best = sweep.best;
    if (best - step >= 0.0f) tryValue(best - step);
    if (best + step <= cap) tryValue(best + step);
  }
  return sweep;
}

// Stage 4c: every row against the image-space bound, and the bound's own error split into the pixels
// whose path the buffers do not hold (missingInformation) and the rest.
void scoreAgainstTheBound(const std::vector<LabRowSpec>& techniques, const std::vector<Image>& images,
                          const MissingInformation& missing, const References& refs, LabResult& result) {
  // The bound of the rows with `bounces` (selectTechniques runs one for every count a row has).
  const auto boundOf = [&](int bounces) {
    std::size_t b = 0;
    while (b < techniques.size() &&
           !(techniques[b].reference() && techniques[b].bounces() == bounces))
      ++b;
    return b;
  };
  const std::size_t b = boundOf(0);
  if (b == techniques.size()) return;
  const Mask& object = refs.full.mask;
  const double n = std::max<double>(1.0, static_cast<double>(object.count()));
  double information = 0.0, buffer = 0.0, middle = 0.0;
  std::size_t informationPixels = 0, middlePixels = 0;
  for (int y = 0; y < object.height; ++y)
    for (int x = 0; x < object.width; ++x) {
      if (!object.at(x, y)) continue;
      const double e = pixelSquaredError(refs.two.color.at(x, y), images[b].at(x, y));
      if (missing.middleLayer.at(x, y)) {
        middle += e;
        ++middlePixels;
      }
      if (missing.any.at(x, y)) {
        information += e;
        ++informationPixels;
      } else {
        buffer += e;
      }
    }
  result.boundInformationMse = information / n;
  result.boundBufferMse = buffer / n;
  result.boundInformationShare = static_cast<double>(informationPixels) / n;
  result.boundMiddleLayerMse = middle / n;
  result.boundMiddleLayerShare = static_cast<double>(middlePixels) / n;
  for (std::size_t i = 0; i < techniques.size(); ++i) {
    TechniqueRow& row = result.rows[i];
    const std::size_t own = boundOf(row.bounces);
    if (own == techniques.size()) continue;
    const double boundMse = result.rows[own].mseModel;
    row.mseBound = compareImages(images[own], images[i], object).mse;
    row.boundRatio = boundMse > 0.0 ? row.mseModel / boundMse : 0.0;
  }
}

// Stage 5: all techniques interleaved, frame after frame; median per technique, ratios to single sample
// (to the first row when single sample did not run).
void timeTechniques(GpuLab& gpu, const std::vector<LabRowSpec>& techniques, int frames,
                    LabResult& result) {
  std::vector<std::vector<double>> times(techniques.size());
  // The bound is a reference, not a contender: one timed frame is enough to show its cost.
  for (int f = 0; f < frames; ++f)
    for (std::size_t i = 0; i < techniques.size(); ++i)
      if (f == 0 || !techniques[i].reference()) times[i].push_back(gpu.renderTechnique(i));
  double unit = 0.0;
  for (std::size_t i = 0; i < techniques.size(); ++i) {
    result.rows[i].medianMs = median(times[i]);
    if (techniques[i].costUnit()) unit = result.rows[i].medianMs;
  }
  if (unit <= 0.0 && !result.rows.empty()) unit = result.rows[0].medianMs;
  for (TechniqueRow& r : result.rows) r.costRatio = unit > 0.0 ? r.medianMs / unit : 0.0;
}

// Stage 6: the pictures (ground truth, model error, a panel per technique, the overview) and the tables.
void writeOutputs(const fs::path& out, const References& refs, const std::vector<Image>& images,
                  const std::string& gpuDescription, LabResult& result,
                  std::chrono::steady_clock::time_point start) {
  const Image& full = refs.full.color;
  const Image& two = refs.two.color;
  const int W = result.width, H = result.height;
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw Error(ErrorKind::Io, "cannot create output directory " + out.string() + ": " + ec.message());
  writePng((out / "ground_truth.png").string(), full);
  const Image modelHeat = errorHeatMap(full, two, refs.full.mask);
  writePng((out / "reference_two_interfaces.png").string(),
           composePanel({{&full, "ray traced (full)"}, {&two, "two interfaces"}, {&modelHeat, "error"}},
                        result.scene + ": two-interface model, MSE " + fmt("%.3g", result.mseTwoVsFull)));
  const int factor = W >= 512 ? 2 : 1;
  std::vector<Image> tiles;
  std::vector<std::string> labels;
  tiles.push_back(downscale(full, factor));
  labels.push_back("ray traced");
  tiles.push_back(downscale(two, factor));
  labels.push_back("two interfaces " + fmt("%.2g", result.mseTwoVsFull));
  for (std::size_t i = 0; i < result.rows.size(); ++i) {
    const TechniqueRow& r = result.rows[i];
    const Image heat = errorHeatMap(full, images[i], refs.full.mask);
    // The time ratio is to single sample when it ran, else to the first row (as in the table).
    const bool singleRan = result.costUnitRow() != nullptr;
    char numbers[256];
    std::snprintf(numbers, sizeof numbers, ": MSE %.3g (two-interface ref. %.3g), invalid %.1f%%, %.1f fetches/px, %.2fx ",
                  r.mseFull, r.mseTwo, 100.0 * r.invalidShare, r.fetchesPerPixel, r.costRatio);
    const std::string caption = result.scene + ", " + r.label + numbers +
                                (singleRan ? "single sample's time" : "the time of " + result.rows.front().label);
    writePng((out / (r.name + ".png")).string(),
             composePanel({{&full, "ray traced"}, {&images[i], r.label}, {&heat, "error (RMS, white 0.25)"}}, caption));
    tiles.push_back(downscale(images[i], factor));
    labels.push_back(r.label + " " + fmt("%.2g", r.mseFull) + " " + fmt("%.2fx", r.costRatio));
  }
  // Overview: rows of four tiles.
  const int perRow = 4, scale = 1;
  std::vector<Image> rows;
  for (std::size_t i = 0; i < tiles.size(); i += perRow) {
    std::vector<PanelItem> items;
    for (std::size_t j = i; j < std::min(tiles.size(), i + perRow); ++j) items.push_back({&tiles[j], labels[j]});
    rows.push_back(composePanel(items, "", 6, scale));
  }
  int cw = 0, ch = 0;
  for (const Image& r : rows) {
    cw = std::max(cw, r.width);
    ch += r.height;
  }
  const std::string title = result.scene + ": MSE vs ray tracing, time vs single sample (" + std::to_string(W) + "x" +
                            std::to_string(H) + ", " + gpuDescription.substr(0, gpuDescription.find(',')) + ")";
  const int titleH = textHeight(title, 1) + 8;
  Image overview(std::max(cw, textWidth(title, 1) + 12), ch + titleH, vec4(0.06f, 0.06f, 0.07f, 1.0f));
  drawText(overview, 6, 4, title, vec3(1.0f), 1);
  int yTop = titleH;
  for (const Image& r : rows) {
    blit(overview, r, 0, yTop);
    yTop += r.height;
  }
  writePng((out / "overview.png").string(), overview);
  writeText(out / "table.md", "# snell-lab: " + result.scene + "\n\n" + result.markdown + "\n" + result.targets);
  result.totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  writeJson(out / "table.json", result);
}

}  // namespace

// The guard band in texels per side: the fraction asked for, grown until both buffer sides are multiples
// of 32 where that is possible: the depth pyramid's levels then halve exactly for five levels (odd sizes
// drop a texel row per level, which shifts the coarse levels the depth-based plane reads).
namespace {
int guardBandMargin(double fraction, int width, int height) {
  int margin = static_cast<int>(std::lround(fraction * std::max(width, height)));
  if (margin > 0)
    for (int m = margin; m < margin + 32; ++m)
      if ((width + 2 * m) % 32 == 0 && (height + 2 * m) % 32 == 0) return m;
  return margin;
}
}  // namespace

LabResult runLab(const LabOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<LabRowSpec> techniques = selectTechniques(options);

  Scene scene = loadScene(options.scenePath);
  if (options.width > 0) scene.camera.width = options.width;
  if (options.height > 0) scene.camera.height = options.height;
  const SceneFrame frame = buildFrame(scene, scene.frameTime(0));

  LabResult result;
  result.scene = scene.name.empty() ? fs::path(options.scenePath).stem().string() : scene.name;
  result.width = frame.camera.width;
  result.height = frame.camera.height;
  result.frames = options.frames;

  const References refs = traceReferences(frame, techniques, options, result);

  // Stage 3: the GPU passes that do not depend on the technique (scene, back faces, pyramids), once:
  // the frame is static. Their read-back buffers are what the C++ side shades from.
  std::vector<LabShader> shaders;
  for (const LabRowSpec& t : techniques) shaders.push_back({t.techniqueId(), t.reference(), t.engineModel()});
  const int margin = guardBandMargin(options.guardBand, result.width, result.height);
  result.guardBand = margin;
  ShadeConstants k = shadeConstants(frame, margin);
  k.normalFilter = options.normalFilter;
  k.params.depthFilter = options.depthFilter;
  k.params.reflectSource = options.reflectSource;
  k.sceneLayer = options.sceneLayer;
  result.sceneLayer = options.sceneLayer;
  // The web page offers every technique, ISR's d_N included.
  const std::vector<float> dN = options.webBundleDir.empty()
                                    ? wymanDnIfNeeded(frame, techniques)
                                    : computeWymanDn(frame.object.positions, frame.object.normals, frame.object.indices);
  GpuLab gpu(options.backend, frame, dN, shaders, options.dirs, k);
  result.gpu = gpu.description();
  result.staticPassMs = gpu.renderStatic();
  const StaticBuffers sb = gpu.readStatic();
  const CpuBuffers cb = cpuBuffers(sb, k, frame);
  const LabParams& params = k.params;
  result.objectDiagonal = params.backRange;

  std::vector<Image> images(techniques.size());
  for (std::size_t i = 0; i < techniques.size(); ++i) {
    EngineSweep sweep;
    if (techniques[i].engine) {
      sweep = sweepEngineParameter(gpu, i, techniques[i], cb, params, sb, refs, options.threads, k.margin);
      gpu.setEngineParameter(i, sweep.best);
    }
    TechniqueRow row = runTechnique(gpu, i, CpuShader{techniques[i], sweep.best, cb, params, k.margin}, sb, refs,
                                    options.threads, images[i]);
    row.engineSweep = sweep.tried;
    row.engineParameter = sweep.best;
    result.rows.push_back(std::move(row));
  }
  scoreAgainstTheBound(techniques, images, missingInformation(refs, frame, sb, k), refs, result);

  timeTechniques(gpu, techniques, options.frames, result);
  result.markdown = markdownTable(result);
  result.targets = targetsText(result) + whichToPick(result);
  if (!options.outDir.empty()) writeOutputs(options.outDir, refs, images, gpu.description(), result, start);
  if (!options.webBundleDir.empty()) {
    std::vector<WebBundleImage> ran;
    for (std::size_t i = 0; i < techniques.size(); ++i) ran.push_back({techniques[i], &images[i]});
    // The front pass's fragment inputs are the same for every row: the last timed draw left them in pass 4's
    // buffers, so no draw is needed.
    writeWebBundle(options.webBundleDir, result.scene, frame, dN, k, ran, refs.full.mask, sb, gpu.readTechnique());
  }
  result.totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace snell::lab
