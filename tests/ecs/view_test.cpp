#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "engine/ecs/registry.h"

namespace qlight::ecs {
namespace {

// Each component remembers its owner so a view that hands the wrong slot is caught.
struct A {
  Entity owner;
};
struct B {
  Entity owner;
  int value;
};
struct C {
  Entity owner;
};

struct Model {
  std::map<uint32_t, Entity> alive;  // by slot index
  std::set<uint32_t> hasA, hasB, hasC;
};

// Returns how many entities matched all of A, B, C (so the caller knows the test had work).
size_t checkView(Registry& registry, const Model& model) {
  std::vector<Entity> ab;
  registry.view<A, B>().each([&](Entity e, A& a, B& b) {
    ASSERT_EQ(a.owner, e);
    ASSERT_EQ(b.owner, e);
    ab.push_back(e);
  });
  std::vector<Entity> abc;
  registry.view<const A, B, const C>().each([&](Entity e, const A& a, B& b, const C& c) {
    ASSERT_EQ(a.owner, e);
    ASSERT_EQ(b.owner, e);
    ASSERT_EQ(c.owner, e);
    abc.push_back(e);
  });
  std::vector<Entity> expectAb, expectAbc;
  for (const auto& [index, e] : model.alive) {
    if (model.hasA.contains(index) && model.hasB.contains(index)) {
      expectAb.push_back(e);
      if (model.hasC.contains(index)) expectAbc.push_back(e);
    }
  }
  auto byIndex = [](Entity x, Entity y) { return x.index < y.index; };
  std::sort(ab.begin(), ab.end(), byIndex);
  std::sort(abc.begin(), abc.end(), byIndex);
  // Sorted equality with the model: every match visited exactly once, nothing else.
  EXPECT_EQ(ab, expectAb);
  EXPECT_EQ(abc, expectAbc);
  return expectAbc.size();
}

TEST(View, RandomizedVisitsEachMatchExactlyOnce) {
  Registry registry;
  Model model;
  std::mt19937 rng(7);
  std::vector<Entity> handles;
  size_t tripleMatches = 0;
  for (int round = 0; round < 20; ++round) {
    for (int op = 0; op < 400; ++op) {
      const unsigned r = rng() % 100;
      if (handles.empty() || r < 25) {
        const Entity e = registry.create();
        handles.push_back(e);
        model.alive[e.index] = e;
        continue;
      }
      const size_t i = rng() % handles.size();
      const Entity e = handles[i];
      if (r < 45) {
        registry.emplace<A>(e, e);
        model.hasA.insert(e.index);
      } else if (r < 60) {
        registry.emplace<B>(e, e, op);
        model.hasB.insert(e.index);
      } else if (r < 70) {
        registry.emplace<C>(e, e);
        model.hasC.insert(e.index);
      } else if (r < 78) {
        registry.remove<A>(e);
        model.hasA.erase(e.index);
      } else if (r < 86) {
        registry.remove<B>(e);
        model.hasB.erase(e.index);
      } else if (r < 90) {
        registry.remove<C>(e);
        model.hasC.erase(e.index);
      } else {
        registry.destroy(e);
        model.alive.erase(e.index);
        model.hasA.erase(e.index);
        model.hasB.erase(e.index);
        model.hasC.erase(e.index);
        handles[i] = handles.back();
        handles.pop_back();
      }
    }
    tripleMatches += checkView(registry, model);
  }
  EXPECT_GT(tripleMatches, 100u);
}

TEST(View, IteratesTheSmallestStorageInDenseOrder) {
  Registry registry;
  std::vector<Entity> all;
  for (int i = 0; i < 100; ++i) {
    const Entity e = registry.create();
    all.push_back(e);
    registry.emplace<A>(e, e);
  }
  // B on a few entities, added in reverse so its dense order differs from A's.
  for (int i = 90; i >= 0; i -= 10) registry.emplace<B>(all[i], all[i], i);
  registry.remove<A>(all[50]);  // a B-holder without A: skipped
  std::vector<Entity> visited;
  registry.view<A, B>().each([&](Entity e, A&, B&) { visited.push_back(e); });
  std::vector<Entity> expected;
  for (Entity e : registry.storage<B>().entities()) {
    if (e != all[50]) expected.push_back(e);
  }
  EXPECT_EQ(visited, expected);
  EXPECT_EQ((registry.view<A, B>().sizeHint()), 10u);
}

TEST(View, ConstComponentsAreHandedAsConst) {
  Registry registry;
  const Entity e = registry.create();
  registry.emplace<A>(e, e);
  registry.emplace<B>(e, e, 1);
  int calls = 0;
  registry.view<const A, B>().each([&](auto& a, auto& b) {
    static_assert(std::is_const_v<std::remove_reference_t<decltype(a)>>);
    static_assert(!std::is_const_v<std::remove_reference_t<decltype(b)>>);
    b.value += 10;
    ++calls;
  });
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(registry.get<B>(e).value, 11);  // writes through the view land in storage
}

TEST(View, EmptyStorageVisitsNothing) {
  Registry registry;
  const Entity e = registry.create();
  registry.emplace<A>(e, e);
  int calls = 0;
  registry.view<A, C>().each([&](A&, C&) { ++calls; });
  EXPECT_EQ(calls, 0);
}

TEST(View, ExceptionInCallbackReleasesTheLock) {
  Registry registry;
  const Entity e = registry.create();
  registry.emplace<A>(e, e);
  EXPECT_THROW(registry.view<A>().each([](A&) { throw std::runtime_error("boom"); }),
               std::runtime_error);
  EXPECT_FALSE(registry.iterating());
  const Entity f = registry.create();
  EXPECT_NO_THROW(registry.emplace<A>(f, f));
}

}  // namespace
}  // namespace qlight::ecs
