#version 460
// The learning pass of one table (Q or the light values V), one thread per row
// (a point's strata or lights): applies the frame's accumulated targets of
// each entry at once (learning rate from its visit count), keeps the value
// above the floor and finite, and rebuilds the row's inclusive CDF of the
// sampling weights (unvisited entries weigh the mean of the visited ones). A row that received no target keeps its values and its
// CDF and costs one read of its counts, so the pass costs what the frame's
// paths touched, not the whole table. (A thread per row and no barriers: on
// lavapipe a workgroup barrier costs more than the row's serial scan.)
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#include "shared/guiding_types.h"
#include "shared/strata.h"

layout(local_size_x = QL_Q_UPDATE_GROUP_SIZE) in;
layout(binding = QL_Q_UPDATE_BIND_VALUES, scalar) buffer Values { float values[]; };
layout(binding = QL_Q_UPDATE_BIND_VISITS, scalar) buffer Visits { uint visits[]; };
layout(binding = QL_Q_UPDATE_BIND_CDF, scalar) writeonly buffer Cdf { float cdf[]; };
layout(binding = QL_Q_UPDATE_BIND_SUMS, scalar) buffer Sums { uint sums[]; };  // fixed point (lo, hi) pairs
layout(binding = QL_Q_UPDATE_BIND_COUNTS, scalar) buffer Counts { uint counts[]; };
// Updates per point (Q table only).
layout(binding = QL_Q_UPDATE_BIND_POINT_UPDATES, scalar) buffer PointUpdates { uint pointUpdates[]; };
layout(binding = QL_Q_UPDATE_BIND_ROW_CLOCKS, scalar) buffer RowClocks { float rowClocks[]; };
layout(push_constant, scalar) uniform Push { TableUpdatePush pc; };

// Sampling weights shrink Q toward the row mean by kShrink pseudo-visits: a stratum
// learned from a few noisy returns does not yet dominate (or vanish from) its row.
const float kShrink = 4.0;

void main() {
  // Rows beyond the dispatch limit of one dimension continue in y.
  uint row = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x +
             gl_LocalInvocationID.x;
  if (row >= pc.rowCount) return;
  uint length = pc.segmentLength;
  uint base = row * length;
  uint targets = 0u;
  for (uint k = 0u; k < length; ++k) targets += counts[base + k];
  if (targets == 0u && pc.everyRow == 0u) return;
  // Tracking: the row's counts age by the forgetting clock's advance since it was last updated
  // (a row without targets is not touched, so it ages when it is next used).
  float kept = keptAfter(pc.clock - rowClocks[row]);
  float visitsKept = visitsKeptOf(kept);
  rowClocks[row] = pc.clock;
  if (pc.cosineWeights != 0u)
    pointUpdates[row] = cappedUpdates(agedCount(pointUpdates[row], kept), targets, pc.confidenceCap);

  // The update; then the sampling weights: a stratum's Q shrunk toward the mean of the
  // row's visited strata (never visited: the mean itself), so an unexplored direction is as
  // likely as an average one, not next to impossible (its BSDF-sampled paths would be
  // fireflies).
  float visitedSum = 0.0;
  uint visited = 0u;
  for (uint k = 0u; k < length; ++k) {
    uint e = base + k;
    uint m = counts[e];
    uint n = agedCount(visits[e], visitsKept);
    float q = values[e];
    if (m == 0u && n != visits[e]) visits[e] = n;
    if (m > 0u) {
      float sum = fixedSumToFloat(sums[2u * e], sums[2u * e + 1u]);
      q = updatedQ(q, sum, m, n, pc.alphaMin, pc.alphaMax, pc.floorValue);
      values[e] = q;
      visits[e] = n + m;
      sums[2u * e] = 0u;
      sums[2u * e + 1u] = 0u;
      counts[e] = 0u;
    }
    if (n + m > 0u) {
      visitedSum += max(q, pc.floorValue);
      visited++;
    }
  }
  float prior = visited > 0u ? visitedSum / float(visited) : 0.0;
  float run = 0.0;
  for (uint k = 0u; k < length; ++k) {
    uint e = base + k;
    float n = float(visits[e]);
    float q = visited > 0u ? (n * max(values[e], pc.floorValue) + kShrink * prior) / (n + kShrink)
                           : max(values[e], pc.floorValue);
    run += pc.cosineWeights != 0u ? guidedStratumWeight(q, k, pc.rows, pc.cols) : q;
    cdf[e] = run;
  }
}
