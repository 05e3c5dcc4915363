// The deep Q network's forward pass (shared/dqn.h), for the path tracer and the training
// passes alike. The includer defines QL_DQN_WEIGHT4(i4), parameters 4 i4 .. 4 i4 + 3 of the
// network it reads (rows and biases start at multiples of 4, so a row is whole vec4s: on
// lavapipe one vec4 fetch and a dot product cost about what one scalar does).
// dqnForwardHidden fills dqnAct4 as the training scratch is laid out (the inputs, then each
// hidden layer's activations, 4 a vec4); dqnOutputZ then gives any one output.
// The loops are unrolled where the shape is a specialization constant (the path passes): the
// activations' indices become constants, so lavapipe keeps them in registers instead of
// gathering from a local array (default network: shade 153-159 -> 117-122 ms at 320x180;
// the largest, 128 x 4, about 8% slower and twice the compile time).
#extension GL_EXT_control_flow_attributes : require
#include "shared/dqn.h"

vec4 dqnAct4[(kDqnMaxInputs + kDqnMaxHidden * kDqnMaxWidth) / 4u];

float dqnActAt(uint i) { return dqnAct4[i >> 2u][i & 3u]; }
float dqnParameter(uint i) { return QL_DQN_WEIGHT4(i >> 2u)[i & 3u]; }

// Row `row4` (in vec4s) of a layer times the activations from `from4` on, over `n4` vec4s.
float dqnRowDot(uint row4, uint from4, uint n4) {
  float z = 0.0;
  [[unroll]] for (uint i = 0u; i < n4; ++i) z += dot(QL_DQN_WEIGHT4(row4 + i), dqnAct4[from4 + i]);
  return z;
}

void dqnForwardHidden(DqnShape s, vec3 position01, vec3 normal) {
  uint inputs = dqnInputs(s);
  [[unroll]] for (uint i4 = 0u; i4 < dqnRoundUp4(inputs) / 4u; ++i4) {
    vec4 x;
    [[unroll]] for (uint c = 0u; c < 4u; ++c) {
      uint i = 4u * i4 + c;
      x[c] = i < inputs ? dqnInput(position01, normal, i, s.bins) : 0.0;
    }
    dqnAct4[i4] = x;
  }
  [[unroll]] for (uint l = 0u; l < s.hidden; ++l) {
    uint from4 = dqnScratchActivation(s, l) / 4u, to4 = dqnScratchActivation(s, l + 1u) / 4u;
    uint weight4 = dqnWeightOffset(s, l) / 4u, bias4 = dqnBiasOffset(s, l) / 4u;
    uint stride4 = dqnRowStride(s, l) / 4u;
    [[unroll]] for (uint o4 = 0u; o4 < s.width / 4u; ++o4) {
      vec4 z = QL_DQN_WEIGHT4(bias4 + o4);
      [[unroll]] for (uint c = 0u; c < 4u; ++c) z[c] += dqnRowDot(weight4 + (4u * o4 + c) * stride4, from4, stride4);
      dqnAct4[to4 + o4] = max(z, vec4(0.0));
    }
  }
}

// Output k's pre-activation z (Q = dqnQ(z)), after dqnForwardHidden.
float dqnOutputZ(DqnShape s, uint k) {
  uint stride4 = dqnRowStride(s, s.hidden) / 4u;
  uint row4 = dqnWeightOffset(s, s.hidden) / 4u + k * stride4;
  return dqnParameter(dqnBiasOffset(s, s.hidden) + k) +
         dqnRowDot(row4, dqnScratchActivation(s, s.hidden) / 4u, stride4);
}

// The sampling distribution of a state, after dqnForwardHidden: dqnCdf gets the inclusive CDF
// of (Q_k + floor) cosInt_k over the strata, the floor a share of the mean Q, so every
// direction stays possible whatever the network outputs; outputs that are not finite fall
// back to uniform Q. Returns the total. The includer includes shared/strata.h.
float dqnCdf[kDqnMaxOutputs];
float guidedStratumWeight(float q, uint k, uint rows, uint cols);

float dqnFillCdf(DqnShape s, float floorShare, uint rows, uint cols) {
  float mean = 0.0;
  [[unroll]] for (uint k = 0u; k < s.outputs; ++k) {
    dqnCdf[k] = dqnQ(dqnOutputZ(s, k));
    mean += dqnCdf[k];
  }
  float floorQ = floorShare * mean / float(s.outputs);
  bool finite = mean > 0.0 && !isinf(mean) && !isnan(mean);
  float run = 0.0;
  [[unroll]] for (uint k = 0u; k < s.outputs; ++k) {
    run += guidedStratumWeight(finite ? dqnCdf[k] + floorQ : 1.0, k, rows, cols);
    dqnCdf[k] = run;
  }
  return run;
}
