// The optics/ parity and property cases (see parity_case.hpp): one
// description per public function. cases/optics.glsl holds nothing but the
// family's include.
#include <snell/optics.hpp>

#include "parity_case.hpp"

namespace {
using snell_parity::InputGen;
using snell_parity::ParityIO;

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

// snellRefract's inputs with a GGX width: smooth (0, negative, NaN), the rough range, above 1, hostile; a
// third of the rays near the critical angle of glass leaving into air, where the rough ray differs most.
std::vector<ParityIO> refractRoughInputs() {
  InputGen g(39);
  std::vector<ParityIO> v;
  for (ParityIO in : refractInputs()) {
    if (g.chance(0.33f)) {
      glm::vec3 n = g.unitVector();
      float eta = g.uniform(1.3f, 1.8f);
      in.v[0] = glm::vec4(atCosine(g, -n, std::min(1.0f, std::max(0.0f, std::sqrt(1.0f - 1.0f / (eta * eta)) + g.uniform(-0.2f, 0.2f)))), eta);
      in.v[1] = glm::vec4(n, in.v[1].w);
    }
    int c = g.integer(0, 19);
    float alpha = g.uniform(1e-4f, 1.0f);
    if (c == 0) alpha = 0.0f;
    if (c == 1) alpha = -g.uniform(0.0f, 1.0f);
    if (c == 2) alpha = g.uniform(1.0f, 10.0f);
    if (c == 3) alpha = g.hostile();
    in.v[2] = glm::vec4(alpha, 0.0f, 0.0f, 0.0f);
    v.push_back(in);
  }
  return v;
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

namespace parity_optics {
using namespace snell;
using snell_parity::CaseExtras;
#include "cases/optics.glsl"
#define SNELL_PARITY_FILE "optics.glsl"

SNELL_PARITY_CASE(snellSafeNormalize, safeNormalizeInputs,
                  (vec3, v, 0),
                  (vec3, n, 0, within(1e-6f, 1e-6f)),
                  {},
                  n = snellSafeNormalize(v);)

SNELL_PARITY_CASE(snellRefract, refractInputs,
                  (vec3, incident, 0)(float, eta, 3)(vec3, normal, 4)(int, policy, 7),
                  (vec3, direction, 0, within(1e-5f, 1e-5f))(bool, tir, 4, exact)(bool, valid, 5, exact),
                  {},
                  SnellRefraction r = snellRefract(incident, normal, eta, policy);
                  direction = r.direction;
                  tir = r.tir;
                  valid = r.valid;)

SNELL_PARITY_CASE(snellRefractRough, refractRoughInputs,
                  (vec3, incident, 0)(float, eta, 3)(vec3, normal, 4)(int, policy, 7)(float, alpha, 8),
                  (vec3, direction, 0, within(1e-5f, 1e-5f))(bool, tir, 4, exact)(bool, valid, 5, exact),
                  {},
                  SnellRefraction r = snellRefractRough(incident, normal, eta, alpha, policy);
                  direction = r.direction;
                  tir = r.tir;
                  valid = r.valid;)

// Same operations on both sides; 1e-5 leaves room for the GPU compiler's FMA
// contraction and reassociation.
SNELL_PARITY_CASE(snellApproxRefract, approxRefractInputs,
                  (vec3, incident, 0)(float, factor, 3)(vec3, normal, 4),
                  (vec3, direction, 0, within(1e-5f, 1e-5f)),
                  {},
                  direction = snellApproxRefract(incident, normal, factor);)

// Four evaluations per input. abs 1e-4: near (not at: see fresnelCos) the
// critical angle, cos_t = sqrt(cos_t^2) magnifies a one-ulp difference in
// cos_t^2 by up to ~150.
SNELL_PARITY_CASE(snellFresnelDielectric, fresnelDielectricInputs,
                  (float, cos0, 0)(float, eta0, 1)(float, cos1, 2)(float, eta1, 3)
                  (float, cos2, 4)(float, eta2, 5)(float, cos3, 6)(float, eta3, 7),
                  (vec4, f, 0, within(1e-4f, 1e-5f)),
                  {},
                  f = vec4(snellFresnelDielectric(cos0, eta0), snellFresnelDielectric(cos1, eta1),
                           snellFresnelDielectric(cos2, eta2), snellFresnelDielectric(cos3, eta3));)

// (cosI, f0) pairs, four evaluations per input.
SNELL_PARITY_CASE(snellFresnelSchlick, fresnelSchlickInputs,
                  (float, cos0, 0)(float, f00, 1)(float, cos1, 2)(float, f01, 3)
                  (float, cos2, 4)(float, f02, 5)(float, cos3, 6)(float, f03, 7),
                  (vec4, f, 0, within(1e-5f, 1e-5f)),
                  {},
                  f = vec4(snellFresnelSchlick(cos0, f00), snellFresnelSchlick(cos1, f01), snellFresnelSchlick(cos2, f02),
                           snellFresnelSchlick(cos3, f03));)

// (nDotL, bias, power) triples, four evaluations per input. rel 1e-4: GPU
// pow() is exp2(y * log2(x)) with polynomial exp2/log2 (llvmpipe), whose
// relative error grows with |y log2 x|; powers reach 1e3 here.
SNELL_PARITY_CASE(snellFresnelBiasPower, fresnelBiasPowerInputs,
                  (vec3, t0, 0)(vec3, t1, 4)(vec3, t2, 8)(vec3, t3, 12),
                  (vec4, f, 0, within(1e-5f, 1e-4f)),
                  {},
                  f = vec4(snellFresnelBiasPower(t0.x, t0.y, t0.z), snellFresnelBiasPower(t1.x, t1.y, t1.z),
                           snellFresnelBiasPower(t2.x, t2.y, t2.z), snellFresnelBiasPower(t3.x, t3.y, t3.z));)

// (eye, normal) pairs, two evaluations per input.
SNELL_PARITY_CASE(snellFresnelCubic, fresnelCubicInputs,
                  (vec3, eye0, 0)(vec3, normal0, 4)(vec3, eye1, 8)(vec3, normal1, 12),
                  (float, f0, 0, within(1e-5f, 1e-5f))(float, f1, 1, within(1e-5f, 1e-5f)),
                  {},
                  f0 = snellFresnelCubic(eye0, normal0);
                  f1 = snellFresnelCubic(eye1, normal1);)

// (iorIncident, iorTransmitted) pairs, four evaluations per input.
SNELL_PARITY_CASE(snellIorToEta, [] { return iorInputs(26); },
                  (vec2, p0, 0)(vec2, p1, 2)(vec2, p2, 4)(vec2, p3, 6),
                  (vec4, eta, 0, within(1e-6f, 1e-5f)),
                  {},
                  eta = vec4(snellIorToEta(p0.x, p0.y), snellIorToEta(p1.x, p1.y), snellIorToEta(p2.x, p2.y),
                             snellIorToEta(p3.x, p3.y));)

SNELL_PARITY_CASE(snellIorToF0, [] { return iorInputs(33); },
                  (vec2, p0, 0)(vec2, p1, 2)(vec2, p2, 4)(vec2, p3, 6),
                  (vec4, f0, 0, within(1e-6f, 1e-5f)),
                  {},
                  f0 = vec4(snellIorToF0(p0.x, p0.y), snellIorToF0(p1.x, p1.y), snellIorToF0(p2.x, p2.y),
                            snellIorToF0(p3.x, p3.y));)

// Both overloads: the explicit weight and SNELL_ICE_NORMAL_BLEND's.
SNELL_PARITY_CASE(snellIceNormalBlend, iceNormalBlendInputs,
                  (vec3, front, 0)(float, weight, 3)(vec3, back, 4),
                  (vec3, blended, 0, within(1e-5f, 1e-5f))(vec3, blendedDefault, 4, within(1e-5f, 1e-5f)),
                  {},
                  blended = snellIceNormalBlend(front, back, weight);
                  blendedDefault = snellIceNormalBlend(front, back);)

// rel 1e-4: GPU exp() is exp2(x * log2(e)) with a polynomial exp2 (llvmpipe);
// results down to exp(-50) carry the rounding of the scaled argument.
SNELL_PARITY_CASE(snellBeerLambert, beerLambertInputs,
                  (vec3, absorption, 0)(float, distance, 3),
                  (vec3, transmittance, 0, within(1e-6f, 1e-4f)),
                  {},
                  transmittance = snellBeerLambert(absorption, distance);)

// Two evaluations per input. The asin series is plain arithmetic on both
// sides; the inputs' normalization (inversesqrt) may differ by an ulp, ~1e-7 rad.
SNELL_PARITY_CASE(snellAngleBetween, angleBetweenInputs,
                  (vec3, u0, 0)(vec3, v0, 4)(vec3, u1, 8)(vec3, v1, 12),
                  (float, angle0, 0, within(1e-5f, 1e-5f))(float, angle1, 1, within(1e-5f, 1e-5f)),
                  {},
                  angle0 = snellAngleBetween(u0, v0);
                  angle1 = snellAngleBetween(u1, v1);)

// (thetaT, thetaI, dV, dN), four evaluations per input.
SNELL_PARITY_CASE(snellWymanDistance, wymanDistanceInputs,
                  (vec4, q0, 0)(vec4, q1, 4)(vec4, q2, 8)(vec4, q3, 12),
                  (vec4, d, 0, within(1e-5f, 1e-5f)),
                  {},
                  d = vec4(snellWymanDistance(q0.x, q0.y, q0.z, q0.w), snellWymanDistance(q1.x, q1.y, q1.z, q1.w),
                           snellWymanDistance(q2.x, q2.y, q2.z, q2.w), snellWymanDistance(q3.x, q3.y, q3.z, q3.w));)

// abs 2e-4: the angle ratio's error (~1e-7 rad / theta_i, theta_i >= 0.01) times
// |dV - dN| <= 10.
SNELL_PARITY_CASE(snellWymanDistanceVec, wymanDistanceVecInputs,
                  (vec3, incident, 0)(float, dV, 3)(vec3, normal, 4)(float, dN, 7)(vec3, refracted, 8),
                  (float, d, 0, within(2e-4f, 1e-5f)),
                  {},
                  d = snellWymanDistanceVec(incident, normal, refracted, dV, dN);)

// 1e-4: t = dot(p0 - o, n) / dot(d, n) with |cos| down to 1e-2 loses ~2 digits
// to cancellation in the denominator.
SNELL_PARITY_CASE(snellRayPlane, rayPlaneInputs,
                  (vec3, origin, 0)(vec3, direction, 4)(vec3, planePoint, 8)(vec3, planeNormal, 12),
                  (float, t, 0, within(1e-4f, 1e-4f))(vec3, position, 1, within(1e-4f, 1e-4f))(bool, valid, 4, exact),
                  {},
                  SnellRayPlaneHit h = snellRayPlane(origin, direction, planePoint, planeNormal);
                  t = h.t;
                  position = h.position;
                  valid = h.valid;)

}  // namespace parity_optics
