#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/ecs/registry.h"

namespace qlight::ecs {
namespace {

struct Alive {
  int id;
};
struct Tag {
  int value;
};
struct Other {
  int value;
};

void expectStructuralError(const std::function<void()>& change) {
  try {
    change();
    ADD_FAILURE() << "structural change during iteration must throw";
  } catch (const std::logic_error& error) {
    EXPECT_NE(std::string(error.what()).find("use deferred()"), std::string::npos) << error.what();
  }
}

TEST(Deferred, DirectStructuralChangesDuringIterationThrow) {
  Registry registry;
  const Entity a = registry.create(), b = registry.create(), fresh = registry.create();
  registry.emplace<Alive>(a, 1);
  registry.emplace<Alive>(b, 2);
  registry.emplace<Tag>(a, 0);
  registry.emplace<Tag>(b, 0);
  int visits = 0;
  registry.view<Alive, const Tag>().each([&](Entity e, Alive&, const Tag&) {
    ++visits;
    expectStructuralError([&] { registry.emplace<Alive>(fresh, 3); });
    expectStructuralError([&] { registry.emplace<Tag>(fresh, 3); });  // read-only is locked too
    expectStructuralError([&] { registry.remove<Alive>(e); });
    expectStructuralError([&] { registry.destroy(e); });
    EXPECT_THROW(registry.flush(), std::logic_error);
    // Not structural: replacing a value in place, and storages the view does not iterate.
    EXPECT_NO_THROW(registry.emplace<Alive>(e, 9));
    EXPECT_NO_THROW(registry.emplace<Other>(e, 1));
    EXPECT_NO_THROW(registry.remove<Alive>(fresh));  // fresh has no Alive: nothing changes
  });
  EXPECT_EQ(visits, 2);
  // The refused destroy left everything in place.
  EXPECT_TRUE(registry.valid(a) && registry.valid(b));
  EXPECT_TRUE(registry.has<Alive>(a) && registry.has<Tag>(a) && registry.has<Other>(a));
  EXPECT_FALSE(registry.has<Alive>(fresh));
  EXPECT_FALSE(registry.iterating());
}

TEST(Deferred, NestedViewsKeepTheOuterLock) {
  Registry registry;
  const Entity a = registry.create(), fresh = registry.create();
  registry.emplace<Alive>(a, 1);
  registry.view<Alive>().each([&](Alive&) {
    registry.view<const Alive>().each([](const Alive&) {});
    EXPECT_THROW(registry.emplace<Alive>(fresh, 2), std::logic_error);
  });
  EXPECT_NO_THROW(registry.emplace<Alive>(fresh, 2));
}

// While iterating, record random destroys, removes, emplaces and creations; the view must
// still visit every original entity exactly once, and flush must apply every change.
TEST(Deferred, RandomizedCommandsDuringIterationApplyAfterFlush) {
  Registry registry;
  std::mt19937 rng(99);
  std::vector<Entity> original;
  for (int i = 0; i < 2000; ++i) {
    const Entity e = registry.create();
    registry.emplace<Alive>(e, i);
    original.push_back(e);
  }
  std::map<uint32_t, int> visits;
  std::set<uint32_t> destroyed, lostAlive, tagged;
  std::vector<Entity> created;
  registry.view<Alive>().each([&](Entity e, Alive&) {
    ++visits[e.index];
    const Entity target = original[rng() % original.size()];  // may be visited or not yet
    switch (rng() % 4) {
      case 0:
        registry.deferred().destroy(target);
        destroyed.insert(target.index);
        break;
      case 1:
        registry.deferred().remove<Alive>(target);
        lostAlive.insert(target.index);
        break;
      case 2:
        registry.deferred().emplace<Tag>(target, 7);
        tagged.insert(target.index);
        break;
      case 3: {
        const Entity spawned = registry.create();  // no storage touched: allowed
        registry.deferred().emplace<Alive>(spawned, -1);
        created.push_back(spawned);
        break;
      }
    }
  });
  ASSERT_EQ(visits.size(), original.size());
  for (const auto& [index, count] : visits) EXPECT_EQ(count, 1) << "entity " << index;
  for (Entity e : created) EXPECT_FALSE(registry.has<Alive>(e));  // not before flush

  const size_t recorded = registry.deferred().size();
  EXPECT_EQ(recorded, original.size());
  const size_t applied = registry.flush();
  EXPECT_TRUE(registry.deferred().empty());
  EXPECT_LE(applied, recorded);
  for (Entity e : original) {
    const bool gone = destroyed.contains(e.index);
    EXPECT_EQ(registry.valid(e), !gone);
    if (gone) continue;
    EXPECT_EQ(registry.has<Alive>(e), !lostAlive.contains(e.index));
    EXPECT_EQ(registry.has<Tag>(e), tagged.contains(e.index));
  }
  for (Entity e : created) ASSERT_EQ(registry.get<Alive>(e).id, -1);
}

TEST(Deferred, FlushAppliesInRecordedOrderAndDropsStaleCommands) {
  Registry registry;
  const Entity e = registry.create(), f = registry.create();
  registry.deferred().emplace<Tag>(e, 1);
  registry.deferred().emplace<Tag>(e, 2);  // later wins
  registry.deferred().emplace<Tag>(f, 1);
  registry.deferred().destroy(f);
  registry.deferred().emplace<Tag>(f, 3);  // f is stale by now: dropped
  registry.deferred().destroy(f);          // dropped
  registry.deferred().remove<Tag>(f);      // dropped
  EXPECT_EQ(registry.flush(), 4u);
  EXPECT_EQ(registry.get<Tag>(e).value, 2);
  EXPECT_FALSE(registry.valid(f));
  EXPECT_EQ(registry.storage<Tag>().size(), 1u);
}

}  // namespace
}  // namespace qlight::ecs
