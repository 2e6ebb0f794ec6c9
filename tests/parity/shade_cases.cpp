// The shade/ parity and property cases (see parity_case.hpp): one description
// per public function of the Sousa / water / glass / ice / refractive-texture-map
// / dispersion / roughness functions of glsl/snell/shade. Cases that sample
// read three textures built here: a LINEAR scene colour with Sousa's mask in
// alpha, a LINEAR reflection map and a NEAREST depth buffer (declared as
// uniforms in cases/shade.glsl).
#include <snell/shade.hpp>

#include "parity_case.hpp"

namespace parity_shade {
// The C++ side of cases/shade.glsl's texture uniforms.
snell::Texture2D parityShadeScene, parityShadeReflection, parityShadeDepth;
}  // namespace parity_shade

namespace {
using glm::vec2;
using glm::vec3;
using glm::vec4;
using snell::Filter;
using snell::Image;
using snell::Texture2D;
using snell_parity::InputGen;
using snell_parity::ParityIO;

const float kNaN = std::numeric_limits<float>::quiet_NaN();

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
  parity_shade::parityShadeScene = Texture2D(scene, Filter::Linear);
  parity_shade::parityShadeReflection = Texture2D(refl, Filter::Linear);
  parity_shade::parityShadeDepth = Texture2D(depth, Filter::Nearest);
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

// The rough cone's functions read floats 0..11: roughness or a cone's radius (0), eta or its angle (1), a path
// length or its exit angle (2), a distance (3), a view-space point in front of the camera (4..6), fovy (7),
// aspect (8), a texture size (9, 10) and a level count or a bounce count (11); a few floats hostile.
std::vector<ParityIO> roughConeInputs() {
  InputGen g(620);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    float x[12];
    x[0] = g.chance(0.1f) ? 0.0f : g.uniform(0.0f, 1.0f);
    x[1] = g.uniform(0.3f, 3.0f);
    x[2] = g.uniform(0.0f, 10.0f);
    x[3] = g.uniform(0.0f, 20.0f);
    x[4] = g.uniform(-3.0f, 3.0f);
    x[5] = g.uniform(-3.0f, 3.0f);
    x[6] = -g.uniform(0.2f, 50.0f);
    x[7] = g.uniform(0.2f, 2.5f);
    x[8] = g.uniform(0.5f, 2.0f);
    x[9] = static_cast<float>(g.integer(1, 4096));
    x[10] = static_cast<float>(g.integer(1, 4096));
    x[11] = static_cast<float>(g.integer(-1, 14));
    for (int k = 0; k < 9; ++k)
      if (g.chance(0.02f)) x[k] = hostile(g);
    ParityIO in{};
    in.v[0] = vec4(x[0], x[1], x[2], x[3]);
    in.v[1] = vec4(x[4], x[5], x[6], x[7]);
    in.v[2] = vec4(x[8], x[9], x[10], x[11]);
    v.push_back(in);
  }
  return v;
}

// A colour texel with each channel hostile (NaN, infinities, denormals, huge) at times, for the colour
// pyramid's reading of it; and an output texel and a level size along one axis of its reduce (even, odd,
// 1, below 1; the texel in range, beyond it, negative).
std::vector<ParityIO> colorTexelInputs() {
  InputGen g(631);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    vec4 t(g.uniform(-2.0f, 8.0f), g.uniform(0.0f, 1.0f), g.uniform(0.0f, 100.0f), g.uniform(0.0f, 1.0f));
    for (int k = 0; k < 4; ++k)
      if (g.chance(0.1f)) t[k] = hostile(g);
    ParityIO in{};
    in.v[0] = t;
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> colorAxisInputs() {
  InputGen g(632);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    const int size = g.chance(0.05f) ? g.integer(-3, 1) : g.integer(1, 4096);
    const int half = std::max(1, size / 2);
    const int px = g.chance(0.05f) ? g.integer(-5, half + 5) : g.integer(0, half - 1);
    ParityIO in{};
    in.v[0] = vec4(float(px), float(size), 0.0f, 0.0f);
    v.push_back(in);
  }
  return v;
}
}  // namespace

