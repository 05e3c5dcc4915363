// What the renderer draws in one frame, extracted from the ECS: mesh instances
// and punctual lights with their world transforms, and the camera.
#pragma once
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "engine/scene/scene_asset.h"

namespace qlight::render {

struct MeshDraw {
  uint32_t mesh = 0;
  glm::mat4 worldFromObject{1.0f};
  // Neither the node nor an ancestor is animated, and no node deforms the mesh: the BVH may
  // copy its triangles into world space once (SceneBvh's merged BLAS).
  bool fixed = false;
};

// A mesh whose vertices its skin or morph weights re-posed, in the space its MeshDraws place
// it (world space for skins: their MeshDraw is the identity). The spans point into the ECS and
// hold until the next SceneWorld::advance.
struct DeformedDraw {
  uint32_t mesh = 0;
  uint64_t version = 0;  // grows with each new pose
  std::span<const glm::vec3> positions;
  std::span<const glm::vec3> normals;
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
  std::vector<DeformedDraw> deformed;
};

// A camera looking down -Z of worldFromCamera (glTF convention).
CameraView cameraFromTransform(const glm::mat4& worldFromCamera, float yfov);

}  // namespace qlight::render
