#include "lab/tracer.hpp"

#include "lab/error.hpp"
#include "lab/progress.hpp"
#include "lab/rough_optics.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
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
  sampledPixels += o.sampledPixels;
  varianceSum += o.varianceSum;
  return *this;
}

namespace {

enum class HitKind { None, Object, Painting };

struct Hit {
  HitKind kind = HitKind::None;
  int object = -1;  // Object: which one
  double t = 0.0;
  unsigned prim = 0;
  double u = 0.0, v = 0.0;
};

void embreeError(void* user, RTCError code, const char* message) {
  auto* sink = static_cast<std::string*>(user);
  if (sink->empty()) *sink = "Embree error " + std::to_string(static_cast<int>(code)) + ": " + (message ? message : "");
}

glm::dvec3 toD(const vec3& v) { return glm::dvec3(v); }

// splitmix64 (Steele, Lea & Flood 2014): a well-mixed 64-bit sequence from any state, so that seeds that
// differ in one bit (neighbouring pixels) start unrelated streams.
std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// The random numbers of one event of one path. Each pixel's paths, and each event along a path, draw from
// their own stream, keyed by where they stand in the pixel's tree of paths (the path's index, then the
// branch taken at each event before). A path that meets one more or one fewer interface, which a camera
// moved by a fraction of a pixel makes some paths do, changes no other path's numbers: the same seed keeps
// the truth's noise of two nearby frames alike (common random numbers), so that it does not read as flicker.
struct Sampler {
  std::uint64_t key = 0;
  std::uint64_t draws = 0;
  std::uint64_t* used = nullptr;  // numbers drawn by the whole path (shared with the events after this one)
  double next() {  // uniform in [0, 1)
    if (used) ++*used;
    ++draws;
    return static_cast<double>(mix64(key + draws * 0x9E3779B97F4A7C15ull) >> 11) * 0x1.0p-53;
  }
  // The stream of the event reached through `branch` (a path's index, a channel, or 0 to go on, 1 to reflect).
  Sampler child(std::uint64_t branch) const {
    Sampler c;
    c.key = mix64(key ^ mix64(branch + 0x632BE59BD9B4E019ull));
    c.used = used;
    return c;
  }
};

// Full mode without Fresnel: a choice number no Fresnel term below 1 exceeds, so only a microfacet's
// total internal reflection (F = 1) reflects.
constexpr double kRefractUnlessTir = 1.0;

Sampler pixelSampler(std::uint64_t seed, int x, int y) {
  Sampler s;
  s.key = mix64(mix64(seed) ^ (static_cast<std::uint64_t>(static_cast<std::uint32_t>(y)) << 32 |
                                 static_cast<std::uint32_t>(x)));
  return s;
}

// The media a ray travels in, innermost last: crossing into an object pushes it, out of one removes it.
// Where two objects overlap, the one entered last is the medium: the surface of the other one there
// separates that medium from itself and does not bend the ray. Deeper nesting than kMax drops the
// outermost medium (no bundled scene comes near).
struct Media {
  static constexpr int kMax = 8;
  std::array<int, kMax> stack{};
  int size = 0;

  int top() const { return size > 0 ? stack[static_cast<std::size_t>(size - 1)] : -1; }
  bool contains(int object) const {
    for (int i = 0; i < size; ++i)
      if (stack[static_cast<std::size_t>(i)] == object) return true;
    return false;
  }
  Media without(int object) const {
    Media m;
    for (int i = 0; i < size; ++i)
      if (stack[static_cast<std::size_t>(i)] != object) m.stack[static_cast<std::size_t>(m.size++)] = stack[static_cast<std::size_t>(i)];
    return m;
  }
  Media with(int object) const {
    Media m = without(object);
    if (m.size == kMax) {
      for (int i = 1; i < kMax; ++i) m.stack[static_cast<std::size_t>(i - 1)] = m.stack[static_cast<std::size_t>(i)];
      --m.size;
    }
    m.stack[static_cast<std::size_t>(m.size++)] = object;
    return m;
  }
};

// Runs row(y, stats) for every image row on `threads` threads, rows handed out in turn; each thread's stats
// are added to `total`. The first exception stops the others and is rethrown.
template <class Row>
void traceRows(int height, unsigned threads, ProgressBar& bar, TraceStats& total, Row&& row) {
  std::atomic<int> nextRow{0};
  std::mutex statsMutex;
  std::exception_ptr failure;
  const auto work = [&] {
    TraceStats local;
    try {
      for (int y = nextRow++; y < height; y = nextRow++) {
        row(y, local);
        bar.advance();
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(statsMutex);
      if (!failure) failure = std::current_exception();
      nextRow = height;
    }
    std::lock_guard<std::mutex> lock(statsMutex);
    total += local;
  };
  std::vector<std::thread> pool;
  for (unsigned i = 1; i < threads; ++i) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  if (failure) {
    bar.finish();
    std::rethrow_exception(failure);
  }
}

}  // namespace

struct ReferenceTracer::Impl {
  RTCDevice device = nullptr;
  RTCScene full = nullptr;        // the objects + the paintings
  RTCScene background = nullptr;  // paintings only (geomID 0)
  std::string error;

