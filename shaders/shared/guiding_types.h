// Q-learned importance sampling (Dahm & Keller 2017; van Mastrigt 2018): GPU
// structs, the update pass's bindings, and the learning-rate arithmetic, shared
// by GLSL and C++. The guide's bindings in the path passes are in bindings.h.
#ifndef QLIGHT_SHARED_GUIDING_TYPES_H
#define QLIGHT_SHARED_GUIDING_TYPES_H
#include "bindings.h"
#include "common.h"
#include "dqn.h"

QL_BEGIN

// A cache point: a surface point with a hemisphere of strata. Its index in the
// point array is its slot in the learned tables, kept for the point's lifetime
// (engine/guiding/cache_point_set.h).
struct GpuCachePoint {
  vec3 position;
  float radius;  // rejection distance it was accepted with
  vec3 normal;
  uint pad;  // CachePoint keeps its slot here (unread by the shaders)
};
QL_CHECK_SIZE(GpuCachePoint, 32);

// Guiding switches (GuidingUniforms.flags).
QL_CONST uint kGuideSample = 1u;      // sample directions from the learned distributions
QL_CONST uint kGuideLearn = 2u;       // update Q from the paths traced this frame
QL_CONST uint kGuideLightLearn = 4u;  // learn light selection V(point, light) and use it for NEE
QL_CONST uint kGuideSpawn = 8u;       // report camera hits with no cache point nearby
// Learn Q from the radiance each vertex's direction actually received (NEE
// included) once the path is done, instead of D&K's one-step TD target.
QL_CONST uint kGuideLearnReturns = 16u;
// Directions as a quadtree per point (shared/direction_tree.h) instead of rows x cols strata.
QL_CONST uint kGuideTree = 32u;
// Directions from the deep Q network at the vertex itself (shared/dqn.h), not from a point.
QL_CONST uint kGuideDqn = 64u;
// NEE at a point with the probability its shadow rays have shown they pay (neeProbabilityOf).
QL_CONST uint kGuideNeeLearn = 128u;
// Russian roulette by the path's expected contribution from Q (pt_shade.comp), not its throughput.
QL_CONST uint kGuideRoulette = 256u;

struct GuidingUniforms {
  uint rows;  // strata rows (equal-height zones in cos theta)
  uint cols;  // strata columns (phi segments)
  uint pointCount;
  uint flags;
  float searchRadius;       // nearest-point search radius
  float cellSize;           // hashed grid cell (searchRadius; lists the points within reach)
  uint hashSize;            // buckets (power of two)
  float selectProbability;  // chance of a guided sample (scaled by the diffuse share)
  float normalCosine;       // a point is compatible when dot(normals) >= this
  float qFloor;             // every Q stays above this, so every direction stays possible
  float lightMix;           // share of the learned light choice (the rest by power)
  uint lightCount;          // lights with learned values (0: light learning off)
  uint spawnCapacity;       // slots in the spawn buffer (fixed slot per pixel group)
  float alphaMin;
  float alphaMax;
  // Updates per stratum a point needs before it guides at the full share: a
  // point with fewer updates has an unreliable Q and samples mostly by the BSDF.
  float confidenceUpdates;
  uint treeNodes;           // nodes per point (kGuideTree)
  float neeMinProbability;  // kGuideNeeLearn: NEE's probability where no shadow ray got through
  uint pad1, pad2;
  DqnUniforms dqn;  // the network (kGuideDqn)
};
QL_CHECK_SIZE(GuidingUniforms, 144);

QL_CONST uint kNoCachePoint = 0xffffffffu;

// Bucket of a grid cell in the hashed grid of cache points (CPU build and GPU
// lookup must agree, so both use this).
QL_FN uint gridCellHash(ivec3 c, uint hashSize) {
  return (uint(c.x) * 73856093u ^ uint(c.y) * 19349663u ^ uint(c.z) * 83492791u) & (hashSize - 1u);
}

