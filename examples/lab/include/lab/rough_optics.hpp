// Rough dielectric interfaces for the reference tracer: the GGX microfacet BSDF
// of Walter, Marschner, Li, Torrance, "Microfacet Models for Refraction through
// Rough Surfaces", EGSR 2007, in double. (n) below is the paper's equation n.
//
// Directions. As in lab/exact_optics.hpp, `incident` is the unit direction of
// TRAVEL (towards the surface) and `outgoing` the unit direction of travel after
// the event; Walter's i and o both point AWAY from the surface, so i = -incident
// and o = outgoing. The normal may face either way: like refractExact we flip it
// to face the incident ray (i.n > 0), which makes Walter's sign(i.n) in (13) and
// (40) +1. eta = n_incident / n_transmitted exactly as refractExact's, i.e.
// Walter's eta_i = eta and eta_o = 1: every formula used depends on the ratio
// only. D and G1 want the microfacet normal on the normal's side (chi+(m.n)).
//
// Radiance convention. evalRoughDielectric is f(i,o)|o.n| with f from (20)/(21)
// as written, i = -incident. For a fixed incident ray it integrates over the
// outgoing directions to the fraction of energy scattered (F and 1 - F in the
// smooth limit): no (n_i/n_t)^2 radiance change on transmission, the smooth
// tracer's convention (closed objects: entering and leaving cancel). (21)'s
// eta_o^2 is kept, and the Jacobian (17) in pdfRoughDielectric carries the same
// eta_o^2, so it cancels in eval/pdf; that is why the weight (41) has no eta
// factor and equals eval/pdf at every direction the sampler returns. A
// radiance-correct transmission would multiply the transmitted weight and eval
// by eta^2.
//
// Smooth limit. alpha < kSmoothAlpha, or NaN, is a smooth interface: the sampler
// then makes the smooth tracer's choice exactly (refractExact with
// TirPolicy::Reflect; reflection when TIR or xi3 < fresnelExact; weight 1), and
// eval/pdf return 0 (a Dirac lobe has no density). Likewise for eta == 1 the
// rough transmission is a Dirac (straight on), which eval/pdf cannot represent.
//
// Absorption. The model scatters once off the microsurface. A sampled facet
// the incident ray cannot see (i.m <= 0), a reflection that leaves below the
// macro surface or a refraction that leaves above it would meet the surface
// again; the model has no term for that, so the sampler returns weight 0 (the
// path is absorbed) and eval/pdf have no such lobe (G's chi+ factors vanish).
// This is the single-scattering energy loss of rough microfacet models.
//
// Bad input gives weight 0 (eval/pdf 0) and a finite unit direction, never NaN:
// a zero or non-finite incident or normal, eta not finite and > 0, alpha = +inf,
// and in the rough case grazing incidence (i.n = 0), where (41) and (20)/(21)
// divide by i.n. Smooth grazing follows refractExact/fresnelExact (F = 1: the
// ray goes on along incident, weight 1), as the smooth tracer does.
#pragma once
#include "lab/exact_optics.hpp"

#include <glm/glm.hpp>

#include <cmath>

