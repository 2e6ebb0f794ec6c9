/*
description: a depth surface's projection and reconstruction, with the work a
  perspective projection does not need left out: the strategies project their
  points and rebuild their texels through these two.
use: SnellScreenPoint sp = snellSurfaceViewToUv(surface, pView);
     SnellViewPoint p = snellSurfaceUvZToView(surface, uv, viewZ);
contract:
  - surface.perspective false: exactly snellViewToUv(surface.clipFromView, pView)
    and snellUvZToView(surface.clipFromView, uv, viewZ).
  - surface.perspective true (snellDepthSurface sets it when clipFromView's
    columns are (a,0,0,0) (0,b,0,0) (c,d,e,-1) (0,0,f,0): the right-handed
    perspective of glm::perspective*, glFrustum and snellPerspective, off-centre
    and jittered ones included; any other matrix takes the general path): the
    same operations without the products with those zero entries, which add
    +-0 to a finite term and make a non-finite one NaN, and non-finite terms
    are invalid either way. The valid flags and values are the general path's
    (in C++ with -ffp-contract=off, bit for bit), except the sign of a
    coordinate that is exactly zero (uv never is: it is 0.5 ndc + 0.5) and of
    an exactly zero ndcZ; with +0 zero entries, as glm::perspective and
    snellPerspective write them, the reconstruction is bit-exact. GPU
    compilers may fold the kept zero products; the parity tolerances cover it.
  - the flag is the surface's promise: call snellDepthSurfaceComplete after
    giving clipFromView another shape (it recomputes the flag and
    perspectiveDet, the reconstruction's validated determinant: 0 makes every
    reconstruction invalid).
options:
  SNELL_PERSPECTIVE_ONLY  0 (default): a surface whose perspective flag is
                          false takes the general path above. 1: the general
                          path is not compiled in, and such a surface projects
                          and reconstructs nothing (valid = false: every
                          strategy misses on it); a perspective surface gives
                          exactly what it gives by default. For shaders whose
                          depth buffers all come from perspective cameras:
                          llvmpipe runs the general path beside the
                          perspective one although the flag is uniform
                          (benchmarks/kernels/gpu_kernel_table.sh: single
                          sample 10 %, normal plane (1 it.) 9 % fewer
                          instructions per pixel); C++ and GPU drivers that
                          branch on uniform values gain little.
source: OpenGL 4.5 core spec sec. 13.6 (clip -> NDC); the equations in
  camera/view_to_uv.glsl and camera/uv_z_to_view.glsl.
*/
#ifndef SNELL_INTERSECT_SURFACE_PROJECTION_GLSL
#define SNELL_INTERSECT_SURFACE_PROJECTION_GLSL
#include "../prelude.glsl"
#include "../camera/view_to_uv.glsl"
#include "../camera/uv_z_to_view.glsl"
#include "depth_surface.glsl"
#ifndef SNELL_PERSPECTIVE_ONLY
#  define SNELL_PERSPECTIVE_ONLY 0
#endif

SNELL_FN_INLINE SnellScreenPoint snellSurfaceViewToUv(SNELL_IN(SnellDepthSurface) s, vec3 pView) {
#if !SNELL_PERSPECTIVE_ONLY
  if (!s.perspective) {
    return snellViewToUv(s.clipFromView, pView);
  }
#endif
  vec4 c0 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 0);
  vec4 c1 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 1);
  vec4 c2 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 2);
  vec4 c3 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 3);
  SnellScreenPoint r;
  r.uv = vec2(0.0f, 0.0f);
  r.ndcZ = 0.0f;
  r.valid = false;
#if SNELL_PERSPECTIVE_ONLY
  if (!s.perspective) {
    return r;
  }
#endif
  // A non-finite coordinate makes its own clip term non-finite here, where the
  // general product spreads it as NaN through a zero entry: invalid either way.
  float cx = c0.x * pView.x + c2.x * pView.z;
  float cy = c1.y * pView.y + c2.y * pView.z;
  float cz = c2.z * pView.z + c3.z;
  float cw = -pView.z;
  // cw's upper bound is implied by cx (c2.x times an infinite z is never
  // finite) unless a compiler folds a constant zero c2.x: tested outright.
  if (!SNELL_FINITE(cx) || !SNELL_FINITE(cy) || !(cw >= SNELL_FLT_MIN && cw <= SNELL_FLT_MAX)) {
    return r;
  }
  // Per component (the same operations as a vec3 clamp; C++ inlines them).
  float ndcX = clamp(cx / cw, -SNELL_FLT_MAX, SNELL_FLT_MAX);
  float ndcY = clamp(cy / cw, -SNELL_FLT_MAX, SNELL_FLT_MAX);
  float ndcZ = cz / cw;
  r.uv = vec2(ndcX, ndcY) * 0.5f + 0.5f;
  r.ndcZ = isnan(ndcZ) ? 0.0f : clamp(ndcZ, -SNELL_FLT_MAX, SNELL_FLT_MAX);
  r.valid = true;
  return r;
}

SNELL_FN_INLINE SnellViewPoint snellSurfaceUvZToView(SNELL_IN(SnellDepthSurface) s, vec2 uv, float viewZ) {
#if !SNELL_PERSPECTIVE_ONLY
  if (!s.perspective) {
    return snellUvZToView(s.clipFromView, uv, viewZ);
  }
#endif
  SnellViewPoint r;
  r.position = vec3(0.0f, 0.0f, 0.0f);
  r.valid = false;
#if SNELL_PERSPECTIVE_ONLY
  if (!s.perspective) {
    return r;
  }
#endif
  // A non-finite uv makes nx or ny non-finite: tested below.
  if (!SNELL_FINITE(viewZ) || !(viewZ <= -SNELL_FLT_MIN)) {
    return r;
  }
  vec4 c0 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 0);
  vec4 c1 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 1);
  vec4 c2 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 2);
  float nx = 2.0f * uv.x - 1.0f;
  float ny = 2.0f * uv.y - 1.0f;
  // 2 uv - 1 overflows for a huge uv; the general path then ends invalid
  // (its a01 = c1.x - n c1.w is NaN), and so does this test, early.
  if (!SNELL_FINITE(nx) || !SNELL_FINITE(ny)) {
    return r;
  }
  // c2.x - n c2.w with c2.w = -1 is c2.x + n; c3.x - n c3.w is a zero (+0 when
  // c3.x and c3.w are +0), added as +0.
  float b0 = -(viewZ * (c2.x + nx) + 0.0f);
  float b1 = -(viewZ * (c2.y + ny) + 0.0f);
  // The zero coefficients a01, a10 stay as products with +0: they decide the
  // sign of an exactly zero result as in the general path. perspectiveDet is
  // c0.x c1.y validated once, 0 when unusable.
  if (s.perspectiveDet == 0.0f) {
    return r;
  }
  float x = (b0 * c1.y - 0.0f * b1) / s.perspectiveDet;
  float y = (c0.x * b1 - b0 * 0.0f) / s.perspectiveDet;
  if (!SNELL_FINITE(x) || !SNELL_FINITE(y)) {
    return r;
  }
  r.position = vec3(x, y, viewZ);
  r.valid = true;
  return r;
}

#endif
