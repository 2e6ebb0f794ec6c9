// Registrations of the optics/ parity cases (see parity_registry.hpp).
#include <snell/optics.hpp>

#include "parity_registry.hpp"

namespace parity_optics {
using namespace snell;
using snell::gpu::SnellParityOut;
// Every entry takes four vec4s; most use fewer, and the common subset has no
// way to mark a parameter unused.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include "cases/optics.glsl"
#pragma GCC diagnostic pop
}  // namespace parity_optics

namespace {
using snell_parity::InputGen;
using snell_parity::ParityIO;

ParityIO run(snell::gpu::SnellParityOut (*entry)(glm::vec4, glm::vec4, glm::vec4, glm::vec4), const ParityIO& in) {
  return snell::gpu::toParityIO(entry(in.v[0], in.v[1], in.v[2], in.v[3]));
}

std::vector<ParityIO> safeNormalizeInputs() {
  InputGen g(11);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    ParityIO in{};
    glm::vec3 x = g.unitVector() * std::exp(g.uniform(-40.0f, 40.0f));
    if (g.chance(0.1f)) x = g.hostileVector();
    in.v[0] = glm::vec4(x, 0.0f);
    v.push_back(in);
  }
  return v;
}

// Edge cases: grazing angles, TIR on both sides of the critical angle, eta = 1,
// normals facing away, unnormalized and hostile vectors, all three policies.
std::vector<ParityIO> refractInputs() {
  InputGen g(12);
  std::vector<ParityIO> v;
  for (int i = 0; i < 12000; ++i) {
    glm::vec3 n = g.unitVector();
    glm::vec3 d = g.unitVector();
    if (g.chance(0.2f)) d = glm::normalize(d - n * glm::dot(d, n) + n * g.uniform(-1e-3f, 1e-3f));  // grazing
    float eta = g.chance(0.5f) ? 1.0f / g.uniform(1.0f, 2.5f) : g.uniform(1.0f, 2.5f);
    if (g.chance(0.05f)) eta = 1.0f;
    if (g.chance(0.1f)) d *= g.uniform(0.01f, 100.0f);
    if (g.chance(0.03f)) d = g.hostileVector();
    if (g.chance(0.03f)) n = g.hostileVector();
    if (g.chance(0.03f)) eta = g.hostile();
    ParityIO in{};
    in.v[0] = glm::vec4(d, eta);
    in.v[1] = glm::vec4(n, static_cast<float>(g.integer(0, 2)));
    v.push_back(in);
  }
  return v;
}

// GPU drivers may flush denormals to zero (D3D requires it for float32;
// llvmpipe 22.3 happens to keep them), the C++ build does not. Where a denormal
// input can flip a branch (a normal's orientation test, a ray's t >= 0), the
// generators draw hostile values without the denormal ones, so the cases hold
// on any driver; the unit tests cover those inputs against the contract.
float hostileNormalOrSpecial(InputGen& g) {
  for (;;) {
    float x = g.hostile();
    if (x == 0.0f || !(std::fabs(x) < 1e-30f)) return x;
  }
}
glm::vec3 hostileVectorNoDenormal(InputGen& g) {
  return glm::vec3(hostileNormalOrSpecial(g), hostileNormalOrSpecial(g), hostileNormalOrSpecial(g));
}
// A direction at angle ~cos from n (grazing when cos is small).
glm::vec3 atCosine(InputGen& g, glm::vec3 n, float cos) {
  glm::vec3 d = g.unitVector();
  glm::vec3 t = d - n * glm::dot(d, n);
  if (glm::dot(t, t) < 1e-6f) t = glm::cross(n, glm::vec3(0.577f, 0.577f, 0.577f));
  t = glm::normalize(t);
  return t * std::sqrt(std::max(0.0f, 1.0f - cos * cos)) + n * cos;
}

