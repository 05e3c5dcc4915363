#version 460
// Inclusive (optionally segmented) scan of one tile per workgroup, in place;
// writes each tile's total for the next level.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#include "shared/prefix_sum.h"

layout(local_size_x = QL_SCAN_GROUP_SIZE) in;
layout(binding = QL_SCAN_BIND_VALUES, scalar) buffer Values { float values[]; };
layout(binding = QL_SCAN_BIND_TILE_SUMS, scalar) writeonly buffer TileSums { float tileSums[]; };
layout(push_constant, scalar) uniform Push { PrefixSumPush pc; };

shared float sTotal[QL_SCAN_GROUP_SIZE];
shared uint sHead[QL_SCAN_GROUP_SIZE];

void main() {
  uint t = gl_LocalInvocationID.x;
  uint base = gl_WorkGroupID.x * pc.tileElements;
  float v[QL_SCAN_ITEMS_PER_THREAD];
  bool head[QL_SCAN_ITEMS_PER_THREAD];
  float run = 0.0;
  bool anyHead = false;
  for (uint i = 0; i < QL_SCAN_ITEMS_PER_THREAD; ++i) {
    uint local = t * QL_SCAN_ITEMS_PER_THREAD + i;
    uint idx = base + local;
    float x = (local < pc.tileElements && idx < pc.count) ? values[idx] : 0.0;
    // Tiles hold whole segments, so a segment starts where the tile offset is a multiple.
    bool h = pc.segmentLength > 0 && local % pc.segmentLength == 0;
    run = h ? x : run + x;
    anyHead = anyHead || h;
    v[i] = run;
    head[i] = h;
  }
  // Segmented Hillis-Steele scan of the per-thread totals.
  sTotal[t] = run;
  sHead[t] = anyHead ? 1u : 0u;
  barrier();
  for (uint offset = 1; offset < QL_SCAN_GROUP_SIZE; offset <<= 1) {
    float earlier = 0.0;
    uint earlierHead = 0u;
    if (t >= offset) {
      earlier = sTotal[t - offset];
      earlierHead = sHead[t - offset];
    }
    barrier();
    if (t >= offset) {
      if (sHead[t] == 0u) sTotal[t] += earlier;
      sHead[t] |= earlierHead;
    }
    barrier();
  }
  float carry = t > 0 ? sTotal[t - 1] : 0.0;
  bool started = false;
  for (uint i = 0; i < QL_SCAN_ITEMS_PER_THREAD; ++i) {
    uint local = t * QL_SCAN_ITEMS_PER_THREAD + i;
    uint idx = base + local;
    started = started || head[i];
    if (local < pc.tileElements && idx < pc.count) values[idx] = started ? v[i] : v[i] + carry;
  }
  if (t == QL_SCAN_GROUP_SIZE - 1) tileSums[gl_WorkGroupID.x] = sTotal[t];
}
