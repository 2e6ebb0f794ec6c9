// The screen as every search reads it: the closed square uv in [0,1]^2. A
// depth read takes uv = 0 and uv = 1 (snellSampleSurface; pixel_to_uv.glsl: uv
// = 1 belongs to the last pixel), so a point projecting exactly onto an edge is
// on screen for the searches too, and one a float ulp past it is off. A square
// camera with its focal terms written as exactly 1 (a 90 degree frustum) makes
// such points exact: (x, y, z) with x = z projects to uv.x = 0, x = -z to 1,
// and x = -(1 + 2^-22) z to the first float past 1, with no rounding on the
// way (ndc = x / -z, uv = ndc / 2 + 1 / 2). The expected values below follow
// from the analytic layers and the contracts' sample positions. The same
// camera also puts a march sample, and a tangent plane's hit, exactly on a
// layer or a bracket's end (InsideExactBoundary).
#include <snell/snell.hpp>

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <cmath>
#include <functional>
#include <limits>

#include "support/depth_scenes.hpp"

namespace {

using namespace snell;

constexpr float kNear = 0.5f, kFar = 40.0f;
constexpr float kOnePast = 1.0f + 0x1p-22f;  // x / -z giving uv = 1 + 2^-23, the first float past 1

glm::mat4 squareCamera() {
  glm::mat4 m = snellPerspectiveWithDepth(1.5707964f, 1.0f, kNear, kFar, SNELL_DEPTH_GL);
  m[0][0] = 1.0f;
  m[1][1] = 1.0f;
  return m;
}

SnellDepthSurface squareSurface(float emptyDepth) {
  return snellDepthSurface(squareCamera(), kNear, kFar, SNELL_DEPTH_GL, emptyDepth);
}

// A depth texture of fronto-parallel texels at view distance dist(i, j) over the texels `covered` accepts.
Texture2D faceDepth(int size, const std::function<double(int, int)>& dist, float emptyDepth,
                    const std::function<bool(int, int)>& covered) {
  Image im(size, size, glm::vec4(emptyDepth, 0.0f, 0.0f, 0.0f));
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i)
      if (covered(i, j))
        im.at(i, j).x = float(snell_test::windowDepth(dist(i, j), double(kNear), double(kFar), SNELL_DEPTH_GL));
  return Texture2D(std::move(im));
}

// A slab-shaped object between the view distances 2 (front faces) and 6 (back faces) over the covered
// texels, as its two depth passes store it (back: GL_GREATER cleared to 0, front: GL_LESS cleared to 1).
struct Slab {
  Texture2D back, front;
  SnellDepthSurface backS = squareSurface(0.0f), frontS = squareSurface(1.0f);
  Slab(int size, const std::function<bool(int, int)>& covered,
       const std::function<double(int, int)>& backDist = [](int, int) { return 6.0; })
      : back(faceDepth(size, backDist, 0.0f, covered)),
        front(faceDepth(size, [](int, int) { return 2.0; }, 1.0f, covered)) {}
  explicit Slab(int size) : Slab(size, [](int, int) { return true; }) {}

  SnellInsideBracket bracket(glm::vec3 o, glm::vec3 d, float maxDistance, int steps) const {
    return snellInsideBracket(o, d, back, backS, front, frontS, maxDistance, steps);
  }
  SnellInsideHit march(glm::vec3 o, glm::vec3 d, float maxDistance, int steps, int refine) const {
    return snellInsideMarch(o, d, back, backS, front, frontS, maxDistance, steps, refine);
  }
};

// A ray on one of the four planes through the eye and a screen edge, inside the slab at view distance 4:
// x = z (uv.x = 0), x = -z (uv.x = 1), y = z (uv.y = 0) or y = -z (uv.y = 1) holds bit for bit along it,
// as origin + t dir computes the two coordinates with the same operations.
struct EdgeRay {
  const char* name;
  glm::vec3 o, d;
  int axis;     // the coordinate on the edge
  float edge;   // its uv there
};

