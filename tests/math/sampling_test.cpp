// Frames, hemisphere/sphere/disk/triangle samplers and MIS weights: each
// sampler's pdf integrates to 1 and its samples follow the pdf (chi-square).
#include "shaders/shared/sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "sphere_quadrature.h"
#include "stats_support.h"

namespace qlight::shared {
namespace {

using qlight::test::chiSquareTest;
using qlight::test::kPiD;
using qlight::test::SphereGrid;
using qlight::test::TestRandom;

void expectOrthonormal(vec3 n) {
  TangentFrame f = frameFromNormal(n);
  EXPECT_NEAR(length(f.tangent), 1.0f, 1e-5f) << n.x << " " << n.y << " " << n.z;
  EXPECT_NEAR(length(f.bitangent), 1.0f, 1e-5f);
  EXPECT_NEAR(dot(f.tangent, f.bitangent), 0.0f, 1e-5f);
  EXPECT_NEAR(dot(f.tangent, n), 0.0f, 1e-5f);
  EXPECT_NEAR(dot(f.bitangent, n), 0.0f, 1e-5f);
  vec3 c = cross(f.tangent, f.bitangent);
  EXPECT_NEAR(length(c - n), 0.0f, 1e-5f) << "not right-handed";
}

TEST(Frame, IsOrthonormalAndRightHanded) {
  TestRandom rnd(1);
  for (int i = 0; i < 10000; ++i) expectOrthonormal(sampleUniformSphere(rnd.next2()));
  for (vec3 n :
       {vec3(0, 0, 1), vec3(0, 0, -1), vec3(1, 0, 0), vec3(0, -1, 0), normalize(vec3(1e-4f, 0, -1)),
        normalize(vec3(0, 1e-4f, 1)), normalize(vec3(1, 1, -1e-7f))})
    expectOrthonormal(n);
}

TEST(Frame, LocalWorldRoundTrip) {
  TestRandom rnd(2);
  for (int i = 0; i < 1000; ++i) {
    TangentFrame f = frameFromNormal(sampleUniformSphere(rnd.next2()));
    vec3 v = sampleUniformSphere(rnd.next2()) * 3.0f;
    EXPECT_NEAR(length(worldFromLocal(f, localFromWorld(f, v)) - v), 0.0f, 1e-5f);
    EXPECT_NEAR(localFromWorld(f, f.normal).z, 1.0f, 1e-6f);
  }
}

// Bins uniform in (z, phi): the integral of any pdf of the form g(z) over a
// bin is exact from g's antiderivative, so expected counts carry no error.
template <class ZCdf>
void checkZPhiSamples(ZCdf&& zCdf, double zLo, vec3 (*sampler)(vec2), uint32_t seed) {
  constexpr int kZBins = 40, kPhiBins = 40, kSamples = 400000;
  std::vector<double> observed(kZBins * kPhiBins, 0.0);
  TestRandom rnd(seed);
  for (int i = 0; i < kSamples; ++i) {
    vec3 w = sampler(rnd.next2());
    ASSERT_NEAR(length(w), 1.0f, 1e-5f);
    double phi = std::atan2(double(w.y), double(w.x));
    if (phi < 0) phi += 2 * kPiD;
    int iz = std::clamp(int((w.z - zLo) / (1.0 - zLo) * kZBins), 0, kZBins - 1);
    int ip = std::clamp(int(phi / (2 * kPiD) * kPhiBins), 0, kPhiBins - 1);
    ASSERT_GE(w.z, zLo - 1e-6);
    observed[iz * kPhiBins + ip] += 1.0;
  }
  std::vector<double> expected(kZBins * kPhiBins);
  for (int iz = 0; iz < kZBins; ++iz) {
    double z0 = zLo + (1.0 - zLo) * iz / kZBins, z1 = zLo + (1.0 - zLo) * (iz + 1) / kZBins;
    for (int ip = 0; ip < kPhiBins; ++ip)
      expected[iz * kPhiBins + ip] = kSamples * (zCdf(z1) - zCdf(z0)) / kPhiBins;
  }
  auto result = chiSquareTest(observed, expected);
  EXPECT_TRUE(result.pass()) << result.describe();
}

TEST(CosineHemisphere, PdfIntegratesToOne) {
  auto r = qlight::test::integrateWithError(
      SphereGrid::uniform(0, kPiD / 2), [](vec3 w) { return cosineHemispherePdf(w.z); }, 256);
  EXPECT_NEAR(r.value, 1.0, 1e-5 + 3 * r.errorEstimate);
  EXPECT_LT(r.errorEstimate, 1e-4);
}

TEST(CosineHemisphere, SamplesFollowPdf) {
  // P(z < t) = t^2 on the hemisphere.
  checkZPhiSamples([](double z) { return z * z; }, 0.0, sampleCosineHemisphere, 3);
}

TEST(UniformHemisphere, PdfIntegratesToOneAndSamplesFollowIt) {
  auto r = qlight::test::integrateWithError(
      SphereGrid::uniform(0, kPiD / 2), [](vec3) { return uniformHemispherePdf(); }, 256);
  EXPECT_NEAR(r.value, 1.0, 1e-5 + 3 * r.errorEstimate);
  checkZPhiSamples([](double z) { return z; }, 0.0, sampleUniformHemisphere, 4);
}

TEST(UniformSphere, PdfIntegratesToOneAndSamplesFollowIt) {
  auto r = qlight::test::integrateWithError(
      SphereGrid::uniform(0, kPiD), [](vec3) { return uniformSpherePdf(); }, 256);
  EXPECT_NEAR(r.value, 1.0, 1e-5 + 3 * r.errorEstimate);
  checkZPhiSamples([](double z) { return 0.5 * (z + 1.0); }, -1.0, sampleUniformSphere, 5);
}

TEST(ConcentricDisk, SamplesAreUniformOnTheDisk) {
  // Uniform on the disk <=> r^2 and phi uniform.
  constexpr int kRBins = 32, kPhiBins = 32, kSamples = 300000;
  std::vector<double> observed(kRBins * kPhiBins, 0.0);
  TestRandom rnd(6);
  for (int i = 0; i < kSamples; ++i) {
    vec2 d = sampleConcentricDisk(rnd.next2());
    double r2 = double(d.x) * d.x + double(d.y) * d.y;
    ASSERT_LE(r2, 1.0 + 1e-6);
    double phi = std::atan2(double(d.y), double(d.x));
    if (phi < 0) phi += 2 * kPiD;
    int ir = std::min(int(r2 * kRBins), kRBins - 1);
    int ip = std::min(int(phi / (2 * kPiD) * kPhiBins), kPhiBins - 1);
    observed[ir * kPhiBins + ip] += 1.0;
  }
  auto result = chiSquareTest(
      observed, std::vector<double>(kRBins * kPhiBins, double(kSamples) / (kRBins * kPhiBins)));
  EXPECT_TRUE(result.pass()) << result.describe();
}

TEST(Triangle, BarycentricsAreValid) {
  TestRandom rnd(7);
  for (int i = 0; i < 100000; ++i) {
    vec3 b = sampleTriangleBarycentrics(rnd.next2());
    ASSERT_GE(b.x, 0.0f);
    ASSERT_GE(b.y, 0.0f);
    ASSERT_GE(b.z, -1e-7f);
    ASSERT_NEAR(b.x + b.y + b.z, 1.0f, 1e-6f);
  }
  for (vec2 u :
       {vec2(0, 0), vec2(0.99999994f, 0.99999994f), vec2(0, 0.99999994f), vec2(0.99999994f, 0)}) {
    vec3 b = sampleTriangleBarycentrics(u);
    EXPECT_GE(std::min(b.x, std::min(b.y, b.z)), -1e-7f);
  }
}

// Cells of side 1/n in (b0, b1); the diagonal b0 + b1 = 1 cuts the diagonal
// cells exactly in half, so the expected counts are exact.
TEST(Triangle, BarycentricsAreUniform) {
  constexpr int kSide = 40, kSamples = 400000;
  std::vector<double> observed(kSide * kSide, 0.0), expected(kSide * kSide, 0.0);
  TestRandom rnd(8);
  for (int i = 0; i < kSamples; ++i) {
    vec3 b = sampleTriangleBarycentrics(rnd.next2());
    int i0 = std::min(int(b.x * kSide), kSide - 1), i1 = std::min(int(b.y * kSide), kSide - 1);
    observed[i0 * kSide + i1] += 1.0;
  }
  double cellShare = 2.0 / (kSide * kSide);  // cell area / triangle area
  for (int i0 = 0; i0 < kSide; ++i0)
    for (int i1 = 0; i1 < kSide; ++i1) {
      if (i0 + i1 < kSide - 1) expected[i0 * kSide + i1] = kSamples * cellShare;
      if (i0 + i1 == kSide - 1) expected[i0 * kSide + i1] = kSamples * cellShare * 0.5;
    }
  auto result = chiSquareTest(observed, expected);
  EXPECT_TRUE(result.pass()) << result.describe();
}

TEST(Triangle, PointsLieOnTheTriangle) {
  vec3 p0(1, 2, 3), p1(4, 0, 3), p2(1, 5, -2);
  EXPECT_NEAR(triangleArea(p0, p1, p2), 0.5 * length(cross(p1 - p0, p2 - p0)), 1e-6);
  EXPECT_NEAR(triangleArea(vec3(0), vec3(2, 0, 0), vec3(0, 3, 0)), 3.0f, 1e-6f);
  TestRandom rnd(9);
  vec3 n = normalize(cross(p1 - p0, p2 - p0));
  for (int i = 0; i < 1000; ++i) {
    vec3 p = sampleTrianglePoint(p0, p1, p2, rnd.next2());
    EXPECT_NEAR(dot(p - p0, n), 0.0f, 1e-5f);
    // Inside: each edge sees p on the inner side.
    EXPECT_GE(dot(cross(p1 - p0, p - p0), n), -1e-5f);
    EXPECT_GE(dot(cross(p2 - p1, p - p1), n), -1e-5f);
    EXPECT_GE(dot(cross(p0 - p2, p - p2), n), -1e-5f);
  }
}

TEST(SolidAnglePdf, ConvertsAreaPdf) {
  EXPECT_FLOAT_EQ(solidAnglePdfFromArea(0.5f, 4.0f, 0.5f), 4.0f);
  EXPECT_FLOAT_EQ(solidAnglePdfFromArea(0.5f, 4.0f, -0.5f), 4.0f);
  EXPECT_EQ(solidAnglePdfFromArea(0.5f, 4.0f, 0.0f), 0.0f);
}

TEST(PowerHeuristic, MatchesFormulaAndSumsToOne) {
  TestRandom rnd(10);
  for (int i = 0; i < 1000; ++i) {
    float a = std::exp(8.0f * rnd.next() - 4.0f), b = std::exp(8.0f * rnd.next() - 4.0f);
    double f = a, g = 2.0 * b;
    EXPECT_NEAR(powerHeuristic(1.0f, a, 2.0f, b), f * f / (f * f + g * g), 1e-6);
    EXPECT_NEAR(powerHeuristic(1.0f, a, 2.0f, b) + powerHeuristic(2.0f, b, 1.0f, a), 1.0, 1e-6);
  }
}

TEST(PowerHeuristic, IsRobustToZerosAndInfinities) {
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(powerHeuristic(1, 3.0f, 1, 3.0f), 0.5f);
  EXPECT_EQ(powerHeuristic(1, inf, 1, 2.0f), 1.0f);
  EXPECT_EQ(powerHeuristic(1, 2.0f, 1, inf), 0.0f);
  EXPECT_EQ(powerHeuristic(1, inf, 1, inf), 0.5f);
  EXPECT_EQ(powerHeuristic(1, 0.0f, 1, 0.0f), 0.0f);
  EXPECT_EQ(powerHeuristic(1, 0.0f, 1, 5.0f), 0.0f);
  EXPECT_EQ(powerHeuristic(1, 5.0f, 1, 0.0f), 1.0f);
  EXPECT_EQ(powerHeuristic(1, nan, 1, 5.0f), 0.0f);
  EXPECT_EQ(powerHeuristic(1, 5.0f, 1, nan), 1.0f);
  // Squares of these overflow float; the ratio form does not.
  EXPECT_NEAR(powerHeuristic(1, 1e30f, 1, 1e29f), 1.0 / 1.01, 1e-6);
  EXPECT_NEAR(powerHeuristic(1, 1e-30f, 1, 1e-29f), 0.01 / 1.01, 1e-6);
}

TEST(Luminance, WeightsSumToOne) {
  EXPECT_NEAR(luminance(vec3(1.0f)), 1.0f, 1e-6f);
  EXPECT_NEAR(luminance(vec3(0, 1, 0)), 0.7152f, 1e-6f);
}

}  // namespace
}  // namespace qlight::shared
