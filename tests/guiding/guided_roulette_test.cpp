// Guided Russian roulette (shared::guidedSurvivalProbability): the survival probability
// follows the path's expected contribution relative to its first vertex's estimate, so a
// guided path toward the light (small throughput, large Q) is kept and a path toward
// darkness ends; it stays inside [floor, cap] so every survivor's weight is bounded and
// every path ends. Its unbiasedness in the renderer is the white furnace of
// guided_high_share_test.cpp (guided roulette on, Russian roulette ending every path): a 5%
// error in the survivors' reweighting moved that furnace by 112 standard errors.
#include <gtest/gtest.h>

#include "shaders/shared/guiding_types.h"

namespace qlight::test {
namespace {

using shared::guidedSurvivalProbability;
using shared::kRouletteMaxSurvival;
using shared::kRouletteMinSurvival;
using shared::kRouletteWindow;

TEST(GuidedRoulette, KeepsPathsExpectedToBringLight) {
  const float firstVertex = 0.2f;
  // A throughput of 0.02 (the guided pdf was 40x the BSDF's) toward Q = 5: the path is
  // expected to bring 0.1, half the first vertex's estimate. The throughput roulette would
  // keep it with probability 0.02; the guided one keeps it at the cap.
  EXPECT_FLOAT_EQ(guidedSurvivalProbability(0.02f, 0.02f * 5.0f, firstVertex, 1.0f),
                  kRouletteMaxSurvival);
  // At exactly 1/kRouletteWindow of the estimate it is still kept (up to the cap).
  EXPECT_FLOAT_EQ(guidedSurvivalProbability(0.5f, firstVertex / kRouletteWindow, firstVertex, 1.0f),
                  kRouletteMaxSurvival);
}

TEST(GuidedRoulette, SurvivalIsProportionalToExpectedContributionBelowTheWindow) {
  const float firstVertex = 1.0f;
  const float a = guidedSurvivalProbability(0.9f, 0.02f, firstVertex, 1.0f);
  const float b = guidedSurvivalProbability(0.9f, 0.04f, firstVertex, 1.0f);
  EXPECT_FLOAT_EQ(a, kRouletteWindow * 0.02f);
  EXPECT_FLOAT_EQ(b, 2.0f * a);
  // Only the ratio to the first vertex matters: the same path in a scene 10x brighter.
  EXPECT_FLOAT_EQ(guidedSurvivalProbability(0.9f, 0.2f, 10.0f * firstVertex, 1.0f), a);
}

TEST(GuidedRoulette, FloorBoundsTheSurvivorsWeight) {
  // Q says the direction is dark (0): the path still survives with the floor's probability,
  // so if Q was wrong its contribution is weighted by at most 1 / floor.
  EXPECT_FLOAT_EQ(guidedSurvivalProbability(0.9f, 0.0f, 1.0f, 1.0f), kRouletteMinSurvival);
  EXPECT_GT(kRouletteMinSurvival, 0.0f);
  EXPECT_LT(kRouletteMaxSurvival, 1.0f);
}

TEST(GuidedRoulette, PointsWithoutConfidenceUseTheThroughput) {
  EXPECT_FLOAT_EQ(guidedSurvivalProbability(0.3f, 10.0f, 1.0f, 0.0f), 0.3f);
  // Half confidence: halfway between the two roulettes.
  const float guided = guidedSurvivalProbability(0.3f, 0.05f, 1.0f, 1.0f);
  EXPECT_FLOAT_EQ(guidedSurvivalProbability(0.3f, 0.05f, 1.0f, 0.5f), 0.5f * (0.3f + guided));
}

}  // namespace
}  // namespace qlight::test
