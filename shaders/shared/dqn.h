// Deep Q guiding (Comi 2019, chapter 3, made realtime: issue 14), shared by GLSL and C++:
// the network's shape and parameter layout, the one-blob input encoding, the output
// activation and loss gradient, the replay records the path tracer writes and the
// push constants of the training passes.
//
// The network maps a continuous state (the vertex's position, one-blob encoded per axis
// over the scene's bounds, and its geometric normal) to one value per hemisphere stratum:
// the same equal-area strata as the tables (strata.h), so the sampling, pdf and MIS code is
// the tables'. Hidden layers are ReLU; the outputs are Q = exp(z), positive whatever the
// weights, and the sampling weights add a floor share of their mean so no direction has
// zero density.
//
// Parameters are one float array: per layer, its weights row by row (one row per output,
// rowStride floats: the inputs rounded up to 4), then its biases (rounded up to 4).
#ifndef QLIGHT_SHARED_DQN_H
#define QLIGHT_SHARED_DQN_H
#include "common.h"

QL_BEGIN

QL_CONST uint kDqnMaxBins = 32u;      // one-blob bins per position axis
QL_CONST uint kDqnMaxWidth = 128u;    // neurons per hidden layer
QL_CONST uint kDqnMaxHidden = 4u;     // hidden layers
QL_CONST uint kDqnMaxOutputs = 256u;  // strata
QL_CONST uint kDqnMaxInputs = 3u * kDqnMaxBins + 4u;

// A record's target before its path brought its return back (or when it never does).
QL_CONST float kDqnNoTarget = -1.0f;

struct DqnShape {
  uint bins;     // one-blob bins per position axis
  uint width;    // neurons per hidden layer
  uint hidden;   // hidden layers
  uint outputs;  // strata
};

QL_FN uint dqnInputs(DqnShape s) { return 3u * s.bins + 3u; }  // position blobs, normal
QL_FN uint dqnRoundUp4(uint n) { return (n + 3u) & ~3u; }
QL_FN uint dqnLayerCount(DqnShape s) { return s.hidden + 1u; }
QL_FN uint dqnLayerInputs(DqnShape s, uint layer) { return layer == 0u ? dqnInputs(s) : s.width; }
QL_FN uint dqnLayerOutputs(DqnShape s, uint layer) {
  return layer == s.hidden ? s.outputs : s.width;
}
QL_FN uint dqnRowStride(DqnShape s, uint layer) { return dqnRoundUp4(dqnLayerInputs(s, layer)); }
QL_FN uint dqnLayerSize(DqnShape s, uint layer) {
  uint outs = dqnLayerOutputs(s, layer);
  return outs * dqnRowStride(s, layer) + dqnRoundUp4(outs);
}
// Where layer `layer`'s weights start; its biases follow its last row.
QL_FN uint dqnWeightOffset(DqnShape s, uint layer) {
  uint offset = 0u;
  for (uint l = 0u; l < layer; ++l) offset += dqnLayerSize(s, l);
  return offset;
}
QL_FN uint dqnBiasOffset(DqnShape s, uint layer) {
  return dqnWeightOffset(s, layer) + dqnLayerOutputs(s, layer) * dqnRowStride(s, layer);
}
QL_FN uint dqnParameterCount(DqnShape s) { return dqnWeightOffset(s, dqnLayerCount(s)); }

// One-blob encoding (Mueller et al. 2019): a Gaussian of width 1/bins centred on x in [0, 1],
// evaluated at each bin's centre. Nearby positions share bins, so the network interpolates.
QL_FN float dqnOneBlob(float x, uint bin, uint bins) {
  float d = (x - (float(bin) + 0.5f) / float(bins)) * float(bins);
  return exp(-0.5f * d * d);
}
// Input i of the state (position in the scene's bounds mapped to [0, 1]^3, unit normal).
QL_FN float dqnInput(vec3 position01, vec3 normal, uint i, uint bins) {
  uint positionInputs = 3u * bins;
  if (i < positionInputs) {
    uint axis = i / bins;
    float x = axis == 0u ? position01.x : (axis == 1u ? position01.y : position01.z);
    return dqnOneBlob(clamp(x, 0.0f, 1.0f), i % bins, bins);
  }
  uint axis = i - positionInputs;
  return axis == 0u ? normal.x : (axis == 1u ? normal.y : (axis == 2u ? normal.z : 0.0f));
}

