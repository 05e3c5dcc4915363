// The demo's camera path: a slow sway around the scene's own camera (so it
// stays inside rooms), then a stop where the image converges.
#pragma once
#include "engine/render/scene_draw.h"

namespace qlight::game {

struct Flythrough {
  render::CameraView base;
  float sceneRadius = 1.0f;
  float moveSeconds = 2.0f;  // after this the camera holds still

  render::CameraView at(float seconds) const;
  bool moving(float seconds) const { return seconds < moveSeconds; }
};

}  // namespace qlight::game