// Grazing, normal incidence, normals facing away, factor 0 / large / inf /
// negative / NaN, unnormalized and hostile vectors.
std::vector<ParityIO> approxRefractInputs() {
  InputGen g(21);
  std::vector<ParityIO> v;
  for (int i = 0; i < 12000; ++i) {
    glm::vec3 n = g.unitVector();
    glm::vec3 d = g.unitVector();
    if (g.chance(0.15f)) d = atCosine(g, -n, g.uniform(-1e-3f, 1e-3f));  // grazing
    if (g.chance(0.05f)) d = -n;                                          // normal incidence
    float factor = g.uniform(0.0f, 4.0f);
    if (g.chance(0.05f)) factor = 0.0f;
    if (g.chance(0.05f)) factor = std::exp(g.uniform(0.0f, 60.0f));
    if (g.chance(0.05f)) factor = g.hostile();
    if (g.chance(0.1f)) d *= g.uniform(0.01f, 100.0f);
    if (g.chance(0.1f)) n *= g.uniform(0.01f, 100.0f);
    if (g.chance(0.03f)) d = hostileVectorNoDenormal(g);
    if (g.chance(0.03f)) n = hostileVectorNoDenormal(g);
    ParityIO in{};
    in.v[0] = glm::vec4(d, factor);
    in.v[1] = glm::vec4(n, 0.0f);
    v.push_back(in);
  }
  return v;
}

// (cosI, eta): both signs of cosI, grazing (0), normal incidence (+-1), out of
// range, TIR (eta > 1 beyond the critical angle) and close to either side of
// it, eta = 1, hostile. Samples with |cos_t^2| < 1e-5 are redrawn: there
// cos_t = sqrt(cos_t^2) has a slope > 150, so a one-ulp difference in cos_t^2
// (FMA contraction by the GPU compiler) would move F by more than the tolerance.
float fresnelCos(InputGen& g, float eta) {
  for (;;) {
    float c = g.uniform(-1.0f, 1.0f);
    int k = g.integer(0, 19);
    if (k == 0) c = 0.0f;
    if (k == 1) c = g.chance(0.5f) ? 1.0f : -1.0f;
    if (k == 2) c = g.uniform(-1e-3f, 1e-3f);
    if (k == 3) c = g.uniform(-3.0f, 3.0f);
    if (k == 4 && eta > 1.0f) {  // within 1e-2 of the critical angle, either side
      double cc = std::sqrt(std::max(0.0, 1.0 - 1.0 / (double(eta) * double(eta))));
      c = static_cast<float>(cc + double(g.uniform(-1e-2f, 1e-2f)));
    }
    if (k == 5) c = g.hostile();
    double e = eta > 0.0f && eta < 1e6f ? double(eta) : 1.0;
    double cd = std::min(std::fabs(double(c)), 1.0);
    double cos2T = (1.0 - e * e) + e * e * cd * cd;
    if (!(std::fabs(cos2T) < 1e-5) || k == 0 || k == 5) return c;
  }
}
float fresnelEta(InputGen& g) {
  float eta = g.chance(0.5f) ? 1.0f / g.uniform(1.0f, 2.5f) : g.uniform(1.0f, 2.5f);
  if (g.chance(0.05f)) eta = 1.0f;
  if (g.chance(0.03f)) eta = g.hostile();
  if (g.chance(0.02f)) eta = std::exp(g.uniform(-20.0f, 20.0f));
  return eta;
}
std::vector<ParityIO> fresnelDielectricInputs() {
  InputGen g(22);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    ParityIO in{};
    float e[4];
    float c[4];
    for (int k = 0; k < 4; ++k) {
      e[k] = fresnelEta(g);
      c[k] = fresnelCos(g, e[k]);
    }
    in.v[0] = glm::vec4(c[0], e[0], c[1], e[1]);
    in.v[1] = glm::vec4(c[2], e[2], c[3], e[3]);
    v.push_back(in);
  }
  return v;
}

