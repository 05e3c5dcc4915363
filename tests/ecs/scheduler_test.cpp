#include "engine/ecs/scheduler.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace qlight::ecs {
namespace {

struct LocalTransform {
  float x;
};
struct WorldTransform {
  float x;
};
struct Light {
  float power;
};
struct Frame {
  int value;
};

auto noop() {
  return [](Registry&) {};
}

size_t position(const std::vector<std::string>& order, const std::string& name) {
  return std::find(order.begin(), order.end(), name) - order.begin();
}

TEST(Scheduler, ProducersRunBeforeConsumersWhateverTheRegistrationOrder) {
  Scheduler scheduler;
  scheduler.add("render").reads<WorldTransform, Light>().run(noop());
  scheduler.add("transforms").reads<LocalTransform>().writes<WorldTransform>().run(noop());
  scheduler.add("lights").reads<WorldTransform>().writes<Light>().run(noop());
  scheduler.add("animation").writes<LocalTransform>().run(noop());
  scheduler.compile();
  EXPECT_EQ(scheduler.order(),
            (std::vector<std::string>{"animation", "transforms", "lights", "render"}));
  EXPECT_EQ(scheduler.levels(), (std::vector<std::vector<std::string>>{
                                    {"animation"}, {"transforms"}, {"lights"}, {"render"}}));
}

TEST(Scheduler, IndependentSystemsAndSameTypeWritersKeepRegistrationOrder) {
  Scheduler scheduler;
  scheduler.add("ui").reads<Frame>().run(noop());
  scheduler.add("b").writes<Light>().run(noop());
  scheduler.add("a").reads<Light>().writes<Light>().run(noop());  // a writer too
  scheduler.add("stats").run(noop());
  scheduler.add("frame").writes<Frame>().run(noop());
  scheduler.compile();
  EXPECT_EQ(scheduler.order(), (std::vector<std::string>{"b", "a", "stats", "frame", "ui"}));
  const auto levels = scheduler.levels();
  ASSERT_EQ(levels.size(), 2u);
  EXPECT_EQ(levels[0], (std::vector<std::string>{"b", "stats", "frame"}));
  EXPECT_EQ(levels[1], (std::vector<std::string>{"a", "ui"}));
}

TEST(Scheduler, PhasesRunInOrderWhateverTheRegistrationOrder) {
  Scheduler scheduler;
  scheduler.add("display").phase(Phase::Present).reads<Frame>().run(noop());
  scheduler.add("learn").phase(Phase::Learn).reads<Light>().run(noop());
  scheduler.add("trace").phase(Phase::Trace).writes<Light>().run(noop());
  scheduler.add("upload").phase(Phase::Upload).reads<WorldTransform>().run(noop());
  scheduler.add("transforms").reads<LocalTransform>().writes<WorldTransform>().run(noop());
  scheduler.add("animation").writes<LocalTransform>().run(noop());
  scheduler.compile();
  EXPECT_EQ(scheduler.order(), (std::vector<std::string>{"animation", "transforms", "upload",
                                                         "trace", "learn", "display"}));
  EXPECT_STREQ(phaseName(Phase::Learn), "learn");
}

TEST(Scheduler, ALaterPhaseWritingWhatAnEarlierReadsIsNoCycle) {
  // The learn phase writes what the next frame's trace reads: that is across frames.
  Scheduler scheduler;
  scheduler.add("learn").phase(Phase::Learn).reads<Frame>().writes<Light>().run(noop());
  scheduler.add("trace").phase(Phase::Trace).reads<Light>().writes<Frame>().run(noop());
  scheduler.compile();
  EXPECT_EQ(scheduler.order(), (std::vector<std::string>{"trace", "learn"}));
}

TEST(Scheduler, RunPhaseRunsOnlyThatPhase) {
  Registry registry;
  Scheduler scheduler;
  std::vector<std::string> ran;
  scheduler.add("trace").phase(Phase::Trace).run([&](Registry&) { ran.push_back("trace"); });
  scheduler.add("simulate").run([&](Registry&) { ran.push_back("simulate"); });
  scheduler.add("learn").phase(Phase::Learn).run([&](Registry&) { ran.push_back("learn"); });
  scheduler.runPhase(registry, Phase::Simulate);
  EXPECT_EQ(ran, (std::vector<std::string>{"simulate"}));
  scheduler.runPhase(registry, Phase::Learn);
  scheduler.runPhase(registry, Phase::Trace);
  EXPECT_EQ(ran, (std::vector<std::string>{"simulate", "learn", "trace"}));
  ran.clear();
  scheduler.runFrame(registry);
  EXPECT_EQ(ran, (std::vector<std::string>{"simulate", "trace", "learn"}));
}

TEST(Scheduler, AccessSpellingMatchesViews) {
  Scheduler scheduler;
  scheduler.add("consumer").access<const WorldTransform>().run(noop());
  scheduler.add("producer").access<const LocalTransform, WorldTransform>().run(noop());
  scheduler.compile();
  EXPECT_EQ(scheduler.order(), (std::vector<std::string>{"producer", "consumer"}));
}

TEST(Scheduler, CycleThrowsNamingItsSystems) {
  Scheduler scheduler;
  scheduler.add("bystander").reads<Frame>().run(noop());
  scheduler.add("alpha").reads<LocalTransform>().writes<WorldTransform>().run(noop());
  scheduler.add("beta").reads<WorldTransform>().writes<Light>().run(noop());
  scheduler.add("gamma").reads<Light>().writes<LocalTransform>().run(noop());
  try {
    scheduler.compile();
    FAIL() << "a read/write cycle must throw";
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    for (const char* name : {"alpha", "beta", "gamma"}) {
      EXPECT_NE(message.find(name), std::string::npos) << message;
    }
    EXPECT_EQ(message.find("bystander"), std::string::npos) << message;
  }
}

TEST(Scheduler, RejectsBadDeclarations) {
  Scheduler scheduler;
  scheduler.add("x").run(noop());
  EXPECT_THROW(scheduler.add("x"), std::runtime_error);
  EXPECT_THROW(scheduler.add(""), std::runtime_error);
  scheduler.add("no function").reads<Frame>();
  EXPECT_THROW(scheduler.compile(), std::runtime_error);
}

TEST(Scheduler, RunFrameRunsInOrderAndFlushesBetweenSystems) {
  Registry registry;
  Scheduler scheduler;
  std::vector<std::string> ran;
  size_t seenByConsumer = 0;
  scheduler.add("consumer").reads<WorldTransform>().run([&](Registry& r) {
    ran.push_back("consumer");
    seenByConsumer = r.storage<WorldTransform>().size();
  });
  scheduler.add("producer").reads<LocalTransform>().writes<WorldTransform>().run([&](Registry& r) {
    ran.push_back("producer");
    r.view<const LocalTransform>().each([&](Entity e, const LocalTransform& local) {
      r.deferred().emplace<WorldTransform>(e, WorldTransform{local.x * 2.0f});
    });
  });
  for (int i = 0; i < 5; ++i) registry.emplace<LocalTransform>(registry.create(), float(i));
  scheduler.runFrame(registry);
  EXPECT_EQ(ran, (std::vector<std::string>{"producer", "consumer"}));
  EXPECT_EQ(seenByConsumer, 5u);  // the producer's deferred emplaces were flushed
  EXPECT_EQ(scheduler.lastTimingsMs().size(), 2u);
}

// Random declarations: either the order honours every declared dependency, or compile()
// throws and a brute-force transitive closure confirms a cycle.
TEST(Scheduler, RandomizedOrdersHonourDependencies) {
  struct T0 {};
  struct T1 {};
  struct T2 {};
  struct T3 {};
  struct T4 {};
  std::mt19937 rng(2024);
  int compiled = 0, cycles = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 2 + int(rng() % 7);
    std::vector<unsigned> readMask(n), writeMask(n);
    Scheduler scheduler;
    for (int s = 0; s < n; ++s) {
      auto builder = scheduler.add("s" + std::to_string(s));
      const unsigned w1 = rng() % 32, w2 = rng() % 32, r = rng() % 32;
      writeMask[s] = w1 & w2;  // sparse writes keep cycles occasional
      readMask[s] = r & ~writeMask[s];
      if (writeMask[s] & 1) builder.writes<T0>();
      if (writeMask[s] & 2) builder.writes<T1>();
      if (writeMask[s] & 4) builder.writes<T2>();
      if (writeMask[s] & 8) builder.writes<T3>();
      if (writeMask[s] & 16) builder.writes<T4>();
      if (readMask[s] & 1) builder.reads<T0>();
      if (readMask[s] & 2) builder.reads<T1>();
      if (readMask[s] & 4) builder.reads<T2>();
      if (readMask[s] & 8) builder.reads<T3>();
      if (readMask[s] & 16) builder.reads<T4>();
      builder.run(noop());
    }
    // before[u][v]: u must run before v.
    std::vector<std::vector<bool>> before(n, std::vector<bool>(n, false));
    for (int u = 0; u < n; ++u) {
      for (int v = 0; v < n; ++v) {
        if (u == v) continue;
        before[u][v] = (writeMask[u] & readMask[v]) || (u < v && (writeMask[u] & writeMask[v]));
      }
    }
    auto closure = before;
    for (int k = 0; k < n; ++k) {
      for (int u = 0; u < n; ++u) {
        for (int v = 0; v < n; ++v)
          closure[u][v] = closure[u][v] || (closure[u][k] && closure[k][v]);
      }
    }
    bool hasCycle = false;
    for (int u = 0; u < n; ++u) hasCycle = hasCycle || closure[u][u];
    if (hasCycle) {
      EXPECT_THROW(scheduler.compile(), std::runtime_error) << "trial " << trial;
      ++cycles;
      continue;
    }
    ASSERT_NO_THROW(scheduler.compile()) << "trial " << trial;
    ++compiled;
    const auto order = scheduler.order();
    ASSERT_EQ(order.size(), size_t(n));
    for (int u = 0; u < n; ++u) {
      for (int v = 0; v < n; ++v) {
        if (before[u][v]) {
          EXPECT_LT(position(order, "s" + std::to_string(u)),
                    position(order, "s" + std::to_string(v)))
              << "trial " << trial;
        }
      }
    }
  }
  EXPECT_GT(compiled, 50);  // both outcomes were exercised
  EXPECT_GT(cycles, 5);
}

}  // namespace
}  // namespace qlight::ecs
