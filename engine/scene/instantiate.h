// Turns a SceneAsset into ECS entities and keeps them moving: animation writes
// LocalTransform, the transform system derives WorldTransform down the hierarchy. Both
// change components through Registry::patch, and only when the value changes, so the dirty
// ranges that GPU uploads read cover exactly what moved.
#pragma once

#include <vector>

#include "engine/ecs/registry.h"
#include "engine/scene/components.h"
#include "engine/scene/scene_asset.h"

namespace qlight::scene {

struct InstantiatedScene {
  // Entity of each SceneAsset node; kNullEntity for nodes outside the shown scene.
  std::vector<ecs::Entity> nodeEntities;
  // The first camera of the scene in hierarchy order, or the default camera made for it.
  ecs::Entity camera = ecs::kNullEntity;
  bool defaultCamera = false;
};

// One entity per node of the shown scene (reachable from rootNodes), with NodeName,
// SceneNode, LocalTransform (the pose at t = 0), WorldTransform (already computed), and as
// the node has them Parent, MeshInstance, Camera, PunctualLight, AnimatedNode, MorphWeights,
// Skinned and DeformedMesh (with a mesh that deforms). A node with EXT_mesh_gpu_instancing
// instances gets a child entity per instance (LocalTransform = the instance's, MeshInstance)
// instead of a MeshInstance of its own. A scene with
// no camera gets one more entity: a Camera from frameBounds(scene.bounds, aspect) with its
// LocalTransform and WorldTransform, named "default camera".
InstantiatedScene instantiate(const SceneAsset& scene, ecs::Registry& registry,
                              float defaultCameraAspect = 16.0f / 9.0f);

// Samples every AnimatedNode's channels at time t (wrapped per animation when loop is set,
// clamped to the keys otherwise) into its LocalTransform and MorphWeights.
void animationSystem(ecs::Registry& registry, const SceneAsset& scene, float t, bool loop = false);

// Re-poses every DeformedMesh whose joints' world transforms or morph weights changed since
// its last deformation (engine/scene/deform.h), after transformSystem.
void deformSystem(ecs::Registry& registry, const SceneAsset& scene);

// WorldTransform = parent's WorldTransform * LocalTransform, parents before children, for
// every entity with both components. An entity whose Parent is gone counts as a root.
void transformSystem(ecs::Registry& registry);

}  // namespace qlight::scene
