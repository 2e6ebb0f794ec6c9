// The reference tracer with several refractive objects, against analytic
// geometry in double precision: nested media (a ray inside glass A entering
// glass B refracts with B's index over A's, and is in A again when it leaves
// B), Beer-Lambert absorption per medium, and the principal path passing each
// object with its own events. The optics here are written with angles
// (theta_t = asin(sin(theta_i) n1 / n2)), independent of the vector form the
// tracer uses.
#include "lab/mesh_generators.hpp"
#include "lab/tracer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

using namespace snell::lab;
using glm::dvec3;

namespace {

struct Sphere {
  dvec3 centre;
  double radius = 1.0;
  double ior = 1.5;
};

// The nearer intersection of o + t d (t > 1e-9) with the sphere, from outside or inside.
std::optional<double> hitSphere(dvec3 o, dvec3 d, const Sphere& s) {
  const dvec3 oc = o - s.centre;
  const double b = glm::dot(oc, d), q = glm::dot(oc, oc) - s.radius * s.radius, disc = b * b - q;
  if (disc < 0.0) return std::nullopt;
  const double r = std::sqrt(disc);
  if (-b - r > 1e-9) return -b - r;
  if (-b + r > 1e-9) return -b + r;
  return std::nullopt;
}

// Snell with angles at a surface of normal n (any side): the refracted direction, or nothing on TIR.
std::optional<dvec3> refractAngles(dvec3 d, dvec3 n, double n1OverN2) {
  if (glm::dot(d, n) > 0.0) n = -n;  // facing the incoming ray
  const double thetaI = std::acos(std::min(1.0, -glm::dot(d, n)));
  const double s = std::sin(thetaI) * n1OverN2;
  if (s > 1.0) return std::nullopt;
  const double thetaT = std::asin(s);
  dvec3 tangent = d - glm::dot(d, n) * n;
  tangent = glm::length(tangent) > 1e-15 ? glm::normalize(tangent) : dvec3(0.0);
  return std::cos(thetaT) * -n + std::sin(thetaT) * tangent;
}

struct Step {
  int object = -1;
  dvec3 point, direction;
};

// The path through non-intersecting spheres (nested or apart), tracking the medium by containment: the
// index on each side of a surface is that of the innermost sphere containing the points just before and
// just after it. Stops on TIR (not expected) or when nothing is hit.
std::vector<Step> analyticPath(dvec3 o, dvec3 d, const std::vector<Sphere>& spheres) {
  const auto mediumAt = [&](dvec3 p) {
    double ior = 1.0, smallest = 1e30;
    for (const Sphere& s : spheres)
      if (glm::length(p - s.centre) < s.radius && s.radius < smallest) {
        smallest = s.radius;
        ior = s.ior;
      }
    return ior;
  };
  std::vector<Step> steps;
  for (int k = 0; k < 16; ++k) {
    double best = 1e30;
    int which = -1;
    for (std::size_t i = 0; i < spheres.size(); ++i)
      if (const auto t = hitSphere(o, d, spheres[i]); t && *t < best) {
        best = *t;
        which = static_cast<int>(i);
      }
    if (which < 0) break;
    const dvec3 p = o + best * d;
    const Sphere& s = spheres[static_cast<std::size_t>(which)];
    const dvec3 n = (p - s.centre) / s.radius;
    const double n1 = mediumAt(p - 1e-7 * d), n2 = mediumAt(p + 1e-7 * d);
    const auto t = refractAngles(d, n, n1 / n2);
    if (!t) break;
    steps.push_back({which, p, *t});
    o = p;
    d = *t;
  }
  return steps;
}

FrameObject icosphere(dvec3 centre, double radius, double ior, snell::vec3 sigma = snell::vec3(0.0f)) {
  Mesh m = makeIcosphere(static_cast<float>(radius), 6);
  for (snell::vec3& p : m.positions) p += snell::vec3(centre);
  return FrameObject{m, static_cast<float>(ior), sigma};
}

Ray rayAt(dvec3 o, dvec3 d) {
  Ray r;
  r.origin = o;
  r.direction = glm::normalize(d);
  return r;
}

double angleBetween(dvec3 a, dvec3 b) { return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)); }

