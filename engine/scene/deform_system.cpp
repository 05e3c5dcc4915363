#include "engine/scene/deform.h"
#include "engine/scene/instantiate.h"

namespace qlight::scene {

void deformSystem(ecs::Registry& registry, const SceneAsset& scene) {
  registry.view<const DeformedMesh>().each([&](ecs::Entity e, const DeformedMesh& current) {
    if (current.mesh >= scene.meshes.size()) return;
    std::vector<glm::mat4> joints;
    if (const Skinned* skinned = registry.tryGet<Skinned>(e)) {
      const SkinAsset& skin = scene.skins[skinned->skin];
      joints.resize(skinned->joints.size());
      for (size_t j = 0; j < joints.size(); ++j) {
        const WorldTransform* world = registry.tryGet<WorldTransform>(skinned->joints[j]);
        joints[j] = (world ? world->worldFromLocal : glm::mat4(1.0f)) * skin.inverseBindMatrices[j];
      }
    }
    const MorphWeights* morph = registry.tryGet<MorphWeights>(e);
    const std::vector<float> weights = morph ? morph->weights : std::vector<float>{};
    // Joints and weights are few; the vertices are many: re-pose only when the inputs moved.
    if (current.version != 0 && joints == current.jointMatrices && weights == current.weights)
      return;
    DeformedVertices posed = deformMesh(scene.meshes[current.mesh], weights, joints);
    registry.patch<DeformedMesh>(e, [&](DeformedMesh& d) {
      d.positions = std::move(posed.positions);
      d.normals = std::move(posed.normals);
      d.jointMatrices = std::move(joints);
      d.weights = weights;
      ++d.version;
    });
  });
}

}  // namespace qlight::scene
