// The ECS components a glTF scene becomes (one entity per node of the shown scene; see
// instantiate.h). Plain structs: each component type is a dense array that can be uploaded
// as is. LocalTransform is defined with the plain scene data (scene_asset.h).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <string>

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
};

struct NodeName {
  std::string name;
};

// The SceneAsset node the entity was made from.
struct SceneNode {
  uint32_t node = 0;
};

}  // namespace qlight::scene
