// An environment map from a file (.hdr, .exr; also .pfm) as the renderer's EnvironmentAsset.
#pragma once
#include <filesystem>

#include "engine/scene/environment_asset.h"

namespace qlight::render {

// Throws std::runtime_error, one line naming the file, when it cannot be read or decoded or
// holds a texel that is NaN, infinite or negative (radiance is finite and non-negative).
scene::EnvironmentAsset loadEnvironmentMap(const std::filesystem::path& path);

}  // namespace qlight::render
