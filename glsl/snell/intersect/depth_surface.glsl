/*
description: how a depth texture describes a surface (the refractive object's
  back faces, or the opaque scene), and the one way every strategy reads it.
use: SnellDepthSurface s = snellDepthSurface(clipFromView, zNear, zFar, SNELL_DEPTH_GL, 0.0f);
     SnellSurfaceSample x = snellSampleSurface(depthTex, uv, s);   // x.viewZ < 0 when x.valid
     s = snellDepthSurfaceComplete(s);   // after filling or changing clipFromView, zNear, zFar, convention
     float v = snellSurfaceLinearDepth(s, depthValue);   // snellLinearizeDepth with s's validated terms
  The surface is per draw: build it once per invocation and pass it to every
  strategy; the per-step code reads its derived fields. In a shader, build it
  from the camera uniforms with the convention, and any lod, depthFilter and
  closed assignments, as constants: the compiler then folds the branches on
  them (on llvmpipe a single sample costs 271 instructions per pixel so, 436
  with the whole surface read from a uniform: benchmarks/kernels).
  clipFromView  the projection the depth texture was rendered with
  zNear, zFar   its clip distances; convention: SNELL_DEPTH_* (camera/conventions.glsl)
  emptyDepth    the texel value meaning "no surface here": the clear value (0.0f for
                back faces drawn with glDepthFunc(GL_GREATER) after clearing to 0,
                1.0f for a scene drawn with GL_LESS after clearing to 1)
  lod           the mip level the searches read (0 = full resolution); set the field
  depthFilter   how a depth is read (set the field; snellIntersectWith sets it from
                SnellIntersectOptions.depthFilter):
                SNELL_DEPTH_FILTER_NEAREST  0 (default) the texel containing uv
                SNELL_DEPTH_FILTER_BILINEAR 1 the window depth interpolated
                  bilinearly between the four texel centres around uv, where
                  all four hold a surface, else the nearest texel. Window depth
                  is affine in screen space over a plane (it is a + b / z), so
                  planes are read exactly between texel centres; at the
                  silhouette no surface is blended with an empty texel. Across a
                  depth discontinuity inside the buffer it still invents a
                  one-texel ramp (Oliveira & Brauwers 2007 sec. 3.1), which is
                  why it is not the default.
  closed        true (default): an empty texel beside the surface hides more of
                it (a closed object's back faces curve away behind the
                silhouette: the plane methods keep their last plane there,
                SNELL_PLANE_HOLD); false: empty texels are open space (the
                opaque scene: the environment shows there), set the field
  derived fields  validated and precomputed once from clipFromView, zNear, zFar and
                convention by snellDepthSurface, or by snellDepthSurfaceComplete for
                a surface filled in field by field or changed afterwards; the
                per-step reads trust them instead of re-checking the source
                fields on every read:
    perspective    true when clipFromView has the shape of a perspective
                   (columns (a,0,0,0) (0,b,0,0) (c,d,e,-1) (0,0,f,0): symmetric,
                   off-centre and jittered frusta). The strategies then project
                   and reconstruct without the products with the zero entries
                   (intersect/surface_projection.glsl: the same results up to
                   the sign of an exact zero)
    perspectiveDet a * b when perspective and that product is finite with
                   |a b| >= SNELL_FLT_MIN (the reconstruction's determinant), else 0
                   (then every reconstruction is invalid, without dividing by it)
    linearizable   zNear, zFar and convention linearize a depth (the conditions
                   of snellLinearizeDepth's contract), nearOverFar zNear / zFar (0
                   for the infinite conventions), depthReversed (REVERSED,
                   INFINITE_REVERSED), depthFarBelow (SNELL_FLT_MIN for
                   INFINITE_REVERSED: a smaller depth is the far plane; else 0),
                   depthFarLimit (zFar; SNELL_FLT_MAX for the infinite
                   conventions): snellSurfaceLinearDepth's terms
contract (snellDepthSurfaceComplete):
  - returns s with every derived field computed from its clipFromView, zNear,
    zFar and convention (snellDepthSurface's result for them); lod,
    depthFilter, closed and emptyDepth are kept. snellDepthSurface calls it.
  - an invalid depth range or convention gives a surface on which every depth
    read is invalid (linearizable false): every strategy misses, with finite
    outputs. A perspective-shaped clipFromView whose a b is not finite or
    below SNELL_FLT_MIN gives perspectiveDet 0: every reconstruction is
    invalid. (Any other matrix goes through the general path, which tests its
    own terms.)
  - a surface whose derived fields disagree with its source fields (filled in
    by hand, or changed without this call) is read through a mix of both (the
    derived terms, zNear for the clamp, clipFromView for the projection): its
    results are finite (never NaN or +-Inf) and flagged, and nothing more is
    promised (a hand-set denormal term may be flushed to 0 on a GPU and not
    in C++). Any field may be hostile (NaN, +-Inf, zero or negative ranges, a
    perspective flag on a general matrix): never a NaN output, never a crash.
    In C++ start such a surface value-initialized (SnellDepthSurface s{};):
    an uninitialized bool is undefined behaviour before any of this.
contract (snellSurfaceLinearDepth):
  - for a complete surface, exactly snellLinearizeDepth(depthValue, s.zNear,
    s.zFar, s.convention) (bit for bit: the same operations, with the
    conventions' branches folded into selects and zNear / zFar precomputed);
    0.0f when s.linearizable is false or depthValue is NaN.
  - for an inconsistent surface: 0.0f or a finite value > 0 (never NaN or
    +-Inf; no clamp with reversed or NaN bounds, whose result GLSL leaves
    undefined).
contract (snellSampleSurface):
  - NEAREST: reads the texel containing uv (no filtering: filtering depth
    invents surfaces between foreground and background, Oliveira & Brauwers
    2007 sec. 3.1) at level lod through SNELL_TEXEL_FETCH (SNELL_TEXEL_FETCH_IN_LEVEL:
    the same hook in GLSL and HLSL; in C++ without fetch's range tests), red channel, and
    costs one fetch. BILINEAR: the four texels (clamped to the edge) through
    SNELL_TEXEL_FETCH, counted as one fetch (one textureGather in a shader that
    has it); valid as NEAREST is (the texel containing uv decides);
    interpolated = true when the four were blended (false for NEAREST, at the
    silhouette and whenever valid is false);
  - valid = false (viewZ = 0) when uv lies outside [0,1]^2 (off screen: no
    information, never clamped to the edge), when uv is NaN, when the texel equals
    emptyDepth, or when the depth does not linearize (NaN, bad zNear/zFar);
  - otherwise viewZ = -snellSurfaceLinearDepth(s, texel) < 0 (finite for a
    complete surface).
source: Oliveira & Brauwers 2007 sec. 3.1 and Algorithm 2 ("invalid texels have
  depth = 0"); depth conventions in camera/linearize_depth.glsl.
*/
#ifndef SNELL_INTERSECT_DEPTH_SURFACE_GLSL
#define SNELL_INTERSECT_DEPTH_SURFACE_GLSL
#include "../prelude.glsl"
#include "../camera/linearize_depth.glsl"
#include "../camera/pixel_to_uv.glsl"
#include "../camera/conventions.glsl"

