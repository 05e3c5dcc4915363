// Writes a SceneAsset as one self-contained glTF 2.0 file (JSON with the buffer embedded as a
// base64 data URI). Used by tools/gen_scenes to ship generated scenes, and by tests to make
// files whose content is known.
#pragma once

#include <filesystem>
#include <string>

#include "engine/scene/scene_asset.h"

namespace qlight::gltf {
using namespace ::qlight::scene;  // glTF I/O reads and writes the scene's plain data

// Written: meshes (one primitive per run of triangles sharing a material, vertices shared by
// the mesh's primitives), materials (emissive above 1 becomes emissiveFactor x
// KHR_materials_emissive_strength; a specularFactor other than 1 is written as
// KHR_materials_specular), nodes, perspective cameras, KHR_lights_punctual lights,
// node TRS animations with their interpolation, the scene's roots. Not written: textures
// (texture references are dropped), skins, morph targets and their weights channels,
// EXT_mesh_gpu_instancing. Throws std::runtime_error naming the path on I/O errors.
std::string toGltfJson(const SceneAsset& scene, const std::string& generator = "qlight");
void saveGltf(const SceneAsset& scene, const std::filesystem::path& path,
              const std::string& generator = "qlight");

// Standard base64 with padding.
std::string base64Encode(const void* data, size_t size);

}  // namespace qlight::gltf
