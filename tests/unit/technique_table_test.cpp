// The technique table (shade/technique_presets.glsl ids and constructor,
// include/snell/technique_table.hpp names): the names users and scripts rely
// on, one row per id in id order, and each id's preset checked against what
// the papers prescribe (strategy and step count per slot), not against the
// table's own constructor.
#include <snell/technique_table.hpp>

#include <gtest/gtest.h>

#include <set>
#include <string>

using namespace snell;

namespace {

struct Expected {
  const char* name;
  int backSource;  // SNELL_SOURCE_BUFFERS or SNELL_SOURCE_WYMAN
  int back, backSteps, exit, exitSteps;  // steps: the strategy's own count (iterations, steps); 0 for single sample
  int bounces = 0;                       // total internal reflections followed inside the object
};

// snell-lab --technique names and table.json "technique" values: scripts and saved tables use them, keep them.
const Expected kExpected[] = {
    {"single", SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_SINGLE, 0, SNELL_STRATEGY_SINGLE, 0},
    {"plane-normal-0", SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_PLANE_NORMAL, 0, SNELL_STRATEGY_PLANE_NORMAL, 0},
    {"plane-normal-1", SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_PLANE_NORMAL, 1, SNELL_STRATEGY_PLANE_NORMAL, 1},
    {"plane-normal-2", SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_PLANE_NORMAL, 2, SNELL_STRATEGY_PLANE_NORMAL, 2},
    {"plane-depth", SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_PLANE_DEPTH, 1, SNELL_STRATEGY_PLANE_DEPTH, 1},
    {"dir", SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_CBS, 5, SNELL_STRATEGY_CBS, 5},  // O&B 2007 sec. 3.3: c = 5
    {"isr", SNELL_SOURCE_WYMAN, SNELL_STRATEGY_SINGLE, 0, SNELL_STRATEGY_SINGLE, 0},  // Wyman 2005: d_V, d_N
    {"linear-march", SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_LINEAR_MARCH, 32, SNELL_STRATEGY_LINEAR_MARCH, 32},
    {"dda", SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_DDA, 256, SNELL_STRATEGY_DDA, 256},
    {"image-space-bound", SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_LINEAR_MARCH, 512, SNELL_STRATEGY_LINEAR_MARCH, 512},
    // Davis & Wyman 2007's bounces inside on the normal plane and the linear march.
    {"plane-normal-2-bounces", SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_PLANE_NORMAL, 2, SNELL_STRATEGY_PLANE_NORMAL, 2, 4},
    {"linear-march-bounces", SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_LINEAR_MARCH, 32, SNELL_STRATEGY_LINEAR_MARCH, 32, 4},
    // The bound of the bounce rows: the same bounce count, every march (the inside one too) at its limits.
    {"image-space-bound-bounces", SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_LINEAR_MARCH, 512, SNELL_STRATEGY_LINEAR_MARCH,
     512, 4},
};

// The count each strategy is known by (what the lab's labels and the papers name).
int mainCount(const SnellIntersectOptions& o) {
  switch (o.strategy) {
    case SNELL_STRATEGY_PLANE_NORMAL:
    case SNELL_STRATEGY_PLANE_DEPTH: return o.planeIterations;
    case SNELL_STRATEGY_CBS: return o.cbsSteps;
    case SNELL_STRATEGY_LINEAR_MARCH: return o.marchSteps;
    case SNELL_STRATEGY_DDA: return o.ddaSteps;
    default: return 0;
  }
}

}  // namespace

TEST(TechniqueTable, OneRowPerIdInIdOrderWithTheDocumentedNames) {
  const auto& table = snellTechniqueTable();
  ASSERT_EQ(table.size(), sizeof kExpected / sizeof kExpected[0]);
  std::set<std::string> names, labels;
  for (std::size_t i = 0; i < table.size(); ++i) {
    EXPECT_EQ(table[i].id, static_cast<int>(i));
    EXPECT_STREQ(table[i].name, kExpected[i].name);
    EXPECT_TRUE(names.insert(table[i].name).second) << table[i].name;
    EXPECT_TRUE(labels.insert(table[i].label).second) << table[i].label;
    EXPECT_EQ(snellFindTechnique(table[i].name), &table[i]);
  }
  EXPECT_EQ(snellFindTechnique("plane-normal"), nullptr);
  EXPECT_EQ(snellFindTechnique(""), nullptr);
}