EdgeRay edgeRay(int k, float lateral) {
  switch (k) {
    case 0: return {"left", {-4.0f, 0.0f, -4.0f}, {-1.0f, lateral, -1.0f}, 0, 0.0f};
    case 1: return {"right", {4.0f, 0.0f, -4.0f}, {1.0f, lateral, -1.0f}, 0, 1.0f};
    case 2: return {"bottom", {0.0f, -4.0f, -4.0f}, {lateral, -1.0f, -1.0f}, 1, 0.0f};
    default: return {"top", {0.0f, 4.0f, -4.0f}, {lateral, 1.0f, -1.0f}, 1, 1.0f};
  }
}

TEST(ScreenEdge, TheSquareCameraPutsTheEdgeRaysExactlyOnTheEdges) {
  const SnellDepthSurface s = squareSurface(0.0f);
  ASSERT_TRUE(s.perspective);
  for (int k = 0; k < 4; ++k) {
    const EdgeRay r = edgeRay(k, 0.3f);
    for (float t : {0.0f, 0.37f, 1.9f, 2.6f}) {
      const SnellScreenPoint sp = snellSurfaceViewToUv(s, r.o + t * r.d);
      ASSERT_TRUE(sp.valid);
      EXPECT_EQ(sp.uv[r.axis], r.edge) << r.name << " t " << t;
    }
  }
  EXPECT_EQ(snellSurfaceViewToUv(s, glm::vec3(4.0f * kOnePast, 0.0f, -4.0f)).uv.x, 1.0f + 0x1p-23f);
}

// Along each edge the march reads every sample (on screen) and the bisection converges on the back face
// at view distance 6, t = 2: samples at i * 4.4 / 8 leave at i = 4 (z = -6.2), the last inside one is 3.
TEST(ScreenEdge, InsideMarchFollowsARayAlongEachScreenEdge) {
  const Slab slab(32);
  for (int k = 0; k < 4; ++k) {
    const EdgeRay r = edgeRay(k, 0.0f);
    SCOPED_TRACE(r.name);
    const float maxDistance = 4.4f * glm::length(r.d);  // tMax = 4.4
    const SnellInsideBracket b = slab.bracket(r.o, r.d, maxDistance, 8);
    ASSERT_TRUE(b.valid);
    EXPECT_NEAR(b.lo, 1.65f, 1e-5f);
    EXPECT_NEAR(b.hi, 2.2f, 1e-5f);
    EXPECT_EQ(b.uv[r.axis], r.edge);
    EXPECT_EQ(b.loUv[r.axis], r.edge);
    EXPECT_EQ(b.side, 1);
    EXPECT_EQ(b.fetches, 2 * 4);
    const SnellInsideHit h = slab.march(r.o, r.d, maxDistance, 8, 10);
    ASSERT_TRUE(h.hit.valid);
    EXPECT_FALSE(h.front);
    EXPECT_EQ(h.hit.fetches, 2 * 4 + 2 * 10);  // every midpoint on the edge is read
    EXPECT_NEAR(h.hit.position.z, -6.0f, 0.55f / 1024.0f + 1e-4f);
    EXPECT_EQ(h.hit.uv[r.axis], r.edge);
  }
}

// The first step leaves (t_1 = 2.4, z = -6.4) and its half is inside (z = -5.2): a bracket from the
// halving, which reads samples on the edge as well. The ray moves across the edge's direction (lateral
// 0.5) so the half is texels away from the origin's pixel.
TEST(ScreenEdge, FirstStepHalvingReadsSamplesOnTheEdges) {
  const Slab slab(32);
  for (int k = 0; k < 4; ++k) {
    const EdgeRay r = edgeRay(k, 0.5f);
    SCOPED_TRACE(r.name);
    const float maxDistance = 2.4f * glm::length(r.d);
    const SnellInsideBracket b = slab.bracket(r.o, r.d, maxDistance, 1);
    ASSERT_TRUE(b.valid);
    EXPECT_NEAR(b.lo, 1.2f, 1e-5f);
    EXPECT_NEAR(b.hi, 2.4f, 1e-5f);
    EXPECT_EQ(b.loUv[r.axis], r.edge);
    EXPECT_EQ(b.uv[r.axis], r.edge);
    EXPECT_EQ(b.side, 1);
    EXPECT_EQ(b.fetches, 4);
  }
}

