// Builds what the renderer draws from a posed scene: mesh instances, punctual
// lights and the camera (the file's first camera, else one framing the bounds).
#pragma once
#include <vector>

#include "engine/render/scene_draw.h"
#include "engine/scene/scene_asset.h"

namespace qlight::render {

SceneDraw drawFromPose(const scene::SceneAsset& asset, const std::vector<glm::mat4>& worldFromNode);

// The first node with a camera in the shown scene, else a camera that frames the bounds.
CameraView sceneCamera(const scene::SceneAsset& asset, const std::vector<glm::mat4>& worldFromNode,
                       float aspect);

// Poses the scene at time t (animations looping) and extracts it.
struct PosedScene {
  SceneDraw draw;
  CameraView camera;
};
PosedScene poseScene(const scene::SceneAsset& asset, float timeSeconds, float aspect);

}  // namespace qlight::render
