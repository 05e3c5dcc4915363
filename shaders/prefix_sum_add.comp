#version 460
// Adds the scanned total of all earlier tiles to every element of a tile.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#include "shared/prefix_sum.h"

layout(local_size_x = QL_SCAN_GROUP_SIZE) in;
layout(binding = QL_SCAN_BIND_VALUES, scalar) buffer Values { float values[]; };
layout(binding = QL_SCAN_BIND_TILE_SUMS, scalar) readonly buffer TileSums { float tileSums[]; };
layout(push_constant, scalar) uniform Push { PrefixSumPush pc; };

void main() {
  uint idx = gl_GlobalInvocationID.x;
  uint tile = idx / pc.tileElements;
  if (idx < pc.count && tile > 0) values[idx] += tileSums[tile - 1];
}