  struct Object {
    Mesh mesh;
    glm::dvec3 iors{1.5};  // per colour channel (channelIors); green is the d line's
    glm::dvec3 sigma{0.0};
    double alpha = 0.0;  // GGX alpha of both interfaces (roughness^2); 0: smooth
  };
  std::vector<Object> objects;
  std::vector<int> objectOfGeom;  // full's geomID -> object index, -1 for the paintings
  std::uint32_t allObjects = 0;   // a bit per object
  bool dispersive = false;        // an object's IOR differs between channels
  std::vector<Painting> paintings;
  std::vector<std::size_t> paintingFirstTriangle;
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

  // Every painting's triangles in one mesh; paintingFirstTriangle[k] is painting k's first.
  void paintingTriangles(std::vector<vec3>& positions, std::vector<std::uint32_t>& indices) {
    paintingFirstTriangle.clear();
    for (const Painting& p : paintings) {
      paintingFirstTriangle.push_back(indices.size() / 3);
      const auto base = static_cast<std::uint32_t>(positions.size());
      positions.insert(positions.end(), p.positions.begin(), p.positions.end());
      for (std::uint32_t i : p.indices) indices.push_back(base + i);
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
    for (std::size_t i = 0; i < objects.size(); ++i) {
      const unsigned id = attachMesh(full, objects[i].mesh.positions, objects[i].mesh.indices);
      if (objectOfGeom.size() <= id) objectOfGeom.resize(id + 1, -1);
      objectOfGeom[id] = static_cast<int>(i);
      allObjects |= 1u << i;
    }
    if (!paintings.empty()) {
      std::vector<vec3> pp;
      std::vector<std::uint32_t> pi;
      paintingTriangles(pp, pi);
      attachMesh(full, pp, pi);
      attachMesh(background, pp, pi);
    }
    rtcCommitScene(full);
    rtcCommitScene(background);
    check("building the Embree scenes");
    // Self-intersection offset: a few float ulps of the largest coordinate.
    double extent = 1.0;
    for (const Object& o : objects) {
      const Bounds b = meshBounds(o.mesh);
      extent = std::max({extent, static_cast<double>(glm::length(b.lo)), static_cast<double>(glm::length(b.hi))});
    }
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
    h.object = sceneIsFull && rh.hit.geomID < objectOfGeom.size() ? objectOfGeom[rh.hit.geomID] : -1;
    h.kind = h.object >= 0 ? HitKind::Object : HitKind::Painting;
    h.t = static_cast<double>(rh.ray.tfar);
    h.prim = rh.hit.primID;
    h.u = static_cast<double>(rh.hit.u);
    h.v = static_cast<double>(rh.hit.v);
    return h;
  }

  struct Surface {
    glm::dvec3 point, geometricNormal, normal;  // both normals unit and outward
  };

  // The nearest hit on the paintings or on an object not in `skip` (a bit per object). With every object
  // skipped, the paintings' own scene answers.
  Hit intersectSkipping(std::uint32_t skip, const glm::dvec3& o, const glm::dvec3& d, double tNear, double tFar,
                        TraceStats& stats) const {
    if ((skip & allObjects) == allObjects) return intersect(background, false, o, d, tNear, tFar, stats);
    for (;;) {
      const Hit h = intersect(full, true, o, d, tNear, tFar, stats);
      if (h.kind != HitKind::Object || (skip & (1u << h.object)) == 0) return h;
      tNear = static_cast<double>(std::nextafter(static_cast<float>(h.t), std::numeric_limits<float>::infinity()));
    }
  }

  // `channel`: 0, 1, 2 (TraceOptions::channel once resolved).
  double iorOf(int object, int channel) const {
    return object < 0 ? 1.0 : objects[static_cast<std::size_t>(object)].iors[channel];
  }

  // Beer-Lambert over a segment in `medium` (-1: air, exactly 1).
  glm::dvec3 beer(int medium, double distance, const TraceOptions& o) const {
    if (!o.absorption || medium < 0) return glm::dvec3(1.0);
    return glm::exp(-objects[static_cast<std::size_t>(medium)].sigma * distance);
  }

  // Crossing object b's surface from media `m`: the relative index, the media on the refracted side and
  // the medium the ray came through. The geometric normal decides the side (`exiting`); a ray that leaves
  // b without having entered it (it started inside, or leaked in) is taken to have been in it.
  struct Crossing {
    double eta = 1.0;
    Media refracted, reflected;
    int before = -1;  // the medium of the segment that led to the surface
  };
  Crossing crossing(const Media& m, int b, bool exiting, int channel) const {
    Crossing c;
    if (exiting) {
      const Media in = m.contains(b) ? m : m.with(b);
      c.reflected = in;
      c.refracted = m.without(b);
      c.before = in.top();
      c.eta = iorOf(in.top(), channel) / iorOf(c.refracted.top(), channel);
    } else {
      const Media out = m.without(b);
      c.reflected = out;
      c.refracted = out.with(b);
      c.before = out.top();
      c.eta = iorOf(out.top(), channel) / iorOf(b, channel);
    }
    return c;
  }

  Surface objectSurface(const Hit& h) const {
    const Mesh& mesh = objects[static_cast<std::size_t>(h.object)].mesh;
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
    const std::size_t k = static_cast<std::size_t>(
        std::upper_bound(paintingFirstTriangle.begin(), paintingFirstTriangle.end(), std::size_t{h.prim}) -
        paintingFirstTriangle.begin() - 1);
    const Painting& p = paintings[k];
    return toD(p.colorAt(vec2(p.uvAt(h.prim - paintingFirstTriangle[k], h.u, h.v))));
  }

  glm::dvec3 env(const glm::dvec3& d) const { return toD(environment.lookup(vec3(d))); }

  // Origin for a ray leaving surface point s in direction d.
  glm::dvec3 spawn(const Surface& s, const glm::dvec3& d) const {
    return s.point + (glm::dot(d, s.geometricNormal) >= 0.0 ? eps : -eps) * s.geometricNormal;
  }

  // ReferenceTracer::radiance with the pixel's random numbers.
  glm::dvec3 radiance(const Ray& ray, const TraceOptions& options, TraceStats* stats, bool* hitObject,
                      Sampler rng) const;

  glm::dvec3 traceFull(const glm::dvec3& o, const glm::dvec3& d, double tNear, double tFar, int depth, double weight,
                       const Media& media, const TraceOptions& opt, TraceStats& stats, bool* firstHitObject,
                       Sampler rng) const {
    const Hit h = intersect(full, true, o, d, tNear, tFar, stats);
    if (firstHitObject) *firstHitObject = h.kind == HitKind::Object;
    if (h.kind == HitKind::None) {
      if (media.size > 0) ++stats.leaks;
      return env(d);
    }
    if (h.kind == HitKind::Painting) return paintingColor(h) * beer(media.top(), h.t, opt);
    const Surface s = objectSurface(h);
    const bool exiting = glm::dot(d, s.geometricNormal) > 0.0;
    const Crossing c = crossing(media, h.object, exiting, opt.channel);
    const glm::dvec3 atten = beer(c.before, h.t, opt);
    if (depth >= opt.maxDepth) {
      ++stats.truncated;
      return glm::dvec3(0.0);
    }
    const double w = weight * std::max({atten.x, atten.y, atten.z});
    const ExactRefraction r = refractExact(d, s.normal, c.eta, TirPolicy::Reflect);
    if (r.tir) ++stats.tirEvents;
    const double alpha = objects[static_cast<std::size_t>(h.object)].alpha;
    if (alpha > 0.0) {
      // One path: reflect with probability F at the sampled microfacet (never, without Fresnel, unless
      // the microfacet itself reflects totally), weighted by eq. 41.
      const double u1 = rng.next(), u2 = rng.next();
      const double u3 = opt.fresnel ? rng.next() : kRefractUnlessTir;
      const RoughScatter rs = sampleRoughDielectric(d, s.normal, c.eta, alpha, u1, u2, u3);
      if (!(rs.weight > 0.0)) return glm::dvec3(0.0);
      return atten * rs.weight *
             traceFull(spawn(s, rs.direction), rs.direction, 0.0, 1e30, depth + 1, w * rs.weight,
                       rs.reflected ? c.reflected : c.refracted, opt, stats, nullptr, rng.child(0));
    }
    if (r.tir)
      return atten * traceFull(spawn(s, r.direction), r.direction, 0.0, 1e30, depth + 1, w, c.reflected, opt, stats,
                               nullptr, rng.child(0));
    const double F = opt.fresnel ? fresnelExact(glm::dot(d, s.normal), c.eta) : 0.0;
    glm::dvec3 L(0.0);
    if (F > 0.0 && w * F >= opt.minWeight) {
      const glm::dvec3 refl = reflectExact(d, s.normal);
      L += F * traceFull(spawn(s, refl), refl, 0.0, 1e30, depth + 1, w * F, c.reflected, opt, stats, nullptr,
                         rng.child(1));
    }
    L += (1.0 - F) * traceFull(spawn(s, r.direction), r.direction, 0.0, 1e30, depth + 1, w * (1.0 - F), c.refracted,
                               opt, stats, nullptr, rng.child(0));
    return atten * L;
  }

  // The principal path with at most `events` interface events on each object (TraceMode::Principal;
  // TwoInterfaces is 2): what image-space techniques that render the objects one after the other, back to
  // front, each reading what lies behind it, can reach at best. The first surface of an object that the
  // path meets is its entry (refract, TIR clamped to the critical angle; Fresnel adds its reflection, traced
  // on with that object left out, as its reflect slot reads the scene without it). Every later one counts
  // as an exit whatever its normal says (the model's back face): refract where Snell allows, else reflect
  // and go on inside; the object's last event clamps TIR to the critical angle. Once out, the object is
  // not met again: its image lies over what is behind it. Another object met inside is nested: entered and
  // left with its own events and the relative index. `done`: a bit per object passed; `count`: the events
  // on each object so far.
  using EventCounts = std::array<std::uint8_t, kMaxObjects>;
  glm::dvec3 tracePrincipal(const glm::dvec3& o, const glm::dvec3& d, double tNear, double tFar, const Media& media,
                            std::uint32_t done, EventCounts count, int events, const TraceOptions& opt,
                            TraceStats& stats, bool* firstHitObject, Sampler rng) const {
    const Hit h = intersectSkipping(done, o, d, tNear, tFar, stats);
    if (firstHitObject) *firstHitObject = h.kind == HitKind::Object;
    if (h.kind == HitKind::None) {
      if (media.size > 0) ++stats.leaks;
      return env(d);
    }
    if (h.kind == HitKind::Painting) return paintingColor(h) * beer(media.top(), h.t, opt);
    const int b = h.object;
    const Surface s = objectSurface(h);
    const int n = ++count[static_cast<std::size_t>(b)];
    // The first surface met is the entry, every later one an exit, whatever the normal says.
    const Crossing c = crossing(media, b, n > 1, opt.channel);
    // A rough interface: the path's events happen about a sampled microfacet normal m, weighted by eq. 41.
    const double alpha = objects[static_cast<std::size_t>(b)].alpha;
    const glm::dvec3 facing = glm::dot(d, s.normal) > 0.0 ? -s.normal : s.normal;
    const glm::dvec3 m = alpha > 0.0 ? ggxSampleNormal(facing, alpha, rng.next(), rng.next()) : s.normal;
    const auto weight = [&](const glm::dvec3& out, bool reflected) {
      return alpha > 0.0 ? ggxScatterWeight(d, out, m, facing, alpha, reflected) : 1.0;
    };
    if (n == 1) {
      const ExactRefraction t = refractExact(d, m, c.eta, TirPolicy::Critical);
      if (t.tir) ++stats.tirEvents;
      const double F = opt.fresnel ? fresnelExact(glm::dot(d, m), c.eta) : 0.0;
      glm::dvec3 L(0.0);
      if (F > 0.0) {
        const glm::dvec3 refl = reflectExact(d, m);
        const double wr = weight(refl, true);
        if (wr > 0.0)
          L += F * wr * tracePrincipal(spawn(s, refl), refl, 0.0, 1e30, c.reflected, done | (1u << b), count, events,
                                       opt, stats, nullptr, rng.child(1));
      }
      const double wt = weight(t.direction, false);
      if (wt > 0.0)
        L += (1.0 - F) * wt * tracePrincipal(spawn(s, t.direction), t.direction, 0.0, 1e30, c.refracted, done, count,
                                             events, opt, stats, nullptr, rng.child(0));
      return beer(c.before, h.t, opt) * L;
    }
    const bool last = n >= events;
    const ExactRefraction t = refractExact(d, m, c.eta, last ? TirPolicy::Critical : TirPolicy::Reflect);
    if (t.tir) ++stats.tirEvents;
    const bool out = last || !t.tir;
    // The critical clamp is the image-space model's, not a scattering event: no weight (its direction,
    // tangent to m, often lies on the inner side of the macro surface, where eq. 41 would absorb it).
    const double w = last && t.tir ? 1.0 : weight(t.direction, !out);
    if (!(w > 0.0)) return glm::dvec3(0.0);
    return beer(c.before, h.t, opt) * w *
           tracePrincipal(spawn(s, t.direction), t.direction, 0.0, 1e30, out ? c.refracted : c.reflected,
                          out ? done | (1u << b) : done, count, events, opt, stats, nullptr, rng.child(0));
  }

  // The frame so far as a picture (renderComposited): what an object drawn later sees of the ones before it.
  struct FrameView {
    glm::dmat4 clipFromWorld{1.0};
    const Image* frame = nullptr;
    // The frame's colour where world point p projects, bilinear between pixel centres (clamped at the
    // edges); false when p is off screen or behind the camera.
    bool sample(const glm::dvec3& p, glm::dvec3* color) const {
      const glm::dvec4 c = clipFromWorld * glm::dvec4(p, 1.0);
      if (!(c.w > 0.0)) return false;
      const double u = 0.5 * (c.x / c.w + 1.0), v = 0.5 * (c.y / c.w + 1.0);
      if (!(u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0)) return false;
      const int W = frame->width, H = frame->height;
      const double fx = std::min(std::max(u * W - 0.5, 0.0), W - 1.0), fy = std::min(std::max(v * H - 0.5, 0.0), H - 1.0);
      const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
      const int x1 = std::min(x0 + 1, W - 1), y1 = std::min(y0 + 1, H - 1);
      const double ax = fx - x0, ay = fy - y0;
      const auto at = [&](int x, int y) { return glm::dvec3(vec3(frame->at(x, y))); };
      *color = (1.0 - ay) * ((1.0 - ax) * at(x0, y0) + ax * at(x1, y0)) + ay * ((1.0 - ax) * at(x0, y1) + ax * at(x1, y1));
      return true;
    }
  };

  // What a ray sees of the paintings and of the objects in `layers` (a bit each), those as the frame shows
  // them where it meets them (off screen: as if they were not there, as a guard band holding the opaque
  // scene only); `skip`: objects it passes through. Else the environment.
  glm::dvec3 layerLookup(const glm::dvec3& o, const glm::dvec3& d, std::uint32_t layers, std::uint32_t skip,
                         const FrameView& view, TraceStats& stats) const {
    skip |= allObjects & ~layers;
    for (;;) {
      const Hit h = intersectSkipping(skip, o, d, 0.0, 1e30, stats);
      if (h.kind == HitKind::None) return env(d);
      if (h.kind == HitKind::Painting) return paintingColor(h);
      glm::dvec3 c;
      if (view.sample(o + h.t * d, &c)) return c;
      skip |= 1u << h.object;
    }
  }

  // One pixel of object b's pass in renderComposited: its exact two-interface path (relative index
  // `eta`), reading the paintings and the objects in `layers` as the frame shows them. False when b's
  // front face is not what the pixel sees first among b and the paintings.
  bool compositedPixel(const Ray& ray, int b, double eta, std::uint32_t layers, const FrameView& view,
                       const TraceOptions& opt, TraceStats& stats, glm::dvec3* color) const {
    const std::uint32_t own = 1u << b;
    const Hit h = intersectSkipping(allObjects & ~own, ray.origin, ray.direction, ray.tNear, ray.tFar, stats);
    if (h.kind != HitKind::Object) return false;
    const glm::dvec3& d = ray.direction;
    const Surface s1 = objectSurface(h);
    if (glm::dot(d, s1.geometricNormal) > 0.0) return false;  // a back face first: the camera is inside
    const ExactRefraction t1 = refractExact(d, s1.normal, 1.0 / eta, TirPolicy::Critical);
    const double F1 = opt.fresnel ? fresnelExact(glm::dot(d, s1.normal), 1.0 / eta) : 0.0;
    glm::dvec3 L(0.0);
    if (F1 > 0.0) {
      const glm::dvec3 refl = reflectExact(d, s1.normal);
      L += F1 * layerLookup(spawn(s1, refl), refl, layers, own, view, stats);
    }
    // Inside: b's next surface, or a painting or a layer object in front of it (one inside b).
    const glm::dvec3 origin = spawn(s1, t1.direction), dir = t1.direction;
    std::uint32_t skip = allObjects & ~(layers | own);
    glm::dvec3 Lt(0.0);
    for (;;) {
      const Hit hk = intersectSkipping(skip, origin, dir, 0.0, 1e30, stats);
      if (hk.kind == HitKind::None) {
        ++stats.leaks;
        Lt = env(dir);
        break;
      }
      const glm::dvec3 inside = beer(b, hk.t, opt);
      if (hk.kind == HitKind::Painting) {
        Lt = paintingColor(hk) * inside;
        break;
      }
      if (hk.object != b) {
        glm::dvec3 c;
        if (view.sample(origin + hk.t * dir, &c)) {
          Lt = c * inside;
          break;
        }
        skip |= 1u << hk.object;
        continue;
      }
      const Surface s2 = objectSurface(hk);
      const ExactRefraction t2 = refractExact(dir, s2.normal, eta, TirPolicy::Critical);
      if (t2.tir) ++stats.tirEvents;
      Lt = inside * layerLookup(spawn(s2, t2.direction), t2.direction, layers, own, view, stats);
      break;
    }
    *color = L + (1.0 - F1) * Lt;
    return true;
  }
};

ReferenceTracer::ReferenceTracer(const SceneFrame& frame)
    : ReferenceTracer(frame.objects, frame.paintings, frame.environment) {}

ReferenceTracer::ReferenceTracer(const Mesh& object, float ior, vec3 absorption, std::vector<Painting> paintings,
                                 Environment environment)
    : ReferenceTracer(std::vector<FrameObject>{FrameObject{object, ior, absorption}}, std::move(paintings),
                      std::move(environment)) {}

ReferenceTracer::ReferenceTracer(const std::vector<FrameObject>& objects, std::vector<Painting> paintings,
                                 Environment environment)
    : impl_(std::make_unique<Impl>()) {
  if (objects.empty() || objects.size() > kMaxObjects)
    throw Error(ErrorKind::Render, "ray tracer: " + std::to_string(objects.size()) + " refractive objects (1 to " +
                                       std::to_string(kMaxObjects) + " are supported)");
  for (std::size_t i = 0; i < objects.size(); ++i) {
    validateMesh(objects[i].mesh, "reference tracer mesh " + std::to_string(i));
    const float roughness = objects[i].roughness;
    if (!(roughness >= 0.0f && roughness <= 1.0f))
      throw Error(ErrorKind::Render, "ray tracer: object " + std::to_string(i) + "'s roughness " +
                                         std::to_string(roughness) + " is not in [0, 1]");
    impl_->objects.push_back(Impl::Object{objects[i].mesh, glm::dvec3(channelIors(objects[i])),
                                          glm::dvec3(objects[i].absorption),
                                          static_cast<double>(roughness) * static_cast<double>(roughness)});
    impl_->dispersive = impl_->dispersive || dispersive(objects[i]);
  }
  impl_->paintings = std::move(paintings);
  impl_->environment = std::move(environment);
  impl_->build();
}

ReferenceTracer::~ReferenceTracer() = default;

double ReferenceTracer::ior() const { return impl_->objects.front().iors.y; }
double ReferenceTracer::offsetEpsilon() const { return impl_->eps; }

glm::dvec3 ReferenceTracer::radiance(const Ray& ray, const TraceOptions& options, TraceStats* stats,
                                     bool* hitObject) const {
  return impl_->radiance(ray, options, stats, hitObject, pixelSampler(options.seed, 0, 0).child(0));
}

glm::dvec3 ReferenceTracer::Impl::radiance(const Ray& ray, const TraceOptions& options, TraceStats* stats,
                                           bool* hitObject, Sampler rng) const {
  TraceStats local;
  TraceStats& s = stats ? *stats : local;
  if (options.channel < -1 || options.channel > 2)
    throw Error(ErrorKind::Render, "ray tracer: channel " + std::to_string(options.channel) + " (-1, 0, 1 or 2)");
  if (options.channel < 0) {
    TraceOptions one = options;
    one.channel = 1;
    if (!dispersive) return radiance(ray, one, &s, hitObject, rng);
    // Each channel along its own path: red's and blue's first hit is green's (the primary ray bends nowhere).
    glm::dvec3 c;
    for (int k = 0; k < 3; ++k) {
      one.channel = k;
      c[k] = radiance(ray, one, &s, k == 1 ? hitObject : nullptr, rng.child(static_cast<std::uint64_t>(k)))[k];
    }
    return c;
  }
  if (options.mode != TraceMode::Full) {
    const int events = options.mode == TraceMode::TwoInterfaces ? 2 : options.events;
    if (events < 2 || events > 255)
      throw Error(ErrorKind::Render, "ray tracer: a principal path needs 2 to 255 interface events (got " +
                                         std::to_string(options.events) + ")");
    return tracePrincipal(ray.origin, ray.direction, ray.tNear, ray.tFar, Media{}, 0u, EventCounts{},
                                 events, options, s, hitObject, rng);
  }
  return traceFull(ray.origin, ray.direction, ray.tNear, ray.tFar, 0, 1.0, Media{}, options, s, hitObject, rng);
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
  if (options.samples < 1 || options.samples > (1 << 20))
    throw Error(ErrorKind::Render, "ray tracer: " + std::to_string(options.samples) +
                                       " samples per pixel (1 to 1048576)");
  const int samples = options.samples;
  ProgressBar bar(what, camera.height, options.progress);
  traceRows(camera.height, threads, bar, result.stats, [&](int y, TraceStats& local) {
    for (int x = 0; x < camera.width; ++x) {
      bool hitObject = false;
      const std::uint64_t tirBefore = local.tirEvents;
      const Ray ray = primaryRay(camera, x, y);
      const Sampler pixel = pixelSampler(options.seed, x, y);
      std::uint64_t used = 0;
      glm::dvec3 sum(0.0), sumSquares(0.0);
      int n = 0, tirPaths = 0;
      do {
        const std::uint64_t before = local.tirEvents;
        Sampler path = pixel.child(static_cast<std::uint64_t>(n));
        path.used = &used;
        const glm::dvec3 c = impl_->radiance(ray, options, &local, n == 0 ? &hitObject : nullptr, path);
        sum += c;
        sumSquares += c * c;
        if (local.tirEvents != before) ++tirPaths;
        ++n;
      } while (used > 0 && n < samples);  // a path with no rough interface is every path
      const glm::dvec3 mean = sum / static_cast<double>(n);
      result.color.at(x, y) = vec4(vec3(mean), 1.0f);
      result.mask.set(x, y, hitObject);
      // Sampled: most of its paths (one met by chance says little of the pixel).
      result.tir.set(x, y, n == 1 ? local.tirEvents != tirBefore : 2 * tirPaths > n);
      if (hitObject) ++local.objectPixels;
      if (n > 1) {
        ++local.sampledPixels;
        // The sample variance over n, per channel: the variance of the mean.
        const glm::dvec3 var = glm::max(sumSquares - sum * mean, glm::dvec3(0.0)) / (static_cast<double>(n - 1) * n);
        if (hitObject) local.varianceSum += (var.x + var.y + var.z) / 3.0;
      }
    }
  });
  bar.finish();
  const std::size_t objectPixels = result.mask.count();
  result.noise = objectPixels > 0 ? result.stats.varianceSum / static_cast<double>(objectPixels) : 0.0;
  result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

TraceResult ReferenceTracer::renderComposited(const Camera& camera, const std::vector<std::size_t>& order,
                                              const std::vector<glm::dvec3>& index, const TraceOptions& options) const {
  const auto start = std::chrono::steady_clock::now();
  const std::string problem = cameraProblem(camera);
  if (!problem.empty()) throw Error(ErrorKind::Render, "ray tracer: camera: " + problem);
  const std::size_t n = impl_->objects.size();
  if (order.size() != n || index.size() != n)
    throw Error(ErrorKind::Render, "ray tracer: the composited model needs an order and an index for each of the " +
                                       std::to_string(n) + " objects");
  bool dispersive = false;
  for (const glm::dvec3& i : index) dispersive = dispersive || i.x != i.y || i.z != i.y;
  std::vector<bool> seen(n, false);
  for (std::size_t o : order) {
    if (o >= n || seen[o]) throw Error(ErrorKind::Render, "ray tracer: the composited model's order must name each object once");
    seen[o] = true;
  }
  TraceResult result;
  result.color = Image(camera.width, camera.height, vec4(0.0f, 0.0f, 0.0f, 1.0f));
  result.mask = Mask(camera.width, camera.height);
  result.tir = Mask(camera.width, camera.height);
  Impl::FrameView view;
  view.clipFromWorld = glm::dmat4(camera.clipFromView()) * glm::dmat4(camera.viewFromWorld());
  view.frame = &result.color;
  unsigned threads = options.threads > 0 ? static_cast<unsigned>(options.threads) : std::thread::hardware_concurrency();
  threads = std::max(1u, std::min(threads, static_cast<unsigned>(camera.height)));
  ProgressBar bar("ray tracing (objects composited)", camera.height * static_cast<int>(n + 1), options.progress);
  // Pass -1 is the opaque scene; pass k draws order[k] over the frame so far, reading it.
  std::uint32_t layers = 0;
  for (int pass = -1; pass < static_cast<int>(n); ++pass) {
    const int b = pass < 0 ? -1 : static_cast<int>(order[static_cast<std::size_t>(pass)]);
    Image next = result.color;
    traceRows(camera.height, threads, bar, result.stats, [&](int y, TraceStats& local) {
      for (int x = 0; x < camera.width; ++x) {
        const Ray ray = primaryRay(camera, x, y);
        glm::dvec3 c;
        if (b < 0) {
          c = impl_->layerLookup(ray.origin, ray.direction, 0u, 0u, view, local);
          const Hit h = impl_->intersect(impl_->full, true, ray.origin, ray.direction, ray.tNear, ray.tFar, local);
          result.mask.set(x, y, h.kind == HitKind::Object);
          next.at(x, y) = vec4(vec3(c), 1.0f);
          continue;
        }
        const std::uint64_t tirBefore = local.tirEvents;
        const glm::dvec3& eta = index[static_cast<std::size_t>(b)];
        bool drawn = impl_->compositedPixel(ray, b, eta.y, layers, view, options, local, &c);
        if (drawn && dispersive) {  // red and blue along their own paths (the same front face as green's)
          glm::dvec3 other;
          for (int k = 0; k < 3; k += 2)
            if (impl_->compositedPixel(ray, b, eta[k], layers, view, options, local, &other)) c[k] = other[k];
        }
        if (drawn) {
          next.at(x, y) = vec4(vec3(c), 1.0f);
          if (local.tirEvents != tirBefore) result.tir.set(x, y, true);
        }
      }
    });
    result.color = std::move(next);
    if (b >= 0) layers |= 1u << b;
  }
  bar.finish();
  result.stats.objectPixels = result.mask.count();
  result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::vector<PathEvent> ReferenceTracer::principalPath(const Ray& ray, int maxEvents, TirPolicy policy) const {
  std::vector<PathEvent> events;
  TraceStats stats;
  glm::dvec3 o = ray.origin, d = ray.direction;
  double tNear = ray.tNear, tFar = ray.tFar;
  Media media;
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
    const Impl::Crossing c = impl_->crossing(media, h.object, exiting, 1);
    const ExactRefraction r = refractExact(d, s.normal, c.eta, policy);
    media = r.tir ? c.reflected : c.refracted;
    e.object = h.object;
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
