#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "engine/ecs/registry.h"

namespace qlight::ecs {
namespace {

struct Radiance {
  float r, g, b;
};
struct Marker {
  int id;
};

std::vector<Entity> makeEntities(Registry& registry, int n) {
  std::vector<Entity> entities;
  for (int i = 0; i < n; ++i) {
    entities.push_back(registry.create());
    registry.emplace<Radiance>(entities.back(), float(i), 0.0f, 0.0f);
  }
  return entities;
}

TEST(Dirty, EmplaceMarksTheNewSlots) {
  Registry registry;
  auto& storage = registry.storage<Radiance>();
  EXPECT_TRUE(storage.dirtyRange().empty());
  makeEntities(registry, 5);
  EXPECT_EQ(storage.dirtyRange(), (DirtyRange{0, 5}));
  storage.clearDirty();
  EXPECT_TRUE(storage.dirtyRange().empty());
  registry.emplace<Radiance>(registry.create(), 1.0f, 1.0f, 1.0f);
  EXPECT_EQ(storage.dirtyRange(), (DirtyRange{5, 6}));
}

TEST(Dirty, PatchAndMarkDirtyCoverExactlyTheModifiedSlots) {
  Registry registry;
  const auto entities = makeEntities(registry, 10);
  auto& storage = registry.storage<Radiance>();
  storage.clearDirty();
  registry.patch<Radiance>(entities[4], [](Radiance& r) { r.g = 2.0f; });
  EXPECT_EQ(storage.dirtyRange(), (DirtyRange{4, 5}));
  EXPECT_EQ(storage.get(entities[4]).g, 2.0f);
  storage.markDirty(entities[7]);
  EXPECT_EQ(storage.dirtyRange(), (DirtyRange{4, 8}));
  const Entity without = registry.create();
  EXPECT_THROW(registry.patch<Radiance>(without, [](Radiance&) {}), std::logic_error);
  EXPECT_THROW(storage.markDirty(without), std::logic_error);
}

TEST(Dirty, RandomizedPatchesGiveTheTightestRange) {
  Registry registry;
  const auto entities = makeEntities(registry, 1000);
  auto& storage = registry.storage<Radiance>();
  std::mt19937 rng(5);
  for (int round = 0; round < 200; ++round) {
    storage.clearDirty();
    size_t lo = storage.size(), hi = 0;
    const int patches = 1 + int(rng() % 5);
    for (int p = 0; p < patches; ++p) {
      const Entity e = entities[rng() % entities.size()];
      registry.patch<Radiance>(e, [](Radiance& r) { r.b += 1.0f; });
      lo = std::min<size_t>(lo, storage.indexOf(e));
      hi = std::max<size_t>(hi, storage.indexOf(e));
    }
    ASSERT_EQ(storage.dirtyRange(), (DirtyRange{lo, hi + 1}));
  }
}

TEST(Dirty, SwapAndPopMarksTheMovedSlotAndBumpsStructure) {
  Registry registry;
  const auto entities = makeEntities(registry, 10);
  auto& storage = registry.storage<Radiance>();
  storage.clearDirty();
  const uint64_t version = storage.structureVersion();
  registry.remove<Radiance>(entities[3]);  // the last entity moves into slot 3
  EXPECT_EQ(storage.dirtyRange(), (DirtyRange{3, 4}));
  EXPECT_EQ(storage.get(entities[9]).r, 9.0f);
  EXPECT_EQ(storage.indexOf(entities[9]), 3u);
  EXPECT_GT(storage.structureVersion(), version);

  storage.clearDirty();
  const Entity last = storage.entities().back();
  registry.remove<Radiance>(last);  // nothing moves: no slot changed value
  EXPECT_TRUE(storage.dirtyRange().empty());
}

TEST(Dirty, ShrinkingClampsTheRange) {
  Registry registry;
  makeEntities(registry, 10);
  auto& storage = registry.storage<Radiance>();
  storage.clearDirty();
  storage.markDirty(storage.entities()[5]);
  storage.markDirty(storage.entities()[9]);
  registry.destroy(storage.entities()[9]);
  EXPECT_EQ(storage.dirtyRange(), (DirtyRange{5, 9}));
  EXPECT_LE(storage.dirtyRange().end, storage.size());
}

TEST(Dirty, StructureVersionIgnoresValueChanges) {
  Registry registry;
  const auto entities = makeEntities(registry, 3);
  auto& storage = registry.storage<Radiance>();
  const uint64_t version = storage.structureVersion();
  registry.patch<Radiance>(entities[0], [](Radiance& r) { r.r = 5.0f; });
  registry.emplace<Radiance>(entities[1], 1.0f, 1.0f, 1.0f);  // replace
  EXPECT_EQ(storage.structureVersion(), version);
  registry.emplace<Radiance>(registry.create(), 0.0f, 0.0f, 0.0f);
  EXPECT_EQ(storage.structureVersion(), version + 1);
}

TEST(Dirty, WritableViewMarksVisitedSlotsConstViewDoesNot) {
  Registry registry;
  const auto entities = makeEntities(registry, 20);
  for (int i : {6, 11, 14}) registry.emplace<Marker>(entities[i], i);
  auto& radiance = registry.storage<Radiance>();
  auto& marker = registry.storage<Marker>();
  radiance.clearDirty();
  marker.clearDirty();
  registry.view<const Radiance, const Marker>().each([](const Radiance&, const Marker&) {});
  EXPECT_TRUE(radiance.dirtyRange().empty());
  EXPECT_TRUE(marker.dirtyRange().empty());
  registry.view<Radiance, const Marker>().each([](Radiance& r, const Marker&) { r.r = -1.0f; });
  EXPECT_EQ(radiance.dirtyRange(), (DirtyRange{6, 15}));  // slots 6..14 were handed out
  EXPECT_TRUE(marker.dirtyRange().empty());
}

}  // namespace
}  // namespace qlight::ecs
