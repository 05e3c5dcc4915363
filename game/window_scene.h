// What the demo window draws each frame, and the clock that animates it.
#pragma once
#include "engine/render/scene_extract.h"
#include "engine/scene/scene_asset.h"

namespace qlight::game {

// The scene posed at `timeSeconds` (animations looping) with its own camera:
// the one place the window asks for the frame's content, so it can later come
// from the ECS instead of render::poseScene.
render::PosedScene currentSceneDraw(const scene::SceneAsset& asset, float timeSeconds,
                                    float aspect);

// Scene time: advances while playing, loops over the animation duration.
struct SceneClock {
  float duration = 0.0f;  // 0: nothing animates
  float time = 0.0f;
  float speed = 1.0f;  // scene seconds per real second
  bool playing = true;

  bool animated() const { return duration > 0.0f; }
  // Advances by `dtSeconds`; true when the scene's pose changed.
  bool advance(float dtSeconds);
};

}  // namespace qlight::game