float schlickCos(InputGen& g) {
  float c = g.uniform(-1.0f, 1.0f);
  int k = g.integer(0, 15);
  if (k == 0) c = 0.0f;
  if (k == 1) c = 1.0f;
  if (k == 2) c = g.uniform(-2.0f, 2.0f);
  if (k == 3) c = g.hostile();
  return c;
}
std::vector<ParityIO> fresnelSchlickInputs() {
  InputGen g(23);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    float f[4];
    for (float& x : f) {
      x = g.uniform(0.0f, 0.2f);
      int k = g.integer(0, 15);
      if (k == 0) x = g.uniform(0.0f, 1.0f);
      if (k == 1) x = g.uniform(-1.0f, 2.0f);
      if (k == 2) x = g.hostile();
    }
    ParityIO in{};
    in.v[0] = glm::vec4(schlickCos(g), f[0], schlickCos(g), f[1]);
    in.v[1] = glm::vec4(schlickCos(g), f[2], schlickCos(g), f[3]);
    v.push_back(in);
  }
  return v;
}

// nDotL over [-0.5, 1.5] (both clamps) with 0 and 1 exactly; Sousa's (0.2, 5)
// and (0.4, 5), random bias/power, power 0 / negative / huge, hostile values.
std::vector<ParityIO> fresnelBiasPowerInputs() {
  InputGen g(24);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    ParityIO in{};
    for (int k = 0; k < 4; ++k) {
      float ndl = g.uniform(-0.5f, 1.5f);
      if (g.chance(0.05f)) ndl = g.chance(0.5f) ? 0.0f : 1.0f;
      float bias = g.uniform(-0.5f, 1.0f);
      float power = g.uniform(0.5f, 8.0f);
      int c = g.integer(0, 19);
      if (c == 0) { bias = 0.2f; power = 5.0f; }
      if (c == 1) { bias = 0.4f; power = 5.0f; }
      if (c == 2) power = 0.0f;
      if (c == 3) power = g.uniform(-5.0f, 0.0f);
      if (c == 4) power = g.uniform(8.0f, 1e3f);
      if (c == 5) ndl = hostileNormalOrSpecial(g);
      if (c == 6) bias = g.hostile();
      if (c == 7) power = hostileNormalOrSpecial(g);
      in.v[k] = glm::vec4(ndl, bias, power, 0.0f);
    }
    v.push_back(in);
  }
  return v;
}

// Both orientations of eye and normal, head-on, grazing, unnormalized, hostile.
std::vector<ParityIO> fresnelCubicInputs() {
  InputGen g(25);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    ParityIO in{};
    for (int k = 0; k < 2; ++k) {
      glm::vec3 n = g.unitVector();
      glm::vec3 e = g.unitVector();
      int c = g.integer(0, 19);
      if (c == 0) e = -n;
      if (c == 1) e = n;
      if (c == 2) e = atCosine(g, n, g.uniform(-1e-3f, 1e-3f));
      if (c == 3) e *= g.uniform(1e-3f, 1e3f);
      if (c == 4) e = g.hostileVector();
      if (c == 5) n = g.hostileVector();
      in.v[2 * k] = glm::vec4(e, 0.0f);
      in.v[2 * k + 1] = glm::vec4(n, 0.0f);
    }
    v.push_back(in);
  }
  return v;
}

// IOR pairs: physical (1..4), equal, extreme ratios (clamped), hostile.
float iorValue(InputGen& g) {
  float x = g.uniform(1.0f, 4.0f);
  int k = g.integer(0, 19);
  if (k == 0) x = 1.0f;
  if (k == 1) x = std::exp(g.uniform(-80.0f, 80.0f));
  if (k == 2) x = g.uniform(-2.0f, 1.0f);
  if (k == 3) x = g.hostile();
  if (k == 4) x = 3e38f;
  return x;
}
std::vector<ParityIO> iorInputs(std::uint32_t seed) {
  InputGen g(seed);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    ParityIO in{};
    float a = iorValue(g), b = g.chance(0.05f) ? a : iorValue(g);
    in.v[0] = glm::vec4(a, b, iorValue(g), iorValue(g));
    in.v[1] = glm::vec4(iorValue(g), iorValue(g), iorValue(g), iorValue(g));
    v.push_back(in);
  }
  return v;
}