// The first sample one float ulp past the right (top) edge: off screen, the march ends with nothing read.
TEST(ScreenEdge, ASampleOneUlpPastTheEdgeIsOffScreen) {
  const Slab slab(32);
  // Straight back along -z from view distance 3 to 4, where x = 4 (1 + 2^-22).
  for (int axis = 0; axis < 2; ++axis) {
    glm::vec3 o(0.0f, 0.0f, -3.0f);
    o[axis] = 4.0f * kOnePast;
    const SnellInsideBracket b = slab.bracket(o, glm::vec3(0.0f, 0.0f, -1.0f), 1.0f, 1);
    EXPECT_FALSE(b.valid);
    EXPECT_EQ(b.fetches, 0) << "axis " << axis;
    // On the edge itself the sample is read (inside: z = -4), and the march ends there, one step long.
    o[axis] = 4.0f;
    EXPECT_EQ(slab.bracket(o, glm::vec3(0.0f, 0.0f, -1.0f), 1.0f, 1).fetches, 2) << "axis " << axis;
  }
}

// The origin off screen past the right (top) edge, the first sample back on screen and behind the back
// face (z = -6.1): the halving's samples at t_1 / 2 (uv 1.031) and t_1 / 4 (uv 1.078) are off screen,
// so the halving ends at the first without reading it: two fetches, no bracket (one step).
TEST(ScreenEdge, HalvingStopsAtTheFirstSampleOffScreen) {
  const Slab slab(32);
  for (int axis = 0; axis < 2; ++axis) {
    glm::vec3 o(0.0f, 0.0f, -5.9f), d(0.0f, 0.0f, -1.0f);
    o[axis] = 1.25f * 5.9f;  // uv 1.125
    d[axis] = -10.0f;
    const float maxDistance = 0.2f * glm::length(d);  // t_1 = 0.2: uv 0.94
    const SnellScreenPoint first = snellSurfaceViewToUv(slab.backS, o + 0.2f * d);
    const SnellScreenPoint half = snellSurfaceViewToUv(slab.backS, o + 0.1f * d);
    ASSERT_LT(first.uv[axis], 1.0f);
    ASSERT_GT(half.uv[axis], 1.0f);
    ASSERT_LT(half.uv[axis], 1.1f);
    const SnellInsideBracket b = slab.bracket(o, d, maxDistance, 1);
    EXPECT_FALSE(b.valid);
    EXPECT_EQ(b.fetches, 2) << "axis " << axis;
  }
}

// The same with the half exactly one float ulp past the edge: straight back along -z from view distance 3,
// the half at distance 4 with x (y) = 4 (1 + 2^-22), the first sample at distance 5 (uv 0.9) beside the
// slab (columns / rows 0..27 covered).
TEST(ScreenEdge, HalvingSampleOneUlpPastTheEdgeIsNotRead) {
  for (int axis = 0; axis < 2; ++axis) {
    const Slab slab(32, [axis](int i, int j) { return (axis == 0 ? i : j) <= 27; });
    glm::vec3 o(0.0f, 0.0f, -3.0f);
    o[axis] = 4.0f * kOnePast;
    const glm::vec3 d(0.0f, 0.0f, -1.0f);
    ASSERT_EQ(snellSurfaceViewToUv(slab.backS, o + 1.0f * d).uv[axis], 1.0f + 0x1p-23f);
    const SnellInsideBracket b = slab.bracket(o, d, 2.0f, 1);
    EXPECT_FALSE(b.valid);
    EXPECT_EQ(b.fetches, 2) << "axis " << axis;
  }
}

// A halving sample exactly one texel (at level 0, 32 texels) from the origin's projection is read: the
// slab covers columns 0..17, the origin (uv.x 0.5, column 16) moves along +x at z = -4 (uv.x = 0.5 + x / 8)
// to t_1 = 0.5 (uv 0.5625, column 18: beside the object, outside), whose half (uv 0.53125, column 17, one
// texel exactly from 0.5) is inside.
TEST(ScreenEdge, HalvingReadsASampleExactlyOneTexelAway) {
  const Slab slab(32, [](int i, int) { return i <= 17; });
  const SnellInsideBracket b = slab.bracket(glm::vec3(0.0f, 0.0f, -4.0f), glm::vec3(1.0f, 0.0f, 0.0f), 0.5f, 1);
  ASSERT_TRUE(b.valid);
  EXPECT_EQ(b.lo, 0.25f);
  EXPECT_EQ(b.hi, 0.5f);
  EXPECT_EQ(b.loUv.x, 0.53125f);
  EXPECT_EQ(b.uv.x, 0.5625f);
  EXPECT_EQ(b.side, 1);  // both layers empty, dir.z = 0: the back
  EXPECT_EQ(b.fetches, 4);
}

