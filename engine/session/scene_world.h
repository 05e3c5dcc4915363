// The scene as ECS entities, advanced each frame by the scheduler's simulate
// and extract phases: animation -> transforms -> extraction of what the
// renderer draws. Cache points live in the same registry (engine/guiding), and
// the Renderer adds the frame's later phases (upload, trace, learn, present) to
// the same scheduler.
#pragma once
#include "engine/ecs/registry.h"
#include "engine/ecs/scheduler.h"
#include "engine/render/scene_draw.h"
#include "engine/scene/instantiate.h"
#include "engine/scene/scene_asset.h"

namespace qlight::session {

class SceneWorld {
 public:
  SceneWorld(const scene::SceneAsset& asset, float aspect);

  // Runs the simulate and extract phases at scene time t (animations loop).
  void advance(float seconds);

  const render::SceneDraw& draw() const { return draw_; }
  // The scene's camera (its own, or the default one framing its bounds).
  render::CameraView camera() const;
  // Whether the last advance moved anything (transforms changed).
  bool moved() const { return moved_; }

  ecs::Registry& registry() { return registry_; }
  ecs::Scheduler& scheduler() { return scheduler_; }
  const ecs::Scheduler& scheduler() const { return scheduler_; }

 private:
  void extract(ecs::Registry& registry);

  const scene::SceneAsset& asset_;
  ecs::Registry registry_;
  ecs::Scheduler scheduler_;
  scene::InstantiatedScene instance_;
  render::SceneDraw draw_;
  float time_ = 0.0f;
  bool moved_ = true;
};

}  // namespace qlight::session
