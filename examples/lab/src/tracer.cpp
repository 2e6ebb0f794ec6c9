#include "lab/tracer.hpp"

#include "lab/error.hpp"
#include "lab/progress.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <string>
#include <thread>
#include <utility>

namespace snell::lab {

TraceStats& TraceStats::operator+=(const TraceStats& o) {
  rays += o.rays;
  objectPixels += o.objectPixels;
  tirEvents += o.tirEvents;
  leaks += o.leaks;
  truncated += o.truncated;
  return *this;
}

namespace {

enum class HitKind { None, Object, Painting };

struct Hit {
  HitKind kind = HitKind::None;
  double t = 0.0;
  unsigned prim = 0;
  double u = 0.0, v = 0.0;
};

void embreeError(void* user, RTCError code, const char* message) {
  auto* sink = static_cast<std::string*>(user);
  if (sink->empty()) *sink = "Embree error " + std::to_string(static_cast<int>(code)) + ": " + (message ? message : "");
}

glm::dvec3 toD(const vec3& v) { return glm::dvec3(v); }

}  // namespace

struct ReferenceTracer::Impl {
  RTCDevice device = nullptr;
  RTCScene full = nullptr;        // object (geomID kObject) + paintings (kPaintings)
  RTCScene background = nullptr;  // paintings only (geomID 0)
  unsigned objectGeom = RTC_INVALID_GEOMETRY_ID, paintingGeomFull = RTC_INVALID_GEOMETRY_ID;
  std::string error;

  Mesh mesh;
  double ior = 1.5;
  glm::dvec3 sigma{0.0};
  std::vector<Painting> paintings;
  Environment environment;
  double eps = 1e-5;

  ~Impl() {
    if (full) rtcReleaseScene(full);
    if (background) rtcReleaseScene(background);
    if (device) rtcReleaseDevice(device);
  }

  void check(const char* what) const {
    if (!error.empty()) throw Error(ErrorKind::Render, std::string(what) + ": " + error);
  }

