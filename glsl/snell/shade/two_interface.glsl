/*
description: the geometry of two-interface refraction: refract the view ray at
  the front face, find where the refracted ray T1 leaves the object in the
  back-face depth buffer (with the back slot's intersection strategy, or, in
  Wyman's variant, by his distance interpolation), refract again with the
  back-face normal found there; with t.bounces > 0, a total internal
  reflection there (and at each later exit) is followed inside the object
  instead of clamped. The exit ray (P2, T2) is then resolved by
  two_interface_shade.glsl against the opaque scene or the environment.
use: SnellTwoInterfacePath p = snellTwoInterfaceTrace(frontPosition, frontNormal, eta, dN,
         backDepth, backNormal, backPyramid, back, frontLayerDepth, frontLayerNormal, frontLayer,
         t, m.tirPolicy);
  frontPosition  P1: view-space position of the front-face fragment (camera at
                 the origin, so the view ray V is frontPosition itself)
  frontNormal    N1: its normal (either orientation, any length)
  eta            n_outside / n_object (snellIorToEta(1.0f, 1.5f) for glass in air)
  dN             Wyman's d_N: thickness along -N1, interpolated from the per-vertex
                 values the host precomputes (include/snell/wyman_dn.hpp); read
                 only by Wyman's variant (slot.source SNELL_SOURCE_WYMAN)
  backDepth, backNormal, backPyramid, back
                 SNELL_OBJECT_BUFFERS (technique_buffers.glsl): the back-face
                 pass: depth (GL_GREATER after clearing to the near value),
                 view-space normals, the depth min/max pyramid of that depth
                 (snellBuildDepthPyramid / glsl/passes/depth_pyramid.frag), and
                 how to read the depth (emptyDepth = the clear value); then
                 the front-face pass (depth drawn with GL_LESS after clearing
                 to the far value, view-space normals, how to read it), read
                 only when t.bounces > 0
  t              the technique (technique_options.glsl): its back slot (source
                 and intersector), its inside slot and bounce count
  tirPolicy      SNELL_TIR_ZERO / _CRITICAL / _REFLECT, at the first interface
                 and the last one the path meets
options: technique_options.glsl, and
  SNELL_TWO_INTERFACE_NORMAL_SAMPLE  how N2 is read from backNormal at the hit
                 uv: 1 (default) SNELL_SAMPLE_LOD at level 0 with the texture's
                 own filter (bilinear for a LINEAR texture: the normal at the hit
                 point, not at the centre of its texel; NEAREST gives the texel
                 containing the uv, as 0 does); 0 SNELL_TEXEL_FETCH of the texel
                 containing the uv (level 0)
contract:
  - T1 = snellRefract(frontPosition, frontNormal, eta, tirPolicy). If it is
    invalid or zero (NaN/zero inputs, eta not finite positive; TIR under ZERO
    when eta > 1), the path is invalid: valid = false, every vector 0, fetches 0.
  - slot.source SNELL_SOURCE_WYMAN: one sample of the back depth at the projection of P1
    gives d_V = |P1| (zBack / P1.z - 1) (front-to-back distance along the view
    ray); d = snellWymanDistanceVec(P1, N1, T1, d_V, dN); P2 = P1 + d T1,
    accepted when snellHitOnSurface(P2) is valid (the back buffer has a
    surface there; 2 fetches). SNELL_SOURCE_BUFFERS (and any value but the
    two named here): snellIntersectWith(P1, T1, back..., slot.intersect).
    SNELL_SOURCE_ENVIRONMENT: no back-face read (0 fetches), the fallback
    below (the ray leaves at P1 along T1: a thin surface).
  - on a hit: N2 = xyz of the back normal read at the hit uv, level 0
    (SNELL_TWO_INTERFACE_NORMAL_SAMPLE: filtered sample or texel fetch; 1
    fetch), normalized and flipped to face T1 (dot(N2, T1) <= 0); T2 =
    snellRefract(T1, N2, 1 / eta, tirPolicy). hit = true, exitPoint = P2,
    exitUv = the hit uv, exitNormal = N2, pathLength = entryLength = |P2 -
    P1| (entryLength keeps the first segment's when bounces add more), tir = TIR at
    the second interface (T2 follows the policy: critical-angle tangent or
    mirror; the reflected ray is not traced further), exitIncident = T1 (the
    ray T2 was refracted from, so that a caller can refract it again, as
    two_interface_shade.glsl does for rough glass); exitIncident = 0 wherever
    T2 is not snellRefract's result at the last interface (a fallback, an
    invalid path).
  - fallback (fellBack = true, the path still valid): no back hit (invalid or
    off-screen texel, empty range; a hit so far that |P2 - P1| overflows a
    float, beyond ~1.8e19 view units, counts as none), a zero or NaN stored
    normal, or TIR under SNELL_TIR_ZERO: the ray leaves as if the second
    interface did not bend it: exitPoint = P2 when found, else P1,
    exitDirection = T1, pathLength = |P2 - P1| when P2 was found, else 0.
  - bounces (t.bounces = B > 0, clamped to [0, SNELL_MAX_BOUNCES]): at the
    back hit and at each later exit but the (B + 1)-th, TIR reflects (R =
    reflect(T, N)) instead of following tirPolicy: the inside slot
    (SNELL_SOURCE_BUFFERS with SNELL_STRATEGY_LINEAR_MARCH: snellInsideMarch
    from the exit point along R between the back layer and the front layer,
    with inside.intersect's marchMaxDistance, marchSteps, marchBisections;
    with SNELL_STRATEGY_PLANE_NORMAL: snellInsidePlane with marchMaxDistance,
    marchSteps, planeIterations) finds where R leaves; N there is read from that layer's normals (as N2,
    1 fetch), flipped to face R, and the ray refracts out, or reflects again,
    the last allowed interface under tirPolicy. bounces = the reflections
    taken (one that ends as a fallback counts); exitPoint, exitUv, exitNormal are the last interface's,
    exitIncident the ray inside that met it;
    exitFront = the last interface is a front face (T2 heads towards the
    camera's side: two_interface_shade.glsl resolves it with the reflect
    slot); pathLength adds every segment inside; tir = TIR at the last
    interface. A reflection the inside march cannot follow (no exit in the
    buffers, a zero normal there, a path length that overflows, an inside slot
    of another source or strategy) ends the path as a fallback (fellBack =
    true): it leaves from the last interface point along R. bounces = 0 is
    the two-interface path above, bit for bit.
  - fetches: the strategy's count plus the normal fetch, plus each bounce's
    march and normal fetch.
source: C. Wyman, "An Approximate Image-Space Approach for Interactive
  Refraction", SIGGRAPH 2005 (two interfaces, back-face normal and depth
  buffers); M. M. Oliveira & M. Brauwers, "Real-Time Refraction Through
  Deformable Objects", I3D 2007, sec. 2.1 (eqs. 1-2), sec. 3 (intersecting T1
  with the back-face depth map, N2 from the normal map at the hit), sec. 5
  (critical-angle TIR policy); C. Davis & C. Wyman, "Interactive Refractions
  with Total Internal Reflection", Graphics Interface 2007 (bounces inside
  between front and back depth maps).
*/
#ifndef SNELL_SHADE_TWO_INTERFACE_GLSL
#define SNELL_SHADE_TWO_INTERFACE_GLSL
#include "../prelude.glsl"
#include "../camera/pixel_to_uv.glsl"
#include "../camera/view_to_uv.glsl"
#include "../optics/safe_normalize.glsl"
#include "../optics/refract.glsl"
#include "../optics/wyman_distance.glsl"
#include "../intersect/hit.glsl"
#include "../intersect/depth_surface.glsl"
#include "../intersect/hit_on_surface.glsl"
#include "../intersect/intersect_with.glsl"
#include "../intersect/inside_march.glsl"
#include "../intersect/inside_plane.glsl"
#include "technique_options.glsl"
#include "technique_buffers.glsl"