#define SNELL_DEPTH_FILTER_NEAREST 0
#define SNELL_DEPTH_FILTER_BILINEAR 1

struct SnellDepthSurface {
  mat4 clipFromView;
  float zNear;
  float zFar;
  int convention;
  float emptyDepth;
  int lod;
  int depthFilter;
  bool closed;
  // Derived (snellDepthSurfaceComplete):
  bool perspective;
  float perspectiveDet;
  bool linearizable;
  bool depthReversed;
  float nearOverFar;
  float depthFarBelow;
  float depthFarLimit;
};

struct SnellSurfaceSample {
  float viewZ;
  bool valid;
  bool interpolated;  // BILINEAR and all four texels held a surface: viewZ is the depth at uv itself
};

SNELL_FN SnellDepthSurface snellDepthSurfaceComplete(SnellDepthSurface s) {
  vec4 c0 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 0);
  vec4 c1 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 1);
  vec4 c2 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 2);
  vec4 c3 = SNELL_CAMERA_MAT_COLUMN(s.clipFromView, 3);
  s.perspective = c0.y == 0.0f && c0.z == 0.0f && c0.w == 0.0f && c1.x == 0.0f && c1.z == 0.0f &&
                  c1.w == 0.0f && c2.w == -1.0f && c3.x == 0.0f && c3.y == 0.0f && c3.w == 0.0f;
  float det = c0.x * c1.y;
  s.perspectiveDet = s.perspective && SNELL_FINITE(det) && abs(det) >= SNELL_FLT_MIN ? det : 0.0f;
  bool infinite = s.convention == SNELL_DEPTH_INFINITE_GL || s.convention == SNELL_DEPTH_INFINITE_REVERSED;
  s.linearizable = s.convention >= 0 && s.convention < SNELL_DEPTH_CONVENTION_COUNT && SNELL_FINITE(s.zNear) &&
                   s.zNear >= SNELL_FLT_MIN && (infinite || (SNELL_FINITE(s.zFar) && s.zFar > s.zNear));
  s.depthReversed = s.convention == SNELL_DEPTH_REVERSED || s.convention == SNELL_DEPTH_INFINITE_REVERSED;
  // Only read when linearizable: zFar is then finite and > zNear, or unused.
  s.nearOverFar = s.linearizable && !infinite ? s.zNear / s.zFar : 0.0f;
  s.depthFarBelow = s.convention == SNELL_DEPTH_INFINITE_REVERSED ? SNELL_FLT_MIN : 0.0f;
  s.depthFarLimit = infinite ? SNELL_FLT_MAX : (s.linearizable ? s.zFar : 0.0f);
  return s;
}