// The tracer's principal path against the analytic one over a grid of rays: same objects in the same
// order, points within 2e-3 and directions within 2e-3 rad (icosphere subdivision 6: sagitta ~5e-5 on the
// unit sphere, and the errors of four interfaces add up).
void expectPathsMatch(const std::vector<Sphere>& spheres, const std::vector<FrameObject>& objects, dvec3 origin,
                      double spread, std::size_t expectedSteps) {
  const ReferenceTracer tracer(objects, {}, Environment::constant(snell::vec3(1.0f)));
  int compared = 0;
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j) {
      const dvec3 d(spread * (i - 3) / 3.0, spread * (j - 3) / 3.0, -1.0);
      const Ray ray = rayAt(origin, d);
      const std::vector<Step> want = analyticPath(ray.origin, ray.direction, spheres);
      if (want.size() != expectedSteps) continue;
      const std::vector<PathEvent> got = tracer.principalPath(ray, static_cast<int>(expectedSteps) + 1, TirPolicy::Reflect);
      ASSERT_EQ(got.size(), expectedSteps + 1) << "ray " << i << "," << j;
      for (std::size_t k = 0; k < expectedSteps; ++k) {
        EXPECT_EQ(got[k].object, want[k].object) << "event " << k;
        EXPECT_LT(glm::length(got[k].point - want[k].point), 2e-3) << "event " << k;
        EXPECT_LT(angleBetween(got[k].direction, want[k].direction), 2e-3) << "event " << k;
      }
      EXPECT_EQ(got.back().type, PathEventType::Escape);
      ++compared;
    }
  EXPECT_GE(compared, 12) << "too few rays crossed every surface";
}

}  // namespace

// A diamond (2.4) ball inside a glass (1.5) ball: at the inner surface the ray refracts with 2.4 / 1.5,
// not 2.4 / 1; leaving it, with 1.5 / 2.4; leaving the glass, with 1 / 1.5.
TEST(LabTracerObjects, NestedBallRefractsWithTheRelativeIndex) {
  const std::vector<Sphere> spheres = {{dvec3(0.0), 1.0, 1.5}, {dvec3(0.0), 0.5, 2.4}};
  expectPathsMatch(spheres, {icosphere(dvec3(0.0), 1.0, 1.5), icosphere(dvec3(0.0), 0.5, 2.4)}, dvec3(0.05, 0.03, 4.0),
                   0.06, 4);
  const std::vector<PathEvent> ev = ReferenceTracer({icosphere(dvec3(0.0), 1.0, 1.5), icosphere(dvec3(0.0), 0.5, 2.4)},
                                                    {}, Environment::constant(snell::vec3(1.0f)))
                                        .principalPath(rayAt(dvec3(0.1, 0.05, 4.0), dvec3(0.0, 0.0, -1.0)), 5,
                                                       TirPolicy::Reflect);
  ASSERT_EQ(ev.size(), 5u);
  EXPECT_EQ(ev[0].type, PathEventType::Enter);
  EXPECT_EQ(ev[1].type, PathEventType::Enter);
  EXPECT_EQ(ev[2].type, PathEventType::Exit);
  EXPECT_EQ(ev[3].type, PathEventType::Exit);
}

// The same index inside and out: the inner surface separates glass from glass and bends nothing.
TEST(LabTracerObjects, NestedBallOfTheSameIndexDoesNotBend) {
  const ReferenceTracer tracer({icosphere(dvec3(0.0), 1.0, 1.5), icosphere(dvec3(0.0), 0.5, 1.5)}, {},
                               Environment::constant(snell::vec3(1.0f)));
  const std::vector<PathEvent> ev = tracer.principalPath(rayAt(dvec3(0.2, 0.1, 4.0), dvec3(0.0, 0.0, -1.0)), 4,
                                                         TirPolicy::Reflect);
  ASSERT_EQ(ev.size(), 4u);
  EXPECT_EQ(ev[1].object, 1);
  EXPECT_LT(angleBetween(ev[1].direction, ev[0].direction), 1e-9);
  EXPECT_LT(angleBetween(ev[2].direction, ev[0].direction), 1e-9);
}

// Two balls apart, one behind the other on the ray: each refracts from air and back.
TEST(LabTracerObjects, BallBehindBallRefractsThroughBoth) {
  const std::vector<Sphere> spheres = {{dvec3(0.0), 1.0, 1.5}, {dvec3(0.3, 0.0, -3.0), 0.8, 1.33}};
  expectPathsMatch(spheres, {icosphere(dvec3(0.0), 1.0, 1.5), icosphere(dvec3(0.3, 0.0, -3.0), 0.8, 1.33)},
                   dvec3(0.0, 0.0, 4.0), 0.08, 4);
}