TEST(TechniqueTable, EachPresetHasThePublishedSlots) {
  for (const SnellTechniqueInfo& t : snellTechniqueTable()) {
    const Expected& e = kExpected[t.id];
    const SnellTechnique o = snellTechniquePreset(t.id);
    EXPECT_EQ(o.back.source, e.backSource) << t.name;
    EXPECT_EQ(o.back.intersect.strategy, e.back) << t.name;
    EXPECT_EQ(mainCount(o.back.intersect), e.backSteps) << t.name;
    EXPECT_EQ(o.exit.intersect.strategy, e.exit) << t.name;
    EXPECT_EQ(mainCount(o.exit.intersect), e.exitSteps) << t.name;
    EXPECT_EQ(o.bounces, e.bounces) << t.name;
    EXPECT_EQ(snellTechniqueBounces(t), e.bounces) << t.name;
    EXPECT_EQ(o.inside.source, SNELL_SOURCE_BUFFERS) << t.name;
    EXPECT_EQ(o.inside.intersect.strategy, SNELL_STRATEGY_LINEAR_MARCH) << t.name;
    EXPECT_EQ(o.back.intersect.rangeSource, SNELL_RANGE_PYRAMID) << t.name;
    // A preset chooses strategies only: the exit and reflect slots keep the environment, whatever the host
    // points them at.
    EXPECT_EQ(o.exit.source, SNELL_SOURCE_ENVIRONMENT) << t.name;
    EXPECT_EQ(o.reflect.source, SNELL_SOURCE_ENVIRONMENT) << t.name;
    EXPECT_EQ(o.exit.fallback, SNELL_FALLBACK_ENVIRONMENT) << t.name;
  }
}

TEST(TechniqueTable, AnIdOutsideTheTableMissesEveryRay) {
  for (int id : {-1, SNELL_TECHNIQUE_COUNT, 1000}) {
    const SnellTechnique o = snellTechniquePreset(id);
    EXPECT_EQ(o.back.intersect.strategy, -1);
    EXPECT_EQ(o.exit.intersect.strategy, -1);
  }
}

TEST(TechniqueTable, DescriptionsComeFromTheOptions) {
  const SnellTechniqueInfo& dir = snellTechniqueTable()[SNELL_TECHNIQUE_DIR];
  EXPECT_EQ(snellDescribeTechnique(dir),
            "Oliveira & Brauwers 2007, conservative binary search; back faces: conservative binary search, 5 steps, "
            "range from the pyramid; exit: the same");
  SnellIntersectOptions march = snellIntersectOptions(SNELL_STRATEGY_LINEAR_MARCH);
  march.marchMaxDistance = 2.5f;
  EXPECT_EQ(snellDescribeIntersect(march), "linear march, 32 view-space steps + 4 bisections over 2.5");
  EXPECT_EQ(snellDescribeIntersect(snellIntersectOptions(-1)), "no strategy (every ray misses)");
  EXPECT_EQ(snellDescribeTechnique(snellTechniqueTable()[SNELL_TECHNIQUE_ISR]),
            "Wyman 2005, distance interpolation; back faces: distance interpolation between d_V and the per-vertex "
            "d_N; exit: single sample");
  // A technique that bounces names its inside slot; the plane inside names its bracket and its planes.
  EXPECT_EQ(snellDescribeTechnique(snellTechniqueTable()[SNELL_TECHNIQUE_LINEAR_MARCH_BOUNCES]),
            "linear march that follows TIR inside (Davis & Wyman 2007: a march between front and back depth); back "
            "faces: linear march, 32 view-space steps + 4 bisections over 10; exit: the same; inside: 4 bounces, each "
            "a march of 16 steps + 5 bisections between the front and back layers");
  SnellTechnique plane = snellPresetPlaneNormalBounces(2);
  plane.inside.intersect.strategy = SNELL_STRATEGY_PLANE_NORMAL;
  plane.inside.intersect.planeIterations = 2;
  EXPECT_EQ(snellDescribeInside(plane), "4 bounces, each a march of 16 steps between the front and back layers, then "
                                        "the normal plane, 2 iterations");
  plane.inside.intersect.strategy = SNELL_STRATEGY_CBS;
  EXPECT_EQ(snellDescribeInside(plane), "4 bounces, none followed (the inside slot has no strategy that works from inside)");
}

