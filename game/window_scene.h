// The clock that animates the demo window's scene.
#pragma once

namespace qlight::game {

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
