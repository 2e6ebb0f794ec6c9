// The reference tracer on rough glass (GGX interfaces, sampled; lab/rough_optics.hpp is checked against
// Walter et al.'s own formulas in rough_optics_test.cpp). What the sampled truth must get right beyond the
// microfacet model: energy (a rough sphere under a uniform sky gains none and loses only what single-
// scattering microfacets shadow), the smooth limit (a nearly smooth interface gives the smooth tracer's
// image up to its own noise), the noise estimate (two seeds differ by what it says), and the seeding
// (per pixel: neither threads nor the order of pixels change a value).
#include "lab/camera.hpp"
#include "lab/error.hpp"
#include "lab/mesh_generators.hpp"
#include "lab/metrics.hpp"
#include "lab/painting.hpp"
#include "lab/tracer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace snell::lab;
using glm::dvec3;

namespace {

FrameObject sphere(float roughness, float radius = 1.0f) {
  FrameObject o;
  o.mesh = makeIcosphere(radius, 5);
  o.ior = 1.5f;
  o.roughness = roughness;
  return o;
}

// A box tilted so that its side walls reflect totally (IOR 1.5).
FrameObject tiltedBox(float roughness) {
  FrameObject o;
  o.mesh = makeBox(snell::vec3(1.6f, 1.0f, 1.2f));
  Transform t;
  t.rotateDegrees = snell::vec3(20.0f, 35.0f, 0.0f);
  applyTransform(o.mesh, t);
  o.ior = 1.5f;
  o.roughness = roughness;
  return o;
}

Camera camera(int size) {
  Camera cam;
  cam.position = snell::vec3(0.0f, 0.0f, 4.0f);
  cam.width = cam.height = size;
  cam.fovYDegrees = 32.0f;
  return cam;
}

std::vector<Painting> checkerBehind() {
  const snell::Image tex =
      makeCheckerTexture(64, 64, snell::ivec2(8, 8), snell::vec3(0.8f, 0.6f, 0.1f), snell::vec3(0.05f, 0.1f, 0.3f));
  return {makePainting(snell::vec3(0.0f, 0.0f, -2.5f), snell::vec2(6.0f, 6.0f), snell::vec3(0.0f), tex)};
}

TraceOptions options(int samples, std::uint64_t seed = 0) {
  TraceOptions o;
  o.progress = false;
  o.samples = samples;
  o.seed = seed;
  return o;
}

double meanOver(const TraceResult& r, int channel) {
  double sum = 0.0;
  for (int y = 0; y < r.mask.height; ++y)
    for (int x = 0; x < r.mask.width; ++x)
      if (r.mask.at(x, y)) sum += static_cast<double>(r.color.at(x, y)[channel]);
  return sum / static_cast<double>(r.mask.count());
}

}  // namespace

// A closed object under a uniform sky of radiance 1 returns at most 1 along every path: each interface
// either reflects or transmits, and eq. 41's weight is below 1 (a weight above it, say a G1 dropped, gains
// energy). Single-scattering microfacets lose what their masking hides, at every one of the path's
// interface events: rough_optics_test.cpp integrates one event's albedo from Walter's formulas (alpha 0.25:
// 0.93 at normal incidence to 0.77 at 80 degrees), and a path through a sphere meets two or more, so the
// sphere keeps 0.976, 0.930 and 0.766 of the light at roughness 0.15, 0.3 and 0.5 (measured; the bounds
// leave a margin). A smooth sphere keeps everything but the branches below minWeight.
TEST(LabTracerRough, ARoughSphereUnderAUniformSkyGainsNoEnergy) {
  for (float roughness : {0.0f, 0.15f, 0.3f, 0.5f}) {
    const ReferenceTracer tracer({sphere(roughness)}, {}, Environment::constant(snell::vec3(1.0f)));
    const TraceResult r = tracer.render(camera(24), options(512));
    ASSERT_GT(r.mask.count(), 200u);
    const double mean = meanOver(r, 1);
    const double sigma = std::sqrt(r.noise);  // the mean's standard error is below any one pixel's
    EXPECT_LE(mean, 1.0 + 3.0 * sigma + 1e-6) << "roughness " << roughness;
    const double loss = roughness == 0.0f ? 2e-3 : roughness <= 0.15f ? 0.04 : roughness <= 0.3f ? 0.10 : 0.28;
    EXPECT_GE(mean, 1.0 - loss) << "roughness " << roughness;
    if (roughness == 0.0f) {
      EXPECT_EQ(r.noise, 0.0);
      EXPECT_EQ(r.stats.sampledPixels, 0u);
    } else {
      EXPECT_GT(r.noise, 0.0);
      EXPECT_EQ(r.stats.sampledPixels, static_cast<std::uint64_t>(r.mask.count()));
    }
  }
}

