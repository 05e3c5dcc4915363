// What the renderer draws in one frame, extracted from the ECS: mesh instances
// and punctual lights with their world transforms, and the camera.
#pragma once
#include <glm/glm.hpp>
#include <vector>

#include "engine/scene/scene_asset.h"

namespace qlight::render {

struct MeshDraw {
  uint32_t mesh = 0;
  glm::mat4 worldFromObject{1.0f};
};

struct PunctualDraw {
  scene::LightAsset light;
  glm::mat4 worldFromLight{1.0f};
};

struct CameraView {
  glm::vec3 position{0.0f};
  glm::vec3 forward{0.0f, 0.0f, -1.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float yfov = 0.8f;  // radians
  bool operator==(const CameraView&) const = default;
};

struct SceneDraw {
  std::vector<MeshDraw> meshes;
  std::vector<PunctualDraw> lights;
};

// A camera looking down -Z of worldFromCamera (glTF convention).
CameraView cameraFromTransform(const glm::mat4& worldFromCamera, float yfov);

}  // namespace qlight::render