  unsigned attachMesh(RTCScene scene, const std::vector<vec3>& positions, const std::vector<std::uint32_t>& indices) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                           3 * sizeof(float), positions.size()));
    auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                              3 * sizeof(unsigned), indices.size() / 3));
    check("creating a triangle geometry");
    for (std::size_t i = 0; i < positions.size(); ++i) {
      vb[3 * i] = positions[i].x;
      vb[3 * i + 1] = positions[i].y;
      vb[3 * i + 2] = positions[i].z;
    }
    std::copy(indices.begin(), indices.end(), ib);
    rtcCommitGeometry(g);
    const unsigned id = rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
    return id;
  }

  void paintingTriangles(std::vector<vec3>& positions, std::vector<std::uint32_t>& indices) const {
    for (const Painting& p : paintings) {
      const auto c = p.corners();
      const auto base = static_cast<std::uint32_t>(positions.size());
      positions.insert(positions.end(), c.begin(), c.end());
      indices.insert(indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
  }

  void build() {
    device = rtcNewDevice(nullptr);
    if (!device) throw Error(ErrorKind::Render, "cannot create an Embree device");
    rtcSetDeviceErrorFunction(device, embreeError, &error);
    full = rtcNewScene(device);
    background = rtcNewScene(device);
    for (RTCScene s : {full, background}) {
      rtcSetSceneFlags(s, RTC_SCENE_FLAG_ROBUST);  // watertight: no rays through shared edges
      rtcSetSceneBuildQuality(s, RTC_BUILD_QUALITY_HIGH);
    }
    objectGeom = attachMesh(full, mesh.positions, mesh.indices);
    if (!paintings.empty()) {
      std::vector<vec3> pp;
      std::vector<std::uint32_t> pi;
      paintingTriangles(pp, pi);
      paintingGeomFull = attachMesh(full, pp, pi);
      attachMesh(background, pp, pi);
    }
    rtcCommitScene(full);
    rtcCommitScene(background);
    check("building the Embree scenes");
    // Self-intersection offset: a few float ulps of the largest coordinate.
    const Bounds b = meshBounds(mesh);
    const double extent = std::max({1.0, static_cast<double>(glm::length(b.lo)), static_cast<double>(glm::length(b.hi))});
    eps = 2e-5 * extent;
  }

  Hit intersect(RTCScene scene, bool sceneIsFull, const glm::dvec3& o, const glm::dvec3& d, double tNear, double tFar,
                TraceStats& stats) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRayHit rh;
    rh.ray.org_x = static_cast<float>(o.x);
    rh.ray.org_y = static_cast<float>(o.y);
    rh.ray.org_z = static_cast<float>(o.z);
    rh.ray.dir_x = static_cast<float>(d.x);
    rh.ray.dir_y = static_cast<float>(d.y);
    rh.ray.dir_z = static_cast<float>(d.z);
    rh.ray.tnear = static_cast<float>(tNear);
    rh.ray.tfar = tFar >= static_cast<double>(std::numeric_limits<float>::max()) ? std::numeric_limits<float>::infinity()
                                                                                 : static_cast<float>(tFar);
    // Embree asserts (and aborts the process) on a ray it deems invalid; the
    // scene loader refuses cameras that would make one, this is the defence.
    if (!std::isfinite(rh.ray.org_x) || !std::isfinite(rh.ray.org_y) || !std::isfinite(rh.ray.org_z) ||
        !std::isfinite(rh.ray.dir_x) || !std::isfinite(rh.ray.dir_y) || !std::isfinite(rh.ray.dir_z) ||
        !(rh.ray.tnear >= 0.0f) || !(rh.ray.tnear <= rh.ray.tfar))
      throw Error(ErrorKind::Render, "ray tracer: a ray with a non-finite origin, direction or range (origin (" +
                                         std::to_string(o.x) + ", " + std::to_string(o.y) + ", " + std::to_string(o.z) +
                                         "), direction (" + std::to_string(d.x) + ", " + std::to_string(d.y) + ", " +
                                         std::to_string(d.z) + ")): the camera or the scene holds values beyond float "
                                         "arithmetic");
    rh.ray.time = 0.0f;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &ctx, &rh);
    ++stats.rays;
    Hit h;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return h;
    h.kind = (sceneIsFull && rh.hit.geomID == objectGeom) ? HitKind::Object : HitKind::Painting;
    h.t = static_cast<double>(rh.ray.tfar);
    h.prim = rh.hit.primID;
    h.u = static_cast<double>(rh.hit.u);
    h.v = static_cast<double>(rh.hit.v);
    return h;
  }

  struct Surface {
    glm::dvec3 point, geometricNormal, normal;  // both normals unit and outward
  };

  Surface objectSurface(const Hit& h) const {
    const std::uint32_t i0 = mesh.indices[3 * h.prim], i1 = mesh.indices[3 * h.prim + 1], i2 = mesh.indices[3 * h.prim + 2];
    const glm::dvec3 p0 = toD(mesh.positions[i0]), p1 = toD(mesh.positions[i1]), p2 = toD(mesh.positions[i2]);
    const double w = 1.0 - h.u - h.v;
    Surface s;
    s.point = w * p0 + h.u * p1 + h.v * p2;
    s.geometricNormal = glm::normalize(glm::cross(p1 - p0, p2 - p0));
    glm::dvec3 n = w * toD(mesh.normals[i0]) + h.u * toD(mesh.normals[i1]) + h.v * toD(mesh.normals[i2]);
    const double len = glm::length(n);
    n = len > 0.0 ? n / len : s.geometricNormal;
    if (glm::dot(n, s.geometricNormal) < 0.0) n = -n;
    s.normal = n;
    return s;
  }

  glm::dvec3 paintingColor(const Hit& h) const {
    const Painting& p = paintings[h.prim / 2];
    const auto uvs = Painting::cornerUvs();
    const bool second = (h.prim % 2) == 1;
    const vec2 a = uvs[0], b = second ? uvs[2] : uvs[1], c = second ? uvs[3] : uvs[2];
    const double w = 1.0 - h.u - h.v;
    const glm::dvec2 uv = w * glm::dvec2(a) + h.u * glm::dvec2(b) + h.v * glm::dvec2(c);
    return toD(p.colorAt(vec2(uv)));
  }

  glm::dvec3 env(const glm::dvec3& d) const { return toD(environment.lookup(vec3(d))); }

  // Origin for a ray leaving surface point s in direction d.
  glm::dvec3 spawn(const Surface& s, const glm::dvec3& d) const {
    return s.point + (glm::dot(d, s.geometricNormal) >= 0.0 ? eps : -eps) * s.geometricNormal;
  }

  glm::dvec3 beer(double distance, const TraceOptions& o) const {
    if (!o.absorption) return glm::dvec3(1.0);
    return glm::exp(-sigma * distance);
  }

  // Background lookup: paintings, else the environment (the object is ignored).
  glm::dvec3 backgroundRadiance(const glm::dvec3& o, const glm::dvec3& d, TraceStats& stats) const {
    const Hit h = intersect(background, false, o, d, 0.0, 1e30, stats);
    if (h.kind == HitKind::None) return env(d);
    return paintingColor(h);
  }

  glm::dvec3 traceFull(const glm::dvec3& o, const glm::dvec3& d, double tNear, double tFar, int depth, double weight,
                       bool inside, const TraceOptions& opt, TraceStats& stats, bool* firstHitObject) const {
    const Hit h = intersect(full, true, o, d, tNear, tFar, stats);
    if (firstHitObject) *firstHitObject = h.kind == HitKind::Object;
    if (h.kind == HitKind::None) {
      if (inside) ++stats.leaks;
      return env(d);
    }
    if (h.kind == HitKind::Painting) return paintingColor(h) * (inside ? beer(h.t, opt) : glm::dvec3(1.0));
    const Surface s = objectSurface(h);
    const bool exiting = glm::dot(d, s.geometricNormal) > 0.0;
    const glm::dvec3 atten = exiting ? beer(h.t, opt) : glm::dvec3(1.0);
    if (depth >= opt.maxDepth) {
      ++stats.truncated;
      return glm::dvec3(0.0);
    }
    const double w = weight * std::max({atten.x, atten.y, atten.z});
    const double eta = exiting ? ior : 1.0 / ior;
    const ExactRefraction r = refractExact(d, s.normal, eta, TirPolicy::Reflect);
    if (r.tir) {
      ++stats.tirEvents;
      return atten * traceFull(spawn(s, r.direction), r.direction, 0.0, 1e30, depth + 1, w, exiting, opt, stats, nullptr);
    }
    const double F = opt.fresnel ? fresnelExact(glm::dot(d, s.normal), eta) : 0.0;
    glm::dvec3 L(0.0);
    if (F > 0.0 && w * F >= opt.minWeight) {
      const glm::dvec3 refl = reflectExact(d, s.normal);
      L += F * traceFull(spawn(s, refl), refl, 0.0, 1e30, depth + 1, w * F, exiting, opt, stats, nullptr);
    }
    L += (1.0 - F) * traceFull(spawn(s, r.direction), r.direction, 0.0, 1e30, depth + 1, w * (1.0 - F), !exiting, opt,
                               stats, nullptr);
    return atten * L;
  }

  // The principal path for `events` interface events (TraceMode::Principal; TwoInterfaces is 2).
  glm::dvec3 tracePrincipal(const Ray& ray, int events, const TraceOptions& opt, TraceStats& stats,
                            bool* firstHitObject) const {
    const Hit h = intersect(full, true, ray.origin, ray.direction, ray.tNear, ray.tFar, stats);
    if (firstHitObject) *firstHitObject = h.kind == HitKind::Object;
    if (h.kind == HitKind::None) return env(ray.direction);
    if (h.kind == HitKind::Painting) return paintingColor(h);
    const glm::dvec3& d = ray.direction;
    const Surface s1 = objectSurface(h);
    const double eta1 = 1.0 / ior;
    const ExactRefraction t1 = refractExact(d, s1.normal, eta1, TirPolicy::Critical);
    if (t1.tir) ++stats.tirEvents;
    const double F1 = opt.fresnel ? fresnelExact(glm::dot(d, s1.normal), eta1) : 0.0;
    glm::dvec3 L(0.0);
    if (F1 > 0.0) {
      const glm::dvec3 refl = reflectExact(d, s1.normal);
      L += F1 * backgroundRadiance(spawn(s1, refl), refl, stats);
    }
    // Inside: every later hit counts as an exit (eta = ior), as the image-space model treats its back face.
    glm::dvec3 origin = spawn(s1, t1.direction), dir = t1.direction, throughput(1.0), Lt(0.0);
    for (int k = 2; k <= events; ++k) {
      const Hit hk = intersect(full, true, origin, dir, 0.0, 1e30, stats);
      if (hk.kind == HitKind::None) {
        ++stats.leaks;
        Lt = throughput * env(dir);
        break;
      }
      if (hk.kind == HitKind::Painting) {
        Lt = throughput * (paintingColor(hk) * beer(hk.t, opt));
        break;
      }
      const Surface sk = objectSurface(hk);
      const bool last = k == events;
      const ExactRefraction tk = refractExact(dir, sk.normal, ior, last ? TirPolicy::Critical : TirPolicy::Reflect);
      if (tk.tir) ++stats.tirEvents;
      throughput = throughput * beer(hk.t, opt);
      if (last || !tk.tir) {
        Lt = throughput * backgroundRadiance(spawn(sk, tk.direction), tk.direction, stats);
        break;
      }
      origin = spawn(sk, tk.direction);
      dir = tk.direction;
    }
    return L + (1.0 - F1) * Lt;
  }
};

