#include "references.hpp"

#include "lab/error.hpp"
#include "lab/metrics.hpp"

#include <snell/camera.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>

namespace snell::lab {

namespace {

// The principal-path lengths whose model floor the lab reports: one bounce inside (3), two (4), four (6).
constexpr int kFloorEvents[] = {3, 4, 6};

Mask both(const Mask& a, const Mask& b) {
  Mask m(a.width, a.height);
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) m.set(x, y, a.at(x, y) && b.at(x, y));
  return m;
}

}  // namespace

TraceOptions truthOptions(const LabOptions& options) {
  TraceOptions to;
  to.mode = TraceMode::Full;
  to.threads = options.threads;
  to.progress = !options.quiet;
  to.samples = options.truthSamples;
  return to;
}

References traceReferences(const SceneFrame& frame, const std::vector<LabRowSpec>& techniques,
                            const LabOptions& options, LabResult& result) {
  References refs;
  refs.tracer = std::make_unique<ReferenceTracer>(frame);
  TraceOptions to = truthOptions(options);
  refs.full = refs.tracer->render(frame.camera, to);
  if (refs.full.stats.sampledPixels > 0) {
    result.truthSamples = to.samples;
    result.truthNoise = refs.full.noise;
  }
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
  refs.escapes = Mask(refs.full.mask.width, refs.full.mask.height);
  for (int y = 0; y < refs.escapes.height; ++y)
    for (int x = 0; x < refs.escapes.width; ++x) {
      if (!refs.full.mask.at(x, y)) continue;
      const std::vector<PathEvent> path = refs.tracer->principalPath(primaryRay(frame.camera, x, y), 3, TirPolicy::Critical);
      refs.escapes.set(x, y, path.size() == 3 && path[0].type == PathEventType::Enter &&
                                 (path[1].type == PathEventType::Exit || path[1].type == PathEventType::CriticalClamp) &&
                                 path[1].object == path[0].object && path[2].type == PathEventType::Escape);
    }
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

void traceComposited(References& refs, const SceneFrame& frame, const std::vector<std::size_t>& order,
                     const std::vector<ShadeConstants>& k, const LabOptions& options, LabResult& result) {
  TraceOptions to;
  to.threads = options.threads;
  to.progress = !options.quiet;
  std::vector<glm::dvec3> index;  // what the passes use (shadeConstants)
  for (const ShadeConstants& c : k) index.push_back(glm::dvec3(c.params.iors));
  refs.composited = refs.tracer->renderComposited(frame.camera, order, index, to);
  result.traceSeconds += refs.composited.stats.seconds;
  result.mseCompositedVsFull = compareImages(refs.full.color, refs.composited.color, refs.full.mask).mse;
}

MissingInformation missingInformation(const References& refs, const SceneFrame& frame,
                                      const std::vector<StaticBuffers>& buffers, const std::vector<ShadeConstants>& ks,
                                      const std::vector<std::size_t>& order) {
  const Mask& object = refs.full.mask;
  MissingInformation info{Mask(object.width, object.height), Mask(object.width, object.height)};
  Mask& missing = info.any;
  std::vector<std::size_t> position(order.size());
  for (std::size_t p = 0; p < order.size(); ++p) position[order[p]] = p;
  // What the buffers hold: the viewport and the guard band around it.
  const int W = buffers.front().backDepth.width, H = buffers.front().backDepth.height;
  const ShadeConstants& k0 = ks.front();  // the camera's matrices: the same for every object
  const glm::dmat4 clipFromWorld = glm::dmat4(k0.params.clipFromView) * glm::dmat4(k0.viewFromWorld);
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
  const auto viewDistance = [&](const glm::dvec3& p) { return -(glm::dmat4(k0.viewFromWorld) * glm::dvec4(p, 1.0)).z; };
  const auto bufferDistance = [&](const Image& depth, int x, int y) {
    return static_cast<double>(snellLinearizeDepth(depth.at(x, y).x, k0.params.zNear, k0.params.zFar, SNELL_DEPTH_GL));
  };
  for (int y = 0; y < object.height; ++y)
    for (int x = 0; x < object.width; ++x) {
      if (!object.at(x, y)) continue;
      const std::vector<PathEvent> in = refs.tracer->principalPath(primaryRay(frame.camera, x, y), 2, TirPolicy::Critical);
      if (in.size() < 2 || in[0].type != PathEventType::Enter ||
          (in[1].type != PathEventType::Exit && in[1].type != PathEventType::CriticalClamp) || in[1].object != in[0].object)
        continue;  // not a two-interface path of its object (grazing, open mesh, nested): nothing to classify
      const std::size_t o = static_cast<std::size_t>(in[0].object);
      const StaticBuffers& sb = buffers[position[o]];
      const double backTolerance = 0.02 * static_cast<double>(ks[o].params.backRange);
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
      if (ev.empty()) continue;
      // The exit ray meets an opaque surface, or another object: in the layer when drawn before this one.
      const bool other = ev[0].type == PathEventType::Enter && ev[0].object >= 0 && static_cast<std::size_t>(ev[0].object) != o;
      if (other && position[static_cast<std::size_t>(ev[0].object)] > position[o]) {
        missing.set(x, y, true);
        continue;
      }
      if (ev[0].type != PathEventType::HitOpaque && !other) continue;
      int sx = 0, sy = 0;
      const double d = viewDistance(ev[0].point);
      if (!texel(ev[0].point, &sx, &sy) || bufferDistance(sb.sceneDepth, sx, sy) < d * (1.0 - 1e-2))
        missing.set(x, y, true);
    }
  return info;
}

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

}  // namespace snell::lab
