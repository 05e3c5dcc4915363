// The shader's nearest-cache-point search (shared header, run on the CPU here)
// against brute force, and the CPU dart acceptance's rejection distance.
#include <gtest/gtest.h>

#include <random>

#include "engine/guiding/point_acceptance.h"
#include "engine/guiding/point_grid.h"

namespace qlight::guiding {
namespace {

glm::vec3 randomUnit(std::mt19937& rng) {
  std::normal_distribution<float> n;
  return glm::normalize(glm::vec3(n(rng), n(rng), n(rng)));
}

TEST(PointSearch, GridSearchEqualsBruteForce) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-3.0f, 3.0f);
  for (float radius : {0.05f, 0.3f, 1.0f}) {
    std::vector<CachePoint> points(3000);
    for (auto& p : points) p = {glm::vec3(u(rng), u(rng), u(rng)), 0.0f, randomUnit(rng), 0};
    PointGrid grid = buildPointGrid(points, radius, 4096);
    for (int q = 0; q < 3000; ++q) {
      glm::vec3 x(u(rng), u(rng), u(rng));
      glm::vec3 n = randomUnit(rng);
      uint32_t expected = shared::kNoCachePoint;
      float best = radius * radius;
      for (uint32_t i = 0; i < points.size(); ++i) {
        glm::vec3 d = points[i].position - x;
        if (glm::dot(d, d) < best && glm::dot(points[i].normal, n) >= 0.5f) {
          best = glm::dot(d, d);
          expected = i;
        }
      }
      ASSERT_EQ(findNearestPoint(grid, points, x, n, radius, 0.5f), expected)
          << "radius " << radius << " query " << q;
    }
  }
}

TEST(PointSearch, WorksAcrossNegativeCoordinatesAndTinyHashTables) {
  std::vector<CachePoint> points = {{glm::vec3(-0.01f, -5.0f, 0.0f), 0, glm::vec3(0, 1, 0), 0},
                                    {glm::vec3(0.01f, -5.0f, 0.0f), 0, glm::vec3(0, 1, 0), 0}};
  PointGrid grid = buildPointGrid(points, 0.1f, 1);  // every cell in one bucket
  EXPECT_EQ(findNearestPoint(grid, points, glm::vec3(-0.02f, -5.0f, 0.0f), glm::vec3(0, 1, 0), 0.1f,
                             0.7f),
            0u);
  EXPECT_EQ(
      findNearestPoint(grid, points, glm::vec3(0.02f, -5.0f, 0.0f), glm::vec3(0, 1, 0), 0.1f, 0.7f),
      1u);
  // The opposite side of the surface is a different hemisphere: no point there.
  EXPECT_EQ(findNearestPoint(grid, points, glm::vec3(0.02f, -5.0f, 0.0f), glm::vec3(0, -1, 0), 0.1f,
                             0.7f),
            shared::kNoCachePoint);
  EXPECT_THROW(buildPointGrid(points, 0.1f, 3), std::invalid_argument);
  EXPECT_THROW(buildPointGrid(points, 0.0f, 4), std::invalid_argument);
}

TEST(PointAcceptance, NoTwoCompatiblePointsCloserThanTheRejectionDistance) {
  std::mt19937 rng(8);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const float r = 0.05f;
  PointAcceptor acceptor(r, 0.7f);
  std::vector<CachePoint> accepted;
  for (int i = 0; i < 20000; ++i) {
    // Candidates on both sides of the plane z = 0.
    glm::vec3 n = i % 2 ? glm::vec3(0, 0, 1) : glm::vec3(0, 0, -1);
    PointCandidate c{glm::vec3(u(rng), u(rng), 0.0f), n, 0.0f};
    CachePoint p;
    if (acceptor.tryAccept(c, r, p)) accepted.push_back(p);
  }
  for (size_t i = 0; i < accepted.size(); ++i)
    for (size_t j = i + 1; j < accepted.size(); ++j)
      if (glm::dot(accepted[i].normal, accepted[j].normal) > 0.7f) {
        ASSERT_GE(glm::distance(accepted[i].position, accepted[j].position), r);
      }
  // Random sequential adsorption on a unit square per side: about 0.7 / r^2
  // points at saturation; 20000 darts get close to it on both sides.
  EXPECT_GT(accepted.size(), size_t(2 * 0.5f / (r * r)));
  EXPECT_LT(accepted.size(), size_t(2 * 1.2f / (r * r)));
}

}  // namespace
}  // namespace qlight::guiding
