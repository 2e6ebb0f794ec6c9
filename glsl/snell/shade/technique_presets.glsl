/*
description: named presets for the published two-interface refraction methods
  and the baselines, all through the same technique (snellTwoInterfaceTrace /
  snellTwoInterfaceRefraction), so the lab compares them fairly. Each returns
  snellTechnique() with the back and exit slots' strategies set (the exit
  slot's source stays the default, ENVIRONMENT: point it at the scene with
  t.exit.source = SNELL_SOURCE_BUFFERS).
use: SnellTechnique t = snellPresetDir();           // then adjust fields
     SnellTechnique t = snellPresetPlaneNormal(2);
presets (back slot / exit slot):
  snellPresetDir()                 Oliveira & Brauwers 2007 (DIR): CBS, 5 steps,
                                   range from the min/max pyramid's top level /
                                   the same
  snellPresetDirBounds(zNearest, zFarthest)  DIR with the bounding-box range
                                   (their suggested speed-up: no reduction
                                   pass); the numbers from snellDepthRangeFromBox;
                                   back slot only, the exit slot keeps the pyramid
  snellPresetIsr()                 Wyman 2005 (ISR): back.source
                                   SNELL_SOURCE_WYMAN, distance interpolation
                                   between d_V and the per-vertex d_N /
                                   single sample
  snellPresetPlaneNormal(n)        Mayer & Assarsson, normal-based plane, n
                                   refinement iterations / the same
  snellPresetPlaneDepth(n)         Mayer & Assarsson, depth-based plane (depth
                                   mips = the pyramid), n iterations / the same
                                   (both plane presets keep planeFarStart's
                                   default, true: the far start of
                                   intersect/plane_far_start.glsl on the closed
                                   back faces; set it false in both slots for
                                   the poster's method)
  snellPresetSingleSample()        the single-sample (GPU Gems) baseline / the same
  snellPresetLinearMarch()         screen-space ray march, view-space steps +
                                   bisection / the same
  snellPresetDdaMarch()            perspective-correct pixel DDA march / the same
  snellPresetPlaneNormalBounces(n) snellPresetPlaneNormal(n) that follows
                                   TIR inside the object: bounces =
                                   SNELL_PRESET_BOUNCES (4), the inside slot's
                                   march SNELL_PRESET_INSIDE_STEPS (16) steps +
                                   SNELL_PRESET_INSIDE_BISECTIONS (5)
                                   bisections (set inside.intersect.
                                   marchMaxDistance to the object's extent);
                                   reads the front-face layer
  snellPresetLinearMarchBounces()  snellPresetLinearMarch() with the same bounces
  snellPresetImageSpaceBoundBounces()  the image-space bound below with the
                                   same bounces, its inside march at the
                                   linear march's compile-time limits too:
                                   what the bounce techniques are measured
                                   against
  snellPresetImageSpaceBound()     not a real-time method: the best any
                                   image-space technique can do with the same
                                   buffers, for measuring the others against:
                                   the linear march at its compile-time limits
                                   (SNELL_LINEAR_MARCH_MAX_STEPS steps of at
                                   most ~1 px, SNELL_LINEAR_MARCH_MAX_REFINE_STEPS
                                   bisections) on bilinear depth reads
                                   (SNELL_DEPTH_FILTER_BILINEAR: exact on
                                   planes between texel centres) / the same;
                                   set back.intersect.marchMaxDistance and
                                   exit.intersect.marchMaxDistance to the depths the
                                   object and the scene span
the technique table (the one list of named techniques: snell-lab's
  --technique names, the benchmarks and the tests all draw on it; names and
  labels for C++ in include/snell/technique_table.hpp):
  id                              name            preset
  SNELL_TECHNIQUE_SINGLE          single          snellPresetSingleSample()
  SNELL_TECHNIQUE_PLANE_NORMAL_0  plane-normal-0  snellPresetPlaneNormal(0)
  SNELL_TECHNIQUE_PLANE_NORMAL_1  plane-normal-1  snellPresetPlaneNormal(1)
  SNELL_TECHNIQUE_PLANE_NORMAL_2  plane-normal-2  snellPresetPlaneNormal(2)
  SNELL_TECHNIQUE_PLANE_DEPTH     plane-depth     snellPresetPlaneDepth(1)
  SNELL_TECHNIQUE_DIR             dir             snellPresetDir()
  SNELL_TECHNIQUE_ISR             isr             snellPresetIsr()
  SNELL_TECHNIQUE_LINEAR_MARCH    linear-march    snellPresetLinearMarch()
  SNELL_TECHNIQUE_DDA             dda             snellPresetDdaMarch()
  SNELL_TECHNIQUE_IMAGE_SPACE_BOUND  image-space-bound  snellPresetImageSpaceBound()
  SNELL_TECHNIQUE_PLANE_NORMAL_2_BOUNCES  plane-normal-2-bounces  snellPresetPlaneNormalBounces(2)
  SNELL_TECHNIQUE_LINEAR_MARCH_BOUNCES    linear-march-bounces    snellPresetLinearMarchBounces()
  SNELL_TECHNIQUE_IMAGE_SPACE_BOUND_BOUNCES  image-space-bound-bounces  snellPresetImageSpaceBoundBounces()
  SNELL_TECHNIQUE_COUNT           the number of ids (ids are 0 .. COUNT - 1)
  SnellTechnique t = snellTechniquePreset(SNELL_TECHNIQUE_PLANE_NORMAL_1);
  Adding a technique: a preset function here, an id, a branch in
  snellTechniquePreset and a row in include/snell/technique_table.hpp (a
  compile-time check there keeps the two the same length).
options: the defaults of technique_options.glsl and of each strategy's file.
contract: pure constructors, no texture access; iteration counts are stored as
  given (each strategy clamps them). snellTechniquePreset of an id outside
  0 .. SNELL_TECHNIQUE_COUNT - 1: snellTechniquePresetSlots(-1, -1), whose
  slots answer every ray with a miss (snellIntersectWith).
source: Oliveira & Brauwers 2007 (sec. 3.3, 5 steps; sec. 6, bounding box);
  Wyman 2005 via O&B 2007 sec. 2.1, eqs. 1-2; Mayer & Assarsson,
  "Constant-Time Light Refraction Simulation" (methods 1 and 2, step 5);
  McGuire & Mara 2014 (DDA); Davis & Wyman 2007 (bounces inside between
  front and back depth maps).
*/
#ifndef SNELL_SHADE_TECHNIQUE_PRESETS_GLSL
#define SNELL_SHADE_TECHNIQUE_PRESETS_GLSL
#include "../prelude.glsl"
#include "technique_options.glsl"

