#include "engine/scene/camera_framing.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/quaternion.hpp>

namespace qlight::scene {

FramedCamera frameBounds(const Bounds& bounds, float aspect, float yfov) {
  if (!(aspect > 0.0f) || !std::isfinite(aspect)) aspect = 1.0f;
  const glm::vec3 center = bounds.center();
  const float radius = bounds.empty() ? 1.0f : std::max(bounds.radius(), 1e-4f);

  // The sphere fits when its angular radius is below the narrower half field of view.
  const float halfY = 0.5f * yfov;
  const float halfX = std::atan(aspect * std::tan(halfY));
  const float distance = 1.05f * radius / std::sin(std::min(halfX, halfY));

  const glm::vec3 towardEye = glm::normalize(glm::vec3(0.3f, 0.35f, 1.0f));
  FramedCamera framed;
  framed.worldFromCamera.translation = center + distance * towardEye;
  framed.worldFromCamera.rotation = glm::quatLookAt(-towardEye, glm::vec3(0.0f, 1.0f, 0.0f));
  framed.camera.name = "default camera";
  framed.camera.yfov = yfov;
  framed.camera.aspectRatio = aspect;
  framed.camera.znear = std::max(0.5f * (distance - radius), 1e-3f * distance);
  framed.camera.zfar = 2.0f * (distance + radius);
  return framed;
}

}  // namespace qlight::scene
