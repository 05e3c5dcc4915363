// The direction tree's density (shaders/shared/direction_tree.h through its CPU mirror):
// it integrates to 1 over the hemisphere, and a sample's density is the one a lookup gives.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engine/guiding/direction_tree_cpu.h"

namespace qlight::guiding {
namespace {

// Root with slot 1 split into node 1, whose slot 2 is split into node 2; uneven weights.
DirectionTree unevenTree() {
  DirectionTree t;
  t.weights = {1.0f, 0.0f, 0.5f, 2.0f, 4.0f, 0.2f, 0.0f, 1.0f, 3.0f, 0.1f, 0.7f, 1.5f};
  t.children = {0, 1, 0, 0, 0, 0, 2, 0, 0, 0, 0, 0};
  // Inner slots weigh the mean of their children.
  t.weights[6] = 0.25f * (3.0f + 0.1f + 0.7f + 1.5f);
  t.weights[1] = 0.25f * (4.0f + 0.2f + t.weights[6] + 1.0f);
  return t;
}

TEST(DirectionTree, DensityIntegratesToOneOverTheHemisphere) {
  const DirectionTree tree = unevenTree();
  // Midpoint rule over (cos theta, phi): dw = dz dphi.
  const int nz = 512, nphi = 2048;
  double sum = 0.0;
  for (int i = 0; i < nz; ++i)
    for (int j = 0; j < nphi; ++j) {
      float z = (i + 0.5f) / nz, phi = 2.0f * float(M_PI) * (j + 0.5f) / nphi;
      float s = std::sqrt(1.0f - z * z);
      sum += treeDensity(tree, {s * std::cos(phi), s * std::sin(phi), z});
    }
  sum *= (1.0 / nz) * (2.0 * M_PI / nphi);
  EXPECT_NEAR(sum, 1.0, 2e-3);
}

TEST(DirectionTree, SamplesCarryTheDensityOfTheirDirection) {
  const DirectionTree tree = unevenTree();
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 0.999f);
  for (int i = 0; i < 2000; ++i) {
    float pdf = 0.0f;
    glm::vec3 d = sampleTreeDirection(tree, {u(rng), u(rng), u(rng)}, pdf);
    ASSERT_NEAR(glm::length(d), 1.0f, 1e-4f);
    ASSERT_GT(pdf, 0.0f);
    ASSERT_NEAR(pdf, treeDensity(tree, d), 1e-3f * pdf);
  }
}

TEST(DirectionTree, ShapeCountsLeavesAndLevels) {
  TreeShape shape = treeShape(unevenTree());
  EXPECT_EQ(shape.leaves, 10u);
  EXPECT_EQ(shape.depth, 3u);
}

}  // namespace
}  // namespace qlight::guiding