ReferenceTracer::ReferenceTracer(const SceneFrame& frame)
    : ReferenceTracer(frame.object, frame.ior, frame.absorption, frame.paintings, frame.environment) {}

ReferenceTracer::ReferenceTracer(const Mesh& object, float ior, vec3 absorption, std::vector<Painting> paintings,
                                 Environment environment)
    : impl_(std::make_unique<Impl>()) {
  validateMesh(object, "reference tracer mesh");
  impl_->mesh = object;
  impl_->ior = static_cast<double>(ior);
  impl_->sigma = glm::dvec3(absorption);
  impl_->paintings = std::move(paintings);
  impl_->environment = std::move(environment);
  impl_->build();
}

ReferenceTracer::~ReferenceTracer() = default;

double ReferenceTracer::ior() const { return impl_->ior; }
double ReferenceTracer::offsetEpsilon() const { return impl_->eps; }

glm::dvec3 ReferenceTracer::radiance(const Ray& ray, const TraceOptions& options, TraceStats* stats,
                                     bool* hitObject) const {
  TraceStats local;
  TraceStats& s = stats ? *stats : local;
  if (options.mode == TraceMode::TwoInterfaces) return impl_->tracePrincipal(ray, 2, options, s, hitObject);
  if (options.mode == TraceMode::Principal) {
    if (options.events < 2)
      throw Error(ErrorKind::Render, "ray tracer: a principal path needs at least 2 interface events (got " +
                                         std::to_string(options.events) + ")");
    return impl_->tracePrincipal(ray, options.events, options, s, hitObject);
  }
  return impl_->traceFull(ray.origin, ray.direction, ray.tNear, ray.tFar, 0, 1.0, false, options, s, hitObject);
}