// Front/back normals: typical (back roughly opposite the viewer), equal (the
// a = 0.5 degenerate blend), a = 0, 1, out of [0, 1], NaN, hostile vectors.
std::vector<ParityIO> iceNormalBlendInputs() {
  InputGen g(27);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    glm::vec3 f = g.unitVector();
    glm::vec3 b = g.unitVector();
    float a = g.uniform(0.0f, 1.0f);
    int c = g.integer(0, 19);
    if (c == 0) { b = f; a = 0.5f; }
    if (c == 1) b = -f;
    if (c == 2) a = 0.0f;
    if (c == 3) a = 1.0f;
    if (c == 4) a = 0.33f;
    if (c == 5) a = g.uniform(-2.0f, 3.0f);
    if (c == 6) a = g.hostile();
    if (c == 7) f = g.hostileVector();
    if (c == 8) b = g.hostileVector();
    if (c == 9) { f *= g.uniform(1e-3f, 1e3f); b *= g.uniform(1e-3f, 1e3f); }
    ParityIO in{};
    in.v[0] = glm::vec4(f, a);
    in.v[1] = glm::vec4(b, 0.0f);
    v.push_back(in);
  }
  return v;
}

// Absorption 0..5 per channel, distances 0..10, zero / negative / huge values,
// results down to exp(-50) and underflow, hostile values.
std::vector<ParityIO> beerLambertInputs() {
  InputGen g(28);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    glm::vec3 s(g.uniform(0.0f, 5.0f), g.uniform(0.0f, 5.0f), g.uniform(0.0f, 5.0f));
    float d = g.uniform(0.0f, 10.0f);
    int c = g.integer(0, 19);
    if (c == 0) d = 0.0f;
    if (c == 1) d = g.uniform(-10.0f, 0.0f);
    if (c == 2) d = g.uniform(10.0f, 1e3f);
    if (c == 3) d = g.hostile();
    if (c == 4) s = g.hostileVector();
    if (c == 5) s = glm::vec3(g.uniform(-1.0f, 0.0f), 0.0f, 1e3f);
    ParityIO in{};
    in.v[0] = glm::vec4(s, d);
    v.push_back(in);
  }
  return v;
}

// Angles from 0 to pi: equal, opposite, tiny (1e-4 .. 1e-2) and near pi, near
// the two branch switches (90 degrees, half-chord 1/2 = 60 degrees),
// unnormalized, hostile.
glm::vec3 rotatedBy(InputGen& g, glm::vec3 a, float theta) {
  glm::vec3 t = atCosine(g, a, 0.0f);
  return a * std::cos(theta) + t * std::sin(theta);
}
std::vector<ParityIO> angleBetweenInputs() {
  InputGen g(29);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    ParityIO in{};
    for (int k = 0; k < 2; ++k) {
      glm::vec3 a = g.unitVector();
      glm::vec3 b = g.unitVector();
      int c = g.integer(0, 19);
      if (c == 0) b = a;
      if (c == 1) b = -a;
      if (c == 2) b = rotatedBy(g, a, std::exp(g.uniform(-9.0f, -4.0f)));
      if (c == 3) b = rotatedBy(g, a, 3.14159265f - std::exp(g.uniform(-9.0f, -4.0f)));
      if (c == 4) b = rotatedBy(g, a, g.uniform(1.0f, 1.1f));
      if (c == 5) b = rotatedBy(g, a, g.uniform(1.5f, 1.65f));
      if (c == 6) { a *= g.uniform(1e-3f, 1e3f); b *= g.uniform(1e-3f, 1e3f); }
      if (c == 7) a = g.hostileVector();
      if (c == 8) b = g.hostileVector();
      in.v[2 * k] = glm::vec4(a, 0.0f);
      in.v[2 * k + 1] = glm::vec4(b, 0.0f);
    }
    v.push_back(in);
  }
  return v;
}

