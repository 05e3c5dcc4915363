// Internal to the glTF loader: each step turns one part of a tinygltf::Model (already parsed
// from a checked file) into SceneAsset data, validating indices and values as it goes.
#pragma once

#include <tiny_gltf.h>

#include "engine/gltf/gltf_context.h"
#include "engine/scene/scene_asset.h"

namespace qlight::gltf::detail {
using namespace ::qlight::scene;

// Materials, then the textures they use (a texture's sRGB flag comes from its uses).
void convertMaterials(const tinygltf::Model& model, SceneAsset& scene, LoadContext& ctx);
void convertTextures(const tinygltf::Model& model, SceneAsset& scene, LoadContext& ctx);

// Meshes; appends the default material when a primitive has none.
void convertMeshes(const tinygltf::Model& model, SceneAsset& scene, LoadContext& ctx);

// Nodes (with the hierarchy checked to be a forest) and the roots of the scene shown.
void convertNodes(const tinygltf::Model& model, SceneAsset& scene, LoadContext& ctx);

// Cameras (orthographic ones become perspective once bounds are known: see
// replaceOrthographicCameras) and KHR_lights_punctual lights.
void convertCameras(const tinygltf::Model& model, SceneAsset& scene, LoadContext& ctx);
void convertLights(const tinygltf::Model& model, SceneAsset& scene, LoadContext& ctx);
void replaceOrthographicCameras(const tinygltf::Model& model, SceneAsset& scene, LoadContext& ctx);

// After nodes: skins and the nodes' skin and morph weights (deforming nodes get meshes of
// their own), then EXT_mesh_gpu_instancing's instance transforms.
void convertSkins(const tinygltf::Model& model, SceneAsset& scene, LoadContext& ctx);
void convertMeshInstancing(const tinygltf::Model& model, SceneAsset& scene, LoadContext& ctx);

// After skins: animation channels (morph weights need the targeted node's mesh).
void convertAnimations(const tinygltf::Model& model, SceneAsset& scene, LoadContext& ctx);

}  // namespace qlight::gltf::detail