// Outputs: Q = exp(z), z clamped so Q stays finite.
QL_CONST float kDqnMaxLogQ = 30.0f;
QL_FN float dqnQ(float z) { return exp(clamp(z, -kDqnMaxLogQ, kDqnMaxLogQ)); }

// The baked grid (--dqn-grid; its size is a specialization constant of the path passes,
// kDqnGrid): after each refresh of the target copy a pass evaluates it at the centre of each
// cell of a grid^3 over the scene's bounds, for each of the 6 axis normals, and stores each
// row's sampling CDF as the tables store a point's; a vertex then reads the row of its cell
// and its normal's nearest axis, and the forward pass leaves the paths.
QL_CONST uint kDqnMaxGrid = 32u;
QL_CONST uint kDqnGridNormals = 6u;  // +x, -x, +y, -y, +z, -z

QL_FN uint dqnGridNormalBin(vec3 n) {
  vec3 a = abs(n);
  uint axis = a.x >= a.y && a.x >= a.z ? 0u : (a.y >= a.z ? 1u : 2u);
  float c = axis == 0u ? n.x : (axis == 1u ? n.y : n.z);
  return 2u * axis + (c < 0.0f ? 1u : 0u);
}
QL_FN vec3 dqnGridNormal(uint bin) {
  float sign = (bin & 1u) != 0u ? -1.0f : 1.0f;
  uint axis = bin >> 1u;
  return vec3(axis == 0u ? sign : 0.0f, axis == 1u ? sign : 0.0f, axis == 2u ? sign : 0.0f);
}
QL_FN uint dqnGridCellAxis(float x01, uint grid) {
  return uint(clamp(x01 * float(grid), 0.0f, float(grid) - 0.5f));  // NaN clamps to 0
}
// Row index of a state (position in [0, 1]^3 of the bounds, geometric normal).
QL_FN uint dqnGridRow(vec3 position01, vec3 normal, uint grid) {
  uint cell =
      dqnGridCellAxis(position01.x, grid) +
      grid * (dqnGridCellAxis(position01.y, grid) + grid * dqnGridCellAxis(position01.z, grid));
  return cell * kDqnGridNormals + dqnGridNormalBin(normal);
}
QL_FN uint dqnGridRows(uint grid) { return grid * grid * grid * kDqnGridNormals; }
// The state a row was evaluated at.
QL_FN vec3 dqnGridRowPosition01(uint row, uint grid) {
  uint cell = row / kDqnGridNormals;
  uint x = cell % grid, y = (cell / grid) % grid, z = cell / (grid * grid);
  return (vec3(float(x), float(y), float(z)) + 0.5f) / float(grid);
}

// The loss of a record is the relative squared error of its stratum's Q against its target
// (both in units of the scene's target scale), (Q - y)^2 / (sg(Q)^2 + eps^2), the relative
// L2 loss of Mueller et al.'s radiance caching: high-dynamic-range returns weigh alike at
// every brightness, and its minimum over noisy targets is still their mean. Its gradient
// with respect to z (dQ/dz = Q), clamped against a single firefly's return:
QL_CONST float kDqnLossEpsilon = 1e-2f;
QL_CONST float kDqnMaxGradient = 100.0f;
QL_FN float dqnLoss(float q, float y) {
  float d = q - y;
  return d * d / (q * q + kDqnLossEpsilon * kDqnLossEpsilon);
}
QL_FN float dqnLossGradientZ(float q, float y) {
  float g = 2.0f * (q - y) * q / (q * q + kDqnLossEpsilon * kDqnLossEpsilon);
  return clamp(g, -kDqnMaxGradient, kDqnMaxGradient);
}