// (thetaT, thetaI, dV, dN): physical ratios in [0, 1], r > 1 (clamped), thetaI = 0,
// negative angles, negative / huge distances, hostile values.
std::vector<ParityIO> wymanDistanceInputs() {
  InputGen g(30);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    ParityIO in{};
    for (int k = 0; k < 4; ++k) {
      float ti = g.uniform(0.0f, 1.5708f);
      float tt = ti * g.uniform(0.0f, 1.0f);
      float dV = g.uniform(0.0f, 10.0f), dN = g.uniform(0.0f, 10.0f);
      int c = g.integer(0, 19);
      if (c == 0) ti = 0.0f;
      if (c == 1) tt = ti;
      if (c == 2) tt = ti * g.uniform(1.0f, 3.0f);
      if (c == 3) { ti = -ti; tt = -tt; }
      if (c == 4) dV = g.uniform(-5.0f, 0.0f);
      if (c == 5) dN = std::exp(g.uniform(0.0f, 80.0f));
      if (c == 6) tt = hostileNormalOrSpecial(g);
      if (c == 7) ti = hostileNormalOrSpecial(g);
      if (c == 8) dV = g.hostile();
      if (c == 9) dN = g.hostile();
      in.v[k] = glm::vec4(tt, ti, dV, dN);
    }
    v.push_back(in);
  }
  return v;
}

// Physical geometry: the refracted ray of snellRefract for eta in [0.4, 1],
// incidence angles >= 0.01 rad (below that the angle ratio is dominated by the
// rounding of the unit vectors, ~1e-7 rad, on both sides) or exactly normal
// incidence; normals facing away; TIR-zero refracted vectors; hostile vectors.
std::vector<ParityIO> wymanDistanceVecInputs() {
  InputGen g(31);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    glm::vec3 n = g.unitVector();
    glm::vec3 d = atCosine(g, -n, g.uniform(0.0f, 0.99995f));
    float eta = g.uniform(0.4f, 1.0f);
    int c = g.integer(0, 19);
    if (c == 0) d = -n;  // normal incidence: both angles exactly 0
    if (c == 1) eta = 1.0f;
    glm::vec3 t = snell::snellRefract(d, n, eta, SNELL_TIR_CRITICAL).direction;
    if (c == 2) n = -n;
    if (c == 3) t = glm::vec3(0.0f);
    if (c == 4) t = g.unitVector();  // not a refraction: r clamped or small
    if (c == 5) d = hostileVectorNoDenormal(g);
    if (c == 6) n = hostileVectorNoDenormal(g);
    if (c == 7) t = hostileVectorNoDenormal(g);
    float dV = g.uniform(0.0f, 10.0f), dN = g.uniform(0.0f, 10.0f);
    if (c == 8) dV = g.hostile();
    if (c == 9) dN = g.uniform(-3.0f, 0.0f);
    ParityIO in{};
    in.v[0] = glm::vec4(d, dV);
    in.v[1] = glm::vec4(n, dN);
    in.v[2] = glm::vec4(t, 0.0f);
    v.push_back(in);
  }
  return v;
}