SNELL_FN SnellTechnique snellTechniquePresetSlots(int backStrategy, int exitStrategy) {
  SnellTechnique t = snellTechnique();
  t.back.intersect = snellIntersectOptions(backStrategy);
  t.exit.intersect = snellIntersectOptions(exitStrategy);
  return t;
}

/* Oliveira & Brauwers 2007, sec. 3.3: CBS with c = 5 (SNELL_CBS_STEPS' default) */
SNELL_FN SnellTechnique snellPresetDir() {
  return snellTechniquePresetSlots(SNELL_STRATEGY_CBS, SNELL_STRATEGY_CBS);
}

/* Oliveira & Brauwers 2007, sec. 6: bounding-box range instead of the reduction */
SNELL_FN SnellTechnique snellPresetDirBounds(float zNearest, float zFarthest) {
  SnellTechnique t = snellPresetDir();
  t.back.intersect.rangeSource = SNELL_RANGE_EXPLICIT;
  t.back.intersect.range.zNearest = zNearest;
  t.back.intersect.range.zFarthest = zFarthest;
  t.back.intersect.range.valid = true;
  return t;
}

/* Wyman 2005 (O&B 2007 eqs. 1-2): the trace's Wyman variant; the exit slot samples once */
SNELL_FN SnellTechnique snellPresetIsr() {
  SnellTechnique t = snellTechniquePresetSlots(SNELL_STRATEGY_SINGLE, SNELL_STRATEGY_SINGLE);
  t.back.source = SNELL_SOURCE_WYMAN;
  return t;
}

