// The demo window's dynamic resolution against a frame whose cost follows the
// pixel count (cost = k scale^2, as a path tracer's does): while the camera
// moves it settles where the target frame time is met, within the deadband; a
// still camera gets the full scale back after the settle frames.
#include "game/dynamic_resolution.h"

#include <gtest/gtest.h>

#include <cmath>

namespace qlight::game {
namespace {

constexpr float kFull = 0.5f;
// 400 ms at the full scale: the target of 100 ms is met at half of it.
double frameCost(float scale) { return 400.0 * (scale / kFull) * (scale / kFull); }

TEST(DynamicResolution, MovingCameraSettlesAtTheTargetFrameTime) {
  DynamicResolution d;
  d.targetMs = 100.0f;
  d.scale = kFull;
  for (int f = 0; f < 30; ++f) d.update(kFull, frameCost(d.scale), true);
  // Held within the deadband, |ideal - scale| <= 8% of the scale: the scale within
  // [0.25 / 1.08, 0.25 / 0.92], the frame time within [0.857, 1.182] x the target.
  EXPECT_GE(d.scale, 0.25f / (1.0f + DynamicResolution::kDeadband) - 1e-6f);
  EXPECT_LE(d.scale, 0.25f / (1.0f - DynamicResolution::kDeadband) + 1e-6f);
  EXPECT_GT(frameCost(d.scale), 100.0 * 0.85);
  EXPECT_LT(frameCost(d.scale), 100.0 * 1.19);
  EXPECT_TRUE(d.lowered(kFull));
}

TEST(DynamicResolution, StillCameraGetsTheFullScaleAfterTheSettleFrames) {
  DynamicResolution d;
  d.scale = kFull;
  for (int f = 0; f < 30; ++f) d.update(kFull, frameCost(d.scale), true);
  ASSERT_LT(d.scale, kFull);
  for (uint32_t f = 1; f < DynamicResolution::kSettleFrames; ++f) {
    d.update(kFull, frameCost(d.scale), false);
    EXPECT_LT(d.scale, kFull) << "raised after " << f << " still frame(s)";
  }
  EXPECT_EQ(d.update(kFull, frameCost(d.scale), false), kFull);
  // Moving again lowers it at once.
  EXPECT_LT(d.update(kFull, frameCost(d.scale), true), kFull);
}

TEST(DynamicResolution, FastFramesKeepTheFullScale) {
  DynamicResolution d;
  d.scale = kFull;
  for (int f = 0; f < 10; ++f) EXPECT_EQ(d.update(kFull, 20.0, true), kFull);
}

TEST(DynamicResolution, BoundedBelowAndIgnoresBadFrameTimes) {
  DynamicResolution d;
  d.scale = kFull;
  for (int f = 0; f < 50; ++f) d.update(kFull, 1e6, true);
  EXPECT_FLOAT_EQ(d.scale, DynamicResolution::kMinShare * kFull);
  const float before = d.scale;
  d.update(kFull, std::nan(""), true);
  d.update(kFull, -5.0, true);
  d.update(kFull, INFINITY, true);
  EXPECT_EQ(d.scale, before);
}

TEST(DynamicResolution, DisabledIsTheFullScale) {
  DynamicResolution d;
  d.enabled = false;
  d.scale = kFull;
  EXPECT_EQ(d.update(kFull, 1e4, true), kFull);
  // A smaller user scale is followed at once.
  EXPECT_EQ(d.update(0.3f, 1e4, true), 0.3f);
}

}  // namespace
}  // namespace qlight::game
