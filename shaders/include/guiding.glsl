// Cache points, their hashed grid and learned Q distributions, as the path
// tracer uses them: nearest compatible point, guided sampling and pdf, and the
// Q-learning targets it accumulates for the update pass (D&K eq. 5).

layout(binding = QL_BIND_GUIDING, scalar) uniform Guiding { GuidingUniforms guiding; };
// Read-only tables are texel buffers (read with imageLoad, as in scene_access.glsl); the Q
// and V CDFs stay samplerBuffers, whose view format varies (R32 for strata, RGBA32 for trees
// and deep Q), where an imageBuffer's format is fixed in the shader.
// The cache points, 2 texels each.
layout(binding = QL_BIND_CACHE_POINTS, rgba32f) uniform readonly restrict imageBuffer uCachePoints;
layout(binding = QL_BIND_GRID_BUCKETS, r32ui) uniform readonly restrict uimageBuffer uGridBuckets;
layout(binding = QL_BIND_GRID_POINTS, r32ui) uniform readonly restrict uimageBuffer uGridPoints;
layout(binding = QL_BIND_Q_CDF) uniform samplerBuffer uQCdf;
// Q's target sums, one 64-bit fixed-point word an entry (one atomic a target); deep Q reads
// the same binding as 32-bit words (its replay records).
layout(binding = QL_BIND_Q_SUM, scalar) buffer QSum64 { uint64_t qSum64[]; };
layout(binding = QL_BIND_Q_SUM, scalar) buffer QSum { uint qSum[]; };
layout(binding = QL_BIND_Q_COUNT, scalar) buffer QCount { uint qCount[]; };
layout(binding = QL_BIND_SPAWN, scalar) buffer Spawn { vec4 spawnEntries[]; };  // 2 per slot
layout(binding = QL_BIND_V_CDF) uniform samplerBuffer uVCdf;
layout(binding = QL_BIND_V_SUM, scalar) buffer VSum64 { uint64_t vSum64[]; };  // fixed point
layout(binding = QL_BIND_V_COUNT, scalar) buffer VCount { uint vCount[]; };
layout(binding = QL_BIND_POINT_UPDATES, r32ui) uniform readonly restrict uimageBuffer uPointUpdates;
// Direction trees (kGuideTree): QL_BIND_Q_CDF holds the slots' weights (4 a texel, one texel a
// node), this the slots' children.
layout(binding = QL_BIND_Q_CHILDREN, rgba32ui) uniform readonly restrict uimageBuffer uQChildren;
// Learned NEE probability: kNeeWordsPerPoint words a point (shared/guiding_types.h).
layout(binding = QL_BIND_NEE_COUNTS, scalar) buffer NeeCounts { uint neeCounts[]; };
// Deep Q (kUseDqn) binds the tables' slots to its own buffers: QL_BIND_Q_CDF holds the
// network the paths sample from (an RGBA32F view: 4 parameters a texel) or its baked grid's
// rows, QL_BIND_Q_SUM the replay ring (DqnRecord, 8 words each) and QL_BIND_Q_COUNT's first
// word the count of this frame's records.
#define QL_DQN_WEIGHT4(i4) texelFetch(uQCdf, int(i4))
#include "include/dqn.glsl"
// With deep Q the vertex's guided distribution is dqnCdf (the inclusive CDF of Q_k cosInt_k,
// filled by dqnRow), or with the baked grid (kDqnGrid > 0) a row of QL_BIND_Q_CDF, which then
// holds the grid's rows instead of the network; either is read through qCdf like a point's
// row, so sampling, pdf and MIS are the tables' code.
bool dqnPerVertex() { return kUseDqn && kDqnGrid == 0u; }

GpuCachePoint cachePointAt(uint i) {
  vec4 a = imageLoad(uCachePoints, int(2u * i));
  vec4 b = imageLoad(uCachePoints, int(2u * i + 1u));
  GpuCachePoint p;
  p.position = a.xyz;
  p.radius = a.w;
  p.normal = b.xyz;
  p.pad = 0u;
  return p;
}
float qCdf(uint i) { return dqnPerVertex() ? dqnCdf[i] : texelFetch(uQCdf, int(i)).x; }
float vCdf(uint i) { return texelFetch(uVCdf, int(i)).x; }

#define QL_CDF_AT(i) qCdf(i)
#include "shared/strata.h"

