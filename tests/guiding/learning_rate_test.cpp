// The batched Q update (all of a frame's targets of one entry at once) against
// applying D&K's update one target at a time.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "shaders/shared/guiding_types.h"

namespace qlight::shared {
namespace {

double sequentialRetained(uint32_t n0, uint32_t m, float aMin, float aMax) {
  double keep = 1.0;
  for (uint32_t i = 0; i < m; ++i) keep *= 1.0 - double(learningRate(n0 + i, aMin, aMax));
  return keep;
}

TEST(LearningRate, ClampsOneOverOnePlusVisits) {
  EXPECT_FLOAT_EQ(learningRate(0, 1e-4f, 0.05f), 0.05f);
  EXPECT_FLOAT_EQ(learningRate(99, 1e-4f, 0.05f), 0.01f);
  EXPECT_FLOAT_EQ(learningRate(1000000, 1e-4f, 0.05f), 1e-4f);
  EXPECT_FLOAT_EQ(learningRate(3, 1e-4f, 1.0f), 0.25f);
}

// The closed form equals the product of the per-update factors for every
// combination of start count, batch size and bounds, including constant rates.
TEST(LearningRate, ClosedFormRetentionMatchesSequentialProduct) {
  std::mt19937 rng(3);
  const float bounds[][2] = {
      {1e-4f, 0.05f}, {0.01f, 0.5f}, {0.1f, 0.1f}, {1e-3f, 1.0f}, {0.2f, 0.9f}};
  for (auto& b : bounds)
    for (int trial = 0; trial < 400; ++trial) {
      uint32_t n0 = std::uniform_int_distribution<uint32_t>(0, 30000)(rng) >> (trial % 12);
      uint32_t m = std::uniform_int_distribution<uint32_t>(0, 3000)(rng) >> (trial % 9);
      double expected = sequentialRetained(n0, m, b[0], b[1]);
      double got = retainedAfterUpdates(n0, m, b[0], b[1]);
      // float arithmetic in the closed form: relative 1e-4 (pow of ~1e4 factors)
      EXPECT_NEAR(got, expected, 1e-4 * expected + 1e-7)
          << "n0 " << n0 << " m " << m << " bounds " << b[0] << " " << b[1];
    }
}

TEST(LearningRate, BatchEqualsSequentialUpdatesWithEqualTargets) {
  const float target = 3.5f;
  for (uint32_t n0 : {0u, 5u, 100u, 50000u})
    for (uint32_t m : {1u, 7u, 300u}) {
      double q = 0.25;
      for (uint32_t i = 0; i < m; ++i) {
        double a = learningRate(n0 + i, 1e-4f, 0.05f);
        q = (1 - a) * q + a * target;
      }
      float batched = updatedQ(0.25f, target * float(m), m, n0, 1e-4f, 0.05f, 1e-6f);
      EXPECT_NEAR(batched, q, 1e-4 * q) << n0 << " " << m;
    }
}

// With the unclamped 1/(1+n) schedule the batch is exactly the running mean of
// every target so far, whatever their values (D&K's consistent schedule).
TEST(LearningRate, HarmonicScheduleIsTheRunningMean) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(0.0f, 10.0f);
  float q = 0.0f;
  uint32_t visits = 0;
  double sum = 0;
  for (int frame = 0; frame < 20; ++frame) {
    uint32_t m = 1 + frame * 3;
    float frameSum = 0;
    for (uint32_t i = 0; i < m; ++i) frameSum += u(rng);
    sum += frameSum;
    q = updatedQ(q, frameSum, m, visits, 1e-9f, 1.0f, 0.0f);
    visits += m;
    EXPECT_NEAR(q, sum / visits, 1e-4 * sum / visits);
  }
}

TEST(LearningRate, NanOrInfNeverEntersATable) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  EXPECT_EQ(updatedQ(0.5f, nan, 3, 10, 1e-4f, 0.05f, 1e-4f), 0.5f);
  EXPECT_EQ(updatedQ(0.5f, inf, 3, 10, 1e-4f, 0.05f, 1e-4f), 0.5f);
  EXPECT_EQ(updatedQ(0.5f, -inf, 3, 10, 1e-4f, 0.05f, 1e-4f), 0.5f);
  EXPECT_EQ(updatedQ(0.5f, -5.0f, 1, 0, 1e-4f, 1.0f, 1e-4f), 0.5f);   // negative radiance: rejected
  EXPECT_EQ(updatedQ(0.0f, 0.0f, 4, 0, 1e-4f, 0.05f, 1e-3f), 1e-3f);  // the floor holds
  EXPECT_TRUE(std::isfinite(updatedQ(3e38f, 3e38f * 2.0f, 2, 0, 1e-4f, 0.05f, 1e-4f)));
}

}  // namespace
}  // namespace qlight::shared
