#version 460
// Deep Q training, second pass: one thread per parameter sums its gradient over the batch
// from dqn_backprop.comp's scratch (a weight: its output's delta times its input's
// activation; a bias: the delta) and takes an Adam step. Padding parameters stay 0.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#include "shared/dqn.h"

layout(local_size_x = 64) in;
layout(binding = QL_DQN_BIND_WEIGHTS, scalar) buffer Weights { float weights[]; };
layout(binding = QL_DQN_BIND_SCRATCH, scalar) readonly buffer Scratch { float scratch[]; };
layout(binding = QL_DQN_BIND_ADAM, scalar) buffer Moments { vec2 moments[]; };
layout(binding = QL_DQN_BIND_GRADIENT, scalar) writeonly buffer Gradient { float gradient[]; };
layout(push_constant, scalar) uniform Push { DqnTrainPush pc; };

void main() {
  uint p = gl_GlobalInvocationID.x;
  DqnShape s = pc.shape;
  if (p >= dqnParameterCount(s)) return;
  uint layer = 0u;
  while (p >= dqnWeightOffset(s, layer + 1u)) layer++;
  uint local = p - dqnWeightOffset(s, layer);
  uint outs = dqnLayerOutputs(s, layer), stride = dqnRowStride(s, layer);
  bool bias = local >= outs * stride;
  uint o = bias ? local - outs * stride : local / stride;
  uint i = bias ? 0u : local % stride;
  if (o >= outs || (!bias && i >= dqnLayerInputs(s, layer))) {
    gradient[p] = 0.0;
    return;
  }
  bool isOutput = layer == s.hidden;
  uint scratchStride = dqnScratchStride(s);
  uint act = dqnScratchActivation(s, layer) + i;
  uint del = isOutput ? dqnScratchOutput(s) : dqnScratchDelta(s, layer + 1u) + o;
  float g = 0.0;
  for (uint b = 0u; b < pc.batch; ++b) {
    uint base = b * scratchStride;
    float d;
    if (isOutput) {
      if (uint(scratch[base + del]) != o) continue;
      d = scratch[base + del + 1u];
    } else {
      d = scratch[base + del];
    }
    g += bias ? d : d * scratch[base + act];
  }
  g /= float(pc.batch);
  gradient[p] = g;
  if (pc.learningRate <= 0.0 || isnan(g) || isinf(g)) return;  // gradient only (tests)
  vec2 m = moments[p];
  m.x = pc.beta1 * m.x + (1.0 - pc.beta1) * g;
  m.y = pc.beta2 * m.y + (1.0 - pc.beta2) * g * g;
  moments[p] = m;
  float mHat = m.x / (1.0 - pow(pc.beta1, float(pc.step)));
  float vHat = m.y / (1.0 - pow(pc.beta2, float(pc.step)));
  weights[p] -= pc.learningRate * mHat / (sqrt(vHat) + pc.epsilon);
}
