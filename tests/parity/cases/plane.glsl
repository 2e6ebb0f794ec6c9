/* Parity cases for the intersect/ functions of the plane family: hit.glsl,
   depth_surface.glsl, surface_point.glsl, single_sample.glsl, plane_refine.glsl,
   plane_far_start.glsl, plane_normal.glsl, plane_depth.glsl, depth_pyramid.glsl.
   Two analytic scenes (tests/support/depth_scenes.hpp) as textures:
     A = sphereBack 160x120, SNELL_DEPTH_GL, emptyDepth 0 (a back-face buffer)
     B = silhouette 160x120, SNELL_DEPTH_REVERSED, emptyDepth 0 (an opaque buffer
         with many empty texels)
   Ray cases: a = (origin, scene 0/1), b = (dir, iterations), c = the projection's
   four entries (A, B, C, D: columns (A,0,0,0) (0,B,0,0) (0,0,C,-1) (0,0,D,0)),
   d = (normalLod, maxLod, farStart / open surface, -). The matrix travels as numbers so both builds use
   the same floats (tan() differs between drivers). Hits leave as
   a = (uv, valid, fetches), b = (position, 0), c = (texel x, texel y at level 0). */
#include "snell/intersect.glsl"

#if defined(SNELL_LANG_GLSL)
uniform sampler2D planeDepthA;    /* NEAREST, one level */
uniform sampler2D planeNormalA;   /* trilinear normal mips */
uniform sampler2D planePyramidA;  /* depth pyramid, NEAREST_MIPMAP_NEAREST */
uniform sampler2D planeDepthB;
uniform sampler2D planeNormalB;
uniform sampler2D planePyramidB;
#endif
#if defined(SNELL_LANG_HLSL)
Texture2D<float4> planeDepthA;
Texture2D<float4> planeNormalA;
Texture2D<float4> planePyramidA;
Texture2D<float4> planeDepthB;
Texture2D<float4> planeNormalB;
Texture2D<float4> planePyramidB;
#endif

SNELL_FN float planeParityFlag(bool b) {
  return b ? 1.0f : 0.0f;
}

SNELL_FN mat4 planeParityMatrix(vec4 c) {
  return SNELL_CAMERA_MAT4_COLUMNS(vec4(c.x, 0.0f, 0.0f, 0.0f), vec4(0.0f, c.y, 0.0f, 0.0f),
                                   vec4(0.0f, 0.0f, c.z, -1.0f), vec4(0.0f, 0.0f, c.w, 0.0f));
}

SNELL_FN SnellDepthSurface planeParitySurface(float scene, vec4 c) {
  if (scene > 0.5f) {
    return snellDepthSurface(planeParityMatrix(c), 0.5f, 40.0f, SNELL_DEPTH_REVERSED, 0.0f);
  }
  return snellDepthSurface(planeParityMatrix(c), 0.5f, 40.0f, SNELL_DEPTH_GL, 0.0f);
}

SNELL_FN SnellParityOut planeParityHit(SnellHit h) {
  SnellParityOut o;
  ivec2 px = snellUvToPixel(h.uv, ivec2(160, 120));
  o.a = vec4(h.uv.x, h.uv.y, planeParityFlag(h.valid), float(h.fetches));
  o.b = vec4(h.position.x, h.position.y, h.position.z, 0.0f);
  o.c = vec4(float(px.x), float(px.y), 0.0f, 0.0f);
  o.d = vec4(0.0f);
  return o;
}

