/*
description: symmetric perspective projection matrices (clipFromView) for each
  depth convention, and their exact analytic inverses (viewFromClip), built the
  same way in every language (so parity cases and users need only 4 scalars).
use: mat4 clipFromView = snellPerspective(fovy, aspect, zNear, zFar);   // = glm::perspective
     mat4 clipFromView = snellPerspectiveWithDepth(fovy, aspect, zNear, zFar, SNELL_DEPTH_REVERSED);
     mat4 viewFromClip = snellPerspectiveInverse(fovy, aspect, zNear, zFar, SNELL_DEPTH_REVERSED);
  fovy          full vertical field of view in radians, in (0, pi)
  aspect        viewport width / height (> 0)
  zNear, zFar   clip-plane distances (0 < zNear < zFar); zFar ignored by INFINITE_*
contract: with A = 1 / (aspect tan(fovy/2)), B = 1 / tan(fovy/2), the matrix maps
  (x, y, z, 1) to (A x, B y, C z + D, -z), so clip w = -z = view distance, and
    GL                 C = -(f + n)/(f - n)   D = -2 f n/(f - n)   (glm::perspective)
    ZERO_ONE           C = f/(n - f)          D = -f n/(f - n)     (glm::perspectiveZO)
    REVERSED           C = n/(f - n)          D = f n/(f - n)      (ZERO_ONE, near/far swapped)
    INFINITE_GL        C = -1                 D = -2 n             (glm::infinitePerspective)
    INFINITE_REVERSED  C = 0                  D = n
  The window depth each one produces is the one of linearize_depth.glsl.
  The inverse maps (xc, yc, zc, wc) to (xc/A, yc/B, -wc, (zc + C wc)/D) exactly
  (no general 4x4 inversion; HLSL has none).
  tan(fovy/2) is snell's own polynomial (Cephes tanf), within 1.7e-7 relative of
  tan on (0, pi/2) and the same on every runtime: glm::perspective's entries A
  and B are matched within 3 ulp, the others bit for bit.
  All three return the zero matrix (every projected point then has w = 0, so
  snellClipToNdc and friends report valid = false) when fovy is not in (0, pi),
  tan(fovy/2) is not finite positive, aspect or zNear are not finite positive,
  zFar is not finite or not > zNear (finite conventions), the convention is
  unknown, or an entry of the matrix returned (for the inverse, of the
  inverse), tan(fovy/2) or aspect tan(fovy/2) would overflow or be denormal (a
  GPU may flush it to 0); a denormal fovy or aspect counts as 0.
  GL is the convention of the paper's equations (Oliveira & Brauwers 2007, sec.
  3.2.1: "the projection matrix used by OpenGL", clip w = -z).
source: GLM 0.9.9 ext/matrix_clip_space.inl (perspectiveRH_NO, perspectiveRH_ZO,
  infinitePerspectiveRH_NO); OpenGL gluPerspective.
*/
#ifndef SNELL_CAMERA_PERSPECTIVE_GLSL
#define SNELL_CAMERA_PERSPECTIVE_GLSL
#include "../prelude.glsl"
#include "conventions.glsl"

