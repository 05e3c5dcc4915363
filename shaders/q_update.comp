#version 460
// The update pass: applies the frame's accumulated Q-learning targets of each
// table entry at once (learning rate from its visit count), keeps the value
// above the floor and finite, and writes the weight the CDF pass sums.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#include "shared/guiding_types.h"
#include "shared/strata.h"

layout(local_size_x = 256) in;
layout(binding = QL_Q_UPDATE_BIND_VALUES, scalar) buffer Values { float values[]; };
layout(binding = QL_Q_UPDATE_BIND_VISITS, scalar) buffer Visits { uint visits[]; };
layout(binding = QL_Q_UPDATE_BIND_WEIGHTS, scalar) writeonly buffer Weights { float weights[]; };
layout(binding = QL_Q_UPDATE_BIND_SUMS, scalar) buffer Sums { uint sums[]; };  // fixed point (lo, hi) pairs
layout(binding = QL_Q_UPDATE_BIND_COUNTS, scalar) buffer Counts { uint counts[]; };
// Updates per point (Q table only).
layout(binding = QL_Q_UPDATE_BIND_POINT_UPDATES, scalar) buffer PointUpdates { uint pointUpdates[]; };
layout(push_constant, scalar) uniform Push { TableUpdatePush pc; };

void main() {
  uint e = gl_GlobalInvocationID.x;
  if (e >= pc.entries) return;
  uint m = counts[e];
  if (m > 0u && pc.cosineWeights != 0u) atomicAdd(pointUpdates[e / pc.segmentLength], m);
  float sum = fixedSumToFloat(sums[2u * e], sums[2u * e + 1u]);
  float next = updatedQ(values[e], sum, m, visits[e], pc.alphaMin, pc.alphaMax, pc.floorValue);
  values[e] = next;
  visits[e] += m;
  sums[2u * e] = 0u;
  sums[2u * e + 1u] = 0u;
  counts[e] = 0u;
  uint k = e % pc.segmentLength;
  weights[e] = pc.cosineWeights != 0u ? guidedStratumWeight(next, k, pc.rows, pc.cols) : next;
}