namespace snell::lab {

// Below this alpha the interface is smooth. D then peaks at 1/(pi alpha^2) ~ 3e13,
// still well inside double, so everything above it is evaluated as rough.
inline constexpr double kSmoothAlpha = 1e-7;

namespace rough_detail {

inline constexpr double kPi = 3.14159265358979323846;

inline bool usable(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && glm::dot(v, v) > 0.0;
}

inline bool usableInput(const glm::dvec3& incident, const glm::dvec3& normal, double eta, double alpha) {
  return usable(incident) && usable(normal) && eta > 0.0 && std::isfinite(eta) && !std::isinf(alpha);
}

// sin^2 of the angle between unit a and b from the cross product: 1 - cos^2
// would lose the small angles a narrow lobe lives at.
inline double sin2(const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 c = glm::cross(a, b);
  return glm::dot(c, c);
}

}  // namespace rough_detail

// GGX distribution (33). cos^4(t) (alpha^2 + tan^2(t))^2 is written as
// (alpha^2 cos^2 + sin^2)^2 so that neither m.n -> 0 nor m -> n divides by 0.
inline double ggxD(const glm::dvec3& m, const glm::dvec3& n, double alpha) {
  const double c = glm::dot(m, n);
  if (!(c > 0.0) || !(alpha > 0.0)) return 0.0;
  const double a2 = alpha * alpha;
  const double k = a2 * c * c + rough_detail::sin2(m, n);
  return a2 / (rough_detail::kPi * k * k);
}

// Smith masking for GGX (34), v pointing away from the surface. Multiplying
// through by |v.n| keeps it finite at grazing v (tan -> inf), where it goes to 0;
// chi+((v.m)/(v.n)) is tested as a product so that v.n = 0 gives 0, not NaN.
inline double ggxG1(const glm::dvec3& v, const glm::dvec3& m, const glm::dvec3& n, double alpha) {
  const double vn = glm::dot(v, n);
  if (!(glm::dot(v, m) * vn > 0.0)) return 0.0;
  const double c = std::abs(vn);
  return 2.0 * c / (c + std::sqrt(c * c + alpha * alpha * rough_detail::sin2(v, n)));
}

// A microfacet normal with density D(m)|m.n| (24), by (35) and (36). cos and sin
// of theta_m come from tan^2 = alpha^2 xi1 / (1 - xi1) without forming the tan,
// so xi1 = 1 gives a horizontal m instead of inf. The frame around n is the
// branchless one of Duff et al. 2017 ("Building an Orthonormal Basis,
// Revisited"): no cross product with a fixed axis that could vanish, accurate
// up to n = -z. It turns over across n.z = 0, which a uniform phi cannot tell.
inline glm::dvec3 ggxSampleNormal(const glm::dvec3& n, double alpha, double xi1, double xi2) {
  const double s = std::copysign(1.0, n.z);
  const double a = -1.0 / (s + n.z);
  const double b = n.x * n.y * a;
  const glm::dvec3 t(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
  const glm::dvec3 u(b, s + n.y * n.y * a, -n.y);
  const double d = (1.0 - xi1) + alpha * alpha * xi1;
  if (!(d > 0.0)) return n;
  const double cosT = std::sqrt((1.0 - xi1) / d), sinT = alpha * std::sqrt(xi1 / d);
  const double phi = 2.0 * rough_detail::kPi * xi2;
  return sinT * (std::cos(phi) * t + std::sin(phi) * u) + cosT * n;
}

// The importance weight (41) of a direction `outgoing` scattered about the microfacet normal m: incident
// and outgoing are travel directions, n the macro normal on m's side (G1's chi+ wants them together). 0
// when outgoing lies on the side of the macro surface that its event (reflected or not) cannot reach,
// or at grazing incidence. The sampler below weighs its choice with it; the tracer's principal path, which
// picks its direction about m itself (refraction, a reflection), does too.
inline double ggxScatterWeight(const glm::dvec3& incident, const glm::dvec3& outgoing, const glm::dvec3& m,
                               const glm::dvec3& n, double alpha, bool reflected) {
  const glm::dvec3 i = -incident;
  const double in = glm::dot(i, n), on = glm::dot(outgoing, n);
  if (in == 0.0 || (reflected ? in * on <= 0.0 : in * on >= 0.0)) return 0.0;
  const double mn = std::abs(glm::dot(m, n));
  if (!(mn > 0.0)) return 0.0;
  return std::abs(glm::dot(i, m)) * ggxG1(i, m, n, alpha) * ggxG1(outgoing, m, n, alpha) / (std::abs(in) * mn);
}

struct RoughScatter {
  glm::dvec3 direction{0.0};  // unit direction of travel
  double weight = 0.0;        // f |o.n| / pdf, (41); 0: absorbed
  bool reflected = false;
};

// One scattering event: m by (35)/(36), reflection (39) when xi3 < F(i,m),
// else refraction (40), weight (41) (F cancels against the choice). Under
// microfacet TIR F = 1 and it reflects, for any xi3: xi3 = 1 means "refract
// unless TIR" (the tracer without Fresnel). (40) reads sqrt(1 + eta (c^2 - 1));
// Snell's law about m needs eta^2 there (with eta the sampler disagrees with
// (21), see rough_optics_test.cpp), so eta^2 it is.
inline RoughScatter sampleRoughDielectric(const glm::dvec3& incident, glm::dvec3 normal, double eta, double alpha,
                                          double xi1, double xi2, double xi3) {
  RoughScatter r;
  if (!rough_detail::usableInput(incident, normal, eta, alpha)) {
    r.direction = rough_detail::usable(incident) ? glm::normalize(incident) : glm::dvec3(0.0, 0.0, 1.0);
    return r;
  }
  if (!(alpha >= kSmoothAlpha)) {  // the smooth tracer's event, bit for bit
    const ExactRefraction t = refractExact(incident, normal, eta, TirPolicy::Reflect);
    r.weight = 1.0;
    r.reflected = t.tir || xi3 < fresnelExact(glm::dot(incident, normal), eta);
    r.direction = t.tir || !r.reflected ? t.direction : reflectExact(incident, normal);
    return r;
  }
  if (glm::dot(normal, incident) > 0.0) normal = -normal;
  const glm::dvec3 i = -incident;
  const double cosI = glm::dot(i, normal);
  r.direction = incident;
  if (!(cosI > 0.0)) return r;
  const glm::dvec3 m = ggxSampleNormal(normal, alpha, xi1, xi2);
  const double c = glm::dot(i, m), mn = glm::dot(m, normal);
  if (!(c > 0.0) || !(mn > 0.0)) return r;
  // fresnelExact's own expression, so that its TIR and ours agree to the bit.
  const double cos2T = (1.0 - eta * eta) + eta * eta * c * c;
  glm::dvec3 o;
  if (xi3 < fresnelExact(c, eta) || cos2T <= 0.0) {
    o = 2.0 * c * m - i;
    r.reflected = true;
  } else {
    o = (eta * c - std::sqrt(cos2T)) * m - eta * i;
  }
  o = glm::normalize(o);
  r.direction = o;
  r.weight = ggxScatterWeight(incident, o, m, normal, alpha, r.reflected);
  return r;
}

namespace rough_detail {

struct RoughLobe {
  double value = 0.0;  // f(i,o) |o.n|
  double pdf = 0.0;    // per solid angle of o
};

inline RoughLobe roughLobe(const glm::dvec3& incident, const glm::dvec3& outgoing, glm::dvec3 normal, double eta,
                           double alpha) {
  RoughLobe l;
  if (!usableInput(incident, normal, eta, alpha) || !usable(outgoing) || !(alpha >= kSmoothAlpha)) return l;
  if (glm::dot(normal, incident) > 0.0) normal = -normal;
  const glm::dvec3 i = -incident, &o = outgoing;
  const double cosI = glm::dot(i, normal), on = glm::dot(o, normal);
  if (!(cosI > 0.0) || on == 0.0) return l;
  glm::dvec3 h;
  if (on > 0.0) {
    h = glm::normalize(i + o);  // (13)
  } else {
    // (16) with eta_i = eta, eta_o = 1. Its sign puts h_t on the side of the
    // lower index, not of n; D and G1 want the facet that did the refracting,
    // which faces n (as (35) samples it), so h is flipped to n's side.
    const glm::dvec3 hv = -(eta * i + o);
    if (!usable(hv)) return l;
    h = glm::normalize(hv);
    if (glm::dot(h, normal) < 0.0) h = -h;
  }
  const double ih = glm::dot(i, h), oh = glm::dot(o, h), hn = glm::dot(h, normal);
  // Only a facet facing i, with o on its far side when refracted, could have sent i to o.
  if (!(ih > 0.0) || (on < 0.0 && !(oh < 0.0))) return l;
  const double F = fresnelExact(ih, eta);
  const double DG = ggxD(h, normal, alpha) * ggxG1(i, h, normal, alpha) * ggxG1(o, h, normal, alpha);  // (23)
  if (on > 0.0) {
    l.value = F * DG / (4.0 * cosI);                       // (20) times |o.n|
    l.pdf = ggxD(h, normal, alpha) * hn * F / (4.0 * oh);  // (24) (14)
  } else {
    const double den = eta * ih + oh, den2 = den * den;
    l.value = ih * -oh / cosI * (1.0 - F) * DG / den2;             // (21) times |o.n|, eta_o^2 = 1
    l.pdf = ggxD(h, normal, alpha) * hn * (1.0 - F) * -oh / den2;  // (24) (17)
  }
  return l;
}

}  // namespace rough_detail

// f(i,o)|o.n| by (20) when outgoing leaves on the incident side, by (21) when it
// leaves on the other; both arguments are travel directions. 0 for smooth alpha.
inline double evalRoughDielectric(const glm::dvec3& incident, const glm::dvec3& outgoing, const glm::dvec3& normal,
                                  double eta, double alpha) {
  return rough_detail::roughLobe(incident, outgoing, normal, eta, alpha).value;
}

// The density per solid angle of sampleRoughDielectric's directions of nonzero
// weight: D|m.n| (24) times F or 1 - F times the Jacobian (14) or (17). It
// integrates to 1 minus the absorbed mass. 0 for smooth alpha.
inline double pdfRoughDielectric(const glm::dvec3& incident, const glm::dvec3& outgoing, const glm::dvec3& normal,
                                 double eta, double alpha) {
  return rough_detail::roughLobe(incident, outgoing, normal, eta, alpha).pdf;
}

}  // namespace snell::lab