SNELL_FN SnellDepthSurface snellDepthSurface(mat4 clipFromView, float zNear, float zFar, int convention,
                                             float emptyDepth) {
  SnellDepthSurface s;
  s.clipFromView = clipFromView;
  s.zNear = zNear;
  s.zFar = zFar;
  s.convention = convention;
  s.emptyDepth = emptyDepth;
  s.lod = 0;
  s.depthFilter = SNELL_DEPTH_FILTER_NEAREST;
  s.closed = true;
  return snellDepthSurfaceComplete(s);
}

/* One division and the clamp of snellLinearizeDepth, the conventions as
   selects: GL and ZERO_ONE n / ((1 - d) + d (n / f)), REVERSED n / (d + (1 - d)
   (n / f)); the infinite ones add d 0 or (1 - d) 0 = +0 to the same first term
   (exact), and their far plane (d = 1 INFINITE_GL, d < SNELL_FLT_MIN
   INFINITE_REVERSED) has a zero denominator: SNELL_FLT_MAX, as the reference
   returns it. Equations in camera/linearize_depth.glsl. */
SNELL_FN_INLINE float snellSurfaceLinearDepth(SNELL_IN(SnellDepthSurface) s, float depthValue) {
  if (!s.linearizable || isnan(depthValue)) {
    return 0.0f;
  }
  float d = clamp(depthValue, 0.0f, 1.0f);
  float e = 1.0f - d;
  float a = s.depthReversed ? d : e;
  float b = s.depthReversed ? e : d;
  if (d < s.depthFarBelow) {
    a = 0.0f;
  }
  // den > 0 for a complete surface but at the infinite conventions' far plane
  // (and where n / f underflows), whose distance is the clamp's top:
  // SNELL_FLT_MAX there, as the reference returns it, without dividing by 0.
  float den = a + b * s.nearOverFar;
  float v = den > 0.0f ? s.zNear / den : SNELL_FLT_MAX;
  // A NaN (only from inconsistent terms) stops here: GPU compilers turn the
  // selects below into fmax / fmin, which would drop it.
  if (!(v > 0.0f)) {
    return 0.0f;
  }
  // clamp(v, zNear, depthFarLimit) as two selects: for a complete surface the
  // same value (zNear <= depthFarLimit); for an inconsistent one (reversed or
  // NaN bounds, where clamp is undefined) defined, and the last test keeps
  // only a finite result > 0.
  v = v < s.zNear ? s.zNear : v;
  v = v > s.depthFarLimit ? s.depthFarLimit : v;
  return v > 0.0f && v <= SNELL_FLT_MAX ? v : 0.0f;
}

