#include "game/flythrough.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace qlight::game {

render::CameraView Flythrough::at(float seconds) const {
  float s = std::min(seconds, moveSeconds) / moveSeconds;  // 0..1 along the path
  float phase = 6.2831853f * s;
  glm::vec3 forward = glm::normalize(base.forward);
  glm::vec3 right = glm::normalize(glm::cross(forward, base.up));
  glm::vec3 up = glm::cross(right, forward);
  float reach = 0.08f * sceneRadius;
  render::CameraView v = base;
  v.position = base.position + right * (reach * std::sin(phase)) +
               up * (0.5f * reach * std::sin(2.0f * phase)) +
               forward * (reach * 0.5f * (1.0f - std::cos(phase)));
  float yaw = 0.12f * std::sin(phase);
  v.forward = glm::vec3(glm::rotate(glm::mat4(1.0f), yaw, up) * glm::vec4(forward, 0.0f));
  v.up = up;
  return v;
}

}  // namespace qlight::game