// Hits in front, behind, origin on the plane (t = 0 exactly: origin = plane
// point), exactly parallel (in and off the plane), grazing (|cos| >= 1e-2, far
// from the 1e-6 parallel threshold), unnormalized, overflowing, hostile.
std::vector<ParityIO> rayPlaneInputs() {
  InputGen g(32);
  std::vector<ParityIO> v;
  for (int i = 0; i < 10000; ++i) {
    glm::vec3 o(g.uniform(-10.0f, 10.0f), g.uniform(-10.0f, 10.0f), g.uniform(-10.0f, 10.0f));
    glm::vec3 p(g.uniform(-10.0f, 10.0f), g.uniform(-10.0f, 10.0f), g.uniform(-10.0f, 10.0f));
    glm::vec3 n = g.unitVector();
    glm::vec3 d = g.unitVector();
    if (std::fabs(glm::dot(d, n)) < 1e-2f) d = atCosine(g, n, 0.5f);
    int c = g.integer(0, 19);
    if (c == 0) o = p;
    // Parallel: dot(d, n) = -n.y n.x + n.x n.y = 0 exactly, ~1e-8 after the
    // function normalizes n, far below the 1e-6 threshold.
    if (c == 1) d = glm::vec3(-n.y, n.x, 0.0f) * g.uniform(0.5f, 2.0f);
    if (c == 2) { d = glm::vec3(1.0f, 0.0f, 0.0f); n = glm::vec3(0.0f, 1.0f, 0.0f); o.y = p.y; }  // in the plane
    if (c == 3) d = atCosine(g, n, g.chance(0.5f) ? g.uniform(1e-2f, 2e-2f) : -g.uniform(1e-2f, 2e-2f));
    if (c == 4) { d *= g.uniform(1e-3f, 1e3f); n *= g.uniform(1e-3f, 1e3f); }
    if (c == 5) o = hostileVectorNoDenormal(g);
    if (c == 6) d = hostileVectorNoDenormal(g);
    if (c == 7) p = hostileVectorNoDenormal(g);
    if (c == 8) n = hostileVectorNoDenormal(g);
    // Huge coordinates: planePoint - origin overflows (t = inf: invalid), or
    // everything scaled by 1e10 (t unchanged, position ~1e10). Random huge
    // origins and plane points are avoided: dot(p0 - o, n) then cancels at the
    // 1e37 scale and t has no meaningful absolute tolerance.
    if (c == 9) {
      n = glm::vec3(1.0f, 0.0f, 0.0f);
      o = glm::vec3(3e38f, o.y, o.z);
      p = glm::vec3(-3e38f, p.y, p.z);
      if (std::fabs(d.x) < 0.1f) d.x = 0.5f;
    }
    if (c == 10) { o *= 1e10f; p *= 1e10f; d *= 1e10f; }
    ParityIO in{};
    in.v[0] = glm::vec4(o, 0.0f);
    in.v[1] = glm::vec4(d, 0.0f);
    in.v[2] = glm::vec4(p, 0.0f);
    in.v[3] = glm::vec4(n, 0.0f);
    v.push_back(in);
  }
  return v;
}
}  // namespace

SNELL_PARITY_CASE({"snellSafeNormalize", "optics.glsl", "caseSnellSafeNormalize", safeNormalizeInputs,
                   [](const ParityIO& in) { return run(parity_optics::caseSnellSafeNormalize, in); }, 0, 3,
                   {1e-6f, 1e-6f}});
SNELL_PARITY_CASE({"snellRefract", "optics.glsl", "caseSnellRefract", refractInputs,
                   [](const ParityIO& in) { return run(parity_optics::caseSnellRefract, in); }, 0x30, 6,
                   {1e-5f, 1e-5f}});

// Same operations on both sides; 1e-5 leaves room for the GPU compiler's FMA
// contraction and reassociation.
SNELL_PARITY_CASE({"snellApproxRefract", "optics.glsl", "caseSnellApproxRefract", approxRefractInputs,
                   [](const ParityIO& in) { return run(parity_optics::caseSnellApproxRefract, in); }, 0, 3,
                   {1e-5f, 1e-5f}});
// abs 1e-4: near (not at: see fresnelCos) the critical angle, cos_t = sqrt(cos_t^2)
// magnifies a one-ulp difference in cos_t^2 by up to ~150.
SNELL_PARITY_CASE({"snellFresnelDielectric", "optics.glsl", "caseSnellFresnelDielectric", fresnelDielectricInputs,
                   [](const ParityIO& in) { return run(parity_optics::caseSnellFresnelDielectric, in); }, 0, 4,
                   {1e-4f, 1e-5f}});
SNELL_PARITY_CASE({"snellFresnelSchlick", "optics.glsl", "caseSnellFresnelSchlick", fresnelSchlickInputs,
                   [](const ParityIO& in) { return run(parity_optics::caseSnellFresnelSchlick, in); }, 0, 4,
                   {1e-5f, 1e-5f}});