SNELL_FN mat4 snellPerspectiveWithDepth(float fovy, float aspect, float zNear, float zFar, int convention) {
  vec4 zero4 = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  mat4 zero = SNELL_CAMERA_MAT4_COLUMNS(zero4, zero4, zero4, zero4);
  bool infinite = convention == SNELL_DEPTH_INFINITE_GL || convention == SNELL_DEPTH_INFINITE_REVERSED;
  if (convention < 0 || convention >= SNELL_DEPTH_CONVENTION_COUNT || !SNELL_FINITE(fovy) ||
      !(fovy >= SNELL_FLT_MIN) || !(fovy < SNELL_PI) || !SNELL_FINITE(aspect) || !(aspect >= SNELL_FLT_MIN) ||
      !SNELL_FINITE(zNear) || !(zNear >= SNELL_FLT_MIN)) {
    return zero;
  }
  if (!infinite && (!SNELL_FINITE(zFar) || !(zFar > zNear))) {
    return zero;
  }
  // tan(fovy / 2) by snell's own polynomial, not tan(): GLSL leaves tan's precision to the
  // implementation, and WebGL 2 on SwiftShader is 6e-5 off, more than a projection can afford.
  // Cephes' tanf (S. L. Moshier): the polynomial on [0, pi/4] and tan x = 1 / tan(pi/2 - x)
  // above it, pi/2 in two parts so that pi/2 - x keeps its digits near pi/2.
  float halfFovy = fovy / 2.0f;
  bool upper = halfFovy > 0.78539818525f;  // float(pi/2) / 2: float(pi/2) - x is exact above it
  float r = halfFovy;
  if (upper) {
    r = (1.57079637050628662f - halfFovy) - 4.37113900018624283e-8f;
  }
  float r2 = r * r;
  float tanR = ((((((9.38540185543e-3f * r2 + 3.11992232697e-3f) * r2 + 2.44301354525e-2f) * r2 +
                   5.34112807005e-2f) * r2 + 1.33387994085e-1f) * r2 + 3.33331568548e-1f) * r2) * r + r;
  float tanHalfFovy = upper ? 1.0f / tanR : tanR;
  // A denormal tan(fovy/2) (fovy near FLT_MIN, halved) or aspect tan(fovy/2) is 0 on a GPU that flushes
  // denormals: the zero matrix there, so here too.
  if (!SNELL_FINITE(tanHalfFovy) || !(tanHalfFovy >= SNELL_FLT_MIN) || !(aspect * tanHalfFovy >= SNELL_FLT_MIN)) {
    return zero;
  }
  // Same operation order as glm::perspective: the GL matrix matches it within tan's error.
  float a = 1.0f / (aspect * tanHalfFovy);
  float b = 1.0f / tanHalfFovy;
  float c = 0.0f;
  float d = 0.0f;
  if (convention == SNELL_DEPTH_GL) {
    c = -(zFar + zNear) / (zFar - zNear);
    d = -(2.0f * zFar * zNear) / (zFar - zNear);
  } else if (convention == SNELL_DEPTH_ZERO_ONE) {
    c = zFar / (zNear - zFar);
    d = -(zFar * zNear) / (zFar - zNear);
  } else if (convention == SNELL_DEPTH_REVERSED) {
    c = zNear / (zFar - zNear);
    d = (zFar * zNear) / (zFar - zNear);
  } else if (convention == SNELL_DEPTH_INFINITE_GL) {
    c = -1.0f;
    d = -2.0f * zNear;
  } else {
    c = 0.0f;
    d = zNear;
  }
  // C is 0 exactly for INFINITE_REVERSED; REVERSED's n / (f - n) is denormal for a far plane past 1e38 n.
  if (!SNELL_FINITE(a) || !SNELL_FINITE(b) || !SNELL_FINITE(c) ||
      !SNELL_FINITE(d) || !(a >= SNELL_FLT_MIN) || !(b >= SNELL_FLT_MIN) ||
      !(abs(d) >= SNELL_FLT_MIN) || (c != 0.0f && !(abs(c) >= SNELL_FLT_MIN))) {
    return zero;
  }
  return SNELL_CAMERA_MAT4_COLUMNS(vec4(a, 0.0f, 0.0f, 0.0f), vec4(0.0f, b, 0.0f, 0.0f),
                                   vec4(0.0f, 0.0f, c, -1.0f), vec4(0.0f, 0.0f, d, 0.0f));
}

SNELL_FN mat4 snellPerspective(float fovy, float aspect, float zNear, float zFar) {
  return snellPerspectiveWithDepth(fovy, aspect, zNear, zFar, SNELL_DEPTH_GL);
}

SNELL_FN mat4 snellPerspectiveInverse(float fovy, float aspect, float zNear, float zFar, int convention) {
  mat4 m = snellPerspectiveWithDepth(fovy, aspect, zNear, zFar, convention);
  // Entries read through SNELL_MUL (m[i] is a column in GLSL but a row in HLSL).
  float a = SNELL_MUL(m, vec4(1.0f, 0.0f, 0.0f, 0.0f)).x;
  float b = SNELL_MUL(m, vec4(0.0f, 1.0f, 0.0f, 0.0f)).y;
  float c = SNELL_MUL(m, vec4(0.0f, 0.0f, 1.0f, 0.0f)).z;
  float d = SNELL_MUL(m, vec4(0.0f, 0.0f, 0.0f, 1.0f)).z;
  vec4 zero4 = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  if (a == 0.0f) {
    return SNELL_CAMERA_MAT4_COLUMNS(zero4, zero4, zero4, zero4);
  }
  float ia = 1.0f / a;
  float ib = 1.0f / b;
  float id = 1.0f / d;
  float cd = c / d;
  // The inverse's own entries may be denormal where the matrix's are not (A near FLT_MAX): zero there, as
  // the contract says for every entry; C / D is 0 exactly for INFINITE_REVERSED.
  if (!SNELL_FINITE(ia) || !SNELL_FINITE(ib) || !SNELL_FINITE(id) || !SNELL_FINITE(cd) ||
      !(ia >= SNELL_FLT_MIN) || !(ib >= SNELL_FLT_MIN) || !(abs(id) >= SNELL_FLT_MIN) ||
      (cd != 0.0f && !(abs(cd) >= SNELL_FLT_MIN))) {
    return SNELL_CAMERA_MAT4_COLUMNS(zero4, zero4, zero4, zero4);
  }
  return SNELL_CAMERA_MAT4_COLUMNS(vec4(ia, 0.0f, 0.0f, 0.0f), vec4(0.0f, ib, 0.0f, 0.0f),
                                   vec4(0.0f, 0.0f, 0.0f, id), vec4(0.0f, 0.0f, -1.0f, cd));
}

#endif
