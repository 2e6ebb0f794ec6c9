// The rough dielectric interface (lab/rough_optics.hpp) against Walter et al.
// 2007 evaluated independently. The main test compares the sampler ((35),
// (36), (39), (40), (41)) with the BSDF ((20), (21), (33), (34)) integrated by
// quadrature over bins of outgoing direction, entering and leaving glass, at
// four incidence angles and four roughnesses: a fault on either side shows as
// bins off by many Monte Carlo standard errors. Then the pdf against the mass
// the sampler keeps, integrated over microfacet normals instead (checks the
// Jacobians (14), (17)); weight == eval / pdf; D and G1 against their closed
// forms in angles; the reciprocity of f; the smooth limit against
// lab/exact_optics.hpp; bad input.
#include "lab/rough_optics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

using namespace snell::lab;
using glm::dvec3;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

// 4-point Gauss-Legendre on [-1, 1].
constexpr double kGx[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
constexpr double kGw[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};

// Integral of g over [a, b]: cells cells of 4 Gauss points.
template <class G>
double integrate1(G g, double a, double b, int cells) {
  double sum = 0.0;
  const double h = (b - a) / cells;
  for (int p = 0; p < cells; ++p)
    for (int s = 0; s < 4; ++s) sum += kGw[s] * g(a + h * (p + 0.5 + 0.5 * kGx[s]));
  return sum * 0.5 * h;
}

// Integral of g over [a, b] x [c, d]: cells x cells cells of 4 x 4 Gauss points.
template <class G>
double integrate2(G g, double a, double b, double c, double d, int cells) {
  double sum = 0.0;
  const double hx = (b - a) / cells, hy = (d - c) / cells;
  for (int p = 0; p < cells; ++p)
    for (int q = 0; q < cells; ++q)
      for (int s = 0; s < 4; ++s)
        for (int t = 0; t < 4; ++t)
          sum += kGw[s] * kGw[t] * g(a + hx * (p + 0.5 + 0.5 * kGx[s]), c + hy * (q + 0.5 + 0.5 * kGx[t]));
  return sum * 0.25 * hx * hy;
}

// Polar coordinates about an axis c (psi from c, beta around it), in a frame of
// the test's own.
struct Polar {
  dvec3 u, v, c;
  explicit Polar(dvec3 axis) : c(glm::normalize(axis)) {
    const dvec3 a = std::abs(c.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
    u = glm::normalize(glm::cross(a, c));
    v = glm::cross(c, u);
  }
  dvec3 at(double psi, double beta) const {
    return std::sin(psi) * (std::cos(beta) * u + std::sin(beta) * v) + std::cos(psi) * c;
  }
  double psiOf(dvec3 o) const { return std::atan2(glm::length(glm::cross(o, c)), glm::dot(o, c)); }
  double betaOf(dvec3 o) const {
    const double b = std::atan2(glm::dot(o, v), glm::dot(o, u));
    return b < 0.0 ? b + 2.0 * kPi : b;
  }
};

// Angles from a lobe's centre: fine at the centre (an eighth of alpha), growing
// by sqrt 2 out to `last`, so that the bins follow a GGX lobe's core and tail.
std::vector<double> angleEdges(double alpha, double last) {
  std::vector<double> e{0.0};
  for (double x = alpha / 8.0; x < 0.98 * last; x *= std::sqrt(2.0)) e.push_back(x);
  e.push_back(last);
  return e;
}

// Outgoing directions (the normal is +z) in two regions that partition the
// sphere: above the surface, binned in polar coordinates about `up` (the mirror
// direction), below it about `down` (the refracted direction, -z under TIR).
struct Bins {
  static constexpr int kBeta = 12;
  Polar frame[2];
  std::vector<double> edges;
  Bins(dvec3 up, dvec3 down, double alpha) : frame{Polar(up), Polar(down)}, edges(angleEdges(alpha, kPi)) {}
  int perRegion() const { return (static_cast<int>(edges.size()) - 1) * kBeta; }
  int size() const { return 2 * perRegion(); }
  static int region(dvec3 o) { return o.z > 0.0 ? 0 : 1; }
  int index(dvec3 o) const {
    const int r = region(o);
    const double psi = frame[r].psiOf(o);
    int k = static_cast<int>(std::upper_bound(edges.begin(), edges.end(), psi) - edges.begin()) - 1;
    k = std::clamp(k, 0, static_cast<int>(edges.size()) - 2);
    const int j = std::min(kBeta - 1, static_cast<int>(frame[r].betaOf(o) / (2.0 * kPi) * kBeta));
    return r * perRegion() + k * kBeta + j;
  }
  // psi in [0, pi] where direction (psi, beta) lies in region r: the horizon
  // cuts the half great circle once, at the zero of o.z = A sin(psi) + B cos(psi).
  std::pair<double, double> inRegion(int r, double beta) const {
    const Polar& f = frame[r];
    const double A = std::cos(beta) * f.u.z + std::sin(beta) * f.v.z, B = f.c.z;
    const double phi0 = std::atan2(B, A), cut = phi0 > 0.0 ? kPi - phi0 : -phi0;
    if (region(f.at(0.5 * (cut + kPi), beta)) == r) return {cut, kPi};
    return {0.0, cut};
  }
  // The integrals of g (of the direction; a dvec2: two integrands at once) over
  // each bin's solid angle: cells x cells cells of 4 x 4 Gauss points in (psi,
  // beta), the psi range clipped to the region for each beta, so that the
  // integrand has no step at the horizon.
  template <class G>
  std::vector<glm::dvec2> integrate(G g, int cells) const {
    std::vector<glm::dvec2> out(static_cast<std::size_t>(size()), glm::dvec2(0.0));
    const double hb = 2.0 * kPi / kBeta / cells;
    for (int r = 0; r < 2; ++r)
      for (int j = 0; j < kBeta; ++j)
        for (int cb = 0; cb < cells; ++cb)
          for (int t = 0; t < 4; ++t) {
            const double beta = 2.0 * kPi * j / kBeta + hb * (cb + 0.5 + 0.5 * kGx[t]);
            const auto [lo, hi] = inRegion(r, beta);
            for (std::size_t k = 0; k + 1 < edges.size(); ++k) {
              const double a = std::max(lo, edges[k]), b = std::min(hi, edges[k + 1]);
              if (!(b > a)) continue;
              const double hp = (b - a) / cells;
              glm::dvec2 sum(0.0);
              for (int cp = 0; cp < cells; ++cp)
                for (int s = 0; s < 4; ++s) {
                  const double psi = a + hp * (cp + 0.5 + 0.5 * kGx[s]);
                  sum += kGw[s] * std::sin(psi) * g(frame[r].at(psi, beta));
                }
              out[static_cast<std::size_t>(r * perRegion() + static_cast<int>(k) * kBeta + j)] +=
                  0.25 * kGw[t] * hb * hp * sum;
            }
          }
    return out;
  }
};

struct Config {
  double thetaDeg, eta, alpha;
};

std::vector<Config> mainConfigs() {
  std::vector<Config> c;
  for (double eta : {1.0 / 1.5, 1.5})
    for (double alpha : {0.0025, 0.0225, 0.09, 0.25})
      for (double theta : {0.0, 30.0, 60.0, 80.0}) c.push_back({theta, eta, alpha});
  return c;
}

// Travelling down onto the surface z = 0 whose normal is +z.
dvec3 travel(double thetaDeg) { return dvec3(std::sin(thetaDeg * kDeg), 0.0, -std::cos(thetaDeg * kDeg)); }
// The normal handed to the header: leaving glass, the outward one (along the travel), as the tracer's meshes give it.
dvec3 normalFor(const Config& c) { return c.eta > 1.0 ? dvec3(0, 0, -1) : dvec3(0, 0, 1); }

Bins binsFor(const Config& c) {
  const dvec3 d = travel(c.thetaDeg);
  const ExactRefraction t = refractExact(d, dvec3(0, 0, 1), c.eta, TirPolicy::Reflect);
  return Bins(dvec3(d.x, d.y, -d.z), t.tir ? dvec3(0, 0, -1) : t.direction, c.alpha);
}

struct Sampled {
  std::vector<double> s1, s2;  // sum of weights, of squared weights, per bin
  double n = 0.0, kept = 0.0, w2 = 0.0, w1 = 0.0;
};

Sampled sampleInto(const Config& c, const Bins& bins, int n, std::uint64_t seed) {
  Sampled r;
  r.s1.assign(static_cast<std::size_t>(bins.size()), 0.0);
  r.s2 = r.s1;
  r.n = n;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const dvec3 d = travel(c.thetaDeg), nrm = normalFor(c);
  for (int k = 0; k < n; ++k) {
    const double x1 = u(rng), x2 = u(rng), x3 = u(rng);
    const RoughScatter s = sampleRoughDielectric(d, nrm, c.eta, c.alpha, x1, x2, x3);
    if (s.weight == 0.0) continue;
    const auto b = static_cast<std::size_t>(bins.index(s.direction));
    r.s1[b] += s.weight;
    r.s2[b] += s.weight * s.weight;
    r.kept += 1.0;
    r.w1 += s.weight;
    r.w2 += s.weight * s.weight;
  }
  return r;
}

// ---------------------------------------------------------------------------
// 1. Sampling against evaluation.

// A bound on the weight (41) of a sample that lands at o, for the tolerance
// only: |i.m| / (|i.n| |m.n|) with G <= 1 dropped, m the half vector (13)/(16).
double weightBound(dvec3 d, dvec3 o, double eta) {
  const dvec3 i = -d;
  dvec3 h = o.z > 0.0 ? i + o : -(eta * i + o);
  if (h.z < 0.0) h = -h;
  h = glm::normalize(h);
  return glm::dot(i, h) > 0.0 && h.z > 0.0 ? glm::dot(i, h) / (i.z * h.z) : 0.0;
}

TEST(RoughOptics, SamplerMatchesBsdfIntegratedOverBins) {
  const auto start = std::chrono::steady_clock::now();
  constexpr int kSamples = 400000;
  int config = 0;
  for (const Config& c : mainConfigs()) {
    const Bins bins = binsFor(c);
    const dvec3 d = travel(c.thetaDeg), nrm = normalFor(c);
    // Per bin: the integral of f|o.n| (what the mean weight must be), and of
    // f|o.n| times the weight bound (bounds the weight's second moment).
    const std::vector<glm::dvec2> q = bins.integrate(
        [&](dvec3 o) {
          const double e = evalRoughDielectric(d, o, nrm, c.eta, c.alpha);
          return glm::dvec2(e, e * weightBound(d, o, c.eta));
        },
        4);
    const Sampled s = sampleInto(c, bins, kSamples, 1000u + static_cast<std::uint64_t>(config++));
    double worst = 0.0, totalQ = 0.0;
    int bad = 0;
    for (std::size_t b = 0; b < q.size(); ++b) {
      const double mc = s.s1[b] / s.n;
      // The standard error of the bin's mean weight; where the samples barely
      // reach, the one the bin's integrals imply.
      const double sigma = std::sqrt(std::max(s.s2[b] / s.n - mc * mc, q[b].y - q[b].x * q[b].x) / s.n);
      const double tol = 5.0 * sigma + 1e-3 * q[b].x + 1e-9;
      worst = std::max(worst, std::abs(mc - q[b].x) / tol);
      totalQ += q[b].x;
      if (std::abs(mc - q[b].x) > tol && ++bad <= 3)
        ADD_FAILURE() << "theta " << c.thetaDeg << " eta " << c.eta << " alpha " << c.alpha << " bin " << b
                      << ": sampled " << mc << ", integrated " << q[b].x << ", tolerance " << tol;
    }
    const double totalMc = s.w1 / s.n;
    const double sigmaTotal = std::sqrt(std::max(s.w2 / s.n - totalMc * totalMc, 0.0) / s.n);
    const double tolTotal = 5.0 * sigmaTotal + 2e-5;
    std::printf(
        "theta %2.0f eta %.3f alpha %.4f: albedo sampled %.6f integrated %.6f (%.2f of its tolerance), "
        "worst bin at %.2f of its tolerance, %d bins off\n",
        c.thetaDeg, c.eta, c.alpha, totalMc, totalQ, std::abs(totalMc - totalQ) / tolTotal, worst, bad);
    EXPECT_NEAR(totalMc, totalQ, tolTotal)
        << "albedo, theta " << c.thetaDeg << " eta " << c.eta << " alpha " << c.alpha;
  }
  std::printf("%.1f s\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

// ---------------------------------------------------------------------------
// 2. The pdf.

// GGX (33) in angles, the form printed in the paper.
double ggxDAngles(double thetaM, double alpha) {
  const double c = std::cos(thetaM), t = std::tan(thetaM), a2 = alpha * alpha;
  return a2 / (kPi * c * c * c * c * (a2 + t * t) * (a2 + t * t));
}

// The mass of the samples that keep a weight, integrated over microfacet
// normals m (the density D(m) cos(theta_m) of (24)) with the reflected and
// refracted directions of exact_optics.hpp: no Jacobian involved. The incident
// ray lies in the xz plane, so phi in [0, pi] counts twice; there i.m grows or
// falls with phi, and each condition (facing i, reflection above, refraction
// below) switches at most once: the phi integral is split where they switch.
double keptMassOverNormals(const Config& c, int cells) {
  const dvec3 d = travel(c.thetaDeg), i = -d;
  const auto facing = [&](dvec3 m) { return glm::dot(i, m) > 0.0; };
  const auto reflects = [&](dvec3 m) { return reflectExact(d, m).z > 0.0; };
  const auto refracts = [&](dvec3 m) {
    const ExactRefraction t = refractExact(d, m, c.eta, TirPolicy::Reflect);
    return !t.tir && t.direction.z < 0.0;
  };
  const auto kept = [&](dvec3 m) {
    const double F = fresnelExact(glm::dot(i, m), c.eta);
    return (reflects(m) ? F : 0.0) + (refracts(m) ? 1.0 - F : 0.0);
  };
  // The theta where a condition switches at phi = 0 or pi are kinks of the
  // phi integral (steps at normal incidence): the theta bins are split there.
  std::vector<double> edges = angleEdges(c.alpha, kPi / 2.0);
  for (double ph : {0.0, kPi}) {
    const auto m = [&](double th) { return dvec3(std::sin(th) * std::cos(ph), 0.0, std::cos(th)); };
    const auto split = [&](auto cond) {
      constexpr int kScan = 4096;
      for (int k = 0; k < kScan; ++k) {
        double lo = 0.5 * kPi * k / kScan, hi = 0.5 * kPi * (k + 1) / kScan;
        const bool atLo = cond(m(lo));
        if (atLo == cond(m(hi))) continue;
        for (int it = 0; it < 60; ++it) {
          const double mid = 0.5 * (lo + hi);
          (cond(m(mid)) == atLo ? lo : hi) = mid;
        }
        edges.push_back(0.5 * (lo + hi));
      }
    };
    split(facing);
    split(reflects);
    split(refracts);
  }
  std::sort(edges.begin(), edges.end());
  double mass = 0.0;
  for (std::size_t k = 0; k + 1 < edges.size(); ++k) {
    const double ht = (edges[k + 1] - edges[k]) / cells;
    for (int ct = 0; ct < cells; ++ct)
      for (int s = 0; s < 4; ++s) {
        const double th = edges[k] + ht * (ct + 0.5 + 0.5 * kGx[s]);
        const auto m = [&](double ph) {
          return dvec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
        };
        const auto cut = [&](auto cond, double lo, double hi) {  // where cond switches in [lo, hi], or lo
          const bool atLo = cond(m(lo));
          if (atLo == cond(m(hi))) return lo;
          for (int it = 0; it < 60; ++it) {
            const double mid = 0.5 * (lo + hi);
            (cond(m(mid)) == atLo ? lo : hi) = mid;
          }
          return 0.5 * (lo + hi);
        };
        const bool facing0 = facing(m(0.0)), facingPi = facing(m(kPi));
        if (!facing0 && !facingPi) continue;
        double lo = 0.0, hi = kPi;
        if (facing0 != facingPi) (facing0 ? hi : lo) = cut(facing, 0.0, kPi);
        std::vector<double> ph{lo, cut(reflects, lo, hi), cut(refracts, lo, hi), hi};
        std::sort(ph.begin(), ph.end());
        double ring = 0.0;
        for (std::size_t p = 0; p + 1 < ph.size(); ++p)
          if (ph[p + 1] > ph[p]) ring += integrate1([&](double x) { return kept(m(x)); }, ph[p], ph[p + 1], cells);
        mass += 0.5 * kGw[s] * ht * 2.0 * ring * ggxDAngles(th, c.alpha) * std::cos(th) * std::sin(th);
      }
  }
  return mass;
}

TEST(RoughOptics, PdfIntegratesToTheMassTheSamplerKeeps) {
  double worst = 0.0;
  for (const Config& c : mainConfigs()) {
    const Bins bins = binsFor(c);
    const dvec3 d = travel(c.thetaDeg), nrm = normalFor(c);
    double pdfMass = 0.0;
    for (const glm::dvec2 v :
         bins.integrate([&](dvec3 o) { return glm::dvec2(pdfRoughDielectric(d, o, nrm, c.eta, c.alpha), 0.0); }, 4))
      pdfMass += v.x;
    const double overNormals = keptMassOverNormals(c, 16);
    constexpr int kN = 100000;
    const Sampled s = sampleInto(c, bins, kN, 77);
    const double kept = s.kept / kN, sigma = std::sqrt(std::max(kept * (1.0 - kept), 1e-4) / kN);
    EXPECT_NEAR(pdfMass, overNormals, 1e-4) << c.thetaDeg << " " << c.eta << " " << c.alpha;
    EXPECT_NEAR(pdfMass, kept, 5.0 * sigma) << c.thetaDeg << " " << c.eta << " " << c.alpha;
    worst = std::max(worst, std::abs(pdfMass - overNormals));
  }
  std::printf("largest |integral of pdf - kept mass over normals|: %.2g\n", worst);
}

TEST(RoughOptics, WeightIsEvalOverPdfAtSampledDirections) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int checked = 0;
  for (const Config& c : mainConfigs()) {
    const dvec3 d = travel(c.thetaDeg), nrm = normalFor(c);
    for (int k = 0; k < 2000; ++k) {
      const RoughScatter s = sampleRoughDielectric(d, nrm, c.eta, c.alpha, u(rng), u(rng), u(rng));
      if (s.weight == 0.0) continue;
      const double e = evalRoughDielectric(d, s.direction, nrm, c.eta, c.alpha);
      const double p = pdfRoughDielectric(d, s.direction, nrm, c.eta, c.alpha);
      ASSERT_GT(p, 0.0);
      EXPECT_NEAR(s.weight, e / p, 1e-8 * s.weight) << c.thetaDeg << " " << c.eta << " " << c.alpha;
      EXPECT_EQ(s.reflected, s.direction.z > 0.0);
      EXPECT_NEAR(glm::length(s.direction), 1.0, 1e-14);
      ++checked;
    }
  }
  EXPECT_GT(checked, 50000);
}

// ---------------------------------------------------------------------------
// The parts: D, G1, the sampled normal, reciprocity.

TEST(RoughOptics, DMatchesItsFormInAnglesAndProjectsToUnitArea) {
  for (const dvec3 n : {dvec3(0, 0, 1), glm::normalize(dvec3(1, -2, 0.5)), dvec3(0, 0, -1)}) {
    const Polar f(n);
    for (double alpha : {0.0025, 0.09, 0.5, 1.0})
      for (double th : {0.0, 1e-4, 0.01, 0.3, 1.0, 1.5})
        for (double ph : {0.0, 2.0}) {
          const double expected = ggxDAngles(th, alpha);
          EXPECT_NEAR(ggxD(f.at(th, ph), n, alpha), expected, 1e-9 * expected) << alpha << " " << th;
        }
    EXPECT_EQ(ggxD(-n, n, 0.3), 0.0);
    EXPECT_EQ(ggxD(f.at(2.0, 1.0), n, 0.3), 0.0);
  }
  for (double alpha : {0.0025, 0.0225, 0.09, 0.25, 1.0}) {
    const std::vector<double> edges = angleEdges(alpha, kPi / 2.0);
    const auto projected = [&](double th) {
      return ggxD(dvec3(std::sin(th), 0.0, std::cos(th)), dvec3(0, 0, 1), alpha) * std::cos(th) * std::sin(th);
    };
    double area = 0.0;  // of the microsurface, projected: the integral of D(m) (m.n)
    for (std::size_t k = 0; k + 1 < edges.size(); ++k)
      area += 2.0 * kPi * integrate1(projected, edges[k], edges[k + 1], 2);
    EXPECT_NEAR(area, 1.0, 1e-6) << alpha;
  }
}

TEST(RoughOptics, G1MatchesSmithLambda) {
  const dvec3 n(0, 0, 1);
  for (double alpha : {0.0025, 0.09, 0.5, 1.0})
    for (double th : {0.0, 0.2, 1.0, 1.4, 1.5607}) {
      // Smith's Lambda for GGX: (-1 + sqrt(1 + 1/a^2)) / 2 with a = 1 / (alpha tan(theta)).
      const double a = 1.0 / (alpha * std::tan(th));
      const double lambda = th == 0.0 ? 0.0 : 0.5 * (-1.0 + std::sqrt(1.0 + 1.0 / (a * a)));
      const dvec3 v(std::sin(th), 0.0, std::cos(th));
      EXPECT_NEAR(ggxG1(v, n, n, alpha), 1.0 / (1.0 + lambda), 1e-12) << alpha << " " << th;
      // Below the surface and seen from below, the same (the chi+ of a ratio).
      EXPECT_NEAR(ggxG1(-v, n, n, alpha), 1.0 / (1.0 + lambda), 1e-12);
      // A facet (above the surface) that v sees from behind: 0.
      if (th > 0.5) {
        const dvec3 m = glm::normalize(dvec3(-std::cos(th), 0.0, std::sin(th)) - 0.1 * v);
        EXPECT_EQ(ggxG1(v, m, n, alpha), 0.0);
      }
    }
  EXPECT_EQ(ggxG1(dvec3(1, 0, 0), n, n, 0.3), 0.0);  // grazing
}

TEST(RoughOptics, SampledNormalHasTheAngleOf35InAnOrthonormalFrame) {
  for (const dvec3 n : {dvec3(0, 0, 1), dvec3(0, 0, -1), dvec3(1, 0, 0), dvec3(0, -1, 0),
                        glm::normalize(dvec3(1, 2, 3)), glm::normalize(dvec3(-0.3, 0.1, -0.95)),
                        glm::normalize(dvec3(1e-9, -1e-9, -1)), glm::normalize(dvec3(1e-9, 0, 1))})
    for (double alpha : {0.01, 0.3, 1.0})
      for (double x1 : {0.0, 0.1, 0.5, 0.9, 0.999})
        for (double x2 : {0.0, 0.3, 0.7}) {
          const dvec3 m = ggxSampleNormal(n, alpha, x1, x2);
          const dvec3 m2 = ggxSampleNormal(n, alpha, x1, x2 + 0.25);
          const double theta = std::atan(alpha * std::sqrt(x1) / std::sqrt(1.0 - x1));
          EXPECT_NEAR(glm::length(m), 1.0, 1e-14);
          EXPECT_NEAR(glm::dot(m, n), std::cos(theta), 1e-14);
          // A quarter turn in phi is a right angle between the tangential parts.
          EXPECT_NEAR(glm::dot(m - glm::dot(m, n) * n, m2 - glm::dot(m2, n) * n), 0.0, 1e-14);
        }
  EXPECT_EQ(ggxSampleNormal(dvec3(0, 0, 1), 0.3, 1.0, 0.2).z, 0.0);  // xi1 = 1: horizontal, not NaN
}

TEST(RoughOptics, BsdfIsReciprocal) {
  // f_r(i,o) = f_r(o,i); f_t(i,o) / eta_o^2 = f_t(o,i) / eta_i^2, the reciprocity of refraction: a check of
  // where eta enters (21) that the sampler cannot give (it never evaluates f).
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const dvec3 n(0, 0, 1);
  int checked = 0;
  for (double eta : {1.0 / 1.5, 1.5, 1.0 / 1.33})
    for (double alpha : {0.05, 0.3})
      for (int k = 0; k < 400; ++k) {
        const double z1 = u(rng), p1 = 2 * kPi * u(rng), z2 = 2 * u(rng) - 1, p2 = 2 * kPi * u(rng);
        const double s1 = std::sqrt(1 - z1 * z1), s2 = std::sqrt(1 - z2 * z2);
        const dvec3 d(s1 * std::cos(p1), s1 * std::sin(p1), -z1), o(s2 * std::cos(p2), s2 * std::sin(p2), z2);
        const double f = evalRoughDielectric(d, o, n, eta, alpha) / std::abs(o.z);
        const bool transmitted = o.z < 0.0;
        const double back = evalRoughDielectric(-o, -d, n, transmitted ? 1.0 / eta : eta, alpha) / std::abs(d.z);
        EXPECT_NEAR(f, transmitted ? back / (eta * eta) : back, 1e-10 * (f + 1e-3));
        if (f > 1e-3) ++checked;
      }
  EXPECT_GT(checked, 500);
}

// ---------------------------------------------------------------------------
// 3. The smooth limit.

// The smooth tracer's event (examples/lab/src/tracer.cpp, traceFull).
RoughScatter smoothEvent(dvec3 d, dvec3 n, double eta, double xi3) {
  const ExactRefraction r = refractExact(d, n, eta, TirPolicy::Reflect);
  if (r.tir) return {r.direction, 1.0, true};
  if (xi3 < fresnelExact(glm::dot(d, n), eta)) return {reflectExact(d, n), 1.0, true};
  return {r.direction, 1.0, false};
}

TEST(RoughOptics, SmoothAlphaIsTheSmoothTracer) {
  const dvec3 tilted = glm::normalize(dvec3(0.2, -0.1, 1.0));
  int near = 0;
  for (double th : {0.0, 20.0, 35.0, 50.0, 70.0, 85.0, 89.9})
    for (double eta : {1.0 / 1.5, 1.5, 1.0 / 1.33, 1.33})
      for (const dvec3 n : {dvec3(0, 0, 1), dvec3(0, 0, -1), tilted, -tilted})
        for (double xi3 : {0.0, 0.03, 0.5, 0.97, 0.999, 1.0}) {
          const dvec3 d = travel(th);
          if (std::abs(glm::dot(d, n)) < 1e-3) continue;
          const RoughScatter e = smoothEvent(d, n, eta, xi3);
          for (double alpha : {0.0, -1.0, 5e-8, kNaN}) {
            const RoughScatter s = sampleRoughDielectric(d, n, eta, alpha, 0.7, 0.2, xi3);
            EXPECT_EQ(s.direction, e.direction) << th << " " << eta << " " << alpha;
            EXPECT_EQ(s.weight, 1.0);
            EXPECT_EQ(s.reflected, e.reflected);
            EXPECT_EQ(evalRoughDielectric(d, e.direction, n, eta, alpha), 0.0);
            EXPECT_EQ(pdfRoughDielectric(d, e.direction, n, eta, alpha), 0.0);
          }
          // Nearly smooth: within 1e-4 of it, away from where a 1e-6 tilt flips the choice or the
          // direction is unstable (the critical angle, grazing).
          const double cosI = std::abs(glm::dot(d, n)), sinT2 = eta * eta * (1.0 - cosI * cosI);
          if (cosI < 0.05 || std::abs(std::sqrt(sinT2) - 1.0) < 0.02) continue;
          if (std::abs(xi3 - fresnelExact(cosI, eta)) < 1e-3) continue;
          for (double x1 : {0.0, 0.3, 0.9})
            for (double x2 : {0.1, 0.6}) {
              const RoughScatter s = sampleRoughDielectric(d, n, eta, 1e-6, x1, x2, xi3);
              EXPECT_LT(glm::length(s.direction - e.direction), 1e-4) << th << " " << eta;
              EXPECT_EQ(s.reflected, e.reflected);
              EXPECT_NEAR(s.weight, 1.0, 1e-4);
              ++near;
            }
        }
  EXPECT_GT(near, 1000);
}

TEST(RoughOptics, XiThreeOfOneRefractsUnlessTheFacetReflectsTotally) {
  // Leaving glass (eta 1.5, critical angle 41.8 degrees) about m = n (xi1 = 0): 30 degrees refracts, 50 reflects.
  const dvec3 n(0, 0, -1);
  const RoughScatter below = sampleRoughDielectric(travel(30.0), n, 1.5, 0.09, 0.0, 0.3, 1.0);
  EXPECT_FALSE(below.reflected);
  EXPECT_GT(below.weight, 0.0);
  EXPECT_LT(below.direction.z, 0.0);
  const RoughScatter beyond = sampleRoughDielectric(travel(50.0), n, 1.5, 0.09, 0.0, 0.3, 1.0);
  EXPECT_TRUE(beyond.reflected);
  EXPECT_GT(beyond.weight, 0.0);
  EXPECT_NEAR(glm::length(beyond.direction - dvec3(travel(50.0).x, 0.0, -travel(50.0).z)), 0.0, 1e-12);
}

// ---------------------------------------------------------------------------
// 4. Bad input.

bool finite(dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

TEST(RoughOptics, BadInputIsAbsorbedWithoutNaN) {
  const dvec3 d = travel(30.0), n(0, 0, 1), o = glm::normalize(dvec3(0.3, 0, -1));
  const dvec3 nan3(kNaN, 0, 1), inf3(kInf, 0, 0), zero(0.0);
  for (double alpha : {0.0, 0.1, kNaN}) {
    for (const auto& [inc, nrm] : {std::pair{d, zero}, std::pair{d, nan3}, std::pair{d, inf3}, std::pair{zero, n},
                                   std::pair{nan3, n}, std::pair{inf3, n}, std::pair{nan3, nan3}}) {
      const RoughScatter s = sampleRoughDielectric(inc, nrm, 1.5, alpha, 0.3, 0.3, 0.9);
      EXPECT_EQ(s.weight, 0.0) << alpha;
      EXPECT_TRUE(finite(s.direction));
      EXPECT_NEAR(glm::length(s.direction), 1.0, 1e-15);
      EXPECT_EQ(evalRoughDielectric(inc, o, nrm, 1.5, alpha), 0.0);
      EXPECT_EQ(pdfRoughDielectric(inc, o, nrm, 1.5, alpha), 0.0);
    }
    for (double eta : {0.0, -1.5, kNaN, kInf}) {
      const RoughScatter s = sampleRoughDielectric(d, n, eta, alpha, 0.3, 0.3, 0.9);
      EXPECT_EQ(s.weight, 0.0) << eta;
      EXPECT_TRUE(finite(s.direction));
    }
    EXPECT_EQ(evalRoughDielectric(d, dvec3(kNaN), n, 1.5, alpha), 0.0);
    EXPECT_EQ(evalRoughDielectric(d, zero, n, 1.5, alpha), 0.0);
  }
  // Infinite alpha: absorbed.
  EXPECT_EQ(sampleRoughDielectric(d, n, 1.5, kInf, 0.3, 0.3, 0.9).weight, 0.0);
  EXPECT_EQ(evalRoughDielectric(d, o, n, 1.5, kInf), 0.0);
  // Grazing incidence on a rough surface: absorbed, for either normal orientation.
  const dvec3 graze(1, 0, 0);
  for (const dvec3 nrm : {n, -n})
    for (double x3 : {0.0, 0.5, 0.999}) {
      const RoughScatter s = sampleRoughDielectric(graze, nrm, 1.0 / 1.5, 0.1, 0.4, 0.6, x3);
      EXPECT_EQ(s.weight, 0.0);
      EXPECT_TRUE(finite(s.direction));
      EXPECT_EQ(evalRoughDielectric(graze, o, nrm, 1.0 / 1.5, 0.1), 0.0);
      EXPECT_EQ(pdfRoughDielectric(graze, o, nrm, 1.0 / 1.5, 0.1), 0.0);
    }
  // Smooth grazing is the smooth tracer's: F = 1, on along the incident direction.
  const RoughScatter s = sampleRoughDielectric(graze, n, 1.0 / 1.5, 0.0, 0.4, 0.6, 0.5);
  EXPECT_EQ(s.weight, 1.0);
  EXPECT_TRUE(s.reflected);
  EXPECT_EQ(s.direction, graze);
  // xi1 = 1 (a horizontal facet) and xi at the ends of [0, 1]: finite.
  for (double x : {0.0, 1.0}) {
    const RoughScatter e = sampleRoughDielectric(d, n, 1.5, 0.3, x, x, x);
    EXPECT_TRUE(finite(e.direction));
    EXPECT_TRUE(std::isfinite(e.weight));
  }
}

}  // namespace