/* Mayer & Assarsson, method 1 + step 5 */
SNELL_FN SnellTechnique snellPresetPlaneNormal(int iterations) {
  SnellTechnique t = snellTechniquePresetSlots(SNELL_STRATEGY_PLANE_NORMAL, SNELL_STRATEGY_PLANE_NORMAL);
  t.back.intersect.planeIterations = iterations;
  t.exit.intersect.planeIterations = iterations;
  return t;
}

/* Mayer & Assarsson, method 2 + step 5 */
SNELL_FN SnellTechnique snellPresetPlaneDepth(int iterations) {
  SnellTechnique t = snellTechniquePresetSlots(SNELL_STRATEGY_PLANE_DEPTH, SNELL_STRATEGY_PLANE_DEPTH);
  t.back.intersect.planeIterations = iterations;
  t.exit.intersect.planeIterations = iterations;
  return t;
}

SNELL_FN SnellTechnique snellPresetSingleSample() {
  return snellTechniquePresetSlots(SNELL_STRATEGY_SINGLE, SNELL_STRATEGY_SINGLE);
}

SNELL_FN SnellTechnique snellPresetLinearMarch() {
  return snellTechniquePresetSlots(SNELL_STRATEGY_LINEAR_MARCH, SNELL_STRATEGY_LINEAR_MARCH);
}

SNELL_FN SnellTechnique snellPresetDdaMarch() {
  return snellTechniquePresetSlots(SNELL_STRATEGY_DDA, SNELL_STRATEGY_DDA);
}

/* The image-space bound: the linear march at its limits, both slots. */
SNELL_FN SnellTechnique snellPresetImageSpaceBound() {
  SnellTechnique t = snellTechniquePresetSlots(SNELL_STRATEGY_LINEAR_MARCH, SNELL_STRATEGY_LINEAR_MARCH);
  t.back.intersect.marchSteps = SNELL_LINEAR_MARCH_MAX_STEPS;
  t.back.intersect.marchBisections = SNELL_LINEAR_MARCH_MAX_REFINE_STEPS;
  t.exit.intersect.marchSteps = SNELL_LINEAR_MARCH_MAX_STEPS;
  t.exit.intersect.marchBisections = SNELL_LINEAR_MARCH_MAX_REFINE_STEPS;
  t.back.intersect.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
  t.exit.intersect.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
  return t;
}

#ifndef SNELL_PRESET_BOUNCES
#  define SNELL_PRESET_BOUNCES 4
#endif
#ifndef SNELL_PRESET_INSIDE_STEPS
#  define SNELL_PRESET_INSIDE_STEPS 16
#endif
#ifndef SNELL_PRESET_INSIDE_BISECTIONS
#  define SNELL_PRESET_INSIDE_BISECTIONS 5
#endif

/* Davis & Wyman 2007 on the normal plane: TIR at the back face followed inside (the inside march between
   the front and back layers) up to SNELL_PRESET_BOUNCES times */
SNELL_FN SnellTechnique snellPresetPlaneNormalBounces(int iterations) {
  SnellTechnique t = snellPresetPlaneNormal(iterations);
  t.bounces = SNELL_PRESET_BOUNCES;
  t.inside.intersect.marchSteps = SNELL_PRESET_INSIDE_STEPS;
  t.inside.intersect.marchBisections = SNELL_PRESET_INSIDE_BISECTIONS;
  return t;
}