#define QL_TREE_WEIGHTS(node) texelFetch(uQCdf, int(node))
#define QL_TREE_CHILDREN(node) imageLoad(uQChildren, int(node))
#include "shared/direction_tree.h"

uint strataCount() { return guiding.rows * guiding.cols; }
bool treeDirections() { return kUseDirectionTrees && (guiding.flags & kGuideTree) != 0u; }

float pointConfidence(uint point) {
  if (kUseDqn) return guiding.dqn.confidence;  // the network's, from its training steps
  return confidenceOf(imageLoad(uPointUpdates, int(point)).x, guiding.confidenceUpdates,
                      strataCount());
}


#define QL_POINT_AT(i) cachePointAt(i)
#define QL_GRID_BUCKET_AT(h) imageLoad(uGridBuckets, int(h)).x
#define QL_GRID_POINT_AT(j) imageLoad(uGridPoints, int(j)).x
#include "shared/point_search.h"

// With deep Q every vertex is its own state: point 0 stands for "the vertex itself".
uint findCachePoint(vec3 p, vec3 n) {
  if (kUseDqn) return 0u;
  if (guiding.pointCount == 0u) return kNoCachePoint;
  return findNearestCachePoint(p, n, guiding.cellSize, guiding.hashSize, guiding.searchRadius,
                               guiding.normalCosine);
}

TangentFrame pointFrame(uint point) { return frameFromNormal(cachePointAt(point).normal); }

// A point's guided distribution as a vertex uses it: its frame, where its entries start
// (strata: the first of its row; tree: its root node) and its total (strata: the CDF's,
// sum Q_k cosInt_k; tree: the mean weight over the unit square), each read once per vertex.
struct GuidedRow {
  TangentFrame frame;
  uint base;
  float total;
};

GuidedRow guidedRow(uint point) {
  GuidedRow r;
  r.frame = pointFrame(point);
  if (treeDirections()) {
    r.base = point * guiding.treeNodes;
    vec4 w = texelFetch(uQCdf, int(r.base));
    r.total = 0.25 * (w.x + w.y + w.z + w.w);
  } else {
    r.base = point * strataCount();
    r.total = qCdf(r.base + strataCount() - 1u);
  }
  return r;
}

// The network's distribution at a vertex (deep Q): evaluated there (dqnFillCdf), or read
// from the baked grid's row of its cell and normal axis, in the frame of its own normal.
GuidedRow dqnRow(vec3 position, vec3 normal) {
  GuidedRow r;
  r.frame = frameFromNormal(normal);
  vec3 p01 = (position - guiding.dqn.sceneMin) * guiding.dqn.sceneInvExtent;
  if (kDqnGrid > 0u) {
    r.base = dqnGridRow(p01, normal, kDqnGrid) * strataCount();
    r.total = qCdf(r.base + strataCount() - 1u);
    return r;
  }
  r.base = 0u;
  // guiding.dqn.shape, as specialization constants: fixed loop counts and activation places.
  DqnShape s = DqnShape(kDqnBins, kDqnWidth, kDqnHidden, kDqnOutputs);
  dqnForwardHidden(s, p01, normal);
  r.total = dqnFillCdf(s, guiding.dqn.floorShare, guiding.rows, guiding.cols);
  return r;
}

// A vertex's experience for the replay ring: its state and the stratum it scattered into;
// the return comes when the path is done (recordQTarget). The frame's records past its quota
// teach nothing.
uint dqnOpenRecord(vec3 position, vec3 normal, uint stratum) {
  uint index = atomicAdd(qCount[0], 1u);
  if (index >= guiding.dqn.frameQuota) return kNoCachePoint;
  uint slot = (guiding.dqn.frameStart + index) % guiding.dqn.capacity;
  vec3 p01 = (position - guiding.dqn.sceneMin) * guiding.dqn.sceneInvExtent;
  uint w = 8u * slot;  // DqnRecord: position01, stratum, normal, target
  qSum[w] = floatBitsToUint(p01.x);
  qSum[w + 1u] = floatBitsToUint(p01.y);
  qSum[w + 2u] = floatBitsToUint(p01.z);
  qSum[w + 3u] = stratum;
  qSum[w + 4u] = floatBitsToUint(normal.x);
  qSum[w + 5u] = floatBitsToUint(normal.y);
  qSum[w + 6u] = floatBitsToUint(normal.z);
  qSum[w + 7u] = floatBitsToUint(kDqnNoTarget);
  return slot;
}

