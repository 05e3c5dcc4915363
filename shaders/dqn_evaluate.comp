#version 460
// Deep Q: the network's Q for every stratum at given states (one thread a state), for the
// window's view of what it learned and for the tests.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#include "shared/dqn.h"

layout(local_size_x = 64) in;
layout(binding = QL_DQN_BIND_WEIGHTS, scalar) readonly buffer Weights { float weights[]; };
layout(binding = QL_DQN_BIND_RECORDS, scalar) readonly buffer States { DqnRecord states[]; };
layout(binding = QL_DQN_BIND_OUTPUT, scalar) writeonly buffer Output { float q[]; };
layout(push_constant, scalar) uniform Push { DqnTrainPush pc; };  // shape, batch: states

#define QL_DQN_WEIGHT4(i4) \
  vec4(weights[4u * (i4)], weights[4u * (i4) + 1u], weights[4u * (i4) + 2u], weights[4u * (i4) + 3u])
#include "include/dqn.glsl"

void main() {
  uint state = gl_GlobalInvocationID.x;
  if (state >= pc.batch) return;
  DqnShape s = pc.shape;
  dqnForwardHidden(s, states[state].position01, states[state].normal);
  for (uint k = 0u; k < s.outputs; ++k) q[state * s.outputs + k] = dqnQ(dqnOutputZ(s, k));
}
