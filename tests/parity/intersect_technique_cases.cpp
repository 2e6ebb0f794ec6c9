// The parity cases of intersect/ that the two-interface technique's scene feeds (technique_inputs.hpp):
// the depth ranges, the strategy options and dispatcher, and the marches inside the object.
#include "technique_inputs.hpp"

namespace parity_technique {
#define SNELL_PARITY_FILE "technique.glsl"

// The function takes nothing; the case echoes its input a.x in output 3.
SNELL_PARITY_CASE(snellDepthRangeInvalid, [] { return smallIntInputs(807, 0, 5); },
                  (float, echoIn, 0),
                  (float, zNearest, 0, exact)(float, zFarthest, 1, exact)(bool, valid, 2, exact)
                  (float, echoOut, 3, exact),
                  techExtras().passThrough({"echoIn"}, {"echoOut"},
                                           "the case echoes its input a.x in output 3 (not the function's)"),
                  SnellDepthRange r = snellDepthRangeInvalid();
                  zNearest = r.zNearest;
                  zFarthest = r.zFarthest;
                  valid = r.valid;
                  echoOut = echoIn;)

// which: 0 the back pyramid, 1 the environment, 2 the scene colour.
SNELL_PARITY_CASE(snellTextureTopLod, [] { return smallIntInputs(808, 0, 2); },
                  (int, which, 0),
                  (int, lod, 0, exact),
                  techExtras(),
                  lod = which == 0 ? snellTextureTopLod(techBackPyramid)
                                   : (which == 1 ? snellTextureTopLod(techEnv) : snellTextureTopLod(techSceneColor));)

SNELL_PARITY_CASE(snellDepthRangeFromPyramid, [] { return smallIntInputs(809, 0, 1); },
                  (bool, toScene, 0),
                  (float, zNearest, 0, within(1e-6f, 1e-6f))(float, zFarthest, 1, within(1e-6f, 1e-6f))
                  (bool, valid, 2, exact),
                  techExtras(),
                  SnellDepthRange r;  // no ?: on structs: WebGL rejects it
                  if (toScene) {
                    r = snellDepthRangeFromPyramid(techScenePyramid);
                  } else {
                    r = snellDepthRangeFromPyramid(techBackPyramid);
                  }
                  zNearest = r.zNearest;
                  zFarthest = r.zFarthest;
                  valid = r.valid;)

// A box seen through a rotation about z by (cos, sin), a scale and a translation.
SNELL_PARITY_CASE(snellDepthRangeFromBox, boxInputs,
                  (vec3, translation, 0)(float, scale, 3)(vec3, boxMin, 4)(vec3, boxMax, 8)(vec2, rotation, 12),
                  (float, zNearest, 0, within(1e-5f, 1e-5f))(float, zFarthest, 1, within(1e-5f, 1e-5f))
                  (bool, valid, 2, exact),
                  techExtras(),
                  mat4 m = SNELL_CAMERA_MAT4_COLUMNS(vec4(scale * rotation.x, scale * rotation.y, 0.0f, 0.0f),
                                                     vec4(-scale * rotation.y, scale * rotation.x, 0.0f, 0.0f),
                                                     vec4(0.0f, 0.0f, scale, 0.0f),
                                                     vec4(translation.x, translation.y, translation.z, 1.0f));
                  SnellDepthRange r = snellDepthRangeFromBox(m, boxMin, boxMax);
                  zNearest = r.zNearest;
                  zFarthest = r.zFarthest;
                  valid = r.valid;)

// The options and presets, packed by TECH_OPTIONS_OUT: every count, flag and setting exact.
SNELL_PARITY_CASE(snellIntersectOptions, [] { return smallIntInputs(810, -1, 10); },
                  (int, strategy, 0),
                  TECH_OPTIONS_EXACT,
                  techExtras(),
                  SnellTechnique t = snellTechnique();
                  t.back.intersect = snellIntersectOptions(strategy);
                  TECH_OPTIONS_OUT(t, snellMaterial(), snellView()))
// Searches and marches through the sphere's back faces and the painting plane: the strategy, its main count
// (iterations, steps, linear steps), to the scene or the back faces, an explicit range or the pyramid's.
SNELL_PARITY_CASE(snellIntersectWith, [] { return dispatchInputs(820); },
                  (vec3, origin, 0)(int, strategy, 3)(vec3, direction, 4)(int, count, 7)(vec4, projection, 8)
                  (bool, toScene, 12)(bool, explicitRange, 13),
                  (vec2, uv, 0, within(1e-4f, 1e-4f))(bool, valid, 2, exact)(int, fetches, 3, exact)
                  (vec3, position, 4, within(1e-4f, 1e-4f)),
                  techExtras(),
                  SnellIntersectOptions o = snellIntersectOptions(strategy);
                  o.planeIterations = count;
                  o.cbsSteps = count;
                  if (o.strategy == SNELL_STRATEGY_BINARY) {
                    o.binarySteps = count;
                  }
                  o.linearSteps = count;
                  o.marchSteps = count;
                  o.ddaSteps = count;
                  if (explicitRange) {
                    o.rangeSource = SNELL_RANGE_EXPLICIT;
                    o.range.zNearest = -3.8f;
                    o.range.zFarthest = -12.0f;
                    o.range.valid = true;
                  }
                  SnellHit h;
                  if (toScene) {
                    h = snellIntersectWith(origin, direction, techSceneDepth, techSceneNormal, techScenePyramid,
                                           techSceneSurface(projection), o);
                  } else {
                    h = snellIntersectWith(origin, direction, techBackDepth, techBackNormal, techBackPyramid,
                                           techBackSurface(projection), o);
                  }
                  uv = h.uv;
                  valid = h.valid;
                  fetches = h.fetches;
                  position = h.position;)
// Rays inside the object: the hit's flags and fetches exact, position and uv 1e-4 (the bisection's last step
// on a grazing ray moves with the GPU's rounding, as snellTwoInterfaceTrace's).
SNELL_PARITY_CASE(snellInsideMarch, [] { return insideInputs(829); },
                  (vec3, origin, 0)(float, maxDistance, 3)(vec3, dir, 4)(int, steps, 7)(int, refineSteps, 8)
                  (vec4, projection, 12),
                  (vec3, position, 0, within(1e-4f, 1e-4f))(int, fetches, 3, exact)(vec2, uv, 4, within(1e-4f, 1e-4f))
                  (bool, valid, 6, exact)(bool, front, 7, exact),
                  techExtras(),
                  SnellInsideHit h = snellInsideMarch(origin, dir, techBackDepth, techBackSurface(projection),
                                                      techFrontDepth, techFrontSurface(projection), maxDistance, steps,
                                                      refineSteps);
                  position = h.hit.position;
                  fetches = h.hit.fetches;
                  uv = h.hit.uv;
                  valid = h.hit.valid;
                  front = h.front;)

// The march alone: lo and hi are sample positions (i dt, or a halving's), exact but for rounding.
SNELL_PARITY_CASE(snellInsideBracket, [] { return insideInputs(833); },
                  (vec3, origin, 0)(float, maxDistance, 3)(vec3, dir, 4)(int, steps, 7)(vec4, projection, 12),
                  (float, lo, 0, within(1e-5f, 1e-5f))(float, hi, 1, within(1e-5f, 1e-5f))(int, side, 2, exact)
                  (int, fetches, 3, exact)(vec2, uv, 4, within(1e-5f, 1e-5f))(bool, valid, 6, exact)
                  (vec2, loUv, 8, within(1e-5f, 1e-5f)),
                  techExtras(),
                  SnellInsideBracket b = snellInsideBracket(origin, dir, techBackDepth, techBackSurface(projection),
                                                            techFrontDepth, techFrontSurface(projection), maxDistance,
                                                            steps);
                  lo = b.lo;
                  hi = b.hi;
                  side = b.side;
                  fetches = b.fetches;
                  uv = b.uv;
                  valid = b.valid;
                  loUv = b.loUv;)

// The normal plane after the march (iterations: the march case's refine count, past the clamp too).
SNELL_PARITY_CASE(snellInsidePlane, [] { return insideInputs(834); },
                  (vec3, origin, 0)(float, maxDistance, 3)(vec3, dir, 4)(int, steps, 7)(int, iterations, 8)
                  (vec4, projection, 12),
                  (vec3, position, 0, within(1e-4f, 1e-4f))(int, fetches, 3, exact)(vec2, uv, 4, within(1e-4f, 1e-4f))
                  (bool, valid, 6, exact)(bool, front, 7, exact),
                  techExtras(),
                  SnellInsideHit h = snellInsidePlane(origin, dir, techBackDepth, techBackNormal,
                                                      techBackSurface(projection), techFrontDepth, techFrontNormal,
                                                      techFrontSurface(projection), maxDistance, steps, iterations);
                  position = h.hit.position;
                  fetches = h.hit.fetches;
                  uv = h.hit.uv;
                  valid = h.hit.valid;
                  front = h.front;)

SNELL_PARITY_CASE(snellInsideSide, [] { return insideSideInputs(830); },
                  (vec3, at, 0)(float, dirZ, 3)(vec2, uv, 4)(vec4, projection, 12),
                  (int, side, 0, exact),
                  techExtras(),
                  side = snellInsideSide(at, uv, techBackDepth, techBackSurface(projection), techFrontDepth,
                                         techFrontSurface(projection), dirZ);)

}  // namespace parity_technique
