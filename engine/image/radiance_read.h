// Reads linear radiance images for environment maps: Radiance .hdr (stb_image), OpenEXR
// (tinyexr) and PFM. Alpha, where the file has it, is dropped (set to 1).
#pragma once
#include <filesystem>

#include "engine/image/image_io.h"

namespace qlight::image {

// Throws std::runtime_error, one line naming the file: missing or unreadable, not decodable,
// an extension other than .hdr, .exr or .pfm.
LinearImage readRadianceImage(const std::filesystem::path& path);

}  // namespace qlight::image