TEST(TechniqueTable, StrategiesUsedNamesTheSlotsTheOptionsCall) {
  SnellTechnique o = snellTechnique();
  SnellMaterial m = snellMaterial();
  o.back.intersect = snellIntersectOptions(SNELL_STRATEGY_CBS);
  o.exit.intersect = snellIntersectOptions(SNELL_STRATEGY_DDA);
  o.reflect.intersect = snellIntersectOptions(SNELL_STRATEGY_SINGLE);
  // The defaults: exit to the environment, reflection of the environment: the back slot alone.
  EXPECT_EQ(snellStrategiesUsed(o, m), 1 << SNELL_STRATEGY_CBS);
  o.exit.source = SNELL_SOURCE_BUFFERS;
  EXPECT_EQ(snellStrategiesUsed(o, m), (1 << SNELL_STRATEGY_CBS) | (1 << SNELL_STRATEGY_DDA));
  o.reflect.source = SNELL_SOURCE_BUFFERS;
  EXPECT_EQ(snellStrategiesUsed(o, m), (1 << SNELL_STRATEGY_CBS) | (1 << SNELL_STRATEGY_DDA) | 1);
  m.reflection = false;
  EXPECT_EQ(snellStrategiesUsed(o, m), (1 << SNELL_STRATEGY_CBS) | (1 << SNELL_STRATEGY_DDA));
  o.back.source = SNELL_SOURCE_WYMAN;  // Wyman's distance replaces the back slot's intersector
  EXPECT_EQ(snellStrategiesUsed(o, m), 1 << SNELL_STRATEGY_DDA);
  o.back.source = SNELL_SOURCE_ENVIRONMENT;  // no back faces read at all
  EXPECT_EQ(snellStrategiesUsed(o, m), 1 << SNELL_STRATEGY_DDA);
  // No strategy (an id outside the table) and ids past the last add nothing: no shift by a negative count.
  o.back.source = SNELL_SOURCE_BUFFERS;
  m.reflection = true;
  o.back.intersect = snellIntersectOptions(-1);
  o.exit.intersect = snellIntersectOptions(SNELL_STRATEGY_COUNT);
  o.reflect.intersect = snellIntersectOptions(1 << 30);
  EXPECT_EQ(snellStrategiesUsed(o, m), 0);
  // Every preset with both scene slots on: the strategies kExpected names (ISR: the exit slot only).
  for (const SnellTechniqueInfo& t : snellTechniqueTable()) {
    SnellTechnique p = snellTechniquePreset(t.id);
    p.exit.source = SNELL_SOURCE_BUFFERS;
    const Expected& e = kExpected[t.id];
    EXPECT_EQ(snellStrategiesUsed(p, snellMaterial()),
              (e.backSource == SNELL_SOURCE_WYMAN ? 0 : 1 << e.back) | (1 << e.exit))
        << t.name;
  }
}

// What a host reads from the rows instead of ids and names: one cost unit
// (single sample, the GPU Gems baseline every time ratio is to), one poster row
// (Mayer & Assarsson's published comparison is normal plane, 1 iteration, vs
// single sample), the references (the image-space bound, and the bound with bounces), and d_N exactly for
// Wyman's method (kExpected's back method, not the table's).
TEST(TechniqueTable, RowsSayWhatAHostTreatsSpecially) {
  int units = 0, posters = 0, references = 0;
  for (const SnellTechniqueInfo& t : snellTechniqueTable()) {
    const Expected& e = kExpected[t.id];
    units += t.costUnit;
    posters += t.posterRow;
    references += t.kind == SnellTechniqueKind::Reference;
    EXPECT_EQ(t.costUnit, std::string(e.name) == "single") << e.name;
    EXPECT_EQ(t.posterRow, std::string(e.name) == "plane-normal-1") << e.name;
    EXPECT_EQ(t.kind == SnellTechniqueKind::Reference, std::string(e.name).rfind("image-space-bound", 0) == 0) << e.name;
    EXPECT_EQ(snellTechniqueNeedsDn(t), e.backSource == SNELL_SOURCE_WYMAN) << e.name;
    EXPECT_EQ(snellFindTechnique(t.id), &t);
  }
  EXPECT_EQ(units, 1);
  EXPECT_EQ(posters, 1);
  EXPECT_EQ(references, 2);  // one per bounce count a row follows: 0 and SNELL_PRESET_BOUNCES
  EXPECT_EQ(snellFindTechnique(SNELL_TECHNIQUE_COUNT), nullptr);
  EXPECT_EQ(snellFindTechnique(-1), nullptr);
}

// "x bound" keeps its meaning for the bounce rows: their bound follows as many bounces, and its inside
// march is as exhaustive as its back and exit marches; every other slot is the two-interface bound's.
TEST(TechniqueTable, TheBoundWithBouncesIsTheBoundThatMarchesInsideAtItsLimits) {
  const SnellTechnique b = snellPresetImageSpaceBound(), bb = snellPresetImageSpaceBoundBounces();
  EXPECT_EQ(bb.bounces, snellPresetPlaneNormalBounces(2).bounces);
  EXPECT_EQ(bb.inside.intersect.marchSteps, SNELL_LINEAR_MARCH_MAX_STEPS);
  EXPECT_EQ(bb.inside.intersect.marchBisections, SNELL_LINEAR_MARCH_MAX_REFINE_STEPS);
  EXPECT_GT(bb.inside.intersect.marchSteps, snellPresetPlaneNormalBounces(2).inside.intersect.marchSteps);
  EXPECT_EQ(bb.back.intersect.marchSteps, b.back.intersect.marchSteps);
  EXPECT_EQ(bb.back.intersect.depthFilter, b.back.intersect.depthFilter);
  EXPECT_EQ(bb.exit.intersect.marchSteps, b.exit.intersect.marchSteps);
  EXPECT_EQ(bb.exit.intersect.marchBisections, b.exit.intersect.marchBisections);
}