// rel 1e-4: GPU pow() is exp2(y * log2(x)) with polynomial exp2/log2 (llvmpipe),
// whose relative error grows with |y log2 x|; powers reach 1e3 here.
SNELL_PARITY_CASE({"snellFresnelBiasPower", "optics.glsl", "caseSnellFresnelBiasPower", fresnelBiasPowerInputs,
                   [](const ParityIO& in) { return run(parity_optics::caseSnellFresnelBiasPower, in); }, 0, 4,
                   {1e-5f, 1e-4f}});
SNELL_PARITY_CASE({"snellFresnelCubic", "optics.glsl", "caseSnellFresnelCubic", fresnelCubicInputs,
                   [](const ParityIO& in) { return run(parity_optics::caseSnellFresnelCubic, in); }, 0, 2,
                   {1e-5f, 1e-5f}});
SNELL_PARITY_CASE({"snellIorToEta", "optics.glsl", "caseSnellIorToEta", [] { return iorInputs(26); },
                   [](const ParityIO& in) { return run(parity_optics::caseSnellIorToEta, in); }, 0, 4,
                   {1e-6f, 1e-5f}});
SNELL_PARITY_CASE({"snellIorToF0", "optics.glsl", "caseSnellIorToF0", [] { return iorInputs(33); },
                   [](const ParityIO& in) { return run(parity_optics::caseSnellIorToF0, in); }, 0, 4,
                   {1e-6f, 1e-5f}});
SNELL_PARITY_CASE({"snellIceNormalBlend", "optics.glsl", "caseSnellIceNormalBlend", iceNormalBlendInputs,
                   [](const ParityIO& in) { return run(parity_optics::caseSnellIceNormalBlend, in); }, 0, 8,
                   {1e-5f, 1e-5f}});
// rel 1e-4: GPU exp() is exp2(x * log2(e)) with a polynomial exp2 (llvmpipe);
// results down to exp(-50) carry the rounding of the scaled argument.
SNELL_PARITY_CASE({"snellBeerLambert", "optics.glsl", "caseSnellBeerLambert", beerLambertInputs,
                   [](const ParityIO& in) { return run(parity_optics::caseSnellBeerLambert, in); }, 0, 3,
                   {1e-6f, 1e-4f}});
// The asin series is plain arithmetic on both sides; the inputs' normalization
// (inversesqrt) may differ by an ulp, ~1e-7 rad.
SNELL_PARITY_CASE({"snellAngleBetween", "optics.glsl", "caseSnellAngleBetween", angleBetweenInputs,
                   [](const ParityIO& in) { return run(parity_optics::caseSnellAngleBetween, in); }, 0, 2,
                   {1e-5f, 1e-5f}});
SNELL_PARITY_CASE({"snellWymanDistance", "optics.glsl", "caseSnellWymanDistance", wymanDistanceInputs,
                   [](const ParityIO& in) { return run(parity_optics::caseSnellWymanDistance, in); }, 0, 4,
                   {1e-5f, 1e-5f}});
// abs 2e-4: the angle ratio's error (~1e-7 rad / theta_i, theta_i >= 0.01) times
// |dV - dN| <= 10.
SNELL_PARITY_CASE({"snellWymanDistanceVec", "optics.glsl", "caseSnellWymanDistanceVec", wymanDistanceVecInputs,
                   [](const ParityIO& in) { return run(parity_optics::caseSnellWymanDistanceVec, in); }, 0, 1,
                   {2e-4f, 1e-5f}});
// 1e-4: t = dot(p0 - o, n) / dot(d, n) with |cos| down to 1e-2 loses ~2 digits
// to cancellation in the denominator; valid (output 4) compares exactly.
SNELL_PARITY_CASE({"snellRayPlane", "optics.glsl", "caseSnellRayPlane", rayPlaneInputs,
                   [](const ParityIO& in) { return run(parity_optics::caseSnellRayPlane, in); }, 0x10, 5,
                   {1e-4f, 1e-4f}});
