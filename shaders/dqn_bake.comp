#version 460
// Deep Q's baked grid (shared/dqn.h): one thread a row (a cell of the grid and an axis
// normal) evaluates the target network at the row's state and stores its sampling CDF,
// which the paths then read as they read a cache point's row. The shape is the path
// passes' specialization (include/features.glsl), so the forward pass is the same unrolled
// code the per-vertex mode runs.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#include "shared/dqn.h"
#include "include/features.glsl"

layout(local_size_x = 64) in;
layout(binding = QL_DQN_BIND_WEIGHTS) uniform samplerBuffer uWeights;  // 4 parameters a texel
layout(binding = QL_DQN_BIND_OUTPUT, scalar) writeonly buffer Rows { float cdf[]; };
layout(push_constant, scalar) uniform Push { DqnBakePush pc; };

#define QL_DQN_WEIGHT4(i4) texelFetch(uWeights, int(i4))
#include "include/dqn.glsl"
#include "shared/strata.h"

void main() {
  uint row = gl_GlobalInvocationID.x;
  if (row >= dqnGridRows(kDqnGrid)) return;
  DqnShape s = DqnShape(kDqnBins, kDqnWidth, kDqnHidden, kDqnOutputs);
  dqnForwardHidden(s, dqnGridRowPosition01(row, kDqnGrid), dqnGridNormal(row % kDqnGridNormals));
  dqnFillCdf(s, pc.floorShare, pc.rows, pc.cols);
  [[unroll]] for (uint k = 0u; k < s.outputs; ++k) cdf[row * s.outputs + k] = dqnCdf[k];
}
