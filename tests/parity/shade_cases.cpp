// Registrations of the parity cases for the Sousa / water / glass / ice /
// refractive-texture-map / dispersion / roughness functions of glsl/snell/shade
// (see parity_registry.hpp). Cases that sample read three textures built here:
// a LINEAR scene colour with Sousa's mask in alpha, a LINEAR reflection map and
// a NEAREST depth buffer.
#include <snell/shade.hpp>

#include "parity_registry.hpp"

namespace parity_shade {
using namespace snell;
using snell::gpu::SnellParityOut;
Texture2D parityShadeScene, parityShadeReflection, parityShadeDepth;
// Every entry takes four vec4s; most use fewer.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include "cases/shade.glsl"
#pragma GCC diagnostic pop
}  // namespace parity_shade

namespace {
using glm::vec2;
using glm::vec3;
using glm::vec4;
using snell::Filter;
using snell::Image;
using snell::Texture2D;
using snell::gpu::SnellParityOut;
using snell_parity::InputGen;
using snell_parity::ParityIO;
using namespace parity_shade;

const float kNaN = std::numeric_limits<float>::quiet_NaN();

ParityIO run(SnellParityOut (*entry)(vec4, vec4, vec4, vec4), const ParityIO& in) {
  return snell::gpu::toParityIO(entry(in.v[0], in.v[1], in.v[2], in.v[3]));
}

// Non-power-of-two G-buffers. The scene's alpha is 0 inside three discs (the
// refractive meshes of Sousa's mask) and 1 elsewhere; colours vary smoothly
// plus noise; depth is piecewise constant in blocks (an occluder layout).
void buildTextures() {
  InputGen g(601);
  Image scene(61, 47), refl(40, 33), depth(61, 47);
  for (int y = 0; y < scene.height; ++y)
    for (int x = 0; x < scene.width; ++x) {
      float u = (static_cast<float>(x) + 0.5f) / 61.0f, v = (static_cast<float>(y) + 0.5f) / 47.0f;
      auto inDisc = [&](float cx, float cy, float r) { return (u - cx) * (u - cx) + (v - cy) * (v - cy) < r * r; };
      bool mask = inDisc(0.35f, 0.5f, 0.22f) || inDisc(0.75f, 0.3f, 0.15f) || inDisc(0.8f, 0.8f, 0.12f);
      scene.at(x, y) = vec4(0.5f + 0.4f * std::sin(7.0f * u) + g.uniform(-0.1f, 0.1f), v + g.uniform(-0.05f, 0.05f),
                            g.uniform(0.0f, 1.0f), mask ? 0.0f : 1.0f);
      int bx = x / 8, by = y / 6;
      depth.at(x, y) = vec4(static_cast<float>((bx * 7 + by * 3) % 11) / 10.0f, 0.0f, 0.0f, 1.0f);
    }
  for (vec4& t : refl.texels) t = vec4(g.uniform(0, 1), g.uniform(0, 1), g.uniform(0, 1), g.uniform(0, 1));
  parityShadeScene = Texture2D(scene, Filter::Linear);
  parityShadeReflection = Texture2D(refl, Filter::Linear);
  parityShadeDepth = Texture2D(depth, Filter::Nearest);
}

std::vector<snell::gpu::ParityTexture> shadeTextures() {
  return {{"parityShadeScene", &parity_shade::parityShadeScene},
          {"parityShadeReflection", &parity_shade::parityShadeReflection},
          {"parityShadeDepth", &parity_shade::parityShadeDepth}};
}

// Hostile values without denormals (GPUs may flush them; see optics_cases.cpp).
float hostile(InputGen& g) {
  for (;;) {
    float x = g.hostile();
    if (x == 0.0f || !(std::fabs(x) < 1e-30f)) return x;
  }
}
vec3 hostileVector(InputGen& g) { return vec3(hostile(g), hostile(g), hostile(g)); }

// uv mostly on screen, some off screen, a few NaN / inf.
vec2 screenUv(InputGen& g) {
  vec2 uv(g.uniform(0.0f, 1.0f), g.uniform(0.0f, 1.0f));
  if (g.chance(0.1f)) uv = vec2(g.uniform(-0.5f, 1.5f), g.uniform(-0.5f, 1.5f));
  if (g.chance(0.03f)) uv.x = hostile(g);
  if (g.chance(0.03f)) uv.y = hostile(g);
  return uv;
}
vec2 bumpXy(InputGen& g) {
  vec2 b(g.uniform(-1.0f, 1.0f), g.uniform(-1.0f, 1.0f));
  if (g.chance(0.05f)) b = vec2(0.0f);
  if (g.chance(0.03f)) b.x = hostile(g);
  if (g.chance(0.03f)) b.y = hostile(g);
  return b;
}
float perturbScale(InputGen& g) {
  float s = g.uniform(0.0f, 0.2f);
  if (g.chance(0.05f)) s = 0.0f;
  if (g.chance(0.05f)) s = 0.05f;
  if (g.chance(0.03f)) s = hostile(g);
  return s;
}

std::vector<ParityIO> unpackBumpInputs() {
  InputGen g(602);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    ParityIO in{};
    vec3 t(g.uniform(0, 1), g.uniform(0, 1), g.uniform(0, 1));
    if (g.chance(0.05f)) t = vec3(0.5f, 0.5f, 1.0f);
    if (g.chance(0.05f)) t = vec3(g.uniform(-10, 10), g.uniform(-10, 10), g.uniform(-10, 10));
    if (g.chance(0.03f)) t = hostileVector(g);
    in.v[0] = vec4(t, 0.0f);
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> perturbInputs(std::uint32_t seed) {
  InputGen g(seed);
  std::vector<ParityIO> v;
  for (int i = 0; i < 12000; ++i) {
    ParityIO in{};
    vec2 uv = screenUv(g), b = bumpXy(g);
    in.v[0] = vec4(uv, b);
    in.v[1] = vec4(perturbScale(g), g.chance(0.2f) ? 1.0f : 0.0f, 0.0f, 0.0f);
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> edgeFadeInputs() {
  InputGen g(603);
  std::vector<ParityIO> v;
  for (int i = 0; i < 12000; ++i) {
    ParityIO in{};
    vec2 uv(g.uniform(-0.3f, 1.3f), g.uniform(-0.3f, 1.3f));
    if (g.chance(0.1f)) uv.x = g.chance(0.5f) ? 0.0f : 1.0f;  // exactly on the border
    if (g.chance(0.03f)) uv.x = hostile(g);
    if (g.chance(0.03f)) uv.y = hostile(g);
    float w = g.uniform(0.0f, 0.3f);
    if (g.chance(0.05f)) w = 0.0f;
    if (g.chance(0.05f)) w = g.uniform(0.5f, 5.0f);
    if (g.chance(0.05f)) w = hostile(g);
    in.v[0] = vec4(uv, w, g.chance(0.2f) ? 1.0f : 0.0f);
    v.push_back(in);
  }
  return v;
}

vec4 colour(InputGen& g) { return vec4(g.uniform(0, 1), g.uniform(0, 1), g.uniform(0, 1), g.uniform(0, 1)); }

std::vector<ParityIO> maskBlendInputs() {
  InputGen g(604);
  std::vector<ParityIO> v;
  for (int i = 0; i < 12000; ++i) {
    ParityIO in{};
    vec4 a = colour(g), b = colour(g);
    int k = g.integer(0, 9);
    if (k == 0) a.w = 0.0f;
    if (k == 1) a.w = 1.0f;
    if (k == 2) a.w = g.uniform(-3.0f, 4.0f);
    if (k == 3) a.w = hostile(g);
    if (g.chance(0.02f)) a.x = kNaN;  // NaN colours propagate
    in.v[0] = a;
    in.v[1] = b;
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> depthAcceptInputs() {
  InputGen g(605);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    ParityIO in{};
    for (int k = 0; k < 4; ++k) {
      float s = g.uniform(0, 1), f = g.uniform(0, 1);
      if (g.chance(0.1f)) s = f;  // equal depths accept
      if (g.chance(0.03f)) s = hostile(g);
      if (g.chance(0.03f)) f = hostile(g);
      int conv = g.integer(-1, 5);
      in.v[k] = vec4(s, f, static_cast<float>(conv), 0.0f);
    }
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> maskedDepthInputs() {
  InputGen g(606);
  std::vector<ParityIO> v;
  for (int i = 0; i < 12000; ++i) {
    ParityIO in{};
    vec2 uv = screenUv(g), b = bumpXy(g);
    in.v[0] = vec4(uv, b);
    float surface = g.uniform(0.0f, 1.0f);
    if (g.chance(0.1f)) surface = static_cast<float>(g.integer(0, 10)) / 10.0f;  // equal to a depth block
    if (g.chance(0.02f)) surface = kNaN;
    in.v[1] = vec4(perturbScale(g), surface, static_cast<float>(g.integer(-1, 5)), 0.0f);
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> noInputs() { return std::vector<ParityIO>(2000, ParityIO{}); }

std::vector<ParityIO> bumpAverageInputs() {
  InputGen g(607);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    ParityIO in{};
    for (int k = 0; k < 4; ++k) {
      vec3 t(g.uniform(0, 1), g.uniform(0, 1), g.uniform(0.5f, 1));
      if (g.chance(0.05f)) t = vec3(0.5f, 0.5f, 0.5f);  // all flat: the sum vanishes
      if (g.chance(0.01f)) t = hostileVector(g);
      in.v[k] = vec4(t, 0.0f);
    }
    v.push_back(in);
  }
  return v;
}

// A tangent-space vector pointing up (z > 0), sometimes hostile or zero.
vec3 upVector(InputGen& g) {
  vec3 n = g.unitVector();
  n.z = std::fabs(n.z) + 0.1f;
  if (g.chance(0.1f)) n *= g.uniform(0.01f, 10.0f);
  if (g.chance(0.02f)) n = vec3(0.0f);
  if (g.chance(0.02f)) n = hostileVector(g);
  return n;
}

std::vector<ParityIO> waterInputs() {
  InputGen g(608);
  std::vector<ParityIO> v;
  for (int i = 0; i < 12000; ++i) {
    ParityIO in{};
    float dist = g.uniform(0.1f, 100.0f);
    if (g.chance(0.05f)) dist = g.uniform(-5.0f, 0.0f);
    if (g.chance(0.03f)) dist = hostile(g);
    bool custom = g.chance(0.3f);
    in.v[0] = vec4(screenUv(g), dist, custom ? 1.0f : 0.0f);
    in.v[1] = vec4(upVector(g), 0.0f);
    in.v[2] = vec4(upVector(g), 0.0f);
    float bias = g.uniform(0.0f, 1.0f), power = g.uniform(0.5f, 8.0f), deep = g.uniform(0.0f, 50.0f);
    if (g.chance(0.05f)) bias = hostile(g);
    if (g.chance(0.05f)) power = hostile(g);
    if (g.chance(0.05f)) deep = hostile(g);
    in.v[3] = vec4(bias, power, deep, g.uniform(0.0f, 0.2f));
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> waterComposeInputs() {
  InputGen g(623);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    ParityIO in{};
    in.v[0] = colour(g);
    in.v[1] = colour(g);
    float dist = g.uniform(0.1f, 100.0f);
    if (g.chance(0.05f)) dist = g.uniform(-5.0f, 0.0f);
    if (g.chance(0.03f)) dist = hostile(g);
    in.v[2] = vec4(upVector(g), dist);
    in.v[3] = vec4(upVector(g), 0.0f);
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> glassInputs() {
  InputGen g(609);
  std::vector<ParityIO> v;
  for (int i = 0; i < 12000; ++i) {
    ParityIO in{};
    in.v[0] = vec4(screenUv(g), 0.0f, 0.0f);
    vec3 t(g.uniform(0, 1), g.uniform(0, 1), g.uniform(0.5f, 1));
    if (g.chance(0.03f)) t = vec3(0.5f);  // unpacks to 0: flat fallback
    if (g.chance(0.02f)) t = hostileVector(g);
    in.v[1] = vec4(t, 0.0f);
    in.v[2] = vec4(upVector(g), 0.0f);
    vec4 diffuse = colour(g);
    if (g.chance(0.03f)) diffuse.x = hostile(g);
    in.v[3] = diffuse;
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> iceInputs() {
  InputGen g(610);
  std::vector<ParityIO> v;
  for (int i = 0; i < 12000; ++i) {
    ParityIO in{};
    vec3 nf = g.unitVector(), nb = g.unitVector();
    vec3 e = g.unitVector();
    if (glm::dot(e, nf) > 0.0f) e = -e;  // mostly front faces
    if (g.chance(0.1f)) e = -nf;         // head-on
    if (g.chance(0.1f)) e *= g.uniform(0.01f, 100.0f);
    if (g.chance(0.1f)) nb = -nf;  // parallel faces
    float a = g.uniform(0.0f, 1.0f);
    if (g.chance(0.1f)) a = g.chance(0.5f) ? 0.0f : 1.0f;
    if (g.chance(0.03f)) a = hostile(g);
    float eta = g.chance(0.7f) ? 1.0003f / 1.3091f : g.uniform(0.5f, 1.0f);
    if (g.chance(0.05f)) eta = hostile(g);
    if (g.chance(0.02f)) e = hostileVector(g);
    if (g.chance(0.02f)) nf = hostileVector(g);
    if (g.chance(0.02f)) nb = hostileVector(g);
    in.v[0] = vec4(e, a);
    in.v[1] = vec4(nf, eta);
    in.v[2] = vec4(nb, g.chance(0.2f) ? 1.0f : 0.0f);
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> iceComposeInputs() {
  InputGen g(611);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    ParityIO in{};
    in.v[0] = colour(g);
    in.v[1] = colour(g);
    float f = g.uniform(0.0f, 1.0f);
    if (g.chance(0.1f)) f = g.uniform(-2.0f, 3.0f);
    if (g.chance(0.05f)) f = hostile(g);
    in.v[2] = vec4(f, 0.0f, 0.0f, 0.0f);
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> crackInputs() {
  InputGen g(612);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    ParityIO in{};
    for (int k = 0; k < 4; ++k) {
      float c = g.uniform(0, 1), f = g.uniform(0, 1), b = g.uniform(0, 1);
      if (g.chance(0.1f)) c = f;
      if (g.chance(0.1f)) c = b;
      if (g.chance(0.05f)) c = g.uniform(-0.5f, 1.5f);
      if (g.chance(0.03f)) c = hostile(g);
      if (g.chance(0.03f)) f = hostile(g);
      if (g.chance(0.03f)) b = hostile(g);
      in.v[k] = vec4(c, f, b, static_cast<float>(g.integer(-1, 5)));
    }
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> rtmParamsInputs() {
  InputGen g(613);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    ParityIO in{};
    in.v[0] = vec4(g.uniform(-10, 10), g.uniform(-10, 10), g.uniform(-10, 10), g.uniform(-10, 10));
    in.v[1] = vec4(g.uniform(-5, 5), g.uniform(0, 5), g.uniform(0, 3), 0.0f);
    if (g.chance(0.05f)) in.v[1].x = hostile(g);
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> rtmAxisInputs() {
  InputGen g(614);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    ParityIO in{};
    for (int k = 0; k < 4; ++k) {
      float lo = g.uniform(-10, 10), hi = lo + g.uniform(0.1f, 20.0f);
      if (g.chance(0.1f)) std::swap(lo, hi);  // reversed extent
      if (g.chance(0.05f)) hi = lo;           // empty extent
      float x = g.uniform(lo - 5.0f, hi + 5.0f);
      if (g.chance(0.03f)) x = g.chance(0.5f) ? 3e38f : -3e38f;  // overflow of x - lo
      if (g.chance(0.03f)) x = hostile(g);
      if (g.chance(0.03f)) lo = hostile(g);
      if (g.chance(0.03f)) hi = hostile(g);
      in.v[k] = vec4(x, lo, hi, 0.0f);
    }
    v.push_back(in);
  }
  return v;
}

// Rays steep enough that the float hit is well conditioned (|dir.y| is at
// least ~0.05: the eye is above the mesh at a moderate distance).
std::vector<ParityIO> rtmInputs() {
  InputGen g(615);
  std::vector<ParityIO> v;
  for (int i = 0; i < 12000; ++i) {
    ParityIO in{};
    vec2 lo(g.uniform(-10, 0), g.uniform(-10, 0));
    vec2 hi = lo + vec2(g.uniform(1, 20), g.uniform(1, 20));
    float restY = g.uniform(-2, 2), depth = g.uniform(0.1f, 5.0f), factor = g.uniform(0.0f, 3.0f);
    vec3 vert(g.uniform(lo.x, hi.x), restY + g.uniform(-0.3f, 0.3f), g.uniform(lo.y, hi.y));
    vec3 n = glm::normalize(vec3(g.uniform(-0.5f, 0.5f), 1.0f, g.uniform(-0.5f, 0.5f)));
    vec3 eye(vert.x + g.uniform(-10, 10), restY + g.uniform(2, 20), vert.z + g.uniform(-10, 10));
    if (g.chance(0.05f)) factor = g.chance(0.5f) ? 0.0f : hostile(g);
    if (g.chance(0.05f)) vert.y = restY - depth - g.uniform(0.1f, 1.0f);  // below the map: no hit
    if (g.chance(0.05f)) eye.y = vert.y - g.uniform(0.5f, 5.0f);           // looking up: no hit
    if (g.chance(0.02f)) vert = hostileVector(g);
    if (g.chance(0.02f)) n = hostileVector(g);
    if (g.chance(0.02f)) eye = hostileVector(g);
    if (g.chance(0.02f)) lo.x = hostile(g);
    if (g.chance(0.02f)) hi.y = lo.y;
    in.v[0] = vec4(vert, factor);
    in.v[1] = vec4(n, depth);
    in.v[2] = vec4(eye, restY);
    in.v[3] = vec4(lo, hi);
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> dispersionIorsInputs() {
  InputGen g(616);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    ParityIO in{};
    float x[8];
    for (int k = 0; k < 4; ++k) {
      float nd = g.uniform(1.0f, 2.5f), abbe = g.uniform(15.0f, 90.0f);
      if (g.chance(0.05f)) abbe = g.uniform(0.0f, 1.0f);
      if (g.chance(0.05f)) nd = g.uniform(0.1f, 1.0f);
      if (g.chance(0.05f)) abbe = hostile(g);
      if (g.chance(0.05f)) nd = hostile(g);
      x[2 * k] = nd;
      x[2 * k + 1] = abbe;
    }
    in.v[0] = vec4(x[0], x[1], x[2], x[3]);
    in.v[1] = vec4(x[4], x[5], x[6], x[7]);
    v.push_back(in);
  }
  return v;
}

// Entering (iorOutside 1: no TIR) and leaving (iorOutside > iors: TIR
// possible); samples within 1e-4 of a channel's critical angle are redrawn
// (there the TIR flag depends on the last bit of cos_t^2).
std::vector<ParityIO> dispersionRefractInputs() {
  InputGen g(617);
  std::vector<ParityIO> v;
  while (v.size() < 12000) {
    ParityIO in{};
    vec3 n = g.unitVector(), d = g.unitVector();
    float nd = g.uniform(1.3f, 1.9f), abbe = g.uniform(20.0f, 70.0f);
    vec3 iors = snell::snellDispersionIors(nd, abbe);
    if (g.chance(0.1f)) iors = vec3(g.uniform(1, 2), g.uniform(1, 2), g.uniform(1, 2));
    float outside = g.chance(0.6f) ? 1.0f : g.uniform(1.0f, 2.5f);
    if (g.chance(0.03f)) outside = hostile(g);
    if (g.chance(0.03f)) iors.y = hostile(g);
    if (g.chance(0.02f)) d = hostileVector(g);
    if (g.chance(0.02f)) n = hostileVector(g);
    bool nearCritical = false;
    double cosI = std::fabs(double(glm::dot(glm::normalize(d), glm::normalize(n))));
    for (int c = 0; c < 3; ++c) {
      double eta = double(snell::snellIorToEta(outside, iors[c]));
      double cos2T = (1.0 - eta * eta) + eta * eta * cosI * cosI;
      if (std::fabs(cos2T) < 1e-4) nearCritical = true;
    }
    if (nearCritical) continue;
    in.v[0] = vec4(d, outside);
    in.v[1] = vec4(n, static_cast<float>(g.integer(0, 2)));
    in.v[2] = vec4(iors, 0.0f);
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> roughnessInputs() {
  InputGen g(618);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    ParityIO in{};
    float x[8];
    for (int k = 0; k < 4; ++k) {
      float r = g.uniform(0.0f, 1.0f);
      if (g.chance(0.1f)) r = g.chance(0.5f) ? 0.0f : 1.0f;
      if (g.chance(0.05f)) r = g.uniform(-2.0f, 3.0f);
      if (g.chance(0.03f)) r = hostile(g);
      x[2 * k] = r;
      x[2 * k + 1] = static_cast<float>(g.integer(-2, 16));
    }
    in.v[0] = vec4(x[0], x[1], x[2], x[3]);
    in.v[1] = vec4(x[4], x[5], x[6], x[7]);
    v.push_back(in);
  }
  return v;
}

#define SHADE_CPU(entry) [](const ParityIO& in) { return run(parity_shade::entry, in); }

}  // namespace

// Tolerances: 1e-6 for pure arithmetic; 1e-4 (abs and rel) where LINEAR
// texture reads enter (llvmpipe's bilinear weights, as in the hook cases) or
// GPU pow() (snellFresnelBiasPower's exp2/log2 polynomials); 1e-5 for
// normalized directions (inversesqrt).
SNELL_PARITY_CASE({"snellUnpackBump", "shade.glsl", "caseSnellUnpackBump", unpackBumpInputs,
                   SHADE_CPU(caseSnellUnpackBump), 0, 3, {1e-6f, 1e-6f}});
SNELL_PARITY_CASE({"snellPerturbUv", "shade.glsl", "caseSnellPerturbUv", [] { return perturbInputs(620); },
                   SHADE_CPU(caseSnellPerturbUv), 0, 2, {1e-6f, 1e-6f}});
SNELL_PARITY_CASE({"snellPerturbSample", "shade.glsl", "caseSnellPerturbSample", [] { return perturbInputs(621); },
                   SHADE_CPU(caseSnellPerturbSample), 0, 4, {1e-4f, 1e-4f}, shadeTextures(), buildTextures});
SNELL_PARITY_CASE({"snellScreenEdgeFade", "shade.glsl", "caseSnellScreenEdgeFade", edgeFadeInputs,
                   SHADE_CPU(caseSnellScreenEdgeFade), 0, 1, {1e-5f, 1e-5f}});
SNELL_PARITY_CASE({"snellRefractionMaskBlend", "shade.glsl", "caseSnellRefractionMaskBlend", maskBlendInputs,
                   SHADE_CPU(caseSnellRefractionMaskBlend), 0, 4, {1e-6f, 1e-6f}});
SNELL_PARITY_CASE({"snellRefractionMasked", "shade.glsl", "caseSnellRefractionMasked",
                   [] { return perturbInputs(622); }, SHADE_CPU(caseSnellRefractionMasked), 0, 4, {1e-4f, 1e-4f},
                   shadeTextures(), buildTextures});
SNELL_PARITY_CASE({"snellRefractionDepthAccept", "shade.glsl", "caseSnellRefractionDepthAccept", depthAcceptInputs,
                   SHADE_CPU(caseSnellRefractionDepthAccept), 0xF, 4, {0.0f, 0.0f}});
SNELL_PARITY_CASE({"snellRefractionMaskedDepth", "shade.glsl", "caseSnellRefractionMaskedDepth", maskedDepthInputs,
                   SHADE_CPU(caseSnellRefractionMaskedDepth), 0, 4, {1e-4f, 1e-4f}, shadeTextures(),
                   buildTextures});
SNELL_PARITY_CASE({"snellWaterParams", "shade.glsl", "caseSnellWaterParams", noInputs,
                   SHADE_CPU(caseSnellWaterParams), 0x7FFF, 15, {0.0f, 0.0f}});
SNELL_PARITY_CASE({"snellWaterBumpAverage", "shade.glsl", "caseSnellWaterBumpAverage", bumpAverageInputs,
                   SHADE_CPU(caseSnellWaterBumpAverage), 0, 3, {1e-5f, 1e-5f}});
SNELL_PARITY_CASE({"snellWater", "shade.glsl", "caseSnellWater", waterInputs, SHADE_CPU(caseSnellWater), 0, 4,
                   {1e-4f, 1e-4f}, shadeTextures(), buildTextures});
SNELL_PARITY_CASE({"snellWaterCompose", "shade.glsl", "caseSnellWaterCompose", waterComposeInputs,
                   SHADE_CPU(caseSnellWaterCompose), 0, 4, {1e-5f, 1e-5f}});
SNELL_PARITY_CASE({"snellGlass", "shade.glsl", "caseSnellGlass", glassInputs, SHADE_CPU(caseSnellGlass), 0, 4,
                   {1e-4f, 1e-4f}, shadeTextures(), buildTextures});
SNELL_PARITY_CASE({"snellIce", "shade.glsl", "caseSnellIce", iceInputs, SHADE_CPU(caseSnellIce), 0x80, 8,
                   {1e-5f, 1e-5f}});
SNELL_PARITY_CASE({"snellIceCompose", "shade.glsl", "caseSnellIceCompose", iceComposeInputs,
                   SHADE_CPU(caseSnellIceCompose), 0, 4, {1e-6f, 1e-6f}});
SNELL_PARITY_CASE({"snellIceCrackKeep", "shade.glsl", "caseSnellIceCrackKeep", crackInputs,
                   SHADE_CPU(caseSnellIceCrackKeep), 0xF, 4, {0.0f, 0.0f}});
SNELL_PARITY_CASE({"snellRefractiveTextureMapParams", "shade.glsl", "caseSnellRefractiveTextureMapParams",
                   rtmParamsInputs, SHADE_CPU(caseSnellRefractiveTextureMapParams), 0x3FF, 10, {0.0f, 0.0f}});
SNELL_PARITY_CASE({"snellRefractiveTextureMapAxis", "shade.glsl", "caseSnellRefractiveTextureMapAxis",
                   rtmAxisInputs, SHADE_CPU(caseSnellRefractiveTextureMapAxis), 0, 4, {1e-6f, 1e-6f}});
// 1e-4: the hit moves by t * (error of the normalized direction); t reaches a
// few tens of units here.
SNELL_PARITY_CASE({"snellRefractiveTextureMap", "shade.glsl", "caseSnellRefractiveTextureMap", rtmInputs,
                   SHADE_CPU(caseSnellRefractiveTextureMap), 0x1800, 13, {1e-4f, 1e-4f}});
SNELL_PARITY_CASE({"snellDispersionIors", "shade.glsl", "caseSnellDispersionIors", dispersionIorsInputs,
                   SHADE_CPU(caseSnellDispersionIors), 0, 16, {1e-6f, 1e-6f}});
SNELL_PARITY_CASE({"snellDispersionRefract", "shade.glsl", "caseSnellDispersionRefract", dispersionRefractInputs,
                   SHADE_CPU(caseSnellDispersionRefract), 0x3000, 14, {1e-5f, 1e-5f}});
SNELL_PARITY_CASE({"snellRoughnessToLod", "shade.glsl", "caseSnellRoughnessToLod", roughnessInputs,
                   SHADE_CPU(caseSnellRoughnessToLod), 0, 4, {1e-6f, 1e-6f}});
