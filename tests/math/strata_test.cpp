// Hemisphere strata (equal solid angle, exact cosine integrals, lookup and
// in-stratum samplers that round-trip) and the Q-guided distribution built
// on them (pdf integrates to 1, samples follow it, CDF search).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "sphere_quadrature.h"
#include "stats_support.h"
#include "strata_harness.h"

namespace qlight::shared {
namespace {

using qlight::test::chiSquareTest;
using qlight::test::kPiD;
using qlight::test::TestRandom;

struct Layout {
  uint rows, cols;
};
const Layout kLayouts[] = {{8u, 8u}, {16u, 8u}, {5u, 7u}, {1u, 1u}};

// Stratum of a direction in double precision, straight from the definition.
int referenceStratum(double z, double phi, uint rows, uint cols) {
  int row = std::clamp(int(std::floor((1.0 - z) * rows)), 0, int(rows) - 1);
  int col = std::clamp(int(std::floor(phi / (2 * kPiD) * cols)), 0, int(cols) - 1);
  return row * int(cols) + col;
}

// Integrates per-stratum measures over a fine (theta, phi) grid whose cells
// are classified by stratumOfDirection at their midpoint. Strata are
// rectangles in (theta, phi), so a cell whose four corners share a stratum
// lies inside it; only the other cells can be misclassified, and their
// measure bounds the error for each stratum they touch.
struct StratumQuadrature {
  std::vector<double> measure, errorBound;
};

template <class CellMeasure>
StratumQuadrature integrateOverStrata(uint rows, uint cols, int nTheta, int nPhi,
                                      CellMeasure&& cellMeasure) {
  const uint n = rows * cols;
  StratumQuadrature q{std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
  auto thetaAt = [&](int i) { return 0.5 * kPiD * i / nTheta; };
  auto phiAt = [&](int j) { return 2 * kPiD * j / nPhi; };
  auto lookup = [&](double th, double ph) {
    return stratumOfDirection(qlight::test::SphereGrid::direction(th, ph), rows, cols);
  };
  std::vector<uint> corners(size_t(nTheta + 1) * (nPhi + 1));
  for (int i = 0; i <= nTheta; ++i)
    for (int j = 0; j <= nPhi; ++j) {
      // Nudge corners inward so they classify like the cell's interior side.
      double th = std::clamp(thetaAt(i), 1e-9, 0.5 * kPiD - 1e-9);
      double ph = std::clamp(phiAt(j), 1e-9, 2 * kPiD - 1e-9);
      corners[size_t(i) * (nPhi + 1) + j] = lookup(th, ph);
    }
  for (int i = 0; i < nTheta; ++i)
    for (int j = 0; j < nPhi; ++j) {
      double t0 = thetaAt(i), t1 = thetaAt(i + 1), p0 = phiAt(j), p1 = phiAt(j + 1);
      double m = cellMeasure(t0, t1, p1 - p0);
      uint k = lookup(0.5 * (t0 + t1), 0.5 * (p0 + p1));
      q.measure[k] += m;
      uint c[4] = {corners[size_t(i) * (nPhi + 1) + j], corners[size_t(i) * (nPhi + 1) + j + 1],
                   corners[size_t(i + 1) * (nPhi + 1) + j],
                   corners[size_t(i + 1) * (nPhi + 1) + j + 1]};
      bool mixed = false;
      for (uint cc : c) mixed = mixed || cc != k;
      if (mixed) {
        q.errorBound[k] += m;
        for (uint cc : c)
          if (cc != k) q.errorBound[cc] += m;
      }
    }
  return q;
}

double cellSolidAngle(double t0, double t1, double dPhi) {
  return (std::cos(t0) - std::cos(t1)) * dPhi;
}
double cellCosineIntegral(double t0, double t1, double dPhi) {
  double s0 = std::sin(t0), s1 = std::sin(t1);
  return 0.5 * (s1 * s1 - s0 * s0) * dPhi;
}

TEST(Strata, HaveEqualSolidAngle) {
  for (Layout l : kLayouts) {
    auto q = integrateOverStrata(l.rows, l.cols, 1500, 1500, cellSolidAngle);
    double expected = 2 * kPiD / (l.rows * l.cols);
    EXPECT_NEAR(stratumSolidAngle(l.rows, l.cols), expected, 1e-6 * expected);
    for (uint k = 0; k < l.rows * l.cols; ++k)
      EXPECT_NEAR(q.measure[k], expected, q.errorBound[k] + 1e-9)
          << l.rows << "x" << l.cols << " stratum " << k;
  }
}

TEST(Strata, CosineIntegralMatchesQuadrature) {
  for (Layout l : kLayouts) {
    auto q = integrateOverStrata(l.rows, l.cols, 1500, 1500, cellCosineIntegral);
    double sum = 0.0;
    for (uint k = 0; k < l.rows * l.cols; ++k) {
      EXPECT_NEAR(stratumCosineIntegral(k, l.rows, l.cols), q.measure[k], q.errorBound[k] + 1e-6)
          << l.rows << "x" << l.cols << " stratum " << k;
      sum += stratumCosineIntegral(k, l.rows, l.cols);
    }
    EXPECT_NEAR(sum, kPiD, 1e-5);  // int cos over the hemisphere
  }
}

TEST(Strata, LookupHandlesEdges) {
  const uint rows = 8, cols = 8;
  EXPECT_EQ(stratumOfDirection(vec3(0, 0, 1), rows, cols), 0u);  // pole -> row 0, column 0
  EXPECT_EQ(stratumOfDirection(vec3(1, 0, 0), rows, cols), (rows - 1) * cols);  // horizon
  EXPECT_EQ(stratumOfDirection(normalize(vec3(1, 0, -0.01f)), rows, cols), (rows - 1) * cols);
  EXPECT_EQ(stratumOfDirection(vec3(0, 0, -1), rows, cols), (rows - 1) * cols);
  // phi just below 2 pi is the last column, phi = pi (either sign of zero) the
  // middle one (all in row 0: z > 0.99).
  EXPECT_EQ(stratumOfDirection(normalize(vec3(0.1f, -1e-9f, 1)), rows, cols), cols - 1);
  EXPECT_EQ(stratumOfDirection(normalize(vec3(-0.1f, 0.0f, 1)), rows, cols), cols / 2);
  EXPECT_EQ(stratumOfDirection(normalize(vec3(-0.1f, -0.0f, 1)), rows, cols), cols / 2);
  // Exact row boundaries belong to the row on the pole side: (upper(r+1), upper(r)].
  for (uint r = 0; r < rows; ++r) {
    float z = stratumRowUpperCos(r, rows);
    vec3 d(std::sqrt(1 - z * z), 0, z);
    EXPECT_EQ(stratumOfDirection(d, rows, cols), std::min(r, rows - 1) * cols) << r;
  }
}

TEST(Strata, LookupMatchesDefinition) {
  TestRandom rnd(21);
  for (Layout l : kLayouts)
    for (int i = 0; i < 20000; ++i) {
      double z = rnd.nextDouble(), phi = 2 * kPiD * rnd.nextDouble();
      // Skip directions within float noise of a boundary.
      double rowPos = (1 - z) * l.rows, colPos = phi / (2 * kPiD) * l.cols;
      if (std::abs(rowPos - std::round(rowPos)) < 1e-4 ||
          std::abs(colPos - std::round(colPos)) < 1e-4)
        continue;
      double s = std::sqrt(1 - z * z);
      vec3 d(float(s * std::cos(phi)), float(s * std::sin(phi)), float(z));
      ASSERT_EQ(int(stratumOfDirection(d, l.rows, l.cols)),
                referenceStratum(z, phi, l.rows, l.cols));
    }
}

std::vector<vec2> roundTripInputs(TestRandom& rnd) {
  const float edges[] = {0.0f, 1e-7f, 0.5f, 1.0f - 1.0f / 16777216.0f, 1.0f - 1e-7f};
  std::vector<vec2> us;
  for (float a : edges)
    for (float b : edges) us.push_back(vec2(a, b));
  for (int i = 0; i < 500; ++i) us.push_back(rnd.next2());
  return us;
}

TEST(Strata, SamplesRoundTripThroughLookup) {
  TestRandom rnd(22);
  std::vector<vec2> us = roundTripInputs(rnd);
  for (Layout l : kLayouts)
    for (uint k = 0; k < l.rows * l.cols; ++k)
      for (vec2 u : us) {
        vec3 a = sampleStratumUniform(k, u, l.rows, l.cols);
        vec3 c = sampleStratumCosine(k, u, l.rows, l.cols);
        ASSERT_EQ(stratumOfDirection(a, l.rows, l.cols), k) << "uniform u=" << u.x << "," << u.y;
        ASSERT_EQ(stratumOfDirection(c, l.rows, l.cols), k) << "cosine u=" << u.x << "," << u.y;
        ASSERT_NEAR(length(a), 1.0f, 1e-5f);
        ASSERT_NEAR(length(c), 1.0f, 1e-5f);
        ASSERT_GE(c.z, 0.0f);
        // Away from the edges, the geometric stratum (double precision) agrees.
        if (u.x > 1e-3f && u.x < 1 - 1e-3f && u.y > 1e-3f && u.y < 1 - 1e-3f) {
          double phi = std::atan2(double(a.y), double(a.x));
          if (phi < 0) phi += 2 * kPiD;
          ASSERT_EQ(referenceStratum(a.z, phi, l.rows, l.cols), int(k));
        }
      }
}

// Sub-bins of one stratum, n in cos(theta) by n in phi; `zWeight(z0, z1)` is
// the mass of a sub-row under the sampler's density (in units of the whole).
template <class ZWeight>
void checkInStratum(uint k, uint rows, uint cols, vec3 (*sampler)(uint, vec2, uint, uint),
                    ZWeight&& zWeight, uint32_t seed) {
  constexpr int kSub = 12, kSamples = 100000;
  const uint row = k / cols, col = k % cols;
  const double c1 = 1.0 - double(row) / rows, c0 = 1.0 - double(row + 1) / rows;
  std::vector<double> observed(kSub * kSub, 0.0), expected(kSub * kSub, 0.0);
  TestRandom rnd(seed);
  for (int i = 0; i < kSamples; ++i) {
    vec3 d = sampler(k, rnd.next2(), rows, cols);
    double phi = std::atan2(double(d.y), double(d.x));
    if (phi < 0) phi += 2 * kPiD;
    int iz = std::clamp(int((c1 - d.z) / (c1 - c0) * kSub), 0, kSub - 1);
    int ip = std::clamp(int((phi / (2 * kPiD) * cols - col) * kSub), 0, kSub - 1);
    observed[iz * kSub + ip] += 1.0;
  }
  for (int iz = 0; iz < kSub; ++iz) {
    double zHi = c1 - (c1 - c0) * iz / kSub, zLo = c1 - (c1 - c0) * (iz + 1) / kSub;
    double w = zWeight(zLo, zHi, c0, c1);
    for (int ip = 0; ip < kSub; ++ip) expected[iz * kSub + ip] = kSamples * w / kSub;
  }
  auto result = chiSquareTest(observed, expected);
  EXPECT_TRUE(result.pass()) << "stratum " << k << ": " << result.describe();
}

TEST(Strata, InStratumSamplersFollowTheirDensities) {
  const uint rows = 8, cols = 8;
  auto uniformZ = [](double lo, double hi, double c0, double c1) { return (hi - lo) / (c1 - c0); };
  auto cosineZ = [](double lo, double hi, double c0, double c1) {
    return (hi * hi - lo * lo) / (c1 * c1 - c0 * c0);
  };
  uint32_t seed = 30;
  for (uint k : {0u, 3u, 27u, 63u}) {
    checkInStratum(k, rows, cols, sampleStratumUniform, uniformZ, seed++);
    checkInStratum(k, rows, cols, sampleStratumCosine, cosineZ, seed++);
  }
}

std::vector<float> randomQ(TestRandom& rnd, uint n) {
  std::vector<float> q(n);
  for (float& v : q) v = std::exp(std::log(1e-2f) + rnd.next() * std::log(1e4f));  // 1e-2 .. 1e2
  return q;
}

// Layout of the CDF buffer in these tests: a decoy cache point at 0, the
// tested one at `base`, so base offsets are exercised.
constexpr uint kBase = 200;

void setupGuided(TestRandom& rnd, uint rows, uint cols, std::vector<float>& q) {
  qlight::test::gCdfBuffer.assign(kBase + rows * cols, 0.0f);
  qlight::test::writeGuidedCdf(randomQ(rnd, rows * cols), 0, rows, cols);
  q = randomQ(rnd, rows * cols);
  qlight::test::writeGuidedCdf(q, kBase, rows, cols);
}

// On a (cos theta, phi) grid aligned with the strata the guided pdf is linear
// in cos(theta) inside every cell, so the midpoint rule is exact and only
// float rounding (~1e-6) remains.
TEST(Guided, PdfIntegratesToOne) {
  TestRandom rnd(40);
  for (Layout l : {Layout{8, 8}, Layout{16, 8}}) {
    for (int trial = 0; trial < 5; ++trial) {
      std::vector<float> q;
      setupGuided(rnd, l.rows, l.cols, q);
      constexpr int kSubZ = 8, kSubPhi = 8;
      const int nz = l.rows * kSubZ, np = l.cols * kSubPhi;
      double sum = 0.0;
      for (int i = 0; i < nz; ++i) {
        double z = 1.0 - (i + 0.5) / nz, s = std::sqrt(1 - z * z);
        for (int j = 0; j < np; ++j) {
          double phi = 2 * kPiD * (j + 0.5) / np;
          vec3 d(float(s * std::cos(phi)), float(s * std::sin(phi)), float(z));
          sum += guidedPdf(kBase, d, l.rows, l.cols) * (1.0 / nz) * (2 * kPiD / np);
        }
      }
      EXPECT_NEAR(sum, 1.0, 1e-5) << l.rows << "x" << l.cols << " trial " << trial;
    }
  }
}

TEST(Guided, SamplesFollowPdf) {
  TestRandom rnd(41);
  for (Layout l : {Layout{8, 8}, Layout{16, 8}}) {
    std::vector<float> q;
    setupGuided(rnd, l.rows, l.cols, q);
    const uint n = l.rows * l.cols;
    double total = 0.0;
    for (uint k = 0; k < n; ++k) total += double(q[k]) * stratumCosineIntegral(k, l.rows, l.cols);
    // 3 x 3 sub-bins per stratum; the pdf is P_k z / cosInt_k inside.
    constexpr int kSub = 3, kSamples = 300000;
    const int nz = l.rows * kSub, np = l.cols * kSub;
    std::vector<double> observed(nz * np, 0.0), expected(nz * np, 0.0);
    for (int i = 0; i < kSamples; ++i) {
      vec3 d;
      float pdf;
      ASSERT_TRUE(sampleGuided(kBase, rnd.next3(), l.rows, l.cols, d, pdf));
      double phi = std::atan2(double(d.y), double(d.x));
      if (phi < 0) phi += 2 * kPiD;
      int iz = std::clamp(int((1.0 - d.z) * nz), 0, nz - 1);
      int ip = std::clamp(int(phi / (2 * kPiD) * np), 0, np - 1);
      observed[iz * np + ip] += 1.0;
    }
    for (int iz = 0; iz < nz; ++iz) {
      double zHi = 1.0 - double(iz) / nz, zLo = 1.0 - double(iz + 1) / nz;
      for (int ip = 0; ip < np; ++ip) {
        uint k = uint(iz / kSub) * l.cols + uint(ip / kSub);
        double pk = double(q[k]) * stratumCosineIntegral(k, l.rows, l.cols) / total;
        double binCos = 0.5 * (zHi * zHi - zLo * zLo) * (2 * kPiD / np);
        expected[iz * np + ip] = kSamples * pk * binCos / stratumCosineIntegral(k, l.rows, l.cols);
      }
    }
    auto result = chiSquareTest(observed, expected);
    EXPECT_TRUE(result.pass()) << l.rows << "x" << l.cols << ": " << result.describe();
  }
}

// The pdf a sample reports equals the pdf evaluated by lookup (for MIS).
TEST(Guided, SampledPdfEqualsEvaluatedPdf) {
  TestRandom rnd(42);
  for (Layout l : kLayouts) {
    std::vector<float> q;
    setupGuided(rnd, l.rows, l.cols, q);
    std::vector<vec3> us;
    for (int i = 0; i < 20000; ++i) us.push_back(rnd.next3());
    for (float e : {0.0f, 1.0f - 1.0f / 16777216.0f}) us.push_back(vec3(e, e, e));
    for (vec3 u : us) {
      vec3 d;
      float pdf;
      ASSERT_TRUE(sampleGuided(kBase, u, l.rows, l.cols, d, pdf));
      ASSERT_EQ(pdf, guidedPdf(kBase, d, l.rows, l.cols));
      ASSERT_GT(pdf, 0.0f);
    }
  }
  EXPECT_EQ(guidedPdf(kBase, vec3(1, 0, -0.1f), 8, 8), 0.0f);
}

TEST(Guided, PdfInStratumIsProbabilityTimesCosineOverIntegral) {
  const uint rows = 8, cols = 8;
  float ci = stratumCosineIntegral(10, rows, cols);
  EXPECT_FLOAT_EQ(guidedPdfInStratum(0.25f, 10, 0.7f, rows, cols), 0.25f * 0.7f / ci);
  EXPECT_EQ(guidedPdfInStratum(0.25f, 10, -0.1f, rows, cols), 0.0f);
}

// sampleCdf against a linear search for the first entry whose inclusive CDF
// exceeds u * total, on CDFs with zero-width entries, at two buffer offsets.
TEST(SampleCdf, MatchesLinearSearch) {
  TestRandom rnd(50);
  for (uint n : {1u, 2u, 3u, 7u, 64u, 128u}) {
    for (uint base : {0u, 37u}) {
      qlight::test::gCdfBuffer.assign(base + n, -1.0f);
      float running = 0.0f;
      for (uint i = 0; i < n; ++i) {
        bool empty = i % 5 == 1 && i + 1 < n;
        running += empty ? 0.0f : 0.1f + rnd.next();
        qlight::test::gCdfBuffer[base + i] = running;
      }
      std::vector<float> us = {0.0f, 1.0f - 1.0f / 16777216.0f, 0.5f};
      for (int i = 0; i < 2000; ++i) us.push_back(rnd.next());
      for (float u : us) {
        float target = u * running;
        uint expected = n - 1;
        for (uint i = 0; i < n; ++i)
          if (qlight::test::gCdfBuffer[base + i] > target) {
            expected = i;
            break;
          }
        ASSERT_EQ(sampleCdf(base, n, u), expected) << "n=" << n << " u=" << u;
        uint got = sampleCdf(base, n, u);
        ASSERT_GT(cdfProbability(base, n, got), 0.0f) << "zero-width entry chosen";
      }
    }
  }
}

// Over a fine uniform grid of u, each entry is chosen in proportion to its
// probability (exactly, up to grid resolution).
TEST(SampleCdf, ChoosesEntriesInProportion) {
  TestRandom rnd(51);
  const uint n = 64;
  std::vector<float> q = randomQ(rnd, n);
  qlight::test::gCdfBuffer.clear();
  qlight::test::writeGuidedCdf(q, 0, 8, 8);
  const int kU = 1 << 20;
  std::vector<int> hits(n, 0);
  for (int i = 0; i < kU; ++i) ++hits[sampleCdf(0, n, (i + 0.5f) / kU)];
  double sumP = 0.0;
  for (uint k = 0; k < n; ++k) {
    double p = cdfProbability(0, n, k);
    sumP += p;
    EXPECT_NEAR(double(hits[k]) / kU, p, 2.0 / kU + 1e-6 * p) << k;
  }
  EXPECT_NEAR(sumP, 1.0, 1e-5);
}

TEST(LambertTarget, SumsQTimesCosineIntegral) {
  TestRandom rnd(60);
  for (Layout l : kLayouts) {
    const uint n = l.rows * l.cols;
    const uint base = 11;
    // Uniform incident radiance L: the scattered radiance is albedo * L.
    qlight::test::gQBuffer.assign(base + n, 2.0f);
    EXPECT_NEAR(lambertScatteredRadianceFactor(base, 0.6f, l.rows, l.cols), 1.2f, 1e-5f);
    std::vector<float> q = randomQ(rnd, n);
    std::copy(q.begin(), q.end(), qlight::test::gQBuffer.begin() + base);
    double expected = 0.0;
    for (uint k = 0; k < n; ++k)
      expected += double(q[k]) * 0.6 / kPiD * stratumCosineIntegral(k, l.rows, l.cols);
    EXPECT_NEAR(lambertScatteredRadianceFactor(base, 0.6f, l.rows, l.cols), expected,
                1e-5 * expected);
    EXPECT_FLOAT_EQ(lambertStratumTransport(q[3 % n], 0.6f, 3 % n, l.rows, l.cols),
                    q[3 % n] * 0.6f / float(kPiD) * stratumCosineIntegral(3 % n, l.rows, l.cols));
  }
}

}  // namespace
}  // namespace qlight::shared
