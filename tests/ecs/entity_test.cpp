#include <gtest/gtest.h>

#include <random>
#include <set>
#include <stdexcept>
#include <unordered_set>
#include <utility>
#include <vector>

#include "engine/ecs/entity_pool.h"
#include "engine/ecs/registry.h"

namespace qlight::ecs {
namespace {

struct Health {
  int hp;
};

TEST(Entity, NullIsNeverValid) {
  Registry registry;
  EXPECT_FALSE(registry.valid(kNullEntity));
  for (int i = 0; i < 100; ++i) EXPECT_NE(registry.create(), kNullEntity);
  EXPECT_FALSE(registry.valid(kNullEntity));
  EXPECT_THROW(registry.get<Health>(kNullEntity), std::logic_error);
}

TEST(Entity, CreateGivesDistinctValidHandles) {
  Registry registry;
  std::unordered_set<Entity> seen;
  for (int i = 0; i < 1000; ++i) {
    const Entity e = registry.create();
    EXPECT_TRUE(registry.valid(e));
    EXPECT_TRUE(seen.insert(e).second);
  }
  EXPECT_EQ(registry.aliveCount(), 1000u);
}

TEST(Entity, DestroyMakesHandleStale) {
  Registry registry;
  const Entity e = registry.create();
  registry.emplace<Health>(e, 10);
  registry.destroy(e);
  EXPECT_FALSE(registry.valid(e));
  EXPECT_FALSE(registry.has<Health>(e));
  EXPECT_EQ(registry.tryGet<Health>(e), nullptr);
  EXPECT_THROW(registry.get<Health>(e), std::logic_error);
  EXPECT_THROW(registry.emplace<Health>(e, 1), std::logic_error);
  EXPECT_THROW(registry.destroy(e), std::logic_error);
  EXPECT_EQ(registry.aliveCount(), 0u);
  EXPECT_EQ(registry.storage<Health>().size(), 0u);
}

TEST(Entity, IndexReuseBumpsGenerationAndNeverAliases) {
  Registry registry;
  const Entity old = registry.create();
  registry.emplace<Health>(old, 1);
  registry.destroy(old);
  const Entity reused = registry.create();
  ASSERT_EQ(reused.index, old.index);  // the free list recycles the slot
  EXPECT_NE(reused.generation, old.generation);
  EXPECT_NE(reused, old);
  EXPECT_FALSE(registry.valid(old));
  EXPECT_TRUE(registry.valid(reused));
  registry.emplace<Health>(reused, 2);
  EXPECT_EQ(registry.tryGet<Health>(old), nullptr);
  EXPECT_FALSE(registry.has<Health>(old));
  EXPECT_THROW(registry.get<Health>(old), std::logic_error);
  EXPECT_THROW(registry.remove<Health>(old), std::logic_error);
  EXPECT_EQ(registry.get<Health>(reused).hp, 2);
}

TEST(Entity, GetErrorNamesTheComponentType) {
  Registry registry;
  const Entity e = registry.create();
  try {
    registry.get<Health>(e);
    FAIL() << "get of a missing component must throw";
  } catch (const std::logic_error& error) {
    EXPECT_NE(std::string(error.what()).find("Health"), std::string::npos) << error.what();
  }
}

TEST(Entity, HashSeparatesGenerations) {
  std::unordered_set<Entity> set{{3, 0}, {3, 1}, {4, 0}};
  EXPECT_EQ(set.size(), 3u);
  EXPECT_EQ(std::hash<Entity>{}(Entity{7, 2}), std::hash<Entity>{}(Entity{7, 2}));
  EXPECT_TRUE(set.contains(Entity{3, 1}));
  EXPECT_FALSE(set.contains(Entity{3, 2}));
}

TEST(Entity, SlotIsRetiredBeforeItsGenerationWraps) {
  EntityPool pool(/*maxGeneration=*/3);
  std::set<std::pair<uint32_t, uint32_t>> issued;
  std::vector<Entity> old;
  Entity e = pool.create();
  for (int i = 0; i < 10; ++i) {
    EXPECT_TRUE(issued.insert({e.index, e.generation}).second) << "handle issued twice";
    EXPECT_LT(e.generation, 3u);
    old.push_back(e);
    pool.destroy(e);
    e = pool.create();
  }
  for (Entity stale : old) EXPECT_FALSE(pool.valid(stale));
  EXPECT_GT(pool.retiredCount(), 0u);
}

// Random create/destroy against a model of every handle ever issued.
TEST(Entity, RandomizedLifetimesMatchModel) {
  Registry registry;
  std::mt19937 rng(1234);
  std::vector<Entity> alive;
  std::vector<Entity> dead;
  std::set<std::pair<uint32_t, uint32_t>> issued;
  for (int op = 0; op < 20000; ++op) {
    if (alive.empty() || rng() % 100 < 55) {
      const Entity e = registry.create();
      ASSERT_TRUE(issued.insert({e.index, e.generation}).second) << "handle aliased";
      alive.push_back(e);
    } else {
      const size_t i = rng() % alive.size();
      registry.destroy(alive[i]);
      dead.push_back(alive[i]);
      alive[i] = alive.back();
      alive.pop_back();
    }
  }
  EXPECT_EQ(registry.aliveCount(), alive.size());
  for (Entity e : alive) EXPECT_TRUE(registry.valid(e));
  for (Entity e : dead) EXPECT_FALSE(registry.valid(e));
}

}  // namespace
}  // namespace qlight::ecs