// A direction at a point: the Q entry it updates and its guided density. Found once per
// direction, for the mixture's pdf and for learning.
struct GuidedLookup {
  uint entry;
  float pdf;
};

// Stratum k's entry, and the density of a direction in it with cos(theta) = cosTheta.
GuidedLookup stratumLookup(GuidedRow r, uint k, float cosTheta) {
  GuidedLookup g;
  g.entry = r.base + k;
  float below = k > 0u ? qCdf(r.base + k - 1u) : 0.0;
  g.pdf = guidedPdfInStratum((qCdf(r.base + k) - below) / r.total, k, cosTheta, guiding.rows,
                             guiding.cols);
  return g;
}

GuidedLookup guidedLookup(GuidedRow r, vec3 local) {
  GuidedLookup g;
  if (treeDirections()) {
    float pdfU;
    g.entry = treeLeafOf(r.base, treeCoordsOfDirection(local), pdfU);
    g.pdf = treeSolidAnglePdf(pdfU, local.z);
  } else {
    g = stratumLookup(r, stratumOfDirection(local, guiding.rows, guiding.cols), local.z);
  }
  return g;
}

// A direction drawn from the point's learned distribution (local: in the point's frame), in
// two halves so that one lookup serves a drawn and a BSDF-sampled direction alike (lavapipe
// runs both sides of the mixture's branch): the draw returns what it knows of the direction's
// entry (strata: the stratum, its pdf left to the lookup; trees: both), guidedLookupAt the rest.
GuidedLookup drawGuidedDirection(GuidedRow r, vec3 u, out vec3 local) {
  GuidedLookup g;
  if (treeDirections()) {
    vec2 coords;
    float pdfU;
    g.entry = sampleTree(r.base, u, coords, pdfU);
    local = directionOfTreeCoords(coords);
    g.pdf = treeSolidAnglePdf(pdfU, local.z);
  } else {
    uint k = sampleCdfTarget(r.base, strataCount(), u.z * r.total);
    local = sampleStratumCosine(k, u.xy, guiding.rows, guiding.cols);
    g.entry = r.base + k;
    g.pdf = 0.0;
  }
  return g;
}

// The entry and guided pdf of `local`: drawn is drawGuidedDirection's result for a drawn
// direction (its stratum is known exactly, where recomputing it from the direction could
// round into a neighbour), else drawn.entry is kNoCachePoint.
GuidedLookup guidedLookupAt(GuidedRow r, vec3 local, GuidedLookup drawn) {
  if (treeDirections()) return drawn.entry != kNoCachePoint ? drawn : guidedLookup(r, local);
  uint k = drawn.entry != kNoCachePoint ? drawn.entry - r.base
                                        : stratumOfDirection(local, guiding.rows, guiding.cols);
  return stratumLookup(r, k, local.z);
}

// Q in a direction at a point (strata: its stratum's, recovered from the CDF of
// Q_k cosInt_k; tree: its leaf's sampling weight).
float storedQ(GuidedRow r, vec3 local) {
  if (treeDirections()) {
    float pdfU;
    treeLeafOf(r.base, treeCoordsOfDirection(local), pdfU);
    return pdfU * r.total;
  }
  uint k = stratumOfDirection(local, guiding.rows, guiding.cols);
  float below = k > 0u ? qCdf(r.base + k - 1u) : 0.0;
  return (qCdf(r.base + k) - below) / stratumCosineIntegral(k, guiding.rows, guiding.cols);
}

// int Q cos(theta) dw over the hemisphere: the irradiance the point's Q describes.
float guidedIrradiance(GuidedRow r) { return treeDirections() ? kPi * r.total : r.total; }

// Radiance the vertex scatters toward wo, estimated from Q at its point: the
// diffuse lobe integrates Q against albedo/pi exactly (per stratum or leaf); the
// specular lobe takes Q from the mirror direction.
float rowScatteredEstimate(GuidedRow r, BsdfParams bsdf, vec3 woLocal, vec3 woWorld,
                           vec3 shadingNormal) {
  float estimate = luminance(bsdfDiffuseAlbedo(bsdf, woLocal.z)) * kInvPi * guidedIrradiance(r);
  vec3 fresnel = specularFresnel(bsdf, woLocal.z);
  if (fresnel != vec3(0.0)) {
    vec3 mirror = reflect(-woWorld, shadingNormal);
    vec3 local = localFromWorld(r.frame, mirror);
    if (local.z > 0.0) estimate += luminance(fresnel) * storedQ(r, local);
  }
  return estimate;
}