// Bindings and push constants of q_update.comp (used for Q and for the light
// values V): one table's values, visit counts, CDFs (the output) and
// fixed-point target sums and counts, and the per-point update counts. One
// thread per row (a point's strata or lights): it applies the row's targets
// and rebuilds the row's CDF, and skips rows that received none.
#define QL_Q_UPDATE_BIND_VALUES 0
#define QL_Q_UPDATE_BIND_VISITS 1
#define QL_Q_UPDATE_BIND_CDF 2
#define QL_Q_UPDATE_BIND_SUMS 3
#define QL_Q_UPDATE_BIND_COUNTS 4
#define QL_Q_UPDATE_BIND_POINT_UPDATES 5
#define QL_Q_UPDATE_BIND_ROW_CLOCKS 6  // the forgetting clock at each row's last update
#define QL_Q_UPDATE_BIND_CHILDREN 7    // the direction tree's child slots (q_tree_update.comp)
#define QL_Q_UPDATE_GROUP_SIZE 64

struct TableUpdatePush {
  uint rowCount;       // workgroups: one per row
  uint segmentLength;  // entries per row (at most kMaxStrata)
  uint rows;           // strata rows and columns when cosineWeights is set
  uint cols;
  uint cosineWeights;  // 1: CDF of Q_k cosInt_k (Q, counts its point's updates); 0: of the values
                       // (V)
  float alphaMin;
  float alphaMax;
  float floorValue;
  uint everyRow;       // 1: rebuild the CDF of rows without targets too (after a reset)
  float clock;         // tracking's forgetting clock (halvings so far; a row ages by its advance)
  uint confidenceCap;  // a point's update count stops here (confidenceCapOf; 0: no cap)
  uint pad0;
};
QL_CHECK_SIZE(TableUpdatePush, 48);

// Push constants of q_tree_update.comp: the learning pass of direction trees, one thread
// per point (its CDF is the slots' sampling weights).
struct TreeUpdatePush {
  uint rowCount;  // points
  uint nodes;     // nodes per point
  float alphaMin;
  float alphaMax;
  float floorValue;
  uint everyRow;       // 1: also the points without targets (after a reset)
  float clock;         // as TableUpdatePush
  float splitShare;    // a leaf with more of its point's weight than this splits
  uint splitVisits;    // ... once it has had this many visits
  uint maxDepth;       // node levels, root included
  uint confidenceCap;  // as TableUpdatePush
  uint pad0;
};
QL_CHECK_SIZE(TreeUpdatePush, 48);

// Push constants of guiding_darts.comp: light paths whose hits are candidate
// points (written to QL_BIND_DART_CANDIDATES).
struct DartsPush {
  uint pathCount;
  uint maxBounces;
  uint lightCount;
  uint seed;
  vec3 sceneCenter;
  float sceneRadius;
  float aoRadius;
  uint aoRays;
  uint capacity;
  uint pad;
};
QL_CHECK_SIZE(DartsPush, 48);

// Targets are summed as 64-bit fixed point (two uint words, 20 fraction bits):
// integer addition does not depend on the order the GPU's atomics run in, so
// learning, and therefore rendering, is the same for the same seed.
QL_CONST float kTargetScale = 1048576.0f;  // 2^20
QL_CONST float kTargetMax = 1.0e9f;        // larger targets are clamped
QL_CONST float kTwoPow32 = 4294967296.0f;

QL_FN float fixedSumToFloat(uint lo, uint hi) {
  return float(hi) * (kTwoPow32 / kTargetScale) + float(lo) / kTargetScale;
}

// Learning rate of update n (n earlier updates): clamp(1 / (1 + n), min, max).
QL_FN float learningRate(uint n, float alphaMin, float alphaMax) {
  return clamp(1.0f / (1.0f + float(n)), alphaMin, alphaMax);
}

