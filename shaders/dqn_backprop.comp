#version 460
// Deep Q training, first pass: one thread per batch entry draws a record from the replay
// ring, runs the online network forward, takes the relative L2 loss of its stratum's Q
// against the record's return (shared/dqn.h) and backpropagates it, writing the inputs,
// the activations and the deltas of every layer to the scratch for the weight pass
// (dqn_adam.comp). A record without a return writes zeros: it adds nothing to the gradient.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#include "shared/dqn.h"

layout(local_size_x = 64) in;
layout(binding = QL_DQN_BIND_WEIGHTS, scalar) readonly buffer Weights { float weights[]; };
layout(binding = QL_DQN_BIND_RECORDS, scalar) readonly buffer Records { DqnRecord records[]; };
layout(binding = QL_DQN_BIND_SCRATCH, scalar) writeonly buffer Scratch { float scratch[]; };
layout(binding = QL_DQN_BIND_LOSS, scalar) writeonly buffer Losses { float losses[]; };
layout(push_constant, scalar) uniform Push { DqnTrainPush pc; };

#define QL_DQN_WEIGHT4(i4) \
  vec4(weights[4u * (i4)], weights[4u * (i4) + 1u], weights[4u * (i4) + 2u], weights[4u * (i4) + 3u])
#include "include/dqn.glsl"

float delta[kDqnMaxWidth];
float below[kDqnMaxWidth];

void main() {
  uint entry = gl_GlobalInvocationID.x;
  if (entry >= pc.batch) return;
  DqnShape s = pc.shape;
  uint base = entry * dqnScratchStride(s);
  DqnRecord r = records[dqnDrawnRecord(pc.step, entry, pc.capacity)];
  if (!(r.target >= 0.0) || isinf(r.target) || r.stratum >= s.outputs) {
    for (uint i = 0u; i < dqnScratchStride(s); ++i) scratch[base + i] = 0.0;
    scratch[base + dqnScratchOutput(s)] = float(s.outputs);  // no output's
    losses[entry] = 0.0;
    return;
  }
  dqnForwardHidden(s, r.position01, r.normal);
  float q = dqnQ(dqnOutputZ(s, r.stratum));
  float y = r.target / pc.targetScale;
  float g = dqnLossGradientZ(q, y);
  losses[entry] = dqnLoss(q, y);
  for (uint i = 0u; i < dqnScratchDelta(s, 1u); ++i) scratch[base + i] = dqnActAt(i);

  // The last hidden layer's deltas: only the record's output has a gradient.
  uint last = s.hidden;
  uint from = dqnScratchActivation(s, last);
  uint row = dqnWeightOffset(s, last) + r.stratum * dqnRowStride(s, last);
  for (uint j = 0u; j < s.width; ++j)
    delta[j] = dqnActAt(from + j) > 0.0 ? g * weights[row + j] : 0.0;
  for (uint j = 0u; j < s.width; ++j) scratch[base + dqnScratchDelta(s, last) + j] = delta[j];
  // Hidden layer l's deltas from layer l + 1's through the weights of layer l (which maps
  // layer l's activations to layer l + 1's).
  for (uint l = last - 1u; l >= 1u; --l) {
    uint w = dqnWeightOffset(s, l), stride = dqnRowStride(s, l);
    uint act = dqnScratchActivation(s, l);
    for (uint j = 0u; j < s.width; ++j) {
      float sum = 0.0;
      if (dqnActAt(act + j) > 0.0)
        for (uint i = 0u; i < s.width; ++i) sum += weights[w + i * stride + j] * delta[i];
      below[j] = sum;
    }
    for (uint j = 0u; j < s.width; ++j) {
      delta[j] = below[j];
      scratch[base + dqnScratchDelta(s, l) + j] = below[j];
    }
  }
  scratch[base + dqnScratchOutput(s)] = float(r.stratum);
  scratch[base + dqnScratchOutput(s) + 1u] = g;
}
