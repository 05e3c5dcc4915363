// The per-pixel RNG: floats in [0, 1), uniform in 1D and in consecutive
// pairs, and no correlation between neighbouring pixels or frames.
#include "shaders/shared/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <unordered_set>
#include <vector>

#include "stats_support.h"

namespace qlight::shared {
namespace {

using qlight::test::chiSquareTest;

TEST(Random, UnitFloatConversionStaysBelowOne) {
  EXPECT_EQ(uintToUnitFloat(0u), 0.0f);
  EXPECT_LT(uintToUnitFloat(0xffffffffu), 1.0f);
  EXPECT_EQ(uintToUnitFloat(0xffffffffu), 1.0f - 1.0f / 16777216.0f);
}

TEST(Random, FloatsAreInUnitInterval) {
  Rng rng = rngSeed(12u, 34u, 56u);
  for (int i = 0; i < 1000000; ++i) {
    float x = rngNextFloat(rng);
    ASSERT_GE(x, 0.0f);
    ASSERT_LT(x, 1.0f);
  }
}

TEST(Random, FloatsAreUniform) {
  constexpr int kBins = 1000;
  constexpr int kDraws = 1000000;
  std::vector<double> observed(kBins, 0.0);
  Rng rng = rngSeed(7u, 0u, 1u);
  for (int i = 0; i < kDraws; ++i) observed[int(rngNextFloat(rng) * kBins)] += 1.0;
  auto result = chiSquareTest(observed, std::vector<double>(kBins, double(kDraws) / kBins));
  EXPECT_TRUE(result.pass()) << result.describe();
}

// Consecutive pairs fill the square evenly (catches serial correlation).
TEST(Random, ConsecutivePairsAreUniform) {
  constexpr int kSide = 64;
  constexpr int kPairs = 1000000;
  std::vector<double> observed(kSide * kSide, 0.0);
  Rng rng = rngSeed(99u, 5u, 3u);
  for (int i = 0; i < kPairs; ++i) {
    vec2 u = rngNext2(rng);
    observed[int(u.x * kSide) * kSide + int(u.y * kSide)] += 1.0;
  }
  auto result =
      chiSquareTest(observed, std::vector<double>(kSide * kSide, double(kPairs) / (kSide * kSide)));
  EXPECT_TRUE(result.pass()) << result.describe();
}

// The first streams of pixel i and its neighbour `offset` away (same frame),
// or of frame f and f + 1 (same pixel): Pearson correlation of their j-th
// draws. Under independence r ~ N(0, 1/n); the bound is the two-sided 1e-4
// normal quantile.
double neighbourCorrelation(uint pixelStep, uint frameStep, int drawIndex, int n) {
  double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
  for (int i = 0; i < n; ++i) {
    Rng a = rngSeed(uint(i), 17u, 42u);
    Rng b = rngSeed(uint(i) + pixelStep, 17u + frameStep, 42u);
    double x = 0, y = 0;
    for (int j = 0; j <= drawIndex; ++j) {
      x = rngNextFloat(a);
      y = rngNextFloat(b);
    }
    sx += x;
    sy += y;
    sxx += x * x;
    syy += y * y;
    sxy += x * y;
  }
  double cov = sxy / n - (sx / n) * (sy / n);
  double vx = sxx / n - (sx / n) * (sx / n);
  double vy = syy / n - (sy / n) * (sy / n);
  return cov / std::sqrt(vx * vy);
}

TEST(Random, NeighbouringPixelsAndFramesAreUncorrelated) {
  constexpr int kPairs = 200000;
  const double bound = qlight::test::kNormalQuantileTwoSidedP1e4 / std::sqrt(double(kPairs));
  struct Case {
    uint pixelStep, frameStep;
  };
  // Right neighbour, the pixel below in a 1920-wide image, the next frame.
  for (Case c : {Case{1u, 0u}, Case{1920u, 0u}, Case{0u, 1u}}) {
    for (int draw : {0, 1, 3}) {
      double r = neighbourCorrelation(c.pixelStep, c.frameStep, draw, kPairs);
      EXPECT_LT(std::abs(r), bound)
          << "pixel step " << c.pixelStep << ", frame step " << c.frameStep << ", draw " << draw;
    }
  }
}

// For a fixed frame and seed, the seed is a bijection of the pixel index.
TEST(Random, PixelsGetDistinctStates) {
  constexpr uint kPixels = 1u << 20;
  std::unordered_set<uint> states;
  states.reserve(kPixels);
  for (uint p = 0; p < kPixels; ++p) states.insert(rngSeed(p, 5u, 9u).state);
  EXPECT_EQ(states.size(), size_t(kPixels));
}

TEST(Random, UserSeedChangesTheStream) {
  Rng a = rngSeed(10u, 20u, 1u);
  Rng b = rngSeed(10u, 20u, 2u);
  int equal = 0;
  for (int i = 0; i < 64; ++i) equal += rngNextUint(a) == rngNextUint(b) ? 1 : 0;
  EXPECT_EQ(equal, 0);
}

}  // namespace
}  // namespace qlight::shared