// A path vertex's experience, written when it scatters (target kDqnNoTarget) and completed
// with its return when the path is done: a ring of these is the replay buffer.
struct DqnRecord {
  vec3 position01;  // in the scene's bounds
  uint stratum;     // of the direction taken, in the frame of the normal
  vec3 normal;      // geometric
  float target;     // the return's luminance (kDqnNoTarget: none yet)
};
QL_CHECK_SIZE(DqnRecord, 32);

// The network's part of the guide's uniforms (GuidingUniforms.dqn, with kGuideDqn).
struct DqnUniforms {
  DqnShape shape;
  vec3 sceneMin;  // position01 = (position - sceneMin) * sceneInvExtent
  uint capacity;  // records in the ring
  vec3 sceneInvExtent;
  uint frameStart;    // where this frame's records start in the ring
  uint frameQuota;    // most records a frame writes (the rest of its vertices teach nothing)
  float confidence;   // guided share factor: ramps up over the first training steps
  float floorShare;   // every stratum's weight gets this share of the mean weight
  float targetScale;  // targets are learned in these units
};
QL_CHECK_SIZE(DqnUniforms, 64);

// Training: the per-record pass (forward, loss, backward) and the per-parameter pass
// (gradient over the batch, Adam).
#define QL_DQN_BIND_WEIGHTS 0   // online network (read by the record pass, written by Adam)
#define QL_DQN_BIND_RECORDS 1   // the replay ring
#define QL_DQN_BIND_SCRATCH 2   // per batch record: inputs, activations, deltas
#define QL_DQN_BIND_ADAM 3      // first and second moments per parameter
#define QL_DQN_BIND_GRADIENT 4  // the step's gradient (tests and stats)
#define QL_DQN_BIND_LOSS 5      // per batch record: its loss (0 for empty records)
#define QL_DQN_BIND_OUTPUT 6    // Q per stratum of each state; dqn_bake: the rows' CDFs

struct DqnTrainPush {
  DqnShape shape;
  uint batch;     // records per step
  uint capacity;  // ring size
  uint step;      // Adam's step (from 1), also the record draw's seed
  float targetScale;
  float learningRate;
  float beta1;
  float beta2;
  float epsilon;
};
QL_CHECK_SIZE(DqnTrainPush, 48);

// dqn_bake.comp (its shape and grid are specialization constants): the sampling weights'
// floor and the strata.
struct DqnBakePush {
  uint rows;  // strata rows and columns
  uint cols;
  float floorShare;
  uint pad;
};
QL_CHECK_SIZE(DqnBakePush, 16);

// Scratch floats per batch record: inputs (rounded to 4), each hidden layer's activations,
// each hidden layer's deltas, then the stratum and the output's gradient.
QL_FN uint dqnScratchStride(DqnShape s) {
  return dqnRoundUp4(dqnInputs(s)) + 2u * s.hidden * s.width + 2u;
}
QL_FN uint dqnScratchActivation(DqnShape s, uint layer) {  // layer 0: the inputs
  return layer == 0u ? 0u : dqnRoundUp4(dqnInputs(s)) + (layer - 1u) * s.width;
}
QL_FN uint dqnScratchDelta(DqnShape s, uint hiddenLayer) {  // hidden layer 1..hidden
  return dqnRoundUp4(dqnInputs(s)) + s.hidden * s.width + (hiddenLayer - 1u) * s.width;
}
QL_FN uint dqnScratchOutput(DqnShape s) { return dqnScratchStride(s) - 2u; }

// The record a batch entry draws: a hash of (step, entry) over the ring.
QL_FN uint dqnHash(uint x) {
  x ^= x >> 16u;
  x *= 0x7feb352du;
  x ^= x >> 15u;
  x *= 0x846ca68bu;
  x ^= x >> 16u;
  return x;
}
QL_FN uint dqnDrawnRecord(uint step, uint entry, uint capacity) {
  return dqnHash(step * 0x9e3779b9u + dqnHash(entry)) % capacity;
}

QL_END

#endif