// Beer-Lambert per medium along the axis (no bending there, Fresnel off): glass A's sigma over its own
// length, the inner ball's over the inner chord only, and the ball apart over its chord.
TEST(LabTracerObjects, AbsorptionFollowsTheMediumOfEachSegment) {
  const snell::vec3 sa(0.3f, 0.1f, 0.0f), sb(0.0f, 0.5f, 0.2f), sc(0.2f, 0.0f, 0.7f);
  const ReferenceTracer tracer({icosphere(dvec3(0.0), 1.0, 1.5, sa), icosphere(dvec3(0.0), 0.5, 1.8, sb),
                                icosphere(dvec3(0.0, 0.0, -3.0), 0.6, 1.3, sc)},
                               {}, Environment::constant(snell::vec3(1.0f)));
  TraceOptions full;
  full.fresnel = false;
  const dvec3 want = glm::exp(-dvec3(sa) * 1.0 - dvec3(sb) * 1.0 - dvec3(sc) * 1.2);
  for (TraceMode mode : {TraceMode::Full, TraceMode::TwoInterfaces}) {
    full.mode = mode;
    const dvec3 got = tracer.radiance(rayAt(dvec3(0.0, 0.0, 4.0), dvec3(0.0, 0.0, -1.0)), full);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 2e-4) << "mode " << static_cast<int>(mode) << " channel " << c;
  }
}

// The two-interface model passes each object with two events: through two balls apart it equals the
// full trace without Fresnel (no TIR on these rays), through a direction-coded environment.
TEST(LabTracerObjects, TwoInterfacesPassEachObjectWithTwoEvents) {
  snell::Image sky(64, 32);
  for (int y = 0; y < sky.height; ++y)
    for (int x = 0; x < sky.width; ++x)
      sky.at(x, y) = snell::vec4(static_cast<float>(x) / 64.0f, static_cast<float>(y) / 32.0f, 0.5f, 1.0f);
  const ReferenceTracer tracer({icosphere(dvec3(0.0), 1.0, 1.5), icosphere(dvec3(0.3, 0.0, -3.0), 0.8, 1.33)}, {},
                               Environment(sky, 0.0f));
  TraceOptions two, full;
  two.mode = TraceMode::TwoInterfaces;
  two.fresnel = full.fresnel = false;
  const std::vector<Sphere> spheres = {{dvec3(0.0), 1.0, 1.5}, {dvec3(0.3, 0.0, -3.0), 0.8, 1.33}};
  int both = 0;
  for (int i = 0; i < 9; ++i) {
    const Ray ray = rayAt(dvec3(0.0, 0.0, 4.0), dvec3(0.01 * (i - 4), 0.005 * i, -1.0));
    const dvec3 a = tracer.radiance(ray, two), b = tracer.radiance(ray, full);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-6) << "ray " << i;
    both += analyticPath(ray.origin, ray.direction, spheres).size() == 4;
  }
  EXPECT_GE(both, 6) << "too few rays crossed both balls";
}

namespace {

// A 32x32 card (colour changing across it) 3 units behind the origin, and a camera before it: the
// composited model's scene.
std::vector<Painting> cardBehind() {
  snell::Image card(32, 32);
  for (int y = 0; y < card.height; ++y)
    for (int x = 0; x < card.width; ++x)
      card.at(x, y) = snell::vec4(static_cast<float>(x) / 32.0f, static_cast<float>((x + y) % 7) / 7.0f,
                                  static_cast<float>(y) / 32.0f, 1.0f);
  return {makePainting(snell::vec3(0.0f, 0.0f, -3.0f), snell::vec2(6.0f, 6.0f), snell::vec3(0.0f), card)};
}

Camera cameraBeforeTheBall() {
  Camera camera;
  camera.position = snell::vec3(0.0f, 0.3f, 4.0f);
  camera.width = camera.height = 48;
  return camera;
}

}  // namespace

// The composited model of one object is the two-interface model: the same paths, traced by another
// route (renderComposited's pass against render's principal path of two events).
TEST(LabTracerObjects, CompositedModelOfOneObjectIsTheTwoInterfaceModel) {
  const ReferenceTracer tracer({icosphere(dvec3(0.1, 0.0, 0.0), 1.0, 1.5, snell::vec3(0.1f, 0.2f, 0.0f))}, cardBehind(),
                               Environment::constant(snell::vec3(0.6f)));
  const Camera camera = cameraBeforeTheBall();
  TraceOptions two;
  two.mode = TraceMode::TwoInterfaces;
  two.progress = false;
  const TraceResult a = tracer.render(camera, two);
  const TraceResult b = tracer.renderComposited(camera, {0}, {glm::dvec3(1.5)}, two);
  ASSERT_GT(a.mask.count(), 300u);
  EXPECT_EQ(a.mask.count(), b.mask.count());
  float worst = 0.0f;
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x)
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(a.color.at(x, y)[c] - b.color.at(x, y)[c]));
  EXPECT_LT(worst, 1e-5f);
}

