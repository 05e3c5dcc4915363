// Internal to the glTF loader: reads a .gltf/.glb file and checks what tinygltf trusts
// blindly (GLB chunk sizes, buffer sizes against their data, buffer views inside their
// buffers, required extensions), so that tinygltf is only called on input it survives.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/gltf/gltf_context.h"
#include "engine/scene/scene_asset.h"

namespace qlight::gltf::detail {
using namespace ::qlight::scene;

struct CheckedGltfFile {
  std::vector<uint8_t> bytes;  // the whole file
  bool binary = false;         // GLB container
  std::string baseDir;         // for external buffers and images
};

// Extensions the loader implements; any other in extensionsRequired is an error.
bool isSupportedRequiredExtension(const std::string& name);

CheckedGltfFile readAndCheckGltfFile(const std::filesystem::path& path, LoadContext& ctx);
// The same checks on a file's bytes already in memory; external buffers and images are
// looked up in baseDir.
CheckedGltfFile checkGltfBytes(std::vector<uint8_t> bytes, const std::filesystem::path& baseDir,
                               LoadContext& ctx);

}  // namespace qlight::gltf::detail