// The fraction of the old value left after m updates starting at visit
// count n0: prod_{i<m} (1 - learningRate(n0 + i)). Closed form: constant
// factors where the rate is clamped, and a telescoping n / (n + 1) product
// where it is 1 / (1 + n). With it, m updates of one frame apply at once:
//   Q <- keep Q + (1 - keep) mean(targets)
// which equals applying them one by one when the targets are equal, and for
// the unclamped 1/(1+n) schedule is exactly the running mean of all targets.
QL_FN float retainedAfterUpdates(uint n0, uint m, float alphaMin, float alphaMax) {
  if (m == 0u) return 1.0f;
  // Rate alphaMax for n < nA, 1/(1+n) for nA <= n < nC, alphaMin for n >= nC.
  float nAf = alphaMax >= 1.0f ? 0.0f : ceil(1.0f / alphaMax - 1.0f);
  float nCf = alphaMin > 0.0f ? floor(1.0f / alphaMin - 1.0f) + 1.0f : 4.0e9f;
  nCf = max(nCf, nAf);
  float lo = float(n0);
  float hi = float(n0) + float(m);  // exclusive
  float countA = max(0.0f, min(hi, nAf) - lo);
  float b0 = max(lo, nAf);
  float b1 = min(hi, nCf);
  float countC = max(0.0f, hi - max(lo, nCf));
  float keep = 1.0f;
  if (countA > 0.0f) keep *= pow(1.0f - alphaMax, countA);
  if (b1 > b0) keep *= b0 / b1;
  if (countC > 0.0f) keep *= pow(1.0f - alphaMin, countC);
  return keep;
}

// The share of its point's update count (its confidence) a row keeps after the forgetting
// clock advanced `halvings` since its last update, and a count after it.
QL_FN float keptAfter(float halvings) { return halvings > 0.0f ? exp2(-halvings) : 1.0f; }
QL_FN uint agedCount(uint count, float kept) {
  return kept < 1.0f ? uint(float(count) * kept) : count;
}

// The share of its visit counts a row keeps: the square of the confidence's, i.e. Q forgets
// twice as fast. The confidence comes back after 4 updates a stratum; by then Q must hold
// mostly new targets, or after a light's jump a point guides at full share by what it learned
// of the old light (tracking study, docs/guiding_log.md: the 6 frames after the jump went from
// 1.03-1.12x unguided's error to 0.90-1.00x).
QL_FN float visitsKeptOf(float kept) { return kept * kept; }

// A point's update count stops where its confidence reaches 1: counted beyond, a point that
// had seen thousands of updates would keep full confidence through a light's jump however
// much forgetting ages the count. 0: no cap (confidenceUpdates 0 trusts every point at once).
QL_FN uint confidenceCapOf(float confidenceUpdates, uint strata) {
  return confidenceUpdates > 0.0f ? uint(ceil(confidenceUpdates * float(strata))) : 0u;
}
QL_FN uint cappedUpdates(uint agedUpdates, uint targets, uint cap) {
  uint n = agedUpdates + targets;
  return cap > 0u ? min(n, cap) : n;
}

// How far a point's learned distribution can be trusted: 0 without updates, 1 after
// confidenceUpdates per stratum (0: at once).
QL_FN float confidenceOf(uint updates, float confidenceUpdates, uint strata) {
  if (confidenceUpdates <= 0.0f) return 1.0f;
  return min(1.0f, float(updates) / (confidenceUpdates * float(strata)));
}

// --- learned NEE probability (kGuideNeeLearn) ---
// Where a point's shadow rays are all blocked (a room lit only through a gap), NEE costs a
// ray and a light sample and adds nothing. Each point counts its shadow rays and those that
// got through; NEE then runs with probability p, at least minProbability, and the light's
// selection pdf carries p, so NEE's contribution is divided by it and the MIS weights of
// both techniques use it: unbiased for any p > 0. p is 1 until the counts say otherwise,
// and 1 wherever more than 1/kNeeBoost of the rays get through.
QL_CONST float kNeeBoost = 8.0f;
// The running counts stop at this many rays, so a point's p follows a light that moves.
QL_CONST float kNeeWindow = 256.0f;

