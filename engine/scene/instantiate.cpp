#include "engine/scene/instantiate.h"

#include "engine/scene/animation.h"
#include "engine/scene/camera_framing.h"
#include "engine/scene/deform.h"
#include "engine/scene/transforms.h"

namespace qlight::scene {
namespace {

Camera toComponent(const CameraAsset& c) { return {c.yfov, c.aspectRatio, c.znear, c.zfar}; }

PunctualLight toComponent(const LightAsset& l) {
  return {l.type, l.color, l.intensity, l.range, l.innerConeAngle, l.outerConeAngle};
}

// Which channel drives each node's translation, rotation and scale (later animations win).
std::vector<AnimatedNode> channelsByNode(const SceneAsset& scene, std::vector<bool>& animated) {
  std::vector<AnimatedNode> byNode(scene.nodes.size());
  animated.assign(scene.nodes.size(), false);
  for (uint32_t a = 0; a < scene.animations.size(); ++a) {
    const std::vector<AnimationChannel>& channels = scene.animations[a].channels;
    for (uint32_t c = 0; c < channels.size(); ++c) {
      AnimatedNode& node = byNode[channels[c].node];
      const ChannelRef ref{a, c};
      switch (channels[c].path) {
        case AnimationPath::Translation:
          node.translation = ref;
          break;
        case AnimationPath::Rotation:
          node.rotation = ref;
          break;
        case AnimationPath::Scale:
          node.scale = ref;
          break;
        case AnimationPath::Weights:
          node.weights = ref;
          break;
      }
      animated[channels[c].node] = true;
    }
  }
  return byNode;
}

// One child entity per EXT_mesh_gpu_instancing instance, each a MeshInstance of the node's
// mesh (so each is one top-level BVH instance of the mesh's one bottom-level BVH).
void instantiateInstances(const NodeAsset& node, uint32_t index, ecs::Entity parent,
                          const glm::mat4& worldFromNode, ecs::Registry& registry) {
  for (const LocalTransform& local : node.instances) {
    const ecs::Entity e = registry.create();
    registry.emplace<SceneNode>(e, SceneNode{index});
    registry.emplace<LocalTransform>(e, local);
    registry.emplace<WorldTransform>(e, WorldTransform{worldFromNode * toMatrix(local)});
    registry.emplace<Parent>(e, Parent{parent});
    registry.emplace<MeshInstance>(e, MeshInstance{uint32_t(node.mesh)});
  }
}

}  // namespace

InstantiatedScene instantiate(const SceneAsset& scene, ecs::Registry& registry,
                              float defaultCameraAspect) {
  InstantiatedScene out;
  out.nodeEntities.assign(scene.nodes.size(), ecs::kNullEntity);
  const std::vector<LocalTransform> locals = animate(scene, 0.0f);
  const std::vector<glm::mat4> world = worldTransforms(scene, locals);
  std::vector<bool> animated;
  const std::vector<AnimatedNode> channels = channelsByNode(scene, animated);

  for (uint32_t i : nodesParentFirst(scene)) {  // parents exist before their children
    const NodeAsset& node = scene.nodes[i];
    const ecs::Entity e = registry.create();
    out.nodeEntities[i] = e;
    registry.emplace<NodeName>(e, NodeName{node.name});
    registry.emplace<SceneNode>(e, SceneNode{i});
    registry.emplace<LocalTransform>(e, locals[i]);
    registry.emplace<WorldTransform>(e, WorldTransform{world[i]});
    if (node.parent >= 0)
      registry.emplace<Parent>(e, Parent{out.nodeEntities[size_t(node.parent)]});
    if (node.mesh >= 0 && node.instances.empty())
      registry.emplace<MeshInstance>(e, MeshInstance{uint32_t(node.mesh)});
    if (node.light >= 0)
      registry.emplace<PunctualLight>(e, toComponent(scene.lights[size_t(node.light)]));
    if (animated[i]) registry.emplace<AnimatedNode>(e, channels[i]);
    if (node.mesh >= 0) {
      const MeshDeformation& deform = scene.meshes[size_t(node.mesh)].deform;
      if (deform.morphed()) registry.emplace<MorphWeights>(e, MorphWeights{restWeights(scene, i)});
      if (node.skin >= 0) registry.emplace<Skinned>(e, Skinned{uint32_t(node.skin), {}});
      if (deform.morphed() || node.skin >= 0)
        registry.emplace<DeformedMesh>(e, DeformedMesh{uint32_t(node.mesh), {}, {}, 0, {}, {}});
      instantiateInstances(node, i, e, world[i], registry);
    }
    if (node.camera >= 0) {
      registry.emplace<Camera>(e, toComponent(scene.cameras[size_t(node.camera)]));
      if (out.camera == ecs::kNullEntity) out.camera = e;
    }
  }

  // Joints are entities once every node is.
  registry.view<Skinned>().each([&](Skinned& skinned) {
    for (uint32_t joint : scene.skins[skinned.skin].joints)
      skinned.joints.push_back(out.nodeEntities[joint]);
  });

  if (out.camera == ecs::kNullEntity) {
    const FramedCamera framed = frameBounds(scene.bounds, defaultCameraAspect);
    const ecs::Entity e = registry.create();
    registry.emplace<NodeName>(e, NodeName{framed.camera.name});
    registry.emplace<LocalTransform>(e, framed.worldFromCamera);
    registry.emplace<WorldTransform>(e, WorldTransform{toMatrix(framed.worldFromCamera)});
    registry.emplace<Camera>(e, toComponent(framed.camera));
    out.camera = e;
    out.defaultCamera = true;
  }
  return out;
}

}  // namespace qlight::scene
