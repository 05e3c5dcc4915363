// Channel sampling against values computed by hand from the glTF interpolation formulas.
#include "engine/scene/animation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/quaternion.hpp>

#include "engine/gltf/gltf_loader.h"
#include "engine/gltf/gltf_writer.h"
#include "engine/scene/procedural.h"
#include "tests/gltf/gltf_test_files.h"

namespace qlight::scene {
namespace {

using gltf::loadGltf;

AnimationChannel channel(AnimationPath path, Interpolation interpolation, std::vector<float> times,
                         std::vector<glm::vec4> values) {
  AnimationChannel c;
  c.path = path;
  c.interpolation = interpolation;
  c.times = std::move(times);
  c.values = std::move(values);
  return c;
}

void expectVec(glm::vec4 actual, glm::vec4 expected, float tolerance = 1e-6f) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
  EXPECT_NEAR(actual.w, expected.w, tolerance);
}

TEST(AnimationSampling, StepHoldsEachKeyUntilTheNext) {
  const AnimationChannel c = channel(AnimationPath::Translation, Interpolation::Step, {0, 1, 2},
                                     {{0, 0, 0, 0}, {1, 0, 0, 0}, {5, 0, 0, 0}});
  const std::pair<float, float> expected[] = {{-1.0f, 0},  {0.0f, 0}, {0.5f, 0},
                                              {0.999f, 0}, {1.0f, 1}, {1.5f, 1},
                                              {1.99f, 1},  {2.0f, 5}, {7.0f, 5}};
  for (auto [t, x] : expected) EXPECT_EQ(sampleChannel(c, t).x, x) << "t = " << t;
}

TEST(AnimationSampling, LinearTranslationAndClamping) {
  const AnimationChannel c = channel(AnimationPath::Translation, Interpolation::Linear, {1, 3},
                                     {{0, 2, 0, 0}, {4, 2, -2, 0}});
  expectVec(sampleChannel(c, 0.0f), {0, 2, 0, 0});  // before the first key
  expectVec(sampleChannel(c, 1.5f), {1, 2, -0.5f, 0});
  expectVec(sampleChannel(c, 2.0f), {2, 2, -1, 0});
  expectVec(sampleChannel(c, 9.0f), {4, 2, -2, 0});  // after the last key
}

// Keys 0 and 2 s: value 0 with out-tangent 1, value 4 with in-tangent 3 (x only). With
// dt = 2: p(u) = h00 0 + h10 (2 * 1) + h01 4 + h11 (2 * 3), h10 = u^3 - 2u^2 + u,
// h01 = -2u^3 + 3u^2, h11 = u^3 - u^2. u = 0.25: 0.28125 + 0.625 - 0.28125 = 0.625;
// u = 0.5: 0.25 + 2 - 0.75 = 1.5; u = 0.75: 0.09375 + 3.375 - 0.84375 = 2.625.
TEST(AnimationSampling, CubicSplineIsTheHermiteOfValuesAndTangents) {
  const AnimationChannel c = channel(AnimationPath::Translation, Interpolation::CubicSpline, {0, 2},
                                     {{9, 9, 9, 0},
                                      {0, 0, 0, 0},
                                      {1, 0, 0, 0},  // key 0: in (ignored), value, out
                                      {3, 0, 0, 0},
                                      {4, 0, 0, 0},
                                      {9, 9, 9, 0}});  // key 1: in, value, out (ignored)
  EXPECT_NEAR(sampleChannel(c, 0.5f).x, 0.625f, 1e-6f);
  EXPECT_NEAR(sampleChannel(c, 1.0f).x, 1.5f, 1e-6f);
  EXPECT_NEAR(sampleChannel(c, 1.5f).x, 2.625f, 1e-6f);
  expectVec(sampleChannel(c, 0.0f), {0, 0, 0, 0});
  expectVec(sampleChannel(c, 2.0f), {4, 0, 0, 0});
  expectVec(sampleChannel(c, -3.0f), {0, 0, 0, 0});  // clamped to the value, not a tangent
  expectVec(sampleChannel(c, 30.0f), {4, 0, 0, 0});
}

// Rotation keys identity and 180 degrees about z with zero tangents: p(u) = h00 q0 + h01 q1,
// normalized. u = 0.5 gives (0, 0, .5, .5) -> 90 degrees; u = 0.25 gives
// (0, 0, 0.15625, 0.84375) normalized.
TEST(AnimationSampling, CubicSplineRotationsAreNormalized) {
  const glm::vec4 zero(0.0f);
  const AnimationChannel c = channel(AnimationPath::Rotation, Interpolation::CubicSpline, {0, 1},
                                     {zero, {0, 0, 0, 1}, zero, zero, {0, 0, 1, 0}, zero});
  const float s = std::sqrt(0.5f);
  expectVec(sampleChannel(c, 0.5f), {0, 0, s, s});
  expectVec(sampleChannel(c, 0.25f), glm::normalize(glm::vec4(0, 0, 0.15625f, 0.84375f)));
  EXPECT_NEAR(glm::length(sampleChannel(c, 0.8f)), 1.0f, 1e-6f);
}

TEST(AnimationSampling, LinearRotationSlerpsTheShorterArc) {
  // 0 and 90 degrees about y; the second key also written as its negation (same rotation).
  const float s = std::sqrt(0.5f);
  for (float sign : {1.0f, -1.0f}) {
    const AnimationChannel c = channel(AnimationPath::Rotation, Interpolation::Linear, {0, 1},
                                       {{0, 0, 0, 1}, sign * glm::vec4(0, s, 0, s)});
    for (float t : {0.0f, 0.25f, 0.5f, 1.0f}) {
      const float half = 0.5f * glm::radians(90.0f * t);
      const glm::vec4 expected(0, std::sin(half), 0, std::cos(half));
      glm::vec4 actual = sampleChannel(c, t);
      if (glm::dot(actual, expected) < 0.0f) actual = -actual;  // q and -q: same rotation
      expectVec(actual, expected, 2e-6f);
    }
  }
}

TEST(AnimationSampling, LoopingWrapsTimePerAnimation) {
  AnimationAsset a;
  a.duration = 4.0f;
  EXPECT_FLOAT_EQ(animationTime(a, 5.0f, true), 1.0f);
  EXPECT_FLOAT_EQ(animationTime(a, -1.0f, true), 3.0f);
  EXPECT_FLOAT_EQ(animationTime(a, 5.0f, false), 5.0f);
  EXPECT_FLOAT_EQ(animationTime(a, NAN, true), 0.0f);
}

TEST(AnimationSampling, AnimatePosesTheTargetedNodesOnly) {
  SceneAsset scene;
  NodeAsset node;
  node.local.translation = {0, 0, 7};
  addNode(scene, node);
  addNode(scene, node);
  AnimationAsset a;
  a.channels.push_back(
      channel(AnimationPath::Scale, Interpolation::Linear, {0, 2}, {{1, 1, 1, 0}, {3, 1, 1, 0}}));
  a.channels[0].node = 1;
  a.duration = 2.0f;
  scene.animations.push_back(a);
  const std::vector<LocalTransform> pose = animate(scene, 1.0f);
  EXPECT_EQ(pose[0].scale, glm::vec3(1.0f));
  EXPECT_EQ(pose[1].scale, glm::vec3(2, 1, 1));
  EXPECT_EQ(pose[1].translation, glm::vec3(0, 0, 7));  // untouched paths keep the rest pose
  EXPECT_EQ(animate(scene, 3.0f, true)[1].scale, glm::vec3(2, 1, 1));  // 3 s loops to 1 s
}

// STEP and CUBICSPLINE survive a round trip through a file (writer and loader).
TEST(AnimationSampling, InterpolationsLoadFromAFile) {
  SceneAsset scene;
  scene.materials.push_back(MaterialAsset{});
  MeshAsset mesh;
  addQuad(mesh, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, 0);
  scene.meshes.push_back(mesh);
  NodeAsset node;
  node.mesh = 0;
  addNode(scene, node);
  AnimationAsset a;
  a.channels.push_back(channel(AnimationPath::Translation, Interpolation::Step, {0, 1, 2},
                               {{0, 0, 0, 0}, {1, 0, 0, 0}, {5, 0, 0, 0}}));
  a.channels.push_back(channel(
      AnimationPath::Rotation, Interpolation::CubicSpline, {0, 1},
      {{0, 0, 0, 0}, {0, 0, 0, 1}, {0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 0}}));
  a.duration = 2.0f;
  scene.animations.push_back(a);
  gltf::testing::TempDir dir;
  gltf::saveGltf(scene, dir / "animated.gltf");
  const SceneAsset back = loadGltf(dir / "animated.gltf");
  ASSERT_EQ(back.animations.size(), 1u);
  ASSERT_EQ(back.animations[0].channels.size(), 2u);
  const AnimationChannel& step = back.animations[0].channels[0];
  const AnimationChannel& cubic = back.animations[0].channels[1];
  EXPECT_EQ(step.interpolation, Interpolation::Step);
  EXPECT_EQ(cubic.interpolation, Interpolation::CubicSpline);
  EXPECT_EQ(sampleChannel(step, 1.5f).x, 1.0f);
  const float s = std::sqrt(0.5f);
  expectVec(sampleChannel(cubic, 0.5f), {0, 0, s, s});
  EXPECT_FLOAT_EQ(back.animations[0].duration, 2.0f);
}

}  // namespace
}  // namespace qlight::scene
