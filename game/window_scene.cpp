#include "game/window_scene.h"

#include <cmath>

namespace qlight::game {

bool SceneClock::advance(float dt) {
  if (!animated() || !playing || speed == 0.0f || dt <= 0.0f) return false;
  time = std::fmod(time + dt * speed, duration);
  if (time < 0.0f) time += duration;
  return true;
}

}  // namespace qlight::game
