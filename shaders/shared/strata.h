// Hemisphere strata of a cache point and the Q-guided direction distribution,
// shared by GLSL and C++ (Comi 2019, 3.2.2; Dahm & Keller 2017, eq. 5).
//
// The local hemisphere (z up) is split into rows x cols strata of equal solid
// angle 2 pi / (rows cols): row r covers cos(theta) in
// [1 - (r+1)/rows, 1 - r/rows] (equal-height zones have equal area), column c
// covers phi in [2 pi c / cols, 2 pi (c+1) / cols]; stratum k = r * cols + c.
// Row 0 touches the pole; the last row touches the horizon.
//
// Guided distribution: stratum k with probability
//   P_k = Q_k cosInt_k / sum_j Q_j cosInt_j   (cosInt_k = int_k cos(theta) dw),
// then cosine-distributed inside it, so the density of a direction in k is
//   P_k cos(theta) / cosInt_k.
// The includer may define, before including this header:
//   QL_CDF_AT(i): inclusive unnormalised CDF of the Q_k cosInt_k at buffer
//                 index i (enables sampleCdf, cdfProbability, guidedPdf,
//                 sampleGuided);
//   QL_Q_AT(i):   Q_k at buffer index i (enables lambertScatteredRadianceFactor).
#ifndef QLIGHT_SHARED_STRATA_H
#define QLIGHT_SHARED_STRATA_H

#include "common.h"

QL_BEGIN

// Most strata (rows x cols) a point may have: its CDF is one segment of the
// segmented prefix scan (gpu::PrefixSum::kMaxSegmentLength).
QL_CONST uint kMaxStrata = 1024u;

QL_FN uint stratumCount(uint rows, uint cols) { return rows * cols; }

// cos(theta) at the pole-side edge of a row; rowUpperCos(rows) == 0. Both the
// lookup and the samplers use these exact floats as row boundaries.
QL_FN float stratumRowUpperCos(uint row, uint rows) { return 1.0f - float(row) / float(rows); }

QL_FN uint stratumRowOfCos(float cosTheta, uint rows) {
  float z = clamp(cosTheta, 0.0f, 1.0f);
  uint row = min(uint((1.0f - z) * float(rows)), rows - 1u);
  // The product above may round across a boundary: settle ties against the
  // boundary floats, row r = (upperCos(r+1), upperCos(r)].
  if (row > 0u && z > stratumRowUpperCos(row, rows)) row -= 1u;
  if (row + 1u < rows && z <= stratumRowUpperCos(row + 1u, rows)) row += 1u;
  return row;
}

QL_FN uint stratumColOfDirection(vec3 local, uint cols) {
  // atan(0, 0) is undefined in GLSL: the pole belongs to column 0.
  float phi = (local.x != 0.0f || local.y != 0.0f) ? atan(local.y, local.x) : 0.0f;
  if (phi < 0.0f) phi += kTwoPi;
  return min(uint(max(phi, 0.0f) * (float(cols) / kTwoPi)), cols - 1u);
}

// Directions below the horizon land in the last row.
QL_FN uint stratumOfDirection(vec3 local, uint rows, uint cols) {
  return stratumRowOfCos(local.z, rows) * cols + stratumColOfDirection(local, cols);
}

QL_FN float stratumSolidAngle(uint rows, uint cols) { return kTwoPi / float(rows * cols); }

// int over stratum k of cos(theta) dw = (2 pi / cols) (c1^2 - c0^2) / 2.
QL_FN float stratumCosineIntegral(uint k, uint rows, uint cols) {
  uint row = k / cols;
  float c1 = stratumRowUpperCos(row, rows);
  float c0 = stratumRowUpperCos(row + 1u, rows);
  return (kPi / float(cols)) * (c1 - c0) * (c1 + c0);
}

