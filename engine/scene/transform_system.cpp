#include <algorithm>
#include <utility>

#include "engine/scene/instantiate.h"
#include "engine/scene/transforms.h"

namespace qlight::scene {
namespace {

// Number of Parent links above e, capped so that a (malformed) cycle cannot hang the walk.
uint32_t depthOf(ecs::Registry& registry, ecs::Entity e, uint32_t cap) {
  uint32_t depth = 0;
  for (const Parent* p = registry.tryGet<Parent>(e); p != nullptr && depth < cap;
       p = registry.tryGet<Parent>(p->entity))
    ++depth;
  return depth;
}

}  // namespace

void transformSystem(ecs::Registry& registry) {
  std::vector<std::pair<uint32_t, ecs::Entity>> order;
  auto view = registry.view<const LocalTransform, const WorldTransform>();
  const auto cap = uint32_t(view.sizeHint() + 1);
  view.each([&](ecs::Entity e, const LocalTransform&, const WorldTransform&) {
    order.emplace_back(depthOf(registry, e, cap), e);
  });
  std::stable_sort(order.begin(), order.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });

  for (const auto& [depth, e] : order) {
    glm::mat4 worldFromLocal = toMatrix(registry.get<LocalTransform>(e));
    if (const Parent* parent = registry.tryGet<Parent>(e)) {
      if (const WorldTransform* parentWorld = registry.tryGet<WorldTransform>(parent->entity))
        worldFromLocal = parentWorld->worldFromLocal * worldFromLocal;
    }
    if (registry.get<WorldTransform>(e).worldFromLocal != worldFromLocal)
      registry.patch<WorldTransform>(e,
                                     [&](WorldTransform& w) { w.worldFromLocal = worldFromLocal; });
  }
}

}  // namespace qlight::scene
