// Slots of the cache point set: a point keeps its slot for its lifetime, a destroyed
// point's slot is the next one taken (and reported for a fresh table row), the GPU array
// holds each point at its slot, and the grid finds points by slot.
#include "engine/guiding/cache_point_set.h"

#include <gtest/gtest.h>

#include "tests/gpu/gpu_fixture.h"

namespace qlight::test {
namespace {

class CachePointSetTest : public GpuTest {};

guiding::CachePoint pointAt(float x) {
  guiding::CachePoint p;
  p.position = glm::vec3(x, 0.0f, 0.0f);
  p.normal = glm::vec3(0.0f, 0.0f, 1.0f);
  return p;
}

std::vector<guiding::CachePoint> gpuPoints(const gpu::Context& ctx, const gpu::BufferView& view,
                                           uint32_t count) {
  std::vector<guiding::CachePoint> out(count);
  view.buffer()->download(ctx, out.data(), count * sizeof(guiding::CachePoint));
  return out;
}

TEST_F(CachePointSetTest, SlotsSurviveDestructionAndFreedSlotsAreReusedWithAFreshRow) {
  ecs::Registry registry;
  guiding::CachePointSet set(ctx(), 4, 0.1f);
  for (float x : {0.0f, 1.0f, 2.0f}) ASSERT_TRUE(set.add(registry, pointAt(x)));
  EXPECT_TRUE(set.sync(registry).reusedSlots.empty());  // fresh slots need no reset

  auto& storage = registry.storage<guiding::CachePoint>();
  registry.destroy(storage.entities().front());  // slot 0; the point in slot 2 moves to index 0
  EXPECT_TRUE(set.sync(registry).reusedSlots.empty());
  EXPECT_EQ(set.count(), 2u);
  std::vector<uint32_t> slots;
  for (const auto& p : storage.values()) slots.push_back(p.slot);
  EXPECT_EQ(slots, (std::vector<uint32_t>{2, 1}));

  ASSERT_TRUE(set.add(registry, pointAt(5.0f)));  // takes the freed slot 0
  EXPECT_EQ(storage.values().back().slot, 0u);
  EXPECT_EQ(set.sync(registry).reusedSlots,
            (std::vector<uint32_t>{0}));          // its learned row must be reset
  ASSERT_TRUE(set.add(registry, pointAt(7.0f)));  // then a never used slot
  EXPECT_EQ(storage.values().back().slot, 3u);
  EXPECT_FALSE(set.add(registry, pointAt(9.0f)));  // the budget is full
  set.sync(registry);

  // The GPU array holds every point at its slot; the grid search finds them by slot.
  auto gpu = gpuPoints(ctx(), set.pointsView(), 4);
  std::vector<guiding::CachePoint> bySlot(4);
  for (const auto& p : storage.values()) {
    EXPECT_EQ(gpu[p.slot].position, p.position) << p.slot;
    bySlot[p.slot] = p;
  }
  for (const auto& p : storage.values())
    EXPECT_EQ(guiding::findNearestPoint(set.grid(), bySlot, p.position, p.normal, 0.1f, 0.7f),
              p.slot);
}

}  // namespace
}  // namespace qlight::test