// At alpha 1e-6 the microfacets are the surface: the rough image is the smooth one plus the noise of choosing
// reflection or refraction by chance, whose size the tracer's own estimate gives. A bias (a weight that
// does not reduce to 1, a refraction about the wrong normal) shows as a difference far above that noise.
TEST(LabTracerRough, ANearlySmoothInterfaceGivesTheSmoothImageUpToItsNoise) {
  const Camera cam = camera(32);
  const ReferenceTracer smooth({sphere(0.0f)}, checkerBehind(), Environment::constant(snell::vec3(0.4f, 0.5f, 0.7f)));
  const ReferenceTracer rough({sphere(1e-3f)}, checkerBehind(), Environment::constant(snell::vec3(0.4f, 0.5f, 0.7f)));
  const TraceResult s = smooth.render(cam, options(1));
  const TraceResult r = rough.render(cam, options(256));
  ASSERT_EQ(s.mask.bits, r.mask.bits);
  const double mse = compareImages(s.color, r.color, s.mask).mse;
  ASSERT_GT(r.noise, 0.0);
  EXPECT_LT(mse, 2.0 * r.noise) << "noise " << r.noise;
  EXPECT_GT(mse, 0.3 * r.noise) << "noise " << r.noise;  // the estimate is not inflated either
}

// The model references too: the two-interface path and the principal path, about microfacet normals, give
// the smooth ones at alpha 1e-6 up to their noise, on a tilted box whose side walls reflect totally
// (the principal path's bounces, the two-interface model's critical clamp).
TEST(LabTracerRough, NearlySmoothModelReferencesAreTheSmoothOnes) {
  const Camera cam = camera(40);
  const ReferenceTracer smooth({tiltedBox(0.0f)}, checkerBehind(), Environment::constant(snell::vec3(0.4f, 0.5f, 0.7f)));
  const ReferenceTracer rough({tiltedBox(1e-3f)}, checkerBehind(), Environment::constant(snell::vec3(0.4f, 0.5f, 0.7f)));
  for (const TraceMode mode : {TraceMode::TwoInterfaces, TraceMode::Principal}) {
    TraceOptions o = options(64);
    o.mode = mode;
    o.events = 4;
    const TraceResult s = smooth.render(cam, o);
    const TraceResult r = rough.render(cam, o);
    ASSERT_EQ(s.mask.bits, r.mask.bits);
    EXPECT_GT(s.tir.count(), 50u);  // the walls do reflect totally
    const double mse = compareImages(s.color, r.color, s.mask).mse;
    EXPECT_LT(mse, 2.0 * r.noise + 1e-6) << "mode " << static_cast<int>(mode) << ", noise " << r.noise;
    // Most paths TIR where the smooth one does: the masks agree but for a few pixels at the edges.
    std::size_t differ = 0;
    for (std::size_t i = 0; i < s.tir.bits.size(); ++i) differ += s.tir.bits[i] != r.tir.bits[i] ? 1u : 0u;
    EXPECT_LT(differ, s.tir.count() / 10 + 5);
  }
}

// The noise estimate against two independent renders: E[MSE(A, B)] = noise(A) + noise(B) where the images
// stay inside [0, 1] (the painting and the sky here do).
TEST(LabTracerRough, TwoSeedsDifferByTheNoiseTheTracerEstimates) {
  const ReferenceTracer tracer({sphere(0.3f)}, checkerBehind(), Environment::constant(snell::vec3(0.4f, 0.5f, 0.7f)));
  const Camera cam = camera(40);
  const TraceResult a = tracer.render(cam, options(64, 1));
  const TraceResult b = tracer.render(cam, options(64, 2));
  const double mse = compareImages(a.color, b.color, a.mask).mse;
  const double expected = a.noise + b.noise;
  ASSERT_GT(a.mask.count(), 400u);
  EXPECT_GT(mse, 0.8 * expected);
  EXPECT_LT(mse, 1.25 * expected);
}

