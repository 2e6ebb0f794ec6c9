// The ground truth: a CPU ray tracer on Embree 3 through the real triangles of
// the refractive meshes, with interpolated (smooth) normals, exact Snell
// refraction and exact Fresnel (double precision, lab/exact_optics.hpp) at
// every interface, total internal reflection followed up to a depth limit,
// Beer-Lambert absorption over the path length inside, and the same
// environment and opaque paintings the GL renderer draws. Several objects are
// nested media: the ray carries the stack of objects it is inside; at a
// surface the relative index is the medium's before over the medium's after
// (where two objects overlap, the one entered last is the medium). Rays through
// the pixel centre (what a rasterizer shades). Smooth objects are traced once
// per pixel, deterministic: no noise. A rough object's interfaces (its
// roughness r > 0) are GGX microfacet surfaces with alpha = r^2 (Walter et al.
// 2007, lab/rough_optics.hpp), sampled: TraceOptions::samples paths per pixel
// whose path meets one, with random numbers seeded per pixel, and the noise
// that leaves in the image estimated (TraceResult::noise).
#pragma once
#include "lab/camera.hpp"
#include "lab/environment.hpp"
#include "lab/exact_optics.hpp"
#include "lab/mask.hpp"
#include "lab/mesh.hpp"
#include "lab/painting.hpp"
#include "lab/scene.hpp"

#include <snell/bridge.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace snell::lab {

enum class TraceMode {
  // Every interface splits into Fresnel-weighted reflection and refraction
  // (TIR: reflection only), recursively, until maxDepth or minWeight.
  Full,
  // What the image-space techniques model: refract in at the first surface,
  // refract out at the next surface the ray meets (TIR clamped to the critical
  // angle, as SNELL_TIR_CRITICAL), then look up the background (paintings,
  // else environment) without meeting the object again. With `fresnel`, the
  // first surface's reflection of the background is added. The principal
  // path below with 2 events (on each object it meets).
  TwoInterfaces,
  // The principal path for at most TraceOptions::events interface events
  // (the entry is the first): refract wherever Snell allows, reflect on TIR
  // and go on inside, no Fresnel branching inside; the last event clamps TIR
  // to the critical angle as the image-space techniques do. A ray that
  // leaves, or is clamped at the last event, looks up the background
  // (paintings, else environment) without meeting the object again: what an
  // image-space method that follows bounces can reach (the model floor for
  // that many events). `fresnel` adds the first surface's reflection. With
  // several objects, the events count per object and the path goes on past an
  // object it left to the others (never back into it): what rendering the
  // objects back to front, each reading what is drawn behind it, can reach.
  // Fresnel then adds each object's first-surface reflection, traced on
  // without that object.
  Principal,
};

struct TraceOptions {
  TraceMode mode = TraceMode::Full;
  int maxDepth = 16;         // Full: interface events on one path (deeper: black)
  int events = 2;            // Principal: interface events on the path per object (2 to 255)
  double minWeight = 1e-4;   // Full: reflection branches below this throughput are dropped
  bool fresnel = true;       // false: transmission only (weight 1; Full: TIR still reflects)
  bool absorption = true;    // Beer-Lambert inside the object
  int threads = 0;           // 0: std::thread::hardware_concurrency()
  bool progress = true;      // progress bar on stderr (only when it is a terminal)
  // The IOR the objects refract with: -1, each colour channel traced with its own (channelIors: three paths
  // per pixel where an object disperses, one where none does); 0, 1, 2: every channel with the red, green
  // (the d line: `ior`) or blue one.
  int channel = -1;
  // Rough objects: paths per pixel whose first path meets a rough interface (the others are traced once:
  // their every path is the same). At each rough interface a path samples a microfacet normal (Walter et al.
  // 2007, eq. 35-36); Full mode then reflects or refracts with probability F (eq. 41's weight), the
  // principal path refracts about it (reflecting on TIR as at a smooth interface), its entry's Fresnel
  // reflection about the same normal. The random numbers of pixel (x, y) come from (seed, x, y) alone: the
  // same seed draws the same numbers at a pixel whatever the thread, the image or the frame. Each path, and
  // each event along it, has its own stream (keyed by the path's index and the branches before it), so a
  // path that meets another number of interfaces in the next frame leaves every other path's numbers alone.
  int samples = 256;
  std::uint64_t seed = 0;
};

