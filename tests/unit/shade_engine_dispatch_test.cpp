// snellEngineRefraction routes each SNELL_ENGINE_* id to the model its header
// names: every id's result equals a direct call of that model's function on
// the same fragment (each model has its own tests against the geometry, in
// shade_engine_models_test.cpp). The fragments are chosen so that every two
// models disagree somewhere, so a route to the wrong model fails.
#include <snell/engine_model_table.hpp>
#include <snell/shade.hpp>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <functional>
#include <string>
#include <vector>

#include "support/rng.hpp"

namespace {

using glm::mat4;
using glm::vec3;
using glm::vec4;
using snell::SnellEngineRefraction;

constexpr float kNear = 0.1f, kFar = 100.0f;

mat4 projection() { return glm::perspective(glm::radians(50.0f), 1.3f, kNear, kFar); }

// The opaque scene at view distance 20 everywhere: behind every fragment, so no model reads its own texel.
snell::Texture2D sceneDepth() {
  const vec4 c = projection() * vec4(0.0f, 0.0f, -20.0f, 1.0f);
  snell::Image img(32, 24, vec4(0.5f * c.z / c.w + 0.5f, 0.0f, 0.0f, 1.0f));
  return snell::Texture2D(img);
}

snell::SnellDepthSurface sceneSurface() {
  snell::SnellDepthSurface s = snell::snellDepthSurface(projection(), kNear, kFar, SNELL_DEPTH_GL, 1.0f);
  s.closed = false;
  return s;
}

// A room-sized proxy box around the fragments (the HDRP models' proxyFromView).
mat4 proxyFromView() {
  return glm::scale(mat4(1.0f), 1.0f / vec3(6.0f, 5.0f, 7.0f)) * glm::translate(mat4(1.0f), -vec3(0.3f, -0.2f, -6.0f));
}

struct Fragment {
  vec3 p, n;
  float eta, parameter;
};

using Model = std::function<SnellEngineRefraction(const Fragment&)>;

// The header's id table, written out: id -> the function it names.
std::vector<std::pair<int, Model>> contractRoutes(const snell::Texture2D& depth) {
  const snell::SnellDepthSurface s = sceneSurface();
  const mat4 clip = s.clipFromView, proxy = proxyFromView();
  return {
      {SNELL_ENGINE_THREEJS,
       [=](const Fragment& f) { return snell::snellEngineThreeJs(f.p, f.n, f.eta, f.parameter, clip); }},
      {SNELL_ENGINE_FILAMENT_SOLID,
       [=](const Fragment& f) { return snell::snellEngineFilamentSolid(f.p, f.n, f.eta, f.parameter, clip); }},
      {SNELL_ENGINE_FILAMENT_THIN,
       [=](const Fragment& f) { return snell::snellEngineFilamentThin(f.p, f.n, f.eta, f.parameter, clip); }},
      {SNELL_ENGINE_HDRP_SPHERE,
       [=, &depth](const Fragment& f) {
         return snell::snellEngineHdrpSphere(f.p, f.n, f.eta, f.parameter, proxy, depth, s);
       }},
      {SNELL_ENGINE_HDRP_BOX,
       [=, &depth](const Fragment& f) {
         return snell::snellEngineHdrpBox(f.p, f.n, f.eta, f.parameter, proxy, depth, s);
       }},
      {SNELL_ENGINE_GODOT,
       [=, &depth](const Fragment& f) { return snell::snellEngineGodot(f.p, f.n, f.parameter, depth, s); }},
  };
}

bool same(const SnellEngineRefraction& a, const SnellEngineRefraction& b) {
  return a.valid == b.valid && a.uv == b.uv && a.sceneWeight == b.sceneWeight && a.direction == b.direction &&
         a.distance == b.distance;
}

TEST(EngineDispatch, EveryIdRunsTheModelItsHeaderNames) {
  const snell::Texture2D depth = sceneDepth();
  const auto routes = contractRoutes(depth);
  ASSERT_EQ(int(routes.size()), SNELL_ENGINE_MODEL_COUNT);
  snell_test::Rng g(7120);
  std::vector<Fragment> fragments;
  for (int i = 0; i < 200; ++i) {
    const float z = g.uniform(2.0f, 8.0f);
    const vec3 p(g.uniform(-0.25f, 0.25f) * z, g.uniform(-0.2f, 0.2f) * z, -z);
    vec3 n = g.unit();
    if (glm::dot(n, p) > 0.0f) n = -n;
    fragments.push_back({p, n, 1.0f / g.uniform(1.1f, 2.0f), g.uniform(0.05f, 1.0f)});
  }
  for (const auto& [id, model] : routes)
    for (const Fragment& f : fragments) {
      const SnellEngineRefraction want = model(f);
      const SnellEngineRefraction got =
          snell::snellEngineRefraction(id, f.p, f.n, f.eta, f.parameter, proxyFromView(), depth, sceneSurface());
      ASSERT_TRUE(same(got, want)) << "id " << id << " (" << snell::snellEngineModelTable()[id].name
                                   << ") does not give its model's result: uv " << got.uv.x << " " << got.uv.y
                                   << " vs " << want.uv.x << " " << want.uv.y;
    }
  // The check has teeth only if no two models agree on every fragment.
  for (std::size_t a = 0; a < routes.size(); ++a)
    for (std::size_t b = a + 1; b < routes.size(); ++b) {
      int differ = 0;
      for (const Fragment& f : fragments) differ += !same(routes[a].second(f), routes[b].second(f));
      EXPECT_GT(differ, 100) << "models " << a << " and " << b << " agree on most fragments";
    }
}

}  // namespace