#ifndef SNELL_TWO_INTERFACE_NORMAL_SAMPLE
#  define SNELL_TWO_INTERFACE_NORMAL_SAMPLE 1
#endif

struct SnellTwoInterfacePath {
  vec3 entryDirection;  // T1
  vec3 exitPoint;       // P2 (P1 when no back hit)
  vec3 exitNormal;      // N2, facing T1
  vec3 exitDirection;   // T2 (T1 on fallback)
  vec2 exitUv;          // uv of P2 in the back buffers (in the front buffers when exitFront)
  float pathLength;     // |P2 - P1|, plus every segment after a bounce
  float entryLength;    // |P2 - P1| of the first segment alone (0 without a back hit)
  int fetches;
  int bounces;          // total internal reflections followed inside
  bool hit;
  bool tir;
  bool fellBack;
  bool valid;
  bool exitFront;       // the last interface is a front face (after a bounce): T2 heads to the camera's side
  vec3 exitIncident;    // the ray inside that met the last interface, when T2 is its refraction (else 0)
};

/* Wyman 2005 / Oliveira & Brauwers 2007 sec. 3: P1, T1 -> P2 (back-face buffer), N2 -> T2 */
SNELL_FN SnellTwoInterfacePath snellTwoInterfaceTrace(vec3 frontPosition, vec3 frontNormal, float eta, float dN,
                                                      SNELL_OBJECT_BUFFERS, SNELL_IN(SnellTechnique) t, int tirPolicy) {
  SnellTwoInterfacePath p;
  p.entryDirection = vec3(0.0f, 0.0f, 0.0f);
  p.exitPoint = vec3(0.0f, 0.0f, 0.0f);
  p.exitNormal = vec3(0.0f, 0.0f, 0.0f);
  p.exitDirection = vec3(0.0f, 0.0f, 0.0f);
  p.exitUv = vec2(0.0f, 0.0f);
  p.pathLength = 0.0f;
  p.entryLength = 0.0f;
  p.fetches = 0;
  p.bounces = 0;
  p.hit = false;
  p.tir = false;
  p.fellBack = true;
  p.valid = false;
  p.exitFront = false;
  p.exitIncident = vec3(0.0f, 0.0f, 0.0f);
  SnellRefraction r1 = snellRefract(frontPosition, frontNormal, eta, tirPolicy);
  if (!r1.valid || dot(r1.direction, r1.direction) == 0.0f || !SNELL_FINITE(frontPosition.x) ||
      !SNELL_FINITE(frontPosition.y) || !SNELL_FINITE(frontPosition.z)) {
    return p;
  }
  vec3 t1 = r1.direction;
  p.entryDirection = t1;
  p.exitPoint = frontPosition;
  p.exitDirection = t1;
  p.valid = true;
  SnellHit h = snellHitMiss(0);
  if (t.back.source == SNELL_SOURCE_WYMAN) {
    SnellScreenPoint sp = snellViewToUv(back.clipFromView, frontPosition);
    if (sp.valid && frontPosition.z < 0.0f) {
      SnellSurfaceSample b = snellSampleSurface(backDepth, sp.uv, back);
      h = snellHitMiss(1);
      if (b.valid) {
        float dV = length(frontPosition) * (b.viewZ / frontPosition.z - 1.0f);
        float d = snellWymanDistanceVec(frontPosition, frontNormal, t1, dV, dN);
        h = snellHitOnSurface(frontPosition + d * t1, backDepth, back, 1);
      }
    }
  } else if (t.back.source != SNELL_SOURCE_ENVIRONMENT) {
    h = snellIntersectWith(frontPosition, t1, backDepth, backNormal, backPyramid, back, t.back.intersect);
  }
  p.fetches = h.fetches;
  // length() squares first: it overflows beyond ~1.8e19 (Wyman's estimate with a huge dN).
  float pathLength = length(h.position - frontPosition);
  if (!h.valid || !SNELL_FINITE(pathLength)) {
    return p;
  }
  p.hit = true;
  p.exitPoint = h.position;
  p.exitUv = h.uv;
  p.pathLength = pathLength;
  p.entryLength = pathLength;
  int bounces = clamp(t.bounces, 0, SNELL_MAX_BOUNCES);
  vec3 d = t1;
  // One interface per pass: the back hit, then each exit the inside slot finds after a bounce. Every
  // interface but the last allowed one reflects on TIR and goes on; the last takes the material's policy.
  for (int k = 0; k <= SNELL_MAX_BOUNCES; ++k) {
    // Only a bounce reaches a front face. Testing bounces first makes the test a constant false for a
    // technique without bounces, so the front layer's read drops out: GPUs without uniform branches
    // (llvmpipe) read both sides of a ?:.
    bool front = bounces > 0 && p.exitFront;
#if SNELL_TWO_INTERFACE_NORMAL_SAMPLE
    vec4 nk = front ? SNELL_SAMPLE_LOD(frontLayerNormal, p.exitUv, 0.0f)
                    : SNELL_SAMPLE_LOD(backNormal, p.exitUv, 0.0f);
#else
    vec4 nk = front
                  ? SNELL_TEXEL_FETCH(frontLayerNormal,
                                      snellUvToPixel(p.exitUv, SNELL_TEXTURE_SIZE(frontLayerNormal, 0)), 0)
                  : SNELL_TEXEL_FETCH(backNormal, snellUvToPixel(p.exitUv, SNELL_TEXTURE_SIZE(backNormal, 0)), 0);
#endif
    p.fetches = p.fetches + 1;
    vec3 n = snellSafeNormalize(vec3(nk.x, nk.y, nk.z));
    if (dot(n, n) == 0.0f) {
      return p;
    }
    if (dot(n, d) > 0.0f) {
      n = -n;
    }
    p.exitNormal = n;
    // bounces == 0 first: a constant for a technique without bounces, so all that follows the first
    // interface drops out (a compiler does not see that k >= 0 here).
    bool last = bounces == 0 || k >= bounces;
    SnellRefraction r2 = snellRefract(d, n, 1.0f / eta, last ? tirPolicy : SNELL_TIR_REFLECT);
    if (last || !r2.tir) {
      p.tir = r2.tir;
      if (!r2.valid || dot(r2.direction, r2.direction) == 0.0f) {
        return p;
      }
      p.exitDirection = r2.direction;
      p.exitIncident = d;
      p.fellBack = false;
      return p;
    }
    // From here a path that cannot be followed leaves along the reflection from the last point (a fallback).
    d = r2.direction;
    p.exitDirection = d;
    p.tir = true;
    p.bounces = k + 1;
    bool insidePlane = t.inside.intersect.strategy == SNELL_STRATEGY_PLANE_NORMAL;
    if (t.inside.source != SNELL_SOURCE_BUFFERS ||
        (!insidePlane && t.inside.intersect.strategy != SNELL_STRATEGY_LINEAR_MARCH)) {
      return p;
    }
    SnellInsideHit ih;
    if (insidePlane) {
      ih = snellInsidePlane(p.exitPoint, d, backDepth, backNormal, back, frontLayerDepth, frontLayerNormal, frontLayer,
                            t.inside.intersect.marchMaxDistance, t.inside.intersect.marchSteps,
                            t.inside.intersect.planeIterations);
    } else {
      ih = snellInsideMarch(p.exitPoint, d, backDepth, back, frontLayerDepth, frontLayer,
                            t.inside.intersect.marchMaxDistance, t.inside.intersect.marchSteps,
                            t.inside.intersect.marchBisections);
    }
    p.fetches = p.fetches + ih.hit.fetches;
    float segment = length(ih.hit.position - p.exitPoint);
    if (!ih.hit.valid || !SNELL_FINITE(p.pathLength + segment)) {
      return p;
    }
    p.exitPoint = ih.hit.position;
    p.exitUv = ih.hit.uv;
    p.exitFront = ih.front;
    p.pathLength = p.pathLength + segment;
  }
  return p;
}

#endif