struct TraceStats {
  double seconds = 0.0;             // wall time of render()
  std::uint64_t rays = 0;           // Embree ray queries
  std::uint64_t objectPixels = 0;   // pixels whose primary ray hits the object
  std::uint64_t tirEvents = 0;      // total internal reflections (Full) / clamps (TwoInterfaces)
  // Paths that left the object without an exit refraction: an open mesh, or a
  // smooth (interpolated) normal that bent the ray across the flat triangle
  // (coarse meshes such as the bunny, a few per thousand object pixels).
  std::uint64_t leaks = 0;
  std::uint64_t truncated = 0;      // paths cut at maxDepth
  std::uint64_t sampledPixels = 0;  // pixels traced with TraceOptions::samples paths (a rough interface met)
  // Over the object pixels: the sum of the channel-averaged variance of each pixel's mean (the paths'
  // sample variance over their count): what TraceResult::noise averages.
  double varianceSum = 0.0;
  TraceStats& operator+=(const TraceStats& o);
};

struct TraceResult {
  Image color;  // linear RGB, alpha 1; row 0 at the bottom
  Mask mask;    // pixels whose primary ray hits the refractive object first
  // Pixels whose path met total internal reflection inside the object (Full: on
  // any branch; TwoInterfaces, Principal: on the principal path, the last
  // event's critical clamp included).
  Mask tir;
  TraceStats stats;
  // The expected MSE (lab/metrics.hpp, unclamped) of `color` against the exact image over `mask`: the
  // variance of the pixels' means, estimated from their paths; 0 when no path met a rough interface. A
  // row's MSE against this image is its MSE against the exact one plus this, on average.
  double noise = 0.0;
};

enum class PathEventType {
  Enter,               // refracted into the object
  Exit,                // refracted out of the object
  TotalInternalReflection,
  CriticalClamp,       // TIR under TirPolicy::Critical: direction tangent to the surface
  HitOpaque,           // stopped on a painting
  Escape,              // left the scene (environment)
};

struct PathEvent {
  PathEventType type = PathEventType::Escape;
  glm::dvec3 point{0.0};      // where it happened (Escape: start of the last segment)
  glm::dvec3 normal{0.0};     // interpolated normal, outward (object events)
  glm::dvec3 direction{0.0};  // direction after the event
  double distance = 0.0;      // length of the segment that led here (Escape: 0)
  int object = -1;            // the refractive object of an object event (SceneFrame::objects' order)
};

class ReferenceTracer {
 public:
  // Copies what it needs; builds the Embree scenes (Error(Render) on failure).
  explicit ReferenceTracer(const SceneFrame& frame);
  ReferenceTracer(const std::vector<FrameObject>& objects, std::vector<Painting> paintings, Environment environment);
  ReferenceTracer(const Mesh& object, float ior, vec3 absorption, std::vector<Painting> paintings,
                  Environment environment);  // one object
  ~ReferenceTracer();
  ReferenceTracer(const ReferenceTracer&) = delete;
  ReferenceTracer& operator=(const ReferenceTracer&) = delete;

  // Renders camera.width x camera.height pixels on options.threads threads.
  TraceResult render(const Camera& camera, const TraceOptions& options) const;

  // The composited two-interface model: what drawing the objects one after the other in `order`, each
  // with its exact two-interface path (refract in with index[object], per colour channel, TIR clamped to the critical
  // angle at the exit, Fresnel reflection at the entry), reading what is drawn behind it as a picture, can
  // reach. Each object's pass covers the pixels where its front face is nearer than the paintings and
  // shades them over the frame so far; its rays see the paintings, and the objects drawn before it as
  // the frame shows them where they meet them (bilinear between pixel centres; off screen: as if they
  // were not there). The floor of any image-space method that composites objects (mask: pixels whose
  // primary ray meets an object first; tir: clamped exits). Every interface is smooth here (roughness ignored).
  TraceResult renderComposited(const Camera& camera, const std::vector<std::size_t>& order,
                               const std::vector<glm::dvec3>& index, const TraceOptions& options) const;

  // Radiance along one ray (linear RGB). hitObject: whether the ray's first
  // hit is the refractive object. One path: at rough interfaces, with random
  // numbers seeded by options.seed alone.
  glm::dvec3 radiance(const Ray& ray, const TraceOptions& options, TraceStats* stats = nullptr,
                      bool* hitObject = nullptr) const;

  // The principal specular path of a ray (every interface smooth, roughness ignored): refraction wherever Snell allows it,
  // TIR handled by `policy` (Reflect: mirror; Critical: tangent clamp), no
  // Fresnel branching, with the objects' IOR at the d line (green); stops at an escape, a painting, or after maxEvents
  // object interfaces. Whether each hit enters or exits is decided by the
  // geometric normal (outward winding), so rays may start inside the object.
  std::vector<PathEvent> principalPath(const Ray& ray, int maxEvents, TirPolicy policy) const;

  double ior() const;  // the first object's (at the d line)
  double offsetEpsilon() const;  // the self-intersection offset along the normal

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace snell::lab