TraceResult ReferenceTracer::render(const Camera& camera, const TraceOptions& options) const {
  const auto start = std::chrono::steady_clock::now();
  const std::string problem = cameraProblem(camera);
  if (!problem.empty()) throw Error(ErrorKind::Render, "ray tracer: camera: " + problem);
  TraceResult result;
  result.color = Image(camera.width, camera.height, vec4(0.0f, 0.0f, 0.0f, 1.0f));
  result.mask = Mask(camera.width, camera.height);
  result.tir = Mask(camera.width, camera.height);
  unsigned threads = options.threads > 0 ? static_cast<unsigned>(options.threads) : std::thread::hardware_concurrency();
  threads = std::max(1u, std::min(threads, static_cast<unsigned>(camera.height)));
  const std::string what = options.mode == TraceMode::Full            ? "ray tracing"
                           : options.mode == TraceMode::TwoInterfaces ? "ray tracing (two interfaces)"
                                                                      : "ray tracing (principal path, " +
                                                                            std::to_string(options.events) + " events)";
  ProgressBar bar(what, camera.height, options.progress);
  std::atomic<int> nextRow{0};
  std::mutex statsMutex;
  std::exception_ptr failure;
  const auto work = [&] {
    TraceStats local;
    try {
      for (int y = nextRow++; y < camera.height; y = nextRow++) {
        for (int x = 0; x < camera.width; ++x) {
          bool hitObject = false;
          const std::uint64_t tirBefore = local.tirEvents;
          const glm::dvec3 c = radiance(primaryRay(camera, x, y), options, &local, &hitObject);
          result.color.at(x, y) = vec4(vec3(c), 1.0f);
          result.mask.set(x, y, hitObject);
          result.tir.set(x, y, local.tirEvents != tirBefore);
          if (hitObject) ++local.objectPixels;
        }
        bar.advance();
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(statsMutex);
      if (!failure) failure = std::current_exception();
      nextRow = camera.height;
    }
    std::lock_guard<std::mutex> lock(statsMutex);
    result.stats += local;
  };
  std::vector<std::thread> pool;
  for (unsigned i = 1; i < threads; ++i) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  bar.finish();
  if (failure) std::rethrow_exception(failure);
  result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::vector<PathEvent> ReferenceTracer::principalPath(const Ray& ray, int maxEvents, TirPolicy policy) const {
  std::vector<PathEvent> events;
  TraceStats stats;
  glm::dvec3 o = ray.origin, d = ray.direction;
  double tNear = ray.tNear, tFar = ray.tFar;
  for (int k = 0; k < maxEvents; ++k) {
    const Hit h = impl_->intersect(impl_->full, true, o, d, tNear, tFar, stats);
    PathEvent e;
    if (h.kind == HitKind::None) {
      e.type = PathEventType::Escape;
      e.point = o;
      e.direction = d;
      events.push_back(e);
      return events;
    }
    e.distance = h.t;
    if (h.kind == HitKind::Painting) {
      e.type = PathEventType::HitOpaque;
      e.point = o + h.t * d;
      e.direction = d;
      events.push_back(e);
      return events;
    }
    const Impl::Surface s = impl_->objectSurface(h);
    const bool exiting = glm::dot(d, s.geometricNormal) > 0.0;
    const ExactRefraction r = refractExact(d, s.normal, exiting ? impl_->ior : 1.0 / impl_->ior, policy);
    e.point = s.point;
    e.normal = s.normal;
    e.direction = r.direction;
    e.type = r.tir ? (policy == TirPolicy::Reflect ? PathEventType::TotalInternalReflection : PathEventType::CriticalClamp)
                   : (exiting ? PathEventType::Exit : PathEventType::Enter);
    events.push_back(e);
    o = impl_->spawn(s, r.direction);
    d = r.direction;
    tNear = 0.0;
    tFar = 1e30;
  }
  return events;
}

}  // namespace snell::lab