// snellPlaneHit on a closed surface whose texels are all empty: a plane hit projecting onto the screen is
// held on its plane (valid, at p, uv = the plane's texel), one projecting past an edge is a miss; both
// after the one read at p's projection.
TEST(ScreenEdge, PlaneHitHoldsPointsOnTheEdgesAndDropsThosePastThem) {
  const Texture2D empty(Image(16, 16, glm::vec4(0.0f)));
  const SnellDepthSurface s = squareSurface(0.0f);
  ASSERT_TRUE(s.closed);
  const glm::vec2 planeUv(0.3f, 0.7f);
  for (float x : {-4.0f, 4.0f})
    for (float y : {-4.0f, 4.0f}) {
      const glm::vec3 p(x, y, -4.0f);  // a corner of the screen: both coordinates on an edge
      const SnellHit h = snellPlaneHit(p, planeUv, empty, s, 5);
      EXPECT_TRUE(h.valid) << x << " " << y;
      EXPECT_EQ(h.position, p);
      EXPECT_EQ(h.uv, planeUv);
      EXPECT_EQ(h.fetches, 6);
    }
  const float past = 4.0f * kOnePast;
  for (const glm::vec3 p : {glm::vec3(past, 0.0f, -4.0f), glm::vec3(-past, 0.0f, -4.0f), glm::vec3(0.0f, past, -4.0f),
                            glm::vec3(0.0f, -past, -4.0f), glm::vec3(4.4f, 0.0f, -4.0f), glm::vec3(0.0f, 4.4f, -4.0f)}) {
    const SnellHit h = snellPlaneHit(p, planeUv, empty, s, 5);
    EXPECT_FALSE(h.valid) << p.x << " " << p.y;
    EXPECT_EQ(h.position, glm::vec3(0.0f));
    EXPECT_EQ(h.uv, glm::vec2(0.0f));
    EXPECT_EQ(h.fetches, 6);
  }
}

// snellInsidePlane along each edge: the bracket of the march above, then the back face's plane (z = -6,
// t = 2) read at the bracket's pixel on the edge and met inside the bracket at a point on the edge: kept,
// twice (2 fetches each).
TEST(ScreenEdge, InsidePlaneKeepsAPlaneHitOnTheEdge) {
  const Slab slab(32);
  const Texture2D normals(Image(32, 32, glm::vec4(0.0f, 0.0f, 1.0f, 1.0f)));
  for (int k = 0; k < 4; ++k) {
    const EdgeRay r = edgeRay(k, 0.0f);
    SCOPED_TRACE(r.name);
    const SnellInsideHit h = snellInsidePlane(r.o, r.d, slab.back, normals, slab.backS, slab.front, normals,
                                              slab.frontS, 4.4f * glm::length(r.d), 8, 2);
    ASSERT_TRUE(h.hit.valid);
    EXPECT_FALSE(h.front);
    EXPECT_NEAR(h.hit.position.z, -6.0f, 1e-4f);
    EXPECT_EQ(h.hit.uv[r.axis], r.edge);
    EXPECT_EQ(h.hit.fetches, 2 * 4 + 2 * 2);
  }
}

// With the most steps there are, the last of them is read too: straight back from view distance 4 to
// 6.002, 512 samples, the last one (t 2.002) behind the back face at distance 6.
TEST(InsideExactBoundary, TheLastOfTheMostStepsIsRead) {
  const Slab slab(32);
  const SnellInsideBracket b =
      slab.bracket(glm::vec3(0.0f, 0.0f, -4.0f), glm::vec3(0.0f, 0.0f, -1.0f), 2.002f, SNELL_LINEAR_MARCH_MAX_STEPS);
  ASSERT_TRUE(b.valid);
  EXPECT_NEAR(b.hi, 2.002f, 1e-5f);
  EXPECT_NEAR(b.lo, 2.002f * 511.0f / 512.0f, 1e-5f);
  EXPECT_EQ(b.fetches, 2 * 512);
}

