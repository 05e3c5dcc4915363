#include "game/window_camera.h"

#include <algorithm>
#include <cmath>

namespace qlight::game {
namespace {
constexpr glm::vec3 kWorldUp{0.0f, 1.0f, 0.0f};
constexpr float kMaxPitch = 1.55f;  // just short of straight up: right = forward x up stays defined
}  // namespace

void FreeCamera::reset(const render::CameraView& view, float newSpeed) {
  glm::vec3 f = glm::normalize(view.forward);
  position = view.position;
  yaw = std::atan2(f.x, -f.z);
  pitch = std::clamp(std::asin(std::clamp(f.y, -1.0f, 1.0f)), -kMaxPitch, kMaxPitch);
  yfov = view.yfov;
  speed = newSpeed;
}

glm::vec3 FreeCamera::forward() const {
  return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw)};
}

void FreeCamera::update(const CameraControls& c, float dt) {
  if (c.wheel != 0.0f) speed = std::clamp(speed * std::pow(kWheelStep, c.wheel), 1e-4f, 1e5f);
  yaw += c.lookPixels.x * kRadiansPerPixel;
  pitch = std::clamp(pitch - c.lookPixels.y * kRadiansPerPixel, -kMaxPitch, kMaxPitch);

  glm::vec3 f = forward();
  glm::vec3 r = glm::normalize(glm::cross(f, kWorldUp));
  glm::vec3 move{0.0f};
  if (c.forward) move += f;
  if (c.back) move -= f;
  if (c.right) move += r;
  if (c.left) move -= r;
  if (c.up) move += kWorldUp;
  if (c.down) move -= kWorldUp;
  if (move == glm::vec3(0.0f)) return;
  float step = speed * (c.fast ? kFastFactor : 1.0f) * dt;
  position += glm::normalize(move) * step;
}

render::CameraView FreeCamera::view() const {
  render::CameraView v;
  v.position = position;
  v.forward = forward();
  v.up = kWorldUp;
  v.yfov = yfov;
  return v;
}

}  // namespace qlight::game