/* SNELL_FN_INLINE: C++ inlines this read into every strategy and loop (by
   value, g++ inlined it only in some and left a copy of the surface per call
   elsewhere; by reference and always inlined it is cheaper in all,
   benchmarks/kernels). */
SNELL_FN_INLINE SnellSurfaceSample snellSampleSurface(SNELL_TEX2D depthTex, vec2 uv, SNELL_IN(SnellDepthSurface) s) {
  SnellSurfaceSample r;
  r.viewZ = 0.0f;
  r.valid = false;
  r.interpolated = false;
  // Written so NaN fails: every comparison with NaN is false.
  if (!(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f)) {
    return r;
  }
  ivec2 size = SNELL_TEXTURE_SIZE(depthTex, s.lod);
  if (size.x <= 0 || size.y <= 0) {
    return r;
  }
  // size > 0 (C++: s.lod is one of the texture's levels) and uv in [0,1]^2:
  // the texel is inside the level (SNELL_TEXEL_FETCH_IN_LEVEL's precondition).
  float d = SNELL_TEXEL_FETCH_IN_LEVEL(depthTex, SNELL_PIXEL_ON_SCREEN(uv, size), s.lod).x;
  if (d == s.emptyDepth) {
    return r;
  }
  if (s.depthFilter == SNELL_DEPTH_FILTER_BILINEAR) {
    // Texel-centre coordinates: texel i's centre sits at i + 0.5.
    SNELL_PRECISE float tx = uv.x * float(size.x) - 0.5f;
    SNELL_PRECISE float ty = uv.y * float(size.y) - 0.5f;
    float fx = floor(tx);
    float fy = floor(ty);
    int x0 = clamp(int(fx), 0, size.x - 1);
    int y0 = clamp(int(fy), 0, size.y - 1);
    int x1 = clamp(int(fx) + 1, 0, size.x - 1);
    int y1 = clamp(int(fy) + 1, 0, size.y - 1);
    float d00 = SNELL_TEXEL_FETCH(depthTex, ivec2(x0, y0), s.lod).x;
    float d10 = SNELL_TEXEL_FETCH(depthTex, ivec2(x1, y0), s.lod).x;
    float d01 = SNELL_TEXEL_FETCH(depthTex, ivec2(x0, y1), s.lod).x;
    float d11 = SNELL_TEXEL_FETCH(depthTex, ivec2(x1, y1), s.lod).x;
    if (d00 != s.emptyDepth && d10 != s.emptyDepth && d01 != s.emptyDepth && d11 != s.emptyDepth) {
      float wx = tx - fx;
      float wy = ty - fy;
      SNELL_PRECISE float d0 = d00 + wx * (d10 - d00);
      SNELL_PRECISE float d1 = d01 + wx * (d11 - d01);
      SNELL_PRECISE float dm = d0 + wy * (d1 - d0);
      d = dm;
      r.interpolated = true;
    }
  }
  float v = snellSurfaceLinearDepth(s, d);
  if (!(v > 0.0f)) {
    r.interpolated = false;
    return r;
  }
  r.viewZ = -v;
  r.valid = true;
  return r;
}

#endif