// A plane met exactly at the bracket's outside sample is kept (lo <= t <= hi): straight back from view
// distance 4, two steps whose second ends exactly on the back layer's depth as its read gives it (the
// differences with 4 are exact in float), the plane there (normal (0, 0, 1)) met at that same t. Both
// planes are kept, 2 reads each, and the hit is on the layer.
TEST(InsideExactBoundary, InsidePlaneKeepsAPlaneMetExactlyAtTheOutsideSample) {
  const Slab slab(32);
  const Texture2D normals(Image(32, 32, glm::vec4(0.0f, 0.0f, 1.0f, 1.0f)));
  const glm::vec3 o(0.1f, 0.1f, -4.0f), d(0.0f, 0.0f, -1.0f);
  const SnellSurfaceSample layer = snellSampleSurface(slab.back, snellSurfaceViewToUv(slab.backS, o).uv, slab.backS);
  ASSERT_TRUE(layer.valid);
  const float maxDistance = -4.0f - layer.viewZ;
  ASSERT_EQ(-4.0f - maxDistance, layer.viewZ);
  const SnellInsideBracket b = slab.bracket(o, d, maxDistance, 2);
  ASSERT_TRUE(b.valid);
  ASSERT_EQ(b.hi, maxDistance);
  const SnellInsideHit h = snellInsidePlane(o, d, slab.back, normals, slab.backS, slab.front, normals, slab.frontS,
                                            maxDistance, 2, 2);
  ASSERT_TRUE(h.hit.valid);
  EXPECT_FALSE(h.front);
  EXPECT_EQ(h.hit.position.z, layer.viewZ);
  EXPECT_EQ(h.hit.fetches, 4 + 2 + 2);
}

// And at the last inside sample (lo): the back face at distance 7 up to column 20, 5 from column 21. From
// view distance 4 along (1, 0, -1), the first of two steps ends at distance 5 exactly as column 21's read
// gives it (in column 19: inside), the second in column 21 behind its face. Column 21's plane is met at
// t = lo exactly: kept. Plane 2, read in column 19 (distance 7), is met past hi: the hit stays at lo.
TEST(InsideExactBoundary, InsidePlaneKeepsAPlaneMetExactlyAtTheInsideSample) {
  const Slab slab(32, [](int, int) { return true; }, [](int i, int) { return i <= 20 ? 7.0 : 5.0; });
  const Texture2D normals(Image(32, 32, glm::vec4(0.0f, 0.0f, 1.0f, 1.0f)));
  const glm::vec3 o(0.1f, 0.1f, -4.0f), d(1.0f, 0.0f, -1.0f);
  const SnellSurfaceSample face = snellSampleSurface(slab.back, glm::vec2(21.5f / 32.0f, 0.5f), slab.backS);
  ASSERT_TRUE(face.valid);
  const float lo = -4.0f - face.viewZ;  // exact: the step that ends on the face
  float maxDistance = 2.0f * lo * glm::length(d);
  for (int k = 0; k < 8 && maxDistance / glm::length(d) / 2.0f != lo; ++k)
    maxDistance = std::nextafter(maxDistance, maxDistance / glm::length(d) / 2.0f < lo ? 10.0f : 0.0f);
  const SnellInsideBracket b = slab.bracket(o, d, maxDistance, 2);
  ASSERT_TRUE(b.valid);
  ASSERT_EQ(b.lo, lo);
  ASSERT_EQ(int(b.loUv.x * 32.0f), 19);
  ASSERT_EQ(int(b.uv.x * 32.0f), 21);
  const SnellInsideHit h = snellInsidePlane(o, d, slab.back, normals, slab.backS, slab.front, normals, slab.frontS,
                                            maxDistance, 2, 2);
  ASSERT_TRUE(h.hit.valid);
  EXPECT_FALSE(h.front);
  EXPECT_EQ(h.hit.position.z, face.viewZ);
  EXPECT_EQ(h.hit.fetches, 4 + 2 + 2);
}

}  // namespace
