// The ECS components a glTF scene becomes (one entity per node of the shown scene; see
// instantiate.h). Plain structs: each component type is a dense array that can be uploaded
// as is. LocalTransform is defined with the plain scene data (scene_asset.h).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <string>
#include <vector>

#include "engine/ecs/entity.h"
#include "engine/scene/scene_asset.h"

namespace qlight::scene {

// The entity's parent in the node hierarchy; absent on roots.
struct Parent {
  ecs::Entity entity = ecs::kNullEntity;
};

// World transform, written by transformSystem from LocalTransform and the parent's.
struct WorldTransform {
  glm::mat4 worldFromLocal{1.0f};
};

// An instance of SceneAsset::meshes[mesh], placed by the entity's WorldTransform.
struct MeshInstance {
  uint32_t mesh = 0;
};

// A perspective camera looking down the entity's -Z, +Y up.
struct Camera {
  float yfov = 0.8f;         // radians
  float aspectRatio = 0.0f;  // 0: the viewport's
  float znear = 0.01f;
  float zfar = std::numeric_limits<float>::infinity();
};

// A KHR_lights_punctual light at the entity, pointing down its -Z (spot, directional).
struct PunctualLight {
  LightType type = LightType::Point;
  glm::vec3 color{1.0f};
  float intensity = 1.0f;  // candela (point, spot) or lux (directional)
  float range = 0.0f;      // 0: infinite
  float innerConeAngle = 0.0f;
  float outerConeAngle = 0.7853981634f;
};

// One animation channel: SceneAsset::animations[animation].channels[channel].
struct ChannelRef {
  static constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
  uint32_t animation = kNone;
  uint32_t channel = 0;

  bool valid() const { return animation != kNone; }
};

// The channels that drive this entity's LocalTransform (the last animation targeting a path
// wins, as in animate()).
struct AnimatedNode {
  ChannelRef translation;
  ChannelRef rotation;
  ChannelRef scale;
  ChannelRef weights;  // morph weights, into MorphWeights
};

// The morph target weights of the entity's mesh (the node's, else the mesh's defaults),
// written by animation.
struct MorphWeights {
  std::vector<float> weights;
};

// A skinned node: SceneAsset::skins[skin], its joints' entities in the skin's order
// (kNullEntity for a joint outside the shown scene: identity). Its MeshInstance is drawn in
// world space (glTF ignores a skinned node's own transform).
struct Skinned {
  uint32_t skin = 0;
  std::vector<ecs::Entity> joints;
};

// The entity's mesh as its skin and morph weights pose it (object space, or world space when
// Skinned), written by deformSystem when the pose changes; `version` counts the changes so an
// uploader sees which meshes are new. The inputs of the last deformation are kept to tell.
struct DeformedMesh {
  uint32_t mesh = 0;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  uint64_t version = 0;  // 0: not deformed yet
  std::vector<glm::mat4> jointMatrices;
  std::vector<float> weights;
};

struct NodeName {
  std::string name;
};

// The SceneAsset node the entity was made from.
struct SceneNode {
  uint32_t node = 0;
};

}  // namespace qlight::scene