namespace parity_shade {
using namespace snell;
using snell_parity::CaseExtras;
#include "cases/shade.glsl"
#define SNELL_PARITY_FILE "shade.glsl"

// Tolerances: 1e-6 for pure arithmetic; 1e-4 (abs and rel) where LINEAR
// texture reads enter (llvmpipe's bilinear weights, as in the hook cases) or
// GPU pow() (snellFresnelBiasPower's exp2/log2 polynomials); 1e-5 for
// normalized directions (inversesqrt).

SNELL_PARITY_CASE(snellUnpackBump, unpackBumpInputs,
                  (vec3, texel, 0),
                  (vec3, n, 0, within(1e-6f, 1e-6f)),
                  CaseExtras().passThrough({"texel"}, {"n"},
                                           "shade/perturb.glsl: 'snellUnpackBump(t) = 2 t - 1, nothing else: NaN "
                                           "propagates'"),
                  n = snellUnpackBump(texel);)

// Both overloads: the explicit scale, and the default one when useDefault.
SNELL_PARITY_CASE(snellPerturbUv, [] { return perturbInputs(620); },
                  (vec2, uv, 0)(vec2, bump, 2)(float, scale, 4)(bool, useDefault, 5),
                  (vec2, perturbed, 0, within(1e-6f, 1e-6f)),
                  {},
                  perturbed = useDefault ? snellPerturbUv(uv, bump) : snellPerturbUv(uv, bump, scale);)

SNELL_PARITY_CASE(snellPerturbSample, [] { return perturbInputs(621); },
                  (vec2, uv, 0)(vec2, bump, 2)(float, scale, 4),
                  (vec4, color, 0, within(1e-4f, 1e-4f)),
                  CaseExtras().sampling(shadeTextures(), buildTextures),
                  color = snellPerturbSample(parityShadeScene, uv, bump, scale);)

// Both overloads: the explicit width, and the default one when useDefault.
SNELL_PARITY_CASE(snellScreenEdgeFade, edgeFadeInputs,
                  (vec2, uv, 0)(float, width, 2)(bool, useDefault, 3),
                  (float, fade, 0, within(1e-5f, 1e-5f)),
                  {},
                  fade = useDefault ? snellScreenEdgeFade(uv) : snellScreenEdgeFade(uv, width);)

SNELL_PARITY_CASE(snellRefractionMaskBlend, maskBlendInputs,
                  (vec4, refrA, 0)(vec4, refrB, 4),
                  (vec4, blended, 0, within(1e-6f, 1e-6f)),
                  CaseExtras().passThrough({"refrA.x", "refrA.y", "refrA.z", "refrB"}, {"blended"},
                                           "shade/refraction_mask.glsl: 'Colours are blended as given (NaN colours "
                                           "propagate)'; the mask alpha (input 3) is checked"),
                  blended = snellRefractionMaskBlend(refrA, refrB);)

SNELL_PARITY_CASE(snellRefractionMasked, [] { return perturbInputs(622); },
                  (vec2, uv, 0)(vec2, bump, 2)(float, scale, 4),
                  (vec4, color, 0, within(1e-4f, 1e-4f)),
                  CaseExtras().sampling(shadeTextures(), buildTextures),
                  color = snellRefractionMasked(parityShadeScene, uv, bump, scale);)

// (sceneDepth, surfaceDepth, convention) triples, four evaluations per input.
SNELL_PARITY_CASE(snellRefractionDepthAccept, depthAcceptInputs,
                  (vec2, depths0, 0)(int, convention0, 2)(vec2, depths1, 4)(int, convention1, 6)
                  (vec2, depths2, 8)(int, convention2, 10)(vec2, depths3, 12)(int, convention3, 14),
                  (bool, accept0, 0, exact)(bool, accept1, 1, exact)(bool, accept2, 2, exact)(bool, accept3, 3, exact),
                  {},
                  accept0 = snellRefractionDepthAccept(depths0.x, depths0.y, convention0);
                  accept1 = snellRefractionDepthAccept(depths1.x, depths1.y, convention1);
                  accept2 = snellRefractionDepthAccept(depths2.x, depths2.y, convention2);
                  accept3 = snellRefractionDepthAccept(depths3.x, depths3.y, convention3);)

SNELL_PARITY_CASE(snellRefractionMaskedDepth, maskedDepthInputs,
                  (vec2, uv, 0)(vec2, bump, 2)(float, scale, 4)(float, surfaceDepth, 5)(int, convention, 6),
                  (vec4, color, 0, within(1e-4f, 1e-4f)),
                  CaseExtras().sampling(shadeTextures(), buildTextures),
                  color = snellRefractionMaskedDepth(parityShadeScene, parityShadeDepth, uv, bump, scale, surfaceDepth,
                                                     convention);)

// No input: every field of the defaults.
SNELL_PARITY_CASE(snellWaterParams, noInputs,
                  /* no inputs */,
                  (vec3, refractionBumpScale, 0, exact)(vec3, reflectionBumpScale, 3, exact)
                  (float, fresnelBias, 6, exact)(float, fresnelPower, 7, exact)(float, deepDistance, 8, exact)
                  (vec3, waterColor, 9, exact)(vec3, deepColor, 12, exact),
                  {},
                  SnellWaterParams p = snellWaterParams();
                  refractionBumpScale = p.refractionBumpScale;
                  reflectionBumpScale = p.reflectionBumpScale;
                  fresnelBias = p.fresnelBias;
                  fresnelPower = p.fresnelPower;
                  deepDistance = p.deepDistance;
                  waterColor = p.waterColor;
                  deepColor = p.deepColor;)

// The four bump texels.
SNELL_PARITY_CASE(snellWaterBumpAverage, bumpAverageInputs,
                  (vec3, t0, 0)(vec3, t1, 4)(vec3, t2, 8)(vec3, t3, 12),
                  (vec3, n, 0, within(1e-5f, 1e-5f)),
                  {},
                  n = snellWaterBumpAverage(t0, t1, t2, t3);)

// The defaults, or (custom) the given fresnel bias and power, deep distance and
// refraction bump scale.
SNELL_PARITY_CASE(snellWater, waterInputs,
                  (vec2, uv, 0)(float, viewDistance, 2)(bool, custom, 3)(vec3, bumpNormal, 4)(vec3, eye, 8)
                  (float, fresnelBias, 12)(float, fresnelPower, 13)(float, deepDistance, 14)(float, bumpScale, 15),
                  (vec4, color, 0, within(1e-4f, 1e-4f)),
                  CaseExtras().sampling(shadeTextures(), buildTextures),
                  SnellWaterParams p = snellWaterParams();
                  if (custom) {
                    p.fresnelBias = fresnelBias;
                    p.fresnelPower = fresnelPower;
                    p.deepDistance = deepDistance;
                    p.refractionBumpScale = vec3(bumpScale, bumpScale, 1.0f);
                  }
                  color = snellWater(parityShadeScene, parityShadeReflection, uv, bumpNormal, eye, viewDistance, p);)

SNELL_PARITY_CASE(snellWaterCompose, waterComposeInputs,
                  (vec4, reflection, 0)(vec4, refraction, 4)(vec3, bumpNormal, 8)(float, viewDistance, 11)
                  (vec3, eye, 12),
                  (vec4, color, 0, within(1e-5f, 1e-5f)),
                  CaseExtras().passThrough({"reflection", "refraction"}, {"color.x", "color.y", "color.z"},
                                           "shade/water.glsl: 'Colours (parameters and texels) are used as given'; "
                                           "snellWaterCompose composes the given reflection (a) and refraction (b); "
                                           "the normal, eye and distance are checked"),
                  color = snellWaterCompose(reflection, refraction, bumpNormal, eye, viewDistance, snellWaterParams());)

SNELL_PARITY_CASE(snellGlass, glassInputs,
                  (vec2, uv, 0)(vec3, bumpTexel, 4)(vec3, eye, 8)(vec4, diffuse, 12),
                  (vec4, color, 0, within(1e-4f, 1e-4f)),
                  CaseExtras()
                      .sampling(shadeTextures(), buildTextures)
                      .passThrough({"diffuse.w"}, {"color.w"},
                                   "shade/glass.glsl: 'Other colours (texels, diffuse.a) are used as given'"),
                  color = snellGlass(parityShadeScene, parityShadeReflection, uv, bumpTexel, diffuse, eye);)

// Both overloads: the given blend weight and eta, or (useDefaults) the defaults.
SNELL_PARITY_CASE(snellIce, iceInputs,
                  (vec3, eye, 0)(float, weight, 3)(vec3, frontNormal, 4)(float, eta, 7)(vec3, backNormal, 8)
                  (bool, useDefaults, 11),
                  (vec3, refracted, 0, within(1e-5f, 1e-5f))(float, fresnel, 3, within(1e-5f, 1e-5f))
                  (vec3, reflected, 4, within(1e-5f, 1e-5f))(bool, valid, 7, exact),
                  {},
                  SnellIce s;  // no ?: on structs: WebGL rejects it
                  if (useDefaults) {
                    s = snellIce(eye, frontNormal, backNormal);
                  } else {
                    s = snellIce(eye, frontNormal, backNormal, weight, eta);
                  }
                  refracted = s.refracted;
                  fresnel = s.fresnel;
                  reflected = s.reflected;
                  valid = s.valid;)

SNELL_PARITY_CASE(snellIceCompose, iceComposeInputs,
                  (vec4, reflection, 0)(vec4, refraction, 4)(float, fresnel, 8),
                  (vec4, color, 0, within(1e-6f, 1e-6f)),
                  CaseExtras().passThrough({"reflection", "refraction"}, {"color"},
                                           "shade/ice.glsl: a mix of the two given colours (reflection a, "
                                           "refraction b); the fresnel weight is checked"),
                  color = snellIceCompose(reflection, refraction, fresnel);)

// (crackDepth, frontDepth, backDepth, convention) quadruples, four evaluations
// per input.
SNELL_PARITY_CASE(snellIceCrackKeep, crackInputs,
                  (vec3, depths0, 0)(int, convention0, 3)(vec3, depths1, 4)(int, convention1, 7)
                  (vec3, depths2, 8)(int, convention2, 11)(vec3, depths3, 12)(int, convention3, 15),
                  (bool, keep0, 0, exact)(bool, keep1, 1, exact)(bool, keep2, 2, exact)(bool, keep3, 3, exact),
                  {},
                  keep0 = snellIceCrackKeep(depths0.x, depths0.y, depths0.z, convention0);
                  keep1 = snellIceCrackKeep(depths1.x, depths1.y, depths1.z, convention1);
                  keep2 = snellIceCrackKeep(depths2.x, depths2.y, depths2.z, convention2);
                  keep3 = snellIceCrackKeep(depths3.x, depths3.y, depths3.z, convention3);)

// Every field the constructor stores.
SNELL_PARITY_CASE(snellRefractiveTextureMapParams, rtmParamsInputs,
                  (vec2, givenMin, 0)(vec2, givenMax, 2)(float, givenRestY, 4)(float, givenDepth, 5)
                  (float, givenFactor, 6),
                  (vec2, extentMin, 0, exact)(vec2, extentMax, 2, exact)(float, restY, 4, exact)
                  (float, depth, 5, exact)(float, refractionFactor, 6, exact)(int, policy, 7, exact)
                  (float, uvMin, 8, exact)(float, uvMax, 9, exact),
                  CaseExtras().passThrough({"givenMin", "givenMax", "givenRestY", "givenDepth", "givenFactor"},
                                           {"extentMin", "extentMax", "restY", "depth", "refractionFactor"},
                                           "a plain constructor: the case packs back the extents, restY, depth "
                                           "and factor it stores (uvMin/uvMax, which it sanitizes, are checked)"),
                  SnellRefractiveTextureMapParams p =
                      snellRefractiveTextureMapParams(givenMin, givenMax, givenRestY, givenDepth, givenFactor);
                  extentMin = p.extentMin;
                  extentMax = p.extentMax;
                  restY = p.restY;
                  depth = p.depth;
                  refractionFactor = p.refractionFactor;
                  policy = p.policy;
                  uvMin = p.uvMin;
                  uvMax = p.uvMax;)

// (x, lo, hi) triples, four evaluations per input.
SNELL_PARITY_CASE(snellRefractiveTextureMapAxis, rtmAxisInputs,
                  (vec3, q0, 0)(vec3, q1, 4)(vec3, q2, 8)(vec3, q3, 12),
                  (vec4, axis, 0, within(1e-6f, 1e-6f)),
                  {},
                  axis = vec4(snellRefractiveTextureMapAxis(q0.x, q0.y, q0.z),
                              snellRefractiveTextureMapAxis(q1.x, q1.y, q1.z),
                              snellRefractiveTextureMapAxis(q2.x, q2.y, q2.z),
                              snellRefractiveTextureMapAxis(q3.x, q3.y, q3.z));)

// Four policies/intervals: the constructor's (CLAMP [0, 1]), SHRINK [0.1, 0.9],
// CLAMP with swapped bounds (0.8, 0.3), SHRINK with (NaN, 2) (-> [0, 1]); the
// position and flags of the first. 1e-4: the hit moves by t * (error of the
// normalized direction); t reaches a few tens of units here.
SNELL_PARITY_CASE(snellRefractiveTextureMap, rtmInputs,
                  (vec3, vertex, 0)(float, factor, 3)(vec3, normal, 4)(float, depth, 7)(vec3, eye, 8)
                  (float, restY, 11)(vec2, extentMin, 12)(vec2, extentMax, 14),
                  (vec2, uvClamp, 0, within(1e-4f, 1e-4f))(vec2, uvShrink, 2, within(1e-4f, 1e-4f))
                  (vec2, uvSwapped, 4, within(1e-4f, 1e-4f))(vec2, uvNaN, 6, within(1e-4f, 1e-4f))
                  (vec3, position, 8, within(1e-4f, 1e-4f))(bool, valid, 11, exact)(bool, inRange, 12, exact),
                  {},
                  SnellRefractiveTextureMapParams p =
                      snellRefractiveTextureMapParams(extentMin, extentMax, restY, depth, factor);
                  SnellRefractiveTextureMapHit h1 = snellRefractiveTextureMap(vertex, normal, eye, p);
                  p.policy = SNELL_RTM_SHRINK;
                  p.uvMin = 0.1f;
                  p.uvMax = 0.9f;
                  SnellRefractiveTextureMapHit h2 = snellRefractiveTextureMap(vertex, normal, eye, p);
                  p.policy = SNELL_RTM_CLAMP;
                  p.uvMin = 0.8f;
                  p.uvMax = 0.3f;
                  SnellRefractiveTextureMapHit h3 = snellRefractiveTextureMap(vertex, normal, eye, p);
                  p.policy = SNELL_RTM_SHRINK;
                  p.uvMin = uintBitsToFloat(0x7fc00000u + 0u * floatBitsToUint(restY));  // quiet NaN, not a constant (Tint rejects a constant NaN)
                  p.uvMax = 2.0f;
                  SnellRefractiveTextureMapHit h4 = snellRefractiveTextureMap(vertex, normal, eye, p);
                  uvClamp = h1.uv;
                  uvShrink = h2.uv;
                  uvSwapped = h3.uv;
                  uvNaN = h4.uv;
                  position = h1.position;
                  valid = h1.valid;
                  inRange = h1.inRange;)

// (iorD, abbe) pairs, four evaluations per input.
SNELL_PARITY_CASE(snellDispersionIors, dispersionIorsInputs,
                  (vec2, p0, 0)(vec2, p1, 2)(vec2, p2, 4)(vec2, p3, 6),
                  (vec3, iors0, 0, within(1e-6f, 1e-6f))(vec3, iors1, 4, within(1e-6f, 1e-6f))
                  (vec3, iors2, 8, within(1e-6f, 1e-6f))(vec3, iors3, 12, within(1e-6f, 1e-6f)),
                  {},
                  iors0 = snellDispersionIors(p0.x, p0.y);
                  iors1 = snellDispersionIors(p1.x, p1.y);
                  iors2 = snellDispersionIors(p2.x, p2.y);
                  iors3 = snellDispersionIors(p3.x, p3.y);)

SNELL_PARITY_CASE(snellDispersionRefract, dispersionRefractInputs,
                  (vec3, incident, 0)(float, iorOutside, 3)(vec3, normal, 4)(int, policy, 7)(vec3, iors, 8),
                  (vec3, red, 0, within(1e-5f, 1e-5f))(vec3, green, 4, within(1e-5f, 1e-5f))
                  (vec3, blue, 8, within(1e-5f, 1e-5f))(bool, tir, 12, exact)(bool, valid, 13, exact),
                  {},
                  SnellDispersion s = snellDispersionRefract(incident, normal, iorOutside, iors, policy);
                  red = s.red;
                  green = s.green;
                  blue = s.blue;
                  tir = s.tir;
                  valid = s.valid;)

// (roughness, levels) pairs, four evaluations per input.
SNELL_PARITY_CASE(snellRoughnessToLod, roughnessInputs,
                  (float, roughness0, 0)(int, levels0, 1)(float, roughness1, 2)(int, levels1, 3)
                  (float, roughness2, 4)(int, levels2, 5)(float, roughness3, 6)(int, levels3, 7),
                  (vec4, lod, 0, within(1e-6f, 1e-6f)),
                  {},
                  lod = vec4(snellRoughnessToLod(roughness0, levels0), snellRoughnessToLod(roughness1, levels1),
                             snellRoughnessToLod(roughness2, levels2), snellRoughnessToLod(roughness3, levels3));)

SNELL_PARITY_CASE(snellRoughConeSlope, roughConeInputs,
                  (float, roughness, 0),
                  (float, slope, 0, within(0.0f, 1e-6f)),
                  {},
                  slope = snellRoughConeSlope(roughness);)

SNELL_PARITY_CASE(snellRoughConeHypot, roughConeInputs,
                  (float, x, 2)(float, y, 4),
                  (float, length, 0, within(1e-6f, 1e-5f)),
                  {},
                  length = snellRoughConeHypot(x, y);)

SNELL_PARITY_CASE(snellRoughConeMeasure, roughConeInputs,
                  (float, x, 2),
                  (float, measure, 0, exact),
                  {},
                  measure = snellRoughConeMeasure(x);)

SNELL_PARITY_CASE(snellRoughConeLevel, roughConeInputs,
                  (float, radius, 2)(float, texelsPerUnit, 3)(int, levels, 11),
                  (float, lod, 0, within(1e-4f, 1e-5f)),
                  {},
                  lod = snellRoughConeLevel(radius, texelsPerUnit, levels);)

SNELL_PARITY_CASE(snellRoughConeTransmit, roughConeInputs,
                  (float, roughness, 0)(float, eta, 1)(float, insideLength, 2)(int, bounces, 11),
                  (float, radius, 0, within(1e-6f, 1e-5f))(float, angle, 1, within(1e-6f, 1e-5f))
                  (float, exitAngle, 2, within(1e-6f, 1e-5f)),
                  {},
                  SnellRoughCone c = snellRoughConeTransmit(roughness, eta, insideLength, bounces);
                  radius = c.radius;
                  angle = c.angle;
                  exitAngle = c.exitAngle;)

SNELL_PARITY_CASE(snellRoughConeReflect, roughConeInputs,
                  (float, roughness, 0),
                  (float, radius, 0, exact)(float, angle, 1, within(0.0f, 1e-6f))(float, exitAngle, 2, exact),
                  {},
                  SnellRoughCone c = snellRoughConeReflect(roughness);
                  radius = c.radius;
                  angle = c.angle;
                  exitAngle = c.exitAngle;)

SNELL_PARITY_CASE(snellRoughConeRadius, roughConeInputs,
                  (float, coneRadius, 0)(float, coneAngle, 1)(float, coneExitAngle, 2)(float, distance, 3),
                  (float, radius, 0, within(1e-6f, 1e-5f)),
                  {},
                  SnellRoughCone c;
                  c.radius = coneRadius;
                  c.angle = coneAngle;
                  c.exitAngle = coneExitAngle;
                  radius = snellRoughConeRadius(c, distance);)

// The level through a perspective projection built from fovy and aspect.
SNELL_PARITY_CASE(snellRoughConeSceneLod, roughConeInputs,
                  (float, coneRadius, 0)(float, coneAngle, 1)(float, coneExitAngle, 2)(float, distance, 3)
                  (vec3, p, 4)(float, fovy, 7)(float, aspect, 8)(ivec2, size, 9)(int, levels, 11),
                  (float, lod, 0, within(1e-4f, 1e-5f)),
                  {},
                  SnellRoughCone c;
                  c.radius = coneRadius;
                  c.angle = coneAngle;
                  c.exitAngle = coneExitAngle;
                  lod = snellRoughConeSceneLod(c, distance, p, snellPerspective(fovy, aspect, 0.1f, 100.0f), size,
                                               levels);)

SNELL_PARITY_CASE(snellRoughConeEnvironmentLod, roughConeInputs,
                  (float, coneRadius, 0)(float, coneAngle, 1)(float, coneExitAngle, 2)(int, levels, 11),
                  (float, lod, 0, within(1e-4f, 1e-5f)),
                  {},
                  SnellRoughCone c;
                  c.radius = coneRadius;
                  c.angle = coneAngle;
                  c.exitAngle = coneExitAngle;
                  lod = snellRoughConeEnvironmentLod(c, levels);)

// The two reads of a rough read at a level (x[3]: 0 to 20 and hostile) of a chain (x[11]: -1 to 14 levels).
SNELL_PARITY_CASE(snellRoughConeTaps, roughConeInputs,
                  (float, lod, 3)(int, levels, 11),
                  (float, coreLod, 0, within(1e-6f, 1e-6f))(float, tailLod, 1, within(1e-6f, 1e-6f))
                  (float, tailWeight, 2, exact),
                  {},
                  SnellRoughTaps t = snellRoughConeTaps(lod, levels);
                  coreLod = t.coreLod;
                  tailLod = t.tailLod;
                  tailWeight = t.tailWeight;)

SNELL_PARITY_CASE(snellRoughConeFetches, roughConeInputs,
                  (float, lod, 3)(int, levels, 11),
                  (int, fetches, 0, exact),
                  {},
                  fetches = snellRoughConeFetches(snellRoughConeTaps(lod, levels));)

// Non-finite channels are tested by their bits: the same texel on every runtime.
SNELL_PARITY_CASE(snellColorPyramidTexel, colorTexelInputs,
                  (vec4, texel, 0),
                  (vec4, read, 0, exact),
                  {},
                  read = snellColorPyramidTexel(texel);)

// Integer arithmetic and one division of integers' floats: the first texel exactly, the weights to rounding.
SNELL_PARITY_CASE(snellColorPyramidAxis, colorAxisInputs,
                  (int, px, 0)(int, size, 1),
                  (int, first, 0, exact)(vec4, weights, 1, within(1e-6f, 1e-6f)),
                  {},
                  SnellColorPyramidAxis a = snellColorPyramidAxis(px, size);
                  first = a.first;
                  weights = a.weights;)

}  // namespace parity_shade