float scatteredEstimate(uint point, BsdfParams bsdf, vec3 woLocal, vec3 woWorld, vec3 shadingNormal) {
  return rowScatteredEstimate(guidedRow(point), bsdf, woLocal, woWorld, shadingNormal);
}

// Q in the direction of a lookup at the point (local.z: its cosine there): both the strata's
// and the tree's densities are Q cos(theta) / irradiance.
float lookedUpQ(GuidedRow r, GuidedLookup g, float cosTheta) {
  return cosTheta > 0.0 && g.pdf > 0.0 ? g.pdf * guidedIrradiance(r) / cosTheta : -1.0;
}

// A non-negative target as a 64-bit fixed-point value: integer sums are exact whatever
// order the atomics run in. The update passes read each as (lo, hi) words (fixedSumToFloat).
uint64_t fixedPoint64(float target) {
  return uint64_t(floor(min(target, kTargetMax) * kTargetScale));
}

void recordQTarget(uint entry, float target) {
  if (entry == kNoCachePoint || !(target >= 0.0) || isinf(target)) return;
  if (kUseDqn) {  // the entry is the vertex's replay record: its target word
    qSum[8u * entry + 7u] = floatBitsToUint(target);
    return;
  }
  atomicAdd(qSum64[entry], fixedPoint64(target));
  atomicAdd(qCount[entry], 1u);
}

// Camera hits that no point covers become candidates for new points. One
// pixel of each group of `stride` reports per sample, into its group's fixed
// slot (w = 1 marks it written), so the candidates do not depend on timing.
void reportUncovered(uint path, uint pathCount, uint sampleId, vec3 p, vec3 n) {
  uint stride = max(8u, (pathCount + guiding.spawnCapacity - 1u) / guiding.spawnCapacity);
  if (path % stride != sampleId % stride) return;
  uint slot = path / stride;
  spawnEntries[2u * slot] = vec4(p, 1.0);
  spawnEntries[2u * slot + 1u] = vec4(n, 0.0);
}

// --- learned light selection, D&K section 4: V(point, light) ---

bool lightLearningOn(uint point) {
  return kUseLightLearning && (guiding.flags & kGuideLightLearn) != 0u && point != kNoCachePoint &&
         guiding.lightCount > 0u;
}

float learnedLightProbability(uint point, uint light) {
  uint base = point * guiding.lightCount;
  float below = light > 0u ? vCdf(base + light - 1u) : 0.0;
  return (vCdf(base + light) - below) / vCdf(base + guiding.lightCount - 1u);
}

uint sampleLearnedLight(uint point, float u) {
  uint base = point * guiding.lightCount;
  float target = u * vCdf(base + guiding.lightCount - 1u);
  uint lo = 0u, hi = guiding.lightCount - 1u;
  while (lo < hi) {
    uint mid = (lo + hi) >> 1u;
    if (vCdf(base + mid) > target) hi = mid; else lo = mid + 1u;
  }
  return lo;
}

// --- learned NEE probability (shared/guiding_types.h, neeProbabilityOf) ---

bool neeLearningOn(uint point) {
  return kUseGuiding && !kUseDqn && (guiding.flags & kGuideNeeLearn) != 0u &&
         point != kNoCachePoint;
}

// The probability that a vertex at `point` samples a light (1 where NEE is not learned).
float neeProbability(uint point) {
  if (!neeLearningOn(point)) return 1.0;
  uint w = kNeeWordsPerPoint * point;
  return neeProbabilityOf(uintBitsToFloat(neeCounts[w + 2u]), uintBitsToFloat(neeCounts[w + 3u]),
                          guiding.neeMinProbability);
}

void recordShadowRay(uint point, bool unoccluded) {
  if (!kLearning || !neeLearningOn(point)) return;
  uint w = kNeeWordsPerPoint * point;
  atomicAdd(neeCounts[w], 1u);
  if (unoccluded) atomicAdd(neeCounts[w + 1u], 1u);
}

void recordVTarget(uint point, uint light, float target) {
  if (!(target >= 0.0) || isinf(target)) return;
  uint entry = point * guiding.lightCount + light;
  atomicAdd(vSum64[entry], fixedPoint64(target));
  atomicAdd(vCount[entry], 1u);
}
