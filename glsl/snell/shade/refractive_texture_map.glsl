/*
description: G. Oliveira's refractive texture mapping, per vertex of a
  perturbed water mesh: the approximate refracted eye ray (incident direction
  plus the inverted normal times a refraction factor) is followed down to a
  planar map lying a given depth below the mesh's rest plane, and the hit's x
  and z are mapped linearly over the mesh extent to the map's uv.
use: SnellRefractiveTextureMapParams p =
         snellRefractiveTextureMapParams(vec2(x0, z0), vec2(x1, z1), restY, depth, factor);
     p.policy = SNELL_RTM_SHRINK; p.uvMin = 0.1f; p.uvMax = 0.9f;   // optional
     SnellRefractiveTextureMapHit h = snellRefractiveTextureMap(vertexPos, vertexNormal, eyePos, p);
     uv = h.uv;
     float u = snellRefractiveTextureMapAxis(x, x_i, x_e);   // eq. 12 alone
  Space: the paper's, y up; the mesh rests in the plane y = restY spanning
  [x_i, x_e] x [z_i, z_e] and the map lies in the plane y = restY - depth.
  vertex, normal  the (perturbed) vertex position and its normal (need not be
                  unit)
  eyePosition     camera position in the same space
  params fields:
    extentMin, extentMax  (x_i, z_i) and (x_e, z_e); the constructor's
    restY                 y_i, the unperturbed mesh's height
    depth                 p_i, the map's depth below restY
    refractionFactor      snellApproxRefract's factor (>= 0)
    policy                SNELL_RTM_CLAMP (constructor default) or SNELL_RTM_SHRINK
    uvMin, uvMax          the policy's interval (constructor: 0, 1)
options:
  SNELL_RTM_CLAMP   uv = clamp(uv_eq, uvMin, uvMax): the paper's first fix
                    (Listing 4 clamps to refraction_uv_min / _max)
  SNELL_RTM_SHRINK  uv = uvMin + (uvMax - uvMin) uv_eq, then clamped to [0, 1]:
                    the paper's second fix, the mesh extent mapped to a shrunk
                    interval such as [0.1, 0.9]. For rays reaching at most m
                    beyond an edge of an extent of length L, uvMin = m / (L + 2m)
                    and uvMax = 1 - uvMin keep every hit in [0, 1]
contract:
  - dir = snellApproxRefract(vertex - eyePosition, normal, refractionFactor)
    (eq. 8, Listing 4); the hit is vertex + t dir on y = restY - depth, i.e.
    t = (depth + (vertex.y - restY)) / (-dir.y) (eqs. 9-11: the final depth p
    is the initial depth plus the vertex's displacement above the rest plane,
    as Listing 4 computes it; the text's eq. 11 prints the displacement with
    the opposite sign, and Listing 4 divides by the signed dir.y, which is
    negative for a ray going down), found with snellRayPlane.
  - uv_eq = ((x - x_i) / (x_e - x_i), (z - z_i) / (z_e - z_i)) (eqs. 12-13), each
    component limited to [-1e6, 1e6]. A reversed extent (x_e < x_i) flips
    that axis: Listing 4's v, flipped for DirectX 7, is extentMin.y = z_e,
    extentMax.y = z_i. An extent with |length| below the smallest normal float
    or a non-finite bound gives 0.5 for that axis.
  - valid is false when there is no hit: the ray does not go down towards the
    map (the vertex is below it, the ray is horizontal or goes up), or vertex,
    normal or eyePosition is zero-length where it matters, NaN or infinite.
    Then position = (vertex.x, restY - depth, vertex.z) (straight down, each
    non-finite component replaced by 0: always finite) and uv is computed from
    it the same way, except that an axis whose vertex coordinate is not finite
    gives 0.5.
  - inRange is true when valid and uv_eq lies in [0, 1]^2 (before the policy).
  - uvMin, uvMax: NaN counts as 0 and 1; both are clamped to [0, 1] and
    ordered (swapped values are swapped back); an unknown policy is CLAMP.
    The returned uv is always finite and in [0, 1]^2.
source: G. Oliveira, "Refractive Texture Mapping, Part Two", Gamasutra 2000,
  Equations 8-13 and Listing 4 (water_compute_refraction), and the two
  out-of-range fixes described after Equation 13.
*/
#ifndef SNELL_SHADE_REFRACTIVE_TEXTURE_MAP_GLSL
#define SNELL_SHADE_REFRACTIVE_TEXTURE_MAP_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"
#include "../optics/approx_refract.glsl"
#include "../optics/ray_plane.glsl"