/* The linear march in the back and exit slots, with bounces as snellPresetPlaneNormalBounces */
SNELL_FN SnellTechnique snellPresetLinearMarchBounces() {
  SnellTechnique t = snellPresetLinearMarch();
  t.bounces = SNELL_PRESET_BOUNCES;
  t.inside.intersect.marchSteps = SNELL_PRESET_INSIDE_STEPS;
  t.inside.intersect.marchBisections = SNELL_PRESET_INSIDE_BISECTIONS;
  return t;
}

/* The image-space bound that follows TIR inside: the inside march exhaustive as well, so a bounce technique's
   "x bound" compares it with the best any image-space method does on the same buffers and bounce count */
SNELL_FN SnellTechnique snellPresetImageSpaceBoundBounces() {
  SnellTechnique t = snellPresetImageSpaceBound();
  t.bounces = SNELL_PRESET_BOUNCES;
  t.inside.intersect.marchSteps = SNELL_LINEAR_MARCH_MAX_STEPS;
  t.inside.intersect.marchBisections = SNELL_LINEAR_MARCH_MAX_REFINE_STEPS;
  return t;
}

#define SNELL_TECHNIQUE_SINGLE 0
#define SNELL_TECHNIQUE_PLANE_NORMAL_0 1
#define SNELL_TECHNIQUE_PLANE_NORMAL_1 2
#define SNELL_TECHNIQUE_PLANE_NORMAL_2 3
#define SNELL_TECHNIQUE_PLANE_DEPTH 4
#define SNELL_TECHNIQUE_DIR 5
#define SNELL_TECHNIQUE_ISR 6
#define SNELL_TECHNIQUE_LINEAR_MARCH 7
#define SNELL_TECHNIQUE_DDA 8
#define SNELL_TECHNIQUE_IMAGE_SPACE_BOUND 9
#define SNELL_TECHNIQUE_PLANE_NORMAL_2_BOUNCES 10
#define SNELL_TECHNIQUE_LINEAR_MARCH_BOUNCES 11
#define SNELL_TECHNIQUE_IMAGE_SPACE_BOUND_BOUNCES 12
#define SNELL_TECHNIQUE_COUNT 13

/* the technique table's constructor: id -> preset */
SNELL_FN SnellTechnique snellTechniquePreset(int technique) {
  if (technique == SNELL_TECHNIQUE_SINGLE) {
    return snellPresetSingleSample();
  }
  if (technique == SNELL_TECHNIQUE_PLANE_NORMAL_0) {
    return snellPresetPlaneNormal(0);
  }
  if (technique == SNELL_TECHNIQUE_PLANE_NORMAL_1) {
    return snellPresetPlaneNormal(1);
  }
  if (technique == SNELL_TECHNIQUE_PLANE_NORMAL_2) {
    return snellPresetPlaneNormal(2);
  }
  if (technique == SNELL_TECHNIQUE_PLANE_DEPTH) {
    return snellPresetPlaneDepth(1);
  }
  if (technique == SNELL_TECHNIQUE_DIR) {
    return snellPresetDir();
  }
  if (technique == SNELL_TECHNIQUE_ISR) {
    return snellPresetIsr();
  }
  if (technique == SNELL_TECHNIQUE_LINEAR_MARCH) {
    return snellPresetLinearMarch();
  }
  if (technique == SNELL_TECHNIQUE_DDA) {
    return snellPresetDdaMarch();
  }
  if (technique == SNELL_TECHNIQUE_IMAGE_SPACE_BOUND) {
    return snellPresetImageSpaceBound();
  }
  if (technique == SNELL_TECHNIQUE_PLANE_NORMAL_2_BOUNCES) {
    return snellPresetPlaneNormalBounces(2);
  }
  if (technique == SNELL_TECHNIQUE_LINEAR_MARCH_BOUNCES) {
    return snellPresetLinearMarchBounces();
  }
  if (technique == SNELL_TECHNIQUE_IMAGE_SPACE_BOUND_BOUNCES) {
    return snellPresetImageSpaceBoundBounces();
  }
  return snellTechniquePresetSlots(-1, -1);
}

#endif
