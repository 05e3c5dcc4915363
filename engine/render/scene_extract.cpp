#include "engine/render/scene_extract.h"

#include "engine/scene/animation.h"
#include "engine/scene/camera_framing.h"
#include "engine/scene/transforms.h"

namespace qlight::render {

SceneDraw drawFromPose(const scene::SceneAsset& asset, const std::vector<glm::mat4>& world) {
  SceneDraw draw;
  for (uint32_t n : scene::nodesParentFirst(asset)) {
    const scene::NodeAsset& node = asset.nodes[n];
    if (node.mesh >= 0) draw.meshes.push_back({uint32_t(node.mesh), world[n]});
    if (node.light >= 0) draw.lights.push_back({asset.lights[node.light], world[n]});
  }
  return draw;
}

CameraView sceneCamera(const scene::SceneAsset& asset, const std::vector<glm::mat4>& world,
                       float aspect) {
  for (uint32_t n : scene::nodesParentFirst(asset)) {
    const scene::NodeAsset& node = asset.nodes[n];
    if (node.camera >= 0) return cameraFromTransform(world[n], asset.cameras[node.camera].yfov);
  }
  scene::FramedCamera framed = scene::frameBounds(asset.bounds, aspect);
  return cameraFromTransform(scene::toMatrix(framed.worldFromCamera), framed.camera.yfov);
}

PosedScene poseScene(const scene::SceneAsset& asset, float timeSeconds, float aspect) {
  auto world = scene::worldTransforms(asset, scene::animate(asset, timeSeconds, /*loop=*/true));
  return {drawFromPose(asset, world), sceneCamera(asset, world, aspect)};
}

}  // namespace qlight::render