// What a point's light is in view of changes faster than where its light comes from: a light
// that moves a little can leave or enter a point's view through a gap. So the counts forget
// kNeeForgetScale times faster than tracking's half-life, and kNeeHalvingsPerRadius times
// per scene radius a light moves whatever tracking's own rate (with tracking off too): a jump
// forgets them all, and a point that was in the dark does not keep skipping NEE at a light
// that has come into view.
QL_CONST float kNeeForgetScale = 8.0f;
QL_CONST float kNeeHalvingsPerRadius = 32.0f;  // 8x the demo's forgetOnLightMove

// Per point, 4 words: this frame's shadow rays and those unoccluded (atomic counts, by the
// trace pass), then the running counts as floats (by nee_update.comp).
QL_CONST uint kNeeWordsPerPoint = 4u;

QL_FN float neeProbabilityOf(float rays, float unoccluded, float minProbability) {
  if (minProbability >= 1.0f) return 1.0f;
  return clamp(kNeeBoost * (unoccluded + 1.0f) / (rays + 1.0f), minProbability, 1.0f);
}

// Guided Russian roulette (kGuideRoulette, pt_shade.comp): a path survives with a
// probability that follows its expected contribution from here on, its throughput's luminance
// times Q in the direction it took, over what its first vertex expected, as in Vorba and
// Krivanek's adjoint-driven roulette (without its splitting). A guided direction toward the
// light has a small throughput because its pdf is large: a throughput roulette ends exactly
// the paths guiding found. Paths expected to bring at least 1/kRouletteWindow of the first
// vertex's estimate are kept (ADRRS's lower weight-window bound with s = 5; on the door scene
// 2 and 4 did as well); the floor bounds a survivor's weight where Q underestimates; the
// point's confidence mixes in the throughput's probability.
QL_CONST float kRouletteWindow = 3.0f;
QL_CONST float kRouletteMinSurvival = 0.05f;
QL_CONST float kRouletteMaxSurvival = 0.95f;  // every path ends (the throughput roulette's cap)

// throughputSurvival: the throughput roulette's (its largest channel); expected: luminance of
// the throughput x Q in the direction taken; firstVertex (> 0): the first vertex's estimate.
QL_FN float guidedSurvivalProbability(float throughputSurvival, float expected, float firstVertex,
                                      float confidence) {
  float guided = kRouletteWindow * expected / firstVertex;
  return min(max(mix(throughputSurvival, guided, confidence), kRouletteMinSurvival),
             kRouletteMaxSurvival);
}

// Bindings and push constants of nee_update.comp: one thread per point folds the frame's
// counts into the running ones.
#define QL_NEE_UPDATE_BIND_COUNTS 0
#define QL_NEE_UPDATE_GROUP_SIZE 64
struct NeeUpdatePush {
  uint rowCount;
  float kept;  // share of the running counts kept (tracking's forgetting)
  uint pad0, pad1;
};
QL_CHECK_SIZE(NeeUpdatePush, 16);

// One entry's update from a frame's m targets summing to targetSum. A
// non-finite result keeps the old value: NaN or Inf never enters a table.
QL_FN float updatedQ(float q, float targetSum, uint m, uint visits, float alphaMin, float alphaMax,
                     float qFloor) {
  if (m == 0u) return max(q, qFloor);
  float keep = retainedAfterUpdates(visits, m, alphaMin, alphaMax);
  float mean = targetSum / float(m);
  float next = keep * q + (1.0f - keep) * mean;
  if (!(next >= 0.0f) || !(next < 3.0e38f)) next = q;  // catches NaN (comparisons fail) and Inf
  return max(next, qFloor);
}

QL_END

#endif
