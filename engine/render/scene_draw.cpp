#include "engine/render/scene_draw.h"

namespace qlight::render {

CameraView cameraFromTransform(const glm::mat4& worldFromCamera, float yfov) {
  CameraView v;
  v.position = glm::vec3(worldFromCamera[3]);
  v.forward = glm::normalize(glm::vec3(worldFromCamera * glm::vec4(0, 0, -1, 0)));
  v.up = glm::normalize(glm::vec3(worldFromCamera * glm::vec4(0, 1, 0, 0)));
  v.yfov = yfov;
  return v;
}

}  // namespace qlight::render
