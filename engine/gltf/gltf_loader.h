// glTF 2.0 import (.gltf with embedded or external buffers, and .glb) into plain data.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "engine/scene/scene_asset.h"

namespace qlight::gltf {
using namespace ::qlight::scene;  // glTF I/O reads and writes the scene's plain data

// Extensions read: KHR_lights_punctual, KHR_materials_emissive_strength,
// KHR_materials_specular (specularFactor only), KHR_texture_transform, KHR_materials_unlit,
// KHR_materials_transmission, KHR_materials_ior, KHR_materials_volume (thickness only),
// EXT_mesh_gpu_instancing; these may be in extensionsRequired.
//
// Loads the file into a SceneAsset. Throws std::runtime_error with one line,
// "<path>: <problem>", for a missing or unreadable file, malformed JSON, missing or truncated
// buffers, anything that would read out of bounds (accessors, buffer views, indices), an
// unsupported required extension, or a value that is not finite. Things it can do without
// (points and lines, morph weight animation, skins, unknown texture extensions) are skipped
// with a warning in SceneAsset::warnings, also printed to stderr.
SceneAsset loadGltf(const std::filesystem::path& path);

// The same from a .gltf's or .glb's bytes in memory (external buffers and images are looked
// up in baseDir; errors and warnings name the file `name`).
SceneAsset loadGltfFromMemory(std::span<const uint8_t> bytes, const std::filesystem::path& baseDir,
                              const std::string& name);

}  // namespace qlight::gltf
