#include "engine/scene/animation.h"
#include "engine/scene/instantiate.h"

namespace qlight::scene {
namespace {

void applyRef(const SceneAsset& scene, ChannelRef ref, float t, bool loop, LocalTransform& local) {
  if (!ref.valid() || ref.animation >= scene.animations.size()) return;
  const AnimationAsset& animation = scene.animations[ref.animation];
  if (ref.channel >= animation.channels.size()) return;
  applyChannel(animation.channels[ref.channel], animationTime(animation, t, loop), local);
}

}  // namespace

void animationSystem(ecs::Registry& registry, const SceneAsset& scene, float t, bool loop) {
  registry.view<const AnimatedNode, const LocalTransform>().each(
      [&](ecs::Entity e, const AnimatedNode& animated, const LocalTransform& current) {
        LocalTransform next = current;
        applyRef(scene, animated.translation, t, loop, next);
        applyRef(scene, animated.rotation, t, loop, next);
        applyRef(scene, animated.scale, t, loop, next);
        if (next != current)
          registry.patch<LocalTransform>(e, [&](LocalTransform& local) { local = next; });
      });
  registry.view<const AnimatedNode, const MorphWeights>().each(
      [&](ecs::Entity e, const AnimatedNode& animated, const MorphWeights& current) {
        const ChannelRef ref = animated.weights;
        if (!ref.valid() || ref.animation >= scene.animations.size()) return;
        const AnimationAsset& animation = scene.animations[ref.animation];
        if (ref.channel >= animation.channels.size()) return;
        std::vector<float> next =
            sampleWeights(animation.channels[ref.channel], animationTime(animation, t, loop));
        next.resize(current.weights.size(), 0.0f);
        if (next != current.weights)
          registry.patch<MorphWeights>(e, [&](MorphWeights& w) { w.weights = std::move(next); });
      });
}

}  // namespace qlight::scene