#define SNELL_RTM_CLAMP 0
#define SNELL_RTM_SHRINK 1

struct SnellRefractiveTextureMapParams {
  vec2 extentMin;
  vec2 extentMax;
  float restY;
  float depth;
  float refractionFactor;
  int policy;
  float uvMin;
  float uvMax;
};

struct SnellRefractiveTextureMapHit {
  vec2 uv;
  vec3 position;
  bool valid;
  bool inRange;
};

SNELL_FN SnellRefractiveTextureMapParams snellRefractiveTextureMapParams(vec2 extentMin, vec2 extentMax, float restY,
                                                                         float depth, float refractionFactor) {
  SnellRefractiveTextureMapParams p;
  p.extentMin = extentMin;
  p.extentMax = extentMax;
  p.restY = restY;
  p.depth = depth;
  p.refractionFactor = refractionFactor;
  p.policy = SNELL_RTM_CLAMP;
  p.uvMin = 0.0f;
  p.uvMax = 1.0f;
  return p;
}

/* Eqs. 12-13 for one axis: (x - lo) / (hi - lo) limited to [-1e6, 1e6]; 0.5
   when x, lo, hi or hi - lo is not finite or |hi - lo| is below the smallest
   normal float. */
SNELL_FN float snellRefractiveTextureMapAxis(float x, float lo, float hi) {
  float len = hi - lo;
  if (!SNELL_FINITE(x) || !SNELL_FINITE(lo) || !SNELL_FINITE(hi) || !SNELL_FINITE(len) ||
      !(abs(len) >= SNELL_FLT_MIN)) {
    return 0.5f;
  }
  // (x - lo) may overflow to +-inf, never NaN; clamp keeps it finite.
  return clamp((x - lo) / len, -1e6f, 1e6f);
}

SNELL_FN SnellRefractiveTextureMapHit snellRefractiveTextureMap(vec3 vertex, vec3 normal, vec3 eyePosition,
                                                                SnellRefractiveTextureMapParams p) {
  SnellRefractiveTextureMapHit h;
  float planeY = p.restY - p.depth;
  vec3 dir = snellApproxRefract(vertex - eyePosition, normal, p.refractionFactor);
  SnellRayPlaneHit hit = snellRayPlane(vertex, dir, vec3(0.0f, planeY, 0.0f), vec3(0.0f, 1.0f, 0.0f));
  // A hit must come from a ray going down: a ray going up from below the map
  // also meets its plane.
  h.valid = hit.valid && dir.y < 0.0f;
  if (h.valid) {
    h.position = hit.position;
  } else {
    h.position = vec3(SNELL_FINITE(vertex.x) ? vertex.x : 0.0f, SNELL_FINITE(planeY) ? planeY : 0.0f,
                      SNELL_FINITE(vertex.z) ? vertex.z : 0.0f);
  }
  float px = h.valid || SNELL_FINITE(vertex.x) ? h.position.x : vertex.x;
  float pz = h.valid || SNELL_FINITE(vertex.z) ? h.position.z : vertex.z;
  vec2 e = vec2(snellRefractiveTextureMapAxis(px, p.extentMin.x, p.extentMax.x),
                snellRefractiveTextureMapAxis(pz, p.extentMin.y, p.extentMax.y));
  h.inRange = h.valid && e.x >= 0.0f && e.x <= 1.0f && e.y >= 0.0f && e.y <= 1.0f;
  float a = isnan(p.uvMin) ? 0.0f : clamp(p.uvMin, 0.0f, 1.0f);
  float b = isnan(p.uvMax) ? 1.0f : clamp(p.uvMax, 0.0f, 1.0f);
  float lo = min(a, b);
  float hi = max(a, b);
  if (p.policy == SNELL_RTM_SHRINK) {
    h.uv = clamp(vec2(lo, lo) + e * (hi - lo), vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
  } else {
    h.uv = clamp(e, vec2(lo, lo), vec2(hi, hi));
  }
  return h;
}

#endif
