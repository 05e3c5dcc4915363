#include "engine/ecs/storage.h"

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <random>
#include <stdexcept>
#include <vector>

#include "engine/ecs/entity_pool.h"

namespace qlight::ecs {
namespace {

struct Mass {
  float kg;
};

TEST(Storage, EmplaceGetContains) {
  Storage<Mass> storage;
  const Entity a{0, 0}, b{1, 0};
  storage.emplace(a, 1.0f);
  storage.emplace(b, 2.0f);
  EXPECT_EQ(storage.size(), 2u);
  EXPECT_TRUE(storage.contains(a));
  EXPECT_FALSE(storage.contains(Entity{2, 0}));
  EXPECT_EQ(storage.get(b).kg, 2.0f);
  EXPECT_EQ(storage.indexOf(a), 0u);
  EXPECT_EQ(storage.indexOf(b), 1u);
  EXPECT_EQ(storage.data()[1].kg, 2.0f);
  EXPECT_THROW(storage.get(Entity{2, 0}), std::logic_error);
}

TEST(Storage, EmplaceOnPresentEntityReplacesInPlace) {
  Storage<Mass> storage;
  const Entity a{0, 0};
  storage.emplace(a, 1.0f);
  const uint64_t version = storage.structureVersion();
  storage.emplace(a, 5.0f);
  EXPECT_EQ(storage.size(), 1u);
  EXPECT_EQ(storage.get(a).kg, 5.0f);
  EXPECT_EQ(storage.structureVersion(), version);
}

TEST(Storage, SwapAndPopMovesLastIntoHole) {
  Storage<Mass> storage;
  const Entity a{0, 0}, b{1, 0}, c{2, 0};
  storage.emplace(a, 1.0f);
  storage.emplace(b, 2.0f);
  storage.emplace(c, 3.0f);
  EXPECT_TRUE(storage.remove(a));
  ASSERT_EQ(storage.size(), 2u);
  EXPECT_EQ(storage.entities()[0], c);
  EXPECT_EQ(storage.data()[0].kg, 3.0f);
  EXPECT_EQ(storage.entities()[1], b);
  EXPECT_EQ(storage.indexOf(c), 0u);
  EXPECT_FALSE(storage.contains(a));
  EXPECT_FALSE(storage.remove(a));  // absent: no-op
}

TEST(Storage, StaleHandleToSameSlotIsNotContained) {
  Storage<Mass> storage;
  storage.emplace(Entity{5, 1}, 1.0f);
  EXPECT_FALSE(storage.contains(Entity{5, 0}));
  EXPECT_FALSE(storage.contains(Entity{5, 2}));
  EXPECT_EQ(storage.tryGet(Entity{5, 0}), nullptr);
  EXPECT_FALSE(storage.remove(Entity{5, 0}));
  // A second generation of the same slot cannot coexist with the first.
  EXPECT_THROW(storage.emplace(Entity{5, 2}, 2.0f), std::logic_error);
  EXPECT_EQ(storage.size(), 1u);
}

TEST(Storage, LargeIndicesUseSparsePages) {
  Storage<Mass> storage;
  const Entity far{3'000'000, 0};
  storage.emplace(far, 4.0f);
  EXPECT_TRUE(storage.contains(far));
  EXPECT_FALSE(storage.contains(Entity{3'000'001, 0}));
  EXPECT_FALSE(storage.contains(Entity{7, 0}));
  EXPECT_EQ(storage.get(far).kg, 4.0f);
}

TEST(Storage, MoveOnlyComponents) {
  Storage<std::unique_ptr<int>> storage;
  storage.emplace(Entity{0, 0}, std::make_unique<int>(1));
  storage.emplace(Entity{1, 0}, std::make_unique<int>(2));
  storage.remove(Entity{0, 0});
  EXPECT_EQ(*storage.get(Entity{1, 0}), 2);
}

// Thousands of random adds/removes (with recycled, re-generationed slots) against a map.
TEST(Storage, RandomizedStaysDenseAndConsistent) {
  EntityPool pool;
  Storage<Mass> storage;
  std::map<uint32_t, std::pair<Entity, float>> model;  // by slot index
  std::vector<Entity> alive;
  std::vector<Entity> dead;
  std::mt19937 rng(42);
  for (int op = 0; op < 8000; ++op) {
    const unsigned r = rng() % 100;
    if (alive.size() < 50 || r < 30) {
      alive.push_back(pool.create());
    } else if (r < 65) {  // add or replace
      const Entity e = alive[rng() % alive.size()];
      const float v = float(op);
      storage.emplace(e, v);
      model[e.index] = {e, v};
    } else if (r < 90) {  // remove
      const Entity e = alive[rng() % alive.size()];
      EXPECT_EQ(storage.remove(e), model.erase(e.index) == 1);
    } else {  // destroy: drop the component, recycle the slot
      const size_t i = rng() % alive.size();
      const Entity e = alive[i];
      storage.remove(e);
      model.erase(e.index);
      pool.destroy(e);
      dead.push_back(e);
      alive[i] = alive.back();
      alive.pop_back();
    }
    ASSERT_EQ(storage.size(), model.size());
    ASSERT_EQ(storage.values().size(), storage.entities().size());
    for (uint32_t i = 0; i < storage.size(); ++i) {
      const Entity e = storage.entities()[i];
      const auto it = model.find(e.index);
      ASSERT_NE(it, model.end()) << "dense slot " << i << " holds an entity without component";
      ASSERT_EQ(it->second.first, e);
      ASSERT_EQ(storage.data()[i].kg, it->second.second);
      ASSERT_EQ(storage.indexOf(e), i);
    }
  }
  for (Entity e : dead) EXPECT_FALSE(storage.contains(e));
}

}  // namespace
}  // namespace qlight::ecs
