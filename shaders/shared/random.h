// Per-pixel random numbers shared by GLSL and C++: a 32-bit PCG generator
// (LCG state, RXS-M-XS output permutation; Jarzynski & Olano 2020, "Hash
// Functions for GPU Rendering") seeded by hashing (pixel, frame, user seed).
// One 32-bit state per pixel keeps the path state small; all pixels walk the
// same period-2^32 cycle from hashed, well-spread starting points.
#ifndef QLIGHT_SHARED_RANDOM_H
#define QLIGHT_SHARED_RANDOM_H

#include "common.h"

QL_BEGIN

struct Rng {
  uint state;
};

// PCG hash: a bijection on 32-bit words with good avalanche.
QL_FN uint pcgHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// Nested hashes: for a fixed (frame, seed) distinct pixels get distinct
// states, and each input changes every bit of the state.
QL_FN Rng rngSeed(uint pixelIndex, uint frameIndex, uint userSeed) {
  Rng rng;
  rng.state = pcgHash(pixelIndex + pcgHash(frameIndex + pcgHash(userSeed)));
  return rng;
}

QL_FN uint rngNextUint(QL_INOUT(Rng) rng) {
  uint old = rng.state;
  rng.state = old * 747796405u + 2891336453u;
  uint word = ((old >> ((old >> 28u) + 4u)) ^ old) * 277803737u;
  return (word >> 22u) ^ word;
}

// The top 24 bits scaled by 2^-24: exact in float and at most 1 - 2^-24, so
// the result is never 1.0 (rounding a full 32-bit value could give 1.0).
QL_FN float uintToUnitFloat(uint bits) { return float(bits >> 8u) * (1.0f / 16777216.0f); }

// Uniform in [0, 1).
QL_FN float rngNextFloat(QL_INOUT(Rng) rng) { return uintToUnitFloat(rngNextUint(rng)); }

QL_FN vec2 rngNext2(QL_INOUT(Rng) rng) {
  float x = rngNextFloat(rng);
  float y = rngNextFloat(rng);
  return vec2(x, y);
}

QL_FN vec3 rngNext3(QL_INOUT(Rng) rng) {
  float x = rngNextFloat(rng);
  float y = rngNextFloat(rng);
  float z = rngNextFloat(rng);
  return vec3(x, y, z);
}

QL_END

#endif
