// The guiding state across frames: points as ECS entities obeying the
// rejection distance, Q learned over frames, and clean resets when the strata
// change or the points are regenerated.
#include <memory>
#include <set>

#include "engine/guiding/cache_point.h"
#include "engine/session/renderer.h"
#include "tests/render/render_support.h"

namespace qlight::test {
namespace {

class QGuidingState : public GpuTest {
 protected:
  // The Cornell box at 32x32, 2 spp per frame, guided with a small point budget.
  std::unique_ptr<session::Renderer> guidedCornell(uint32_t budget, uint32_t darts) {
    asset_ = gltf::loadGltf(assetPath("cornell_box.gltf"));
    render::RenderSettings s = smallSettings(32, 32, 2);
    s.samplesPerFrame = 2;
    settings_.pointBudget = budget;
    settings_.dartPaths = darts;
    return std::make_unique<session::Renderer>(ctx(), asset_, s, settings_, 1.0f);
  }
  scene::SceneAsset asset_;
  guiding::GuidingSettings settings_;
};

TEST_F(QGuidingState, PointsLearnAndResetCleanly) {
  auto owner = guidedCornell(2048, 8192);
  session::Renderer& renderer = *owner;
  guiding::GuidingSettings g = settings_;
  const guiding::QGuide& guide = *renderer.guide();
  ecs::Registry& registry = renderer.world().registry();

  // Points are entities; compatible ones keep the rejection distance.
  auto& points = registry.storage<guiding::CachePoint>();
  ASSERT_GT(points.size(), 100u);
  ASSERT_EQ(points.size(), guide.stats().points);
  const float r = guide.stats().rejectionMin;
  for (size_t i = 0; i < points.size(); ++i)
    for (size_t j = i + 1; j < points.size(); ++j) {
      const auto& a = points.data()[i];
      const auto& b = points.data()[j];
      if (glm::dot(a.normal, b.normal) >= g.normalCosine) {
        ASSERT_GE(glm::distance(a.position, b.position), r * (1.0f - 1e-5f));
      }
    }

  session::FrameResult last;
  auto frames = [&](int n) {
    for (int f = 0; f < n; ++f) last = renderer.renderFrame(0.0f);
  };
  std::vector<float> initial = guide.readQ(0);
  for (float q : initial) ASSERT_FLOAT_EQ(q, g.initialQ);
  frames(6);
  // Learning moved some point's table away from the uniform start.
  bool learned = false;
  for (uint32_t p = 0; p < guide.stats().points && !learned; ++p)
    for (float q : guide.readQ(p)) learned |= std::abs(q - g.initialQ) > 1e-6f;
  EXPECT_TRUE(learned);

  // New strata: tables of the new size, back to the uniform start.
  g.rows = 4;
  g.cols = 16;
  renderer.setGuiding(g);
  for (uint32_t p = 0; p < guide.stats().points; p += 97) {
    std::vector<float> q = guide.readQ(p);
    ASSERT_EQ(q.size(), 64u);
    for (float v : q) ASSERT_FLOAT_EQ(v, g.initialQ);
  }
  frames(2);  // renders on with the new tables (the fixture fails on validation messages)
  // ... and still finds its points (they and their grid survive a strata change).
  EXPECT_GT(last.counters.coveredVertices, 0u);

  // Regenerated points start over.
  renderer.setGuiding(g, /*regenerate=*/true);
  EXPECT_EQ(guide.stats().spawnedPoints, 0u);
  EXPECT_EQ(registry.storage<guiding::CachePoint>().size(), guide.stats().points);
  for (float v : guide.readQ(0)) ASSERT_FLOAT_EQ(v, g.initialQ);
}

// A point's learned row is its slot's, not its dense index's: destroying another point
// (swap-and-pop moves the last point into the hole) leaves every row with its point, and
// the slot freed is taken by the next point with a fresh row.
TEST_F(QGuidingState, SlotsStayWithTheirPointsWhenOthersAreDestroyed) {
  auto owner = guidedCornell(1024, 4096);
  session::Renderer& renderer = *owner;
  const guiding::QGuide& guide = *renderer.guide();
  ecs::Registry& registry = renderer.world().registry();
  for (int f = 0; f < 6; ++f) renderer.renderFrame(0.0f);

  auto& points = registry.storage<guiding::CachePoint>();
  ASSERT_GT(points.size(), 10u);
  const ecs::Entity moved = points.entities().back();  // swap-and-pop moves it
  const guiding::CachePoint before = points.get(moved);
  const std::vector<float> movedRow = guide.readQ(before.slot);
  const ecs::Entity destroyed = points.entities().front();
  const uint32_t freedSlot = points.get(destroyed).slot;
  const uint32_t count = guide.stats().points;
  registry.destroy(destroyed);
  renderer.update(0.0f);  // the upload phase finds the point gone

  EXPECT_EQ(guide.stats().points, count - 1);
  ASSERT_EQ(points.get(moved).slot, before.slot);
  EXPECT_EQ(points.get(moved).position, before.position);
  EXPECT_EQ(guide.readQ(before.slot), movedRow);
  std::set<uint32_t> slots;
  for (const guiding::CachePoint& p : points.values()) slots.insert(p.slot);
  EXPECT_EQ(slots.size(), points.size());
  EXPECT_EQ(slots.count(freedSlot), 0u);
  // Rendering on with a hole in the slots is fine (the fixture checks validation).
  EXPECT_GT(renderer.renderFrame(0.0f).counters.coveredVertices, 0u);
}

}  // namespace
}  // namespace qlight::test