// Raw maps from (cos theta, phi fraction) or u to a direction in stratum k,
// without the edge fix-up of sampleStratum*: use those to sample.
QL_FN vec3 stratumDirection(uint k, float cosTheta, float phiFraction, uint cols) {
  float phi = kTwoPi * (float(k % cols) + phiFraction) / float(cols);
  float sinTheta = sqrt(max(0.0f, 1.0f - cosTheta * cosTheta));
  return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

QL_FN vec3 stratumDirectionUniform(uint k, vec2 u, uint rows, uint cols) {
  uint row = k / cols;
  float c1 = stratumRowUpperCos(row, rows);
  float c0 = stratumRowUpperCos(row + 1u, rows);
  return stratumDirection(k, c1 - u.x * (c1 - c0), u.y, cols);
}

// cos^2(theta) uniform in [c0^2, c1^2]: density proportional to cos(theta).
QL_FN vec3 stratumDirectionCosine(uint k, vec2 u, uint rows, uint cols) {
  uint row = k / cols;
  float c1 = stratumRowUpperCos(row, rows);
  float c0 = stratumRowUpperCos(row + 1u, rows);
  float z2 = c0 * c0 + (1.0f - u.x) * (c1 * c1 - c0 * c0);
  return stratumDirection(k, min(sqrt(z2), c1), u.y, cols);
}

// The samplers below guarantee stratumOfDirection(result) == k: when float
// rounding puts an edge sample (u within ~1e-7 of 0 or 1) across a boundary,
// it is pulled 1/2048 of the stratum inward. The moved mass is ~1e-7, and the
// pdf a caller evaluates by lookup always refers to the sampled stratum.
QL_CONST float kStratumEdgePull = 1.0f / 1024.0f;

// Uniform in solid angle inside stratum k (density 1 / stratumSolidAngle).
QL_FN vec3 sampleStratumUniform(uint k, vec2 u, uint rows, uint cols) {
  vec3 d = stratumDirectionUniform(k, u, rows, cols);
  if (stratumOfDirection(d, rows, cols) != k)
    d = stratumDirectionUniform(k, mix(u, vec2(0.5f), kStratumEdgePull), rows, cols);
  return d;
}

// Cosine-distributed inside stratum k (density cos(theta) / cosInt_k).
QL_FN vec3 sampleStratumCosine(uint k, vec2 u, uint rows, uint cols) {
  vec3 d = stratumDirectionCosine(k, u, rows, cols);
  if (stratumOfDirection(d, rows, cols) != k)
    d = stratumDirectionCosine(k, mix(u, vec2(0.5f), kStratumEdgePull), rows, cols);
  return d;
}

// Unnormalised probability of choosing stratum k: what the CDF pass sums.
QL_FN float guidedStratumWeight(float q, uint k, uint rows, uint cols) {
  return q * stratumCosineIntegral(k, rows, cols);
}

// Density of a direction with cos(theta) = cosTheta inside stratum k, chosen
// with probability pk.
QL_FN float guidedPdfInStratum(float pk, uint k, float cosTheta, uint rows, uint cols) {
  return pk * max(cosTheta, 0.0f) / stratumCosineIntegral(k, rows, cols);
}

// Lambertian vertex (albedo a): int_k Q_k (a / pi) cos(theta) dw.
QL_FN float lambertStratumTransport(float q, float albedo, uint k, uint rows, uint cols) {
  return q * albedo * kInvPi * stratumCosineIntegral(k, rows, cols);
}

#ifdef QL_CDF_AT
// Index i in [0, n) with CDF(i-1) <= target = u * total < CDF(i): the first entry whose
// inclusive CDF exceeds the target, so zero-width entries are never chosen
// (except that u * total rounding up to total falls back to n - 1). Needs
// n >= 1 and a positive total: keep every Q_k above a positive floor, within
// ~1e6 of the largest, or float CDF steps vanish.
QL_FN uint sampleCdfTarget(uint base, uint n, float target) {
  uint lo = 0u;
  uint hi = n - 1u;
  while (lo < hi) {
    uint mid = (lo + hi) / 2u;
    if (QL_CDF_AT(base + mid) > target)
      hi = mid;
    else
      lo = mid + 1u;
  }
  return lo;
}

QL_FN uint sampleCdf(uint base, uint n, float u) {
  return sampleCdfTarget(base, n, u * QL_CDF_AT(base + n - 1u));
}

QL_FN float cdfProbability(uint base, uint n, uint i) {
  float below = i > 0u ? QL_CDF_AT(base + i - 1u) : 0.0f;
  return (QL_CDF_AT(base + i) - below) / QL_CDF_AT(base + n - 1u);
}

// Guided density of any local direction (0 below the horizon), for MIS.
QL_FN float guidedPdf(uint base, vec3 local, uint rows, uint cols) {
  if (local.z <= 0.0f) return 0.0f;
  uint k = stratumOfDirection(local, rows, cols);
  return guidedPdfInStratum(cdfProbability(base, rows * cols, k), k, local.z, rows, cols);
}

// u.z picks the stratum, u.xy the direction inside it. Returns false (pdf 0)
// for the measure-zero horizon direction.
QL_FN bool sampleGuided(uint base, vec3 u, uint rows, uint cols, QL_OUT(vec3) local,
                        QL_OUT(float) pdf) {
  uint n = rows * cols;
  uint k = sampleCdf(base, n, u.z);
  local = sampleStratumCosine(k, vec2(u.x, u.y), rows, cols);
  pdf = guidedPdfInStratum(cdfProbability(base, n, k), k, local.z, rows, cols);
  return pdf > 0.0f;
}
#endif

#ifdef QL_Q_AT
// The learned part of the Q-learning target at a Lambertian vertex:
// sum_k Q_k (albedo / pi) cosInt_k (D&K eq. 5, integral exact per stratum).
QL_FN float lambertScatteredRadianceFactor(uint base, float albedo, uint rows, uint cols) {
  uint n = rows * cols;
  float sum = 0.0f;
  for (uint k = 0u; k < n; ++k)
    sum += lambertStratumTransport(QL_Q_AT(base + k), albedo, k, rows, cols);
  return sum;
}
#endif

QL_END

#endif
