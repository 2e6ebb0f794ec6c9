/*
description: how a depth texture describes a surface (the refractive object's
  back faces, or the opaque scene), and the one way every strategy reads it.
use: SnellDepthSurface s = snellDepthSurface(clipFromView, zNear, zFar, SNELL_DEPTH_GL, 0.0f);
     SnellSurfaceSample x = snellSampleSurface(depthTex, uv, s);   // x.viewZ < 0 when x.valid
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
  perspective   set by snellDepthSurface: true when clipFromView has the shape of a
                perspective (columns (a,0,0,0) (0,b,0,0) (c,d,e,-1) (0,0,f,0):
                symmetric, off-centre and jittered frusta). The strategies then
                project and reconstruct without the products with the zero
                entries (intersect/surface_projection.glsl: the same results up
                to the sign of an exact zero); a surface filled in field by
                field must set it (false is always correct), as must code
                that gives clipFromView another shape afterwards
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
  - otherwise viewZ = -snellLinearizeDepth(texel) < 0, finite.
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
  bool perspective;
};

struct SnellSurfaceSample {
  float viewZ;
  bool valid;
  bool interpolated;  // BILINEAR and all four texels held a surface: viewZ is the depth at uv itself
};

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
  vec4 c0 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 0);
  vec4 c1 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 1);
  vec4 c2 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 2);
  vec4 c3 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 3);
  s.perspective = c0.y == 0.0f && c0.z == 0.0f && c0.w == 0.0f && c1.x == 0.0f && c1.z == 0.0f &&
                  c1.w == 0.0f && c2.w == -1.0f && c3.x == 0.0f && c3.y == 0.0f && c3.w == 0.0f;
  return s;
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
  float v = snellLinearizeDepth(d, s.zNear, s.zFar, s.convention);
  if (!(v > 0.0f)) {
    r.interpolated = false;
    return r;
  }
  r.viewZ = -v;
  r.valid = true;
  return r;
}

#endif
