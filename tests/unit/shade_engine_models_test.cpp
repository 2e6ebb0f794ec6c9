// The engines' screen-space refraction models (shade/engine_models/) against
// the geometry each one describes, built independently in double: Snell's law
// in angle form (sin t = eta sin i in the plane of incidence), the tangent
// sphere and the slab intersected as a quadratic and a plane, the proxy box's
// far side found by bisection on the inside test, and the projection of the
// point each engine reads. Hostile inputs give the documented results.
#include <snell/engine_model_table.hpp>
#include <snell/shade.hpp>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "support/rng.hpp"

namespace {

using glm::dmat4;
using glm::dvec2;
using glm::dvec3;
using glm::dvec4;
using glm::mat4;
using glm::vec2;
using glm::vec3;
using glm::vec4;
using snell::SnellEngineRefraction;

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();
constexpr float kNear = 0.1f, kFar = 100.0f;

mat4 projection() { return glm::perspective(glm::radians(50.0f), 1.3f, kNear, kFar); }

// A W x H depth buffer holding the opaque scene at view distance `distance` everywhere (GL window depth),
// or empty (1) when distance <= 0.
snell::Texture2D flatDepth(float distance) {
  snell::Image img(32, 24);
  float d = 1.0f;
  if (distance > 0.0f) {
    const vec4 c = projection() * vec4(0.0f, 0.0f, -distance, 1.0f);
    d = 0.5f * c.z / c.w + 0.5f;
  }
  for (vec4& t : img.texels) t = vec4(d, 0.0f, 0.0f, 1.0f);
  return snell::Texture2D(img);
}

snell::SnellDepthSurface sceneSurface() {
  snell::SnellDepthSurface s = snell::snellDepthSurface(projection(), kNear, kFar, SNELL_DEPTH_GL, 1.0f);
  s.closed = false;
  return s;
}

// The uv a view-space point projects to, in double.
dvec2 project(const dvec3& x) {
  const dvec4 c = dmat4(projection()) * dvec4(x, 1.0);
  return 0.5 * dvec2(c.x / c.w, c.y / c.w) + 0.5;
}

// Snell's law in angle form: the transmitted direction in the plane of incidence with sin t = eta sin i, for a
// unit incident d and unit normal n facing it (dot(d, n) < 0).
dvec3 snellAngle(const dvec3& d, const dvec3& n, double eta) {
  const double cosI = -glm::dot(d, n);
  const dvec3 tangent = d + cosI * n;  // sin i times the in-plane unit tangent
  const double sinI = glm::length(tangent);
  const double sinT = eta * sinI;
  const double cosT = std::sqrt(1.0 - sinT * sinT);
  return sinI > 0.0 ? tangent / sinI * sinT - n * cosT : -n;
}

// A fragment in front of the camera: position in the frustum's middle, a normal facing the eye, an ior.
struct Fragment {
  vec3 p, n;
  float ior;
};

Fragment randomFragment(snell_test::Rng& g) {
  for (;;) {
    const float z = g.uniform(2.0f, 8.0f);
    Fragment f{vec3(g.uniform(-0.25f, 0.25f) * z, g.uniform(-0.2f, 0.2f) * z, -z), g.unit(), g.uniform(1.1f, 2.0f)};
    if (glm::dot(f.n, glm::normalize(f.p)) > -0.2f) continue;  // keep away from grazing entry
    return f;
  }
}

void expectUv(const SnellEngineRefraction& e, const dvec2& want, double tol, const std::string& what) {
  ASSERT_TRUE(e.valid) << what;
  EXPECT_NEAR(e.uv.x, want.x, tol) << what;
  EXPECT_NEAR(e.uv.y, want.y, tol) << what;
}

TEST(EngineModels, ThreeJsReadsThePointAThicknessAlongTheRefractedRay) {
  snell_test::Rng g(7101);
  for (int i = 0; i < 200; ++i) {
    const Fragment f = randomFragment(g);
    const float t = g.uniform(0.05f, 2.0f);
    const dvec3 d = glm::normalize(dvec3(f.p));
    const dvec3 T = snellAngle(d, dvec3(f.n), 1.0 / double(f.ior));
    const dvec3 x = dvec3(f.p) + double(t) * T;
    if ((dmat4(projection()) * dvec4(x, 1.0)).w <= 0.0) continue;
    const SnellEngineRefraction e = snell::snellEngineThreeJs(f.p, f.n, 1.0f / f.ior, t, projection());
    expectUv(e, project(x), 2e-5, "fragment " + std::to_string(i));
    EXPECT_FLOAT_EQ(e.distance, t);
    EXPECT_EQ(e.sceneWeight, 1.0f);
    EXPECT_NEAR(glm::dot(dvec3(e.direction), T), 1.0, 1e-5);
  }
}

TEST(EngineModels, FilamentSolidReadsWhereTheRayLeavesTheTangentSphere) {
  snell_test::Rng g(7102);
  for (int i = 0; i < 200; ++i) {
    const Fragment f = randomFragment(g);
    const double t = g.uniform(0.05f, 2.0f);
    const dvec3 p(f.p), n(f.n), d = glm::normalize(p);
    const dvec3 T = snellAngle(d, n, 1.0 / double(f.ior));
    // The sphere of diameter t tangent at p: |p + s T - c|^2 = (t/2)^2, the far root.
    const dvec3 c = p - n * (t / 2.0);
    const double b = 2.0 * glm::dot(T, p - c), cc = glm::dot(p - c, p - c) - t * t / 4.0;
    const double s = (-b + std::sqrt(b * b - 4.0 * cc)) / 2.0;
    const SnellEngineRefraction e =
        snell::snellEngineFilamentSolid(f.p, f.n, 1.0f / f.ior, static_cast<float>(t), projection());
    expectUv(e, project(p + s * T), 2e-5, "fragment " + std::to_string(i));
    EXPECT_NEAR(e.distance, s, 1e-5 * t);
  }
}

TEST(EngineModels, FilamentThinCrossesASlabAndReadsTheFragmentItselfWithoutOne) {
  snell_test::Rng g(7103);
  for (int i = 0; i < 200; ++i) {
    const Fragment f = randomFragment(g);
    const double t = g.uniform(0.01f, 0.5f);
    const dvec3 p(f.p), n(f.n), d = glm::normalize(p);
    const dvec3 T = snellAngle(d, n, 1.0 / double(f.ior));
    // The slab's far plane: dot(x - p, n) = -t.
    const double s = -t / glm::dot(T, n);
    const SnellEngineRefraction e =
        snell::snellEngineFilamentThin(f.p, f.n, 1.0f / f.ior, static_cast<float>(t), projection());
    expectUv(e, project(p + s * T), 2e-5, "fragment " + std::to_string(i));
    const SnellEngineRefraction zero = snell::snellEngineFilamentThin(f.p, f.n, 1.0f / f.ior, 0.0f, projection());
    expectUv(zero, project(p), 1e-6, "no microThickness, fragment " + std::to_string(i));
  }
}

// A view-space box: centre, half extents, rotated by `angle` about y; its proxyFromView and an inside test.
struct ProxyBox {
  dvec3 centre, half;
  double angle;
  dmat4 localFromView() const {
    dmat4 m = glm::scale(dmat4(1.0), 1.0 / half);
    m = m * glm::rotate(dmat4(1.0), -angle, dvec3(0, 1, 0));
    return m * glm::translate(dmat4(1.0), -centre);
  }
  bool inside(const dvec3& x) const {
    const dvec3 l = dvec3(localFromView() * dvec4(x, 1.0));
    return std::abs(l.x) <= 1.0 && std::abs(l.y) <= 1.0 && std::abs(l.z) <= 1.0;
  }
  // The far side along o + s dir (o inside), by bisection on inside().
  dvec3 exit(const dvec3& o, const dvec3& dir) const {
    double lo = 0.0, hi = 1.0;
    while (inside(o + hi * dir)) hi *= 2.0;
    for (int k = 0; k < 200; ++k) {
      const double mid = 0.5 * (lo + hi);
      (inside(o + mid * dir) ? lo : hi) = mid;
    }
    return o + lo * dir;
  }
};

const ProxyBox kRoom{dvec3(0.3, -0.2, -6.0), dvec3(6.0, 5.0, 7.0), 0.4};

TEST(EngineModels, HdrpBoxLeavesTheSlabAlongTheViewRayAndReadsTheProxyHit) {
  snell_test::Rng g(7104);
  const snell::Texture2D empty = flatDepth(0.0f);
  const snell::SnellDepthSurface scene = sceneSurface();
  int checked = 0;
  for (int i = 0; i < 200; ++i) {
    const Fragment f = randomFragment(g);
    const double t = g.uniform(0.05f, 1.0f);
    const dvec3 p(f.p), n(f.n), d = glm::normalize(p);
    const dvec3 T = snellAngle(d, n, 1.0 / double(f.ior));
    const dvec3 o = p + T * (-t / glm::dot(T, n));
    if (!kRoom.inside(o)) continue;
    const dvec3 h = kRoom.exit(o, d);
    const SnellEngineRefraction e = snell::snellEngineHdrpBox(f.p, f.n, 1.0f / f.ior, static_cast<float>(t),
                                                              mat4(kRoom.localFromView()), empty, scene);
    const dvec2 uv = project(h);
    expectUv(e, uv, 2e-4, "fragment " + std::to_string(i));
    // The edge fade, evaluated from the expected uv.
    const auto S = [](double x) {
      x = std::min(1.0, std::max(0.0, x));
      return x * x * (3.0 - 2.0 * x);
    };
    const double fade = S((1.0 - std::abs(2.0 * uv.x - 1.0)) / 0.1) * S((1.0 - std::abs(2.0 * uv.y - 1.0)) / 0.1);
    EXPECT_NEAR(e.sceneWeight, fade, 5e-3);
    EXPECT_NEAR(e.distance, -t / glm::dot(T, n), 1e-5);
    ++checked;
  }
  EXPECT_GT(checked, 150);
}

TEST(EngineModels, HdrpSphereRefractsOutOfTheTangentSphereAndReadsTheProxyHit) {
  snell_test::Rng g(7105);
  const snell::Texture2D empty = flatDepth(0.0f);
  const snell::SnellDepthSurface scene = sceneSurface();
  int checked = 0;
  for (int i = 0; i < 200; ++i) {
    const Fragment f = randomFragment(g);
    const double t = g.uniform(0.05f, 1.5f);
    const dvec3 p(f.p), n(f.n), d = glm::normalize(p);
    const dvec3 T = snellAngle(d, n, 1.0 / double(f.ior));
    const dvec3 c = p - n * (t / 2.0);
    const double b = 2.0 * glm::dot(T, p - c), cc = glm::dot(p - c, p - c) - t * t / 4.0;
    const dvec3 x = p + T * ((-b + std::sqrt(b * b - 4.0 * cc)) / 2.0);
    // Leaving the sphere: the normal facing the inside ray is the inward one, the ratio ior.
    const dvec3 r2 = snellAngle(T, glm::normalize(c - x), double(f.ior));
    if (!kRoom.inside(x)) continue;
    const dvec3 h = kRoom.exit(x, r2);
    if ((dmat4(projection()) * dvec4(h, 1.0)).w <= 0.0) continue;
    const SnellEngineRefraction e = snell::snellEngineHdrpSphere(f.p, f.n, 1.0f / f.ior, static_cast<float>(t),
                                                                 mat4(kRoom.localFromView()), empty, scene);
    expectUv(e, project(h), 2e-4, "fragment " + std::to_string(i));
    EXPECT_NEAR(glm::dot(dvec3(e.direction), r2), 1.0, 1e-5);
    ++checked;
  }
  EXPECT_GT(checked, 150);
}

TEST(EngineModels, HdrpReadsTheFragmentItselfWhereTheSceneIsInFront) {
  // The opaque scene at distance 1.5, every fragment behind it (z in [2, 8]): HDRP's halo test.
  snell_test::Rng g(7106);
  const snell::Texture2D near = flatDepth(1.5f);
  for (int i = 0; i < 50; ++i) {
    const Fragment f = randomFragment(g);
    const SnellEngineRefraction e = snell::snellEngineHdrpBox(f.p, f.n, 1.0f / f.ior, 0.3f,
                                                              mat4(kRoom.localFromView()), near, sceneSurface());
    expectUv(e, project(dvec3(f.p)), 1e-6, "fragment " + std::to_string(i));
  }
}

TEST(EngineModels, ProxyExitIsTheBoxsFarSide) {
  // The unit box about the origin, from its centre: 1 / |dir| along each axis; from outside behind: 0.
  EXPECT_FLOAT_EQ(snell::snellEngineProxyExit(vec3(0.0f), vec3(0, 0, -1), mat4(1.0f)), 1.0f);
  EXPECT_FLOAT_EQ(snell::snellEngineProxyExit(vec3(0.5f, 0, 0), vec3(2, 0, 0), mat4(1.0f)), 0.25f);
  EXPECT_EQ(snell::snellEngineProxyExit(vec3(3, 0, 0), vec3(1, 0, 0), mat4(1.0f)), 0.0f);
  EXPECT_EQ(snell::snellEngineProxyExit(vec3(0.0f), vec3(0.0f), mat4(1.0f)), SNELL_FLT_MAX);
  EXPECT_EQ(snell::snellEngineProxyExit(vec3(kNaN), vec3(1, 0, 0), mat4(1.0f)), 0.0f);
}

TEST(EngineModels, GodotShiftsTheScreenUvAgainstTheNormalUnlessTheSceneIsClose) {
  snell_test::Rng g(7107);
  const snell::Texture2D empty = flatDepth(0.0f);
  for (int i = 0; i < 100; ++i) {
    const Fragment f = randomFragment(g);
    const float k = g.uniform(-0.2f, 0.2f);
    const dvec2 u0 = project(dvec3(f.p));
    const dvec2 u1 = u0 - double(k) * dvec2(f.n.x, f.n.y);
    expectUv(snell::snellEngineGodot(f.p, f.n, k, empty, sceneSurface()), u1, 1e-6, "far scene");
    // The scene half a unit behind the fragment: smoothstep(0, 1, 0.5) = 0.5 of the shift.
    const snell::Texture2D half = flatDepth(-f.p.z + 0.5f);
    expectUv(snell::snellEngineGodot(f.p, f.n, k, half, sceneSurface()), u0 + 0.5 * (u1 - u0), 2e-3,
             "scene 0.5 behind");
    // The scene in front of the fragment: no shift.
    const snell::Texture2D front = flatDepth(1.0f);
    expectUv(snell::snellEngineGodot(f.p, f.n, k, front, sceneSurface()), u0, 1e-6, "scene in front");
  }
  // The editor's range: a scale of 5 shifts as 1 does.
  const vec3 p(0.0f, 0.0f, -4.0f), n = glm::normalize(vec3(0.3f, 0.2f, 1.0f));
  EXPECT_EQ(snell::snellEngineGodot(p, n, 5.0f, empty, sceneSurface()).uv,
            snell::snellEngineGodot(p, n, 1.0f, empty, sceneSurface()).uv);
}

TEST(EngineModels, HostileInputsGiveTheDocumentedResults) {
  const snell::Texture2D empty = flatDepth(0.0f);
  const mat4 room = mat4(kRoom.localFromView());
  const vec3 p(0.2f, 0.1f, -4.0f), n(0.0f, 0.0f, 1.0f);
  for (int model = 0; model < SNELL_ENGINE_MODEL_COUNT; ++model) {
    const auto run = [&](vec3 pp, vec3 nn, float eta, float param) {
      return snell::snellEngineRefraction(model, pp, nn, eta, param, room, empty, sceneSurface());
    };
    const std::string name = snell::snellEngineModelTable()[model].name;
    for (const SnellEngineRefraction& e : {run(vec3(kNaN), n, 0.66f, 0.5f), run(p, vec3(0.0f), 0.66f, 0.5f),
                                           run(vec3(0.0f), n, 0.66f, 0.5f), run(p, vec3(kInf, 0, 0), 0.66f, 0.5f)}) {
      EXPECT_FALSE(e.valid) << name;
      EXPECT_EQ(e.uv, vec2(0.0f)) << name;
      EXPECT_EQ(e.sceneWeight, 0.0f) << name;
      EXPECT_EQ(e.direction, vec3(0.0f)) << name;
      EXPECT_EQ(e.distance, 0.0f) << name;
    }
    // A NaN or negative parameter counts as 0; every result stays finite.
    for (float param : {kNaN, -1.0f, kInf, 1e30f}) {
      const SnellEngineRefraction e = run(p, glm::normalize(vec3(0.3f, -0.2f, 1.0f)), 0.66f, param);
      EXPECT_TRUE(e.valid) << name;
      EXPECT_TRUE(std::isfinite(e.uv.x) && std::isfinite(e.uv.y)) << name << " parameter " << param;
      EXPECT_TRUE(e.sceneWeight >= 0.0f && e.sceneWeight <= 1.0f) << name;
      EXPECT_FALSE(std::isnan(e.distance)) << name;
    }
    if (model != SNELL_ENGINE_GODOT) {
      // eta NaN, zero or denormal: invalid; TIR at the entry (eta > 1, grazing): the fragment's own texel.
      for (float eta : {kNaN, 0.0f, 1e-40f, -1.0f}) EXPECT_FALSE(run(p, n, eta, 0.5f).valid) << name;
      const vec3 grazing = glm::normalize(glm::cross(glm::normalize(p), vec3(0, 1, 0)) + 0.05f * glm::normalize(-p));
      const SnellEngineRefraction tir = run(p, grazing, 1.5f, 0.5f);
      expectUv(tir, project(dvec3(p)), 1e-6, name + " TIR");
      EXPECT_EQ(tir.distance, 0.0f) << name;
    }
  }
  EXPECT_FALSE(snell::snellEngineRefraction(SNELL_ENGINE_MODEL_COUNT, p, n, 0.66f, 0.5f, room, empty, sceneSurface()).valid);
  EXPECT_FALSE(snell::snellEngineRefraction(-1, p, n, 0.66f, 0.5f, room, empty, sceneSurface()).valid);
}

TEST(EngineModels, ABackFacingNormalIsTurnedTowardsTheEye) {
  snell_test::Rng g(7108);
  const snell::Texture2D empty = flatDepth(0.0f);
  const mat4 room = mat4(kRoom.localFromView());
  for (int i = 0; i < 100; ++i) {
    const Fragment f = randomFragment(g);
    for (int model = 0; model < SNELL_ENGINE_MODEL_COUNT; ++model) {
      const float param = model == SNELL_ENGINE_GODOT ? 0.1f : 0.4f;
      const SnellEngineRefraction a =
          snell::snellEngineRefraction(model, f.p, f.n, 1.0f / f.ior, param, room, empty, sceneSurface());
      const SnellEngineRefraction b =
          snell::snellEngineRefraction(model, f.p, -f.n, 1.0f / f.ior, param, room, empty, sceneSurface());
      const std::string name = snell::snellEngineModelTable()[model].name;
      EXPECT_EQ(a.uv, b.uv) << name;
      EXPECT_EQ(a.direction, b.direction) << name;
      EXPECT_EQ(a.distance, b.distance) << name;
      EXPECT_EQ(a.sceneWeight, b.sceneWeight) << name;
    }
  }
}

TEST(EngineModels, TheTableListsEveryModelOnceInIdOrder) {
  std::set<std::string> names;
  for (int i = 0; i < SNELL_ENGINE_MODEL_COUNT; ++i) {
    const snell::SnellEngineModelInfo& m = snell::snellEngineModelTable()[i];
    EXPECT_EQ(m.id, i);
    EXPECT_TRUE(names.insert(m.name).second) << m.name;
    EXPECT_EQ(snell::snellFindEngineModel(m.name), &m);
  }
  EXPECT_EQ(snell::snellFindEngineModel("engine-unreal"), nullptr);
}

}  // namespace