SNELL_FN SnellParityOut planeParityOut(vec4 a, vec4 b) {
  SnellParityOut o;
  o.a = a;
  o.b = b;
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

/* a.x = fetches (integral) */
SNELL_FN SnellParityOut caseSnellHitMiss(vec4 a, vec4 b, vec4 c, vec4 d) {
  return planeParityHit(snellHitMiss(int(a.x)));
}

/* c = matrix entries, d = (zNear, zFar, convention, emptyDepth); out a = entries back, b = the rest */
SNELL_FN SnellParityOut caseSnellDepthSurface(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDepthSurface s = snellDepthSurface(planeParityMatrix(c), d.x, d.y, int(d.z), d.w);
  vec4 c0 = SNELL_MUL(s.clipFromView, vec4(1.0f, 0.0f, 0.0f, 0.0f));
  vec4 c1 = SNELL_MUL(s.clipFromView, vec4(0.0f, 1.0f, 0.0f, 0.0f));
  vec4 c2 = SNELL_MUL(s.clipFromView, vec4(0.0f, 0.0f, 1.0f, 0.0f));
  vec4 c3 = SNELL_MUL(s.clipFromView, vec4(0.0f, 0.0f, 0.0f, 1.0f));
  SnellParityOut o;
  o.a = vec4(c0.x, c1.y, c2.z, c3.z);
  o.b = vec4(s.zNear, s.zFar, float(s.convention), s.emptyDepth);
  o.c = vec4(float(s.lod), c2.w, c0.y + c0.z + c0.w + c1.x + c1.z + c1.w, c2.x + c2.y + c3.x + c3.y + c3.w);
  o.d = vec4(0.0f);
  return o;
}

/* a = (uv, -, scene), b.w = lod (pyramid when > 0); out a = (viewZ, valid) */
SNELL_FN SnellParityOut caseSnellSampleSurface(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDepthSurface s = planeParitySurface(a.w, c);
  s.lod = int(b.w);
  s.depthFilter = int(b.z);
  SnellSurfaceSample x;
  if (a.w > 0.5f) {
    x = s.lod > 0 ? snellSampleSurface(planePyramidB, vec2(a.x, a.y), s) : snellSampleSurface(planeDepthB, vec2(a.x, a.y), s);
  } else {
    x = s.lod > 0 ? snellSampleSurface(planePyramidA, vec2(a.x, a.y), s) : snellSampleSurface(planeDepthA, vec2(a.x, a.y), s);
  }
  return planeParityOut(vec4(x.viewZ, planeParityFlag(x.valid), 0.0f, 0.0f), vec4(0.0f));
}

/* a = (uv, viewZ, -), b = (m20, m21, -, -) off-centre terms, c = entries; out a = (position, valid) */
SNELL_FN SnellParityOut caseSnellUvZToView(vec4 a, vec4 b, vec4 c, vec4 d) {
  mat4 m = SNELL_CAMERA_MAT4_COLUMNS(vec4(c.x, 0.0f, 0.0f, 0.0f), vec4(0.0f, c.y, 0.0f, 0.0f),
                                     vec4(b.x, b.y, c.z, -1.0f), vec4(0.0f, 0.0f, c.w, 0.0f));
  SnellViewPoint p = snellUvZToView(m, vec2(a.x, a.y), a.z);
  return planeParityOut(vec4(p.position.x, p.position.y, p.position.z, planeParityFlag(p.valid)), vec4(0.0f));
}

/* The surface's own projection (surface_projection.glsl): b = (m20, m21) off-centre
   terms and m10, a shear that makes the matrix general; a.w > 0.5 clears the
   perspective flag. Out b.x = the flag snellDepthSurface set. */
SNELL_FN SnellDepthSurface planeParityShapedSurface(vec4 b, vec4 c) {
  mat4 m = SNELL_CAMERA_MAT4_COLUMNS(vec4(c.x, 0.0f, 0.0f, 0.0f), vec4(b.z, c.y, 0.0f, 0.0f),
                                     vec4(b.x, b.y, c.z, -1.0f), vec4(0.0f, 0.0f, c.w, 0.0f));
  return snellDepthSurface(m, 0.5f, 40.0f, SNELL_DEPTH_GL, 0.0f);
}

/* a = (pView, clear flag); out a = (uv, ndcZ, valid), b.x = flag */
SNELL_FN SnellParityOut caseSnellSurfaceViewToUv(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDepthSurface s = planeParityShapedSurface(b, c);
  float flag = planeParityFlag(s.perspective);
  if (a.w > 0.5f) {
    s.perspective = false;
  }
  SnellScreenPoint sp = snellSurfaceViewToUv(s, vec3(a.x, a.y, a.z));
  return planeParityOut(vec4(sp.uv.x, sp.uv.y, sp.ndcZ, planeParityFlag(sp.valid)), vec4(flag, 0.0f, 0.0f, 0.0f));
}

/* a = (uv, viewZ, clear flag); out a = (position, valid), b.x = flag */
SNELL_FN SnellParityOut caseSnellSurfaceUvZToView(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDepthSurface s = planeParityShapedSurface(b, c);
  float flag = planeParityFlag(s.perspective);
  if (a.w > 0.5f) {
    s.perspective = false;
  }
  SnellViewPoint p = snellSurfaceUvZToView(s, vec2(a.x, a.y), a.z);
  return planeParityOut(vec4(p.position.x, p.position.y, p.position.z, planeParityFlag(p.valid)),
                        vec4(flag, 0.0f, 0.0f, 0.0f));
}

/* a = (uv, -, scene); out a = (position, valid), b = (uv, 0, 0) */
SNELL_FN SnellParityOut caseSnellSurfacePoint(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDepthSurface s = planeParitySurface(a.w, c);
  SnellSurfacePoint p;
  if (a.w > 0.5f) {
    p = snellSurfacePoint(planeDepthB, vec2(a.x, a.y), s);
  } else {
    p = snellSurfacePoint(planeDepthA, vec2(a.x, a.y), s);
  }
  return planeParityOut(vec4(p.position.x, p.position.y, p.position.z, planeParityFlag(p.valid)),
                        vec4(p.uv.x, p.uv.y, 0.0f, 0.0f));
}

SNELL_FN SnellParityOut caseSnellIntersectSingleSample(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDepthSurface s = planeParitySurface(a.w, c);
  vec3 o = vec3(a.x, a.y, a.z);
  vec3 v = vec3(b.x, b.y, b.z);
  if (a.w > 0.5f) {
    return planeParityHit(snellIntersectSingleSample(o, v, planeDepthB, s));
  }
  return planeParityHit(snellIntersectSingleSample(o, v, planeDepthA, s));
}

/* a = (p, scene), b.w = fetchesSoFar */
SNELL_FN SnellParityOut caseSnellHitOnSurface(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDepthSurface s = planeParitySurface(a.w, c);
  vec3 p = vec3(a.x, a.y, a.z);
  if (a.w > 0.5f) {
    return planeParityHit(snellHitOnSurface(p, planeDepthB, s, int(b.w)));
  }
  return planeParityHit(snellHitOnSurface(p, planeDepthA, s, int(b.w)));
}

SNELL_FN SnellParityOut caseSnellPlaneHit(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDepthSurface s = planeParitySurface(a.w, c);
  vec3 p = vec3(a.x, a.y, a.z);
  vec2 planeUv = vec2(d.x, d.y);
  if (a.w > 0.5f) {
    return planeParityHit(snellPlaneHit(p, planeUv, planeDepthB, s, int(b.w)));
  }
  return planeParityHit(snellPlaneHit(p, planeUv, planeDepthA, s, int(b.w)));
}

/* d.z > 0.5: farStart (every other ray) */
SNELL_FN SnellParityOut caseSnellIntersectPlaneNormal(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDepthSurface s = planeParitySurface(a.w, c);
  vec3 o = vec3(a.x, a.y, a.z);
  vec3 v = vec3(b.x, b.y, b.z);
  bool farStart = d.z > 0.5f;
  if (a.w > 0.5f) {
    return planeParityHit(snellIntersectPlaneNormal(o, v, planeDepthB, planeNormalB, planePyramidB, s, d.x, int(b.w), farStart));
  }
  return planeParityHit(snellIntersectPlaneNormal(o, v, planeDepthA, planeNormalA, planePyramidA, s, d.x, int(b.w), farStart));
}

/* The origin's own projection as originUv; scene B with d.z > 0.5 is an open
   surface (no far start). Out a = (position, valid), b = (t, fetches, 0, 0). */
SNELL_FN SnellParityOut caseSnellPlaneFarStart(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDepthSurface s = planeParitySurface(a.w, c);
  vec3 o = vec3(a.x, a.y, a.z);
  vec3 v = vec3(b.x, b.y, b.z);
  vec2 uv = snellSurfaceViewToUv(s, o).uv;
  SnellFarPlane f;
  if (a.w > 0.5f) {
    s.closed = !(d.z > 0.5f);
    f = snellPlaneFarStart(o, v, uv, planePyramidB, s);
  } else {
    f = snellPlaneFarStart(o, v, uv, planePyramidA, s);
  }
  return planeParityOut(vec4(f.position.x, f.position.y, f.position.z, planeParityFlag(f.valid)),
                        vec4(f.t, float(f.fetches), 0.0f, 0.0f));
}

/* a = (q, scene), b = (unit dir, -), d.y = maxLod; out a = (B, valid), b = (normal, fetches) */
SNELL_FN SnellParityOut caseSnellDepthPlaneAt(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDepthSurface s = planeParitySurface(a.w, c);
  vec3 q = vec3(a.x, a.y, a.z);
  vec3 v = vec3(b.x, b.y, b.z);
  SnellDepthPlane p;
  if (a.w > 0.5f) {
    p = snellDepthPlaneAt(q, v, planePyramidB, s, int(d.y));
  } else {
    p = snellDepthPlaneAt(q, v, planePyramidA, s, int(d.y));
  }
  return planeParityOut(vec4(p.position.x, p.position.y, p.position.z, planeParityFlag(p.valid)),
                        vec4(p.normal.x, p.normal.y, p.normal.z, float(p.fetches)));
}

SNELL_FN SnellParityOut caseSnellIntersectPlaneDepth(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDepthSurface s = planeParitySurface(a.w, c);
  vec3 o = vec3(a.x, a.y, a.z);
  vec3 v = vec3(b.x, b.y, b.z);
  if (a.w > 0.5f) {
    return planeParityHit(snellIntersectPlaneDepth(o, v, planePyramidB, s, int(d.y), int(b.w), d.z > 0.5f));
  }
  return planeParityHit(snellIntersectPlaneDepth(o, v, planePyramidA, s, int(d.y), int(b.w), d.z > 0.5f));
}

/* a = (depthValue, zNear, zFar, convention), b.x = emptyDepth; out a = texel */
SNELL_FN SnellParityOut caseSnellDepthPyramidBase(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDepthSurface s = snellDepthSurface(planeParityMatrix(vec4(1.0f, 1.0f, -1.0f, -1.0f)), a.y, a.z, int(a.w), b.x);
  return planeParityOut(snellDepthPyramidBase(a.x, s), vec4(0.0f));
}

/* a = (px.x, px.y, lod, scene) integral; out a = texel of level lod + 1 */
SNELL_FN SnellParityOut caseSnellDepthMinMaxReduce(vec4 a, vec4 b, vec4 c, vec4 d) {
  ivec2 px = ivec2(int(a.x), int(a.y));
  if (a.w > 0.5f) {
    return planeParityOut(snellDepthMinMaxReduce(planePyramidB, int(a.z), px, 0.0f), vec4(0.0f));
  }
  return planeParityOut(snellDepthMinMaxReduce(planePyramidA, int(a.z), px, 0.0f), vec4(0.0f));
}
