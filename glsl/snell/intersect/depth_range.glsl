/*
description: the depth range [zNearest, zFarthest] the texture-space searches
  (conservative binary search, binary, linear+binary) walk, from the two
  sources Oliveira & Brauwers name: the top level of the depth min/max pyramid
  (their 2nd pass, exact for the buffer) or the object's bounding box (their
  suggested speed-up: no reduction pass, a looser range). Plus the top mip
  level of a texture, which the range and the depth-based plane need.
use: SnellDepthRange r = snellDepthRangeFromPyramid(pyramidTex);
     SnellDepthRange r = snellDepthRangeFromBox(viewFromObject, boxMin, boxMax);
     int top = snellTextureTopLod(tex);
  pyramidTex      a depth min/max pyramid (intersect/depth_pyramid.glsl layout:
                  y nearest, z farthest view distance, w coverage), all levels
  viewFromObject  object-to-view transform (camera at the origin looking down -Z)
  boxMin, boxMax  the object-space axis-aligned bounding box
options:
  SNELL_DEPTH_RANGE_MARGIN  relative widening of the pyramid range (1e-3f):
                            zNearest * (1 - m), zFarthest * (1 + m), so a
                            fronto-parallel surface (Zmin == Zmax, which the
                            searches reject) still gets a range and the
                            surface lies strictly inside it
contract:
  - snellTextureTopLod: floor(log2(max(width, height))) of level 0 (the last
    level of a full GL mip chain); 0 for a 1x1 or size-0 texture.
  - snellDepthRangeFromPyramid: one SNELL_TEXEL_FETCH of texel (0, 0) at the
    top level; valid when its coverage w > 0 and 0 < y <= z are finite;
    zNearest = -y (1 - margin), zFarthest = -z (1 + margin). Invalid (all 0)
    for an empty buffer.
  - snellDepthRangeFromBox: the 8 corners transformed by viewFromObject
    (w = 1 assumed: an affine transform); zNearest = the largest corner z,
    zFarthest = the smallest, no fetch. Valid when every corner z is finite
    and zFarthest < 0; a box reaching to or behind the camera plane gets
    zNearest = -FLT_MIN (the searches then start at the ray origin). A flat box
    facing the camera (zNearest == zFarthest) is widened by
    SNELL_DEPTH_RANGE_MARGIN as for the pyramid. Invalid: all 0.
source: M. M. Oliveira, M. Brauwers, "Real-Time Refraction Through Deformable
  Objects", I3D 2007, sec. 3 (2nd pass: min/max reduction) and sec. 6
  ("using the limits of the object's bounding box as Zmin and Zmax").
*/
#ifndef SNELL_INTERSECT_DEPTH_RANGE_GLSL
#define SNELL_INTERSECT_DEPTH_RANGE_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"

#ifndef SNELL_DEPTH_RANGE_MARGIN
#  define SNELL_DEPTH_RANGE_MARGIN 1e-3f
#endif

struct SnellDepthRange {
  float zNearest;
  float zFarthest;
  bool valid;
};

SNELL_FN SnellDepthRange snellDepthRangeInvalid() {
  SnellDepthRange r;
  r.zNearest = 0.0f;
  r.zFarthest = 0.0f;
  r.valid = false;
  return r;
}

SNELL_FN int snellTextureTopLod(SNELL_TEX2D tex) {
  ivec2 size = SNELL_TEXTURE_SIZE(tex, 0);
  int m = max(size.x, size.y);
  int lod = 0;
  for (int i = 0; i < 31; ++i) {
    if (m <= 1) {
      break;
    }
    m = m / 2;
    lod = lod + 1;
  }
  return lod;
}

/* Oliveira & Brauwers 2007, sec. 3, 2nd pass: the top level of the min/max reduction */
SNELL_FN SnellDepthRange snellDepthRangeFromPyramid(SNELL_TEX2D pyramidTex) {
  int top = snellTextureTopLod(pyramidTex);
  vec4 t = SNELL_TEXEL_FETCH(pyramidTex, ivec2(0, 0), top);
  if (!(t.w > 0.0f) || !(t.y > 0.0f) || !(t.z >= t.y) || !SNELL_FINITE(t.z)) {
    return snellDepthRangeInvalid();
  }
  SnellDepthRange r;
  r.zNearest = -t.y * (1.0f - SNELL_DEPTH_RANGE_MARGIN);
  r.zFarthest = -t.z * (1.0f + SNELL_DEPTH_RANGE_MARGIN);
  r.valid = true;
  return r;
}

/* Oliveira & Brauwers 2007, sec. 6: the bounding box as Zmin, Zmax */
SNELL_FN SnellDepthRange snellDepthRangeFromBox(mat4 viewFromObject, vec3 boxMin, vec3 boxMax) {
  float zNearest = -SNELL_FLT_MAX;
  float zFarthest = SNELL_FLT_MAX;
  for (int i = 0; i < 8; ++i) {
    float x = (i == 1 || i == 3 || i == 5 || i == 7) ? boxMax.x : boxMin.x;
    float y = (i == 2 || i == 3 || i == 6 || i == 7) ? boxMax.y : boxMin.y;
    float z = i >= 4 ? boxMax.z : boxMin.z;
    vec4 p = SNELL_MUL(viewFromObject, vec4(x, y, z, 1.0f));
    if (!SNELL_FINITE(p.z)) {
      return snellDepthRangeInvalid();
    }
    zNearest = max(zNearest, p.z);
    zFarthest = min(zFarthest, p.z);
  }
  if (!(zFarthest < 0.0f)) {
    return snellDepthRangeInvalid();
  }
  SnellDepthRange r;
  r.zNearest = min(zNearest, -SNELL_FLT_MIN);
  r.zFarthest = zFarthest;
  if (!(r.zFarthest < r.zNearest)) {
    r.zNearest = r.zNearest * (1.0f - SNELL_DEPTH_RANGE_MARGIN);
    r.zFarthest = r.zFarthest * (1.0f + SNELL_DEPTH_RANGE_MARGIN);
  }
  r.valid = true;
  return r;
}

#endif