namespace {

// KHR_materials_dispersion's n(lambda) = n_d + (n_d - 1) / V_d * (523655 / lambda^2 - 1.5168), lambda in nm,
// at the C (red), d (green) and F (blue) lines: written from the extension's text, not from
// snellDispersionIors, which channelIors calls.
dvec3 khrDispersionIors(double nd, double abbe) {
  const auto n = [&](double lambda) { return nd + (nd - 1.0) / abbe * (523655.0 / (lambda * lambda) - 1.5168); };
  return dvec3(n(656.27), n(587.56), n(486.13));
}

}  // namespace

// A dispersive ball (flint, n_d 1.62, V_d 20): its IORs per channel are the ones KHR_materials_dispersion's
// text gives, and each colour channel of the tracer's picture is that channel of the picture of a ball of
// one glass with that channel's IOR (the same facets, so the paths agree to rounding), through a
// direction-coded environment; red's and blue's differ from green's, so one path for all would fail.
TEST(LabTracerObjects, DispersiveBallTracesEachChannelWithItsOwnIndex) {
  snell::Image sky(256, 128);
  for (int y = 0; y < sky.height; ++y)
    for (int x = 0; x < sky.width; ++x) {
      const float u = static_cast<float>(x) / 256.0f, v = static_cast<float>(y) / 128.0f;
      sky.at(x, y) = snell::vec4(10.0f * u, 10.0f * v, 5.0f * (u + v), 1.0f);
    }
  const Environment environment(sky, 0.0f);
  FrameObject ball = icosphere(dvec3(0.0), 1.0, 1.62);
  ball.abbe = 20.0f;
  const dvec3 iors = khrDispersionIors(1.62, 20.0);
  const dvec3 channel = dvec3(channelIors(ball));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(channel[c], iors[c], 2e-6) << "channel " << c;
  const ReferenceTracer tracer({ball}, {}, environment);
  std::vector<std::unique_ptr<ReferenceTracer>> oneGlass;
  for (int c = 0; c < 3; ++c) {
    FrameObject o = icosphere(dvec3(0.0), 1.0, channel[c]);
    oneGlass.push_back(std::make_unique<ReferenceTracer>(std::vector<FrameObject>{o}, std::vector<Painting>{}, environment));
  }
  int differ = 0;
  for (TraceMode mode : {TraceMode::Full, TraceMode::TwoInterfaces}) {
    TraceOptions options;
    options.mode = mode;
    for (int i = 0; i < 9; ++i) {
      const Ray ray = rayAt(dvec3(0.0, 0.0, 4.0), dvec3(0.04 * (i - 4), 0.012 * i, -1.0));
      const dvec3 got = tracer.radiance(ray, options);
      dvec3 want[3];
      for (int c = 0; c < 3; ++c) {
        want[c] = oneGlass[static_cast<std::size_t>(c)]->radiance(ray, options);
        EXPECT_NEAR(got[c], want[c][c], 1e-9) << "ray " << i << " channel " << c;
      }
      if (std::abs(want[0].x - want[1].x) > 1e-3 && std::abs(want[2].z - want[1].z) > 1e-3) ++differ;
    }
  }
  EXPECT_GE(differ, 12) << "the channels' glasses give the same picture: nothing was compared";
}

// The composited model of a dispersive ball: one path per channel there too, as the two-interface model.
TEST(LabTracerObjects, CompositedModelOfADispersiveBallIsTheTwoInterfaceModel) {
  FrameObject ball = icosphere(dvec3(0.1, 0.0, 0.0), 1.0, 1.62);
  ball.abbe = 20.0f;
  const ReferenceTracer tracer({ball}, cardBehind(), Environment::constant(snell::vec3(0.6f)));
  const Camera camera = cameraBeforeTheBall();
  TraceOptions two;
  two.mode = TraceMode::TwoInterfaces;
  two.progress = false;
  const TraceResult a = tracer.render(camera, two);
  const TraceResult b = tracer.renderComposited(camera, {0}, {dvec3(channelIors(ball))}, two);
  two.channel = 1;  // one path per pixel, green's IOR for every channel: what ignoring dispersion draws
  const TraceResult green = tracer.render(camera, two);
  ASSERT_GT(a.mask.count(), 300u);
  float worst = 0.0f, dispersion = 0.0f;
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x)
      for (int c = 0; c < 3; ++c) {
        worst = std::max(worst, std::abs(a.color.at(x, y)[c] - b.color.at(x, y)[c]));
        dispersion = std::max(dispersion, std::abs(a.color.at(x, y)[c] - green.color.at(x, y)[c]));
      }
  EXPECT_LT(worst, 1e-5f);
  EXPECT_GT(dispersion, 0.1f) << "the channels' paths do not differ on this frame";
}