// A pixel's random numbers come from (seed, x, y) alone: the same seed gives the same image on any number of
// threads; another seed gives another image.
TEST(LabTracerRough, SamplesAreSeededPerPixel) {
  const ReferenceTracer tracer({sphere(0.3f)}, checkerBehind(), Environment::constant(snell::vec3(0.5f)));
  const Camera cam = camera(20);
  TraceOptions o = options(16, 7);
  o.threads = 1;
  const TraceResult one = tracer.render(cam, o);
  o.threads = 2;
  const TraceResult two = tracer.render(cam, o);
  EXPECT_EQ(one.color.texels, two.color.texels);
  EXPECT_NEAR(one.noise, two.noise, 1e-12 * one.noise);  // the same terms, summed per thread in another order
  o.seed = 8;
  EXPECT_NE(tracer.render(cam, o).color.texels, one.color.texels);
}

// Common random numbers: a camera moved by a quarter pixel keeps each pixel's numbers, so the truth's noise
// of the two frames is nearly the same and mostly cancels in their difference, which a flicker measure reads.
// A box whose walls reflect totally makes some paths meet another number of interfaces after the move; were
// a pixel's paths one stream, each such path would shift the numbers of every path after it in the pixel.
// The MSE between the frames (the noise's change and the image's own) against the MSE between two seeds at
// one frame (the noise's change were it drawn afresh): one stream per pixel gave 0.18, one per path and
// event gives 0.06.
TEST(LabTracerRough, ASubPixelCameraMoveKeepsTheNoise) {
  const ReferenceTracer tracer({tiltedBox(0.3f)}, checkerBehind(), Environment::constant(snell::vec3(0.4f, 0.5f, 0.7f)));
  const Camera cam = camera(40);
  const TraceResult a = tracer.render(cam, options(64, 3));
  const TraceResult moved = tracer.render(pannedCamera(cam, snell::vec2(0.25f, 0.0f)), options(64, 3));
  const TraceResult reseeded = tracer.render(cam, options(64, 4));
  Mask both = a.mask;
  for (std::size_t i = 0; i < both.bits.size(); ++i) both.bits[i] = a.mask.bits[i] && moved.mask.bits[i];
  ASSERT_GT(both.count(), 400u);
  const double moveChange = compareImages(a.color, moved.color, both).mse;
  const double seedChange = compareImages(a.color, reseeded.color, both).mse;
  ASSERT_GT(seedChange, 0.0);
  EXPECT_LT(moveChange, 0.1 * seedChange) << "move " << moveChange << ", seed " << seedChange;
}

// Rougher glass blurs the checker behind it more: the spread of the object's pixels shrinks with roughness.
TEST(LabTracerRough, RougherGlassBlursMore) {
  double previous = 1e30;
  for (float roughness : {0.0f, 0.15f, 0.3f, 0.5f}) {
    const ReferenceTracer tracer({sphere(roughness)}, checkerBehind(), Environment::constant(snell::vec3(0.3f)));
    const TraceResult r = tracer.render(camera(32), options(256));
    const double mean = meanOver(r, 0);
    double spread = 0.0;
    for (int y = 0; y < r.mask.height; ++y)
      for (int x = 0; x < r.mask.width; ++x)
        if (r.mask.at(x, y)) spread += std::pow(static_cast<double>(r.color.at(x, y).x) - mean, 2.0);
    spread /= static_cast<double>(r.mask.count());
    EXPECT_LT(spread, previous) << "roughness " << roughness;
    previous = spread;
  }
}

TEST(LabTracerRough, BadSampleCountsAndRoughnessAreRefused) {
  const ReferenceTracer tracer({sphere(0.3f)}, {}, Environment::constant(snell::vec3(0.5f)));
  TraceOptions o = options(0);
  EXPECT_THROW(tracer.render(camera(8), o), Error);
  EXPECT_THROW(ReferenceTracer({sphere(1.5f)}, {}, Environment::constant(snell::vec3(0.5f))), Error);
  FrameObject nan = sphere(0.0f);
  nan.roughness = std::nanf("");
  EXPECT_THROW(ReferenceTracer({nan}, {}, Environment::constant(snell::vec3(0.5f))), Error);
}
