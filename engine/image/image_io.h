// Writes renders: PNG for people (tonemapped sRGB), PFM and EXR for linear radiance.
#pragma once
#include <cstdint>
#include <filesystem>
#include <vector>

namespace qlight::image {

struct LinearImage {
  uint32_t width = 0, height = 0;
  std::vector<float> rgba;  // linear radiance, row-major from the top row, 4 floats a pixel
};

enum class Tonemap : uint32_t { Clamp = 0, Aces = 1 };

// Picks the format from the extension (.png, .pfm, .exr); throws std::runtime_error
// naming the file on an unknown extension or a failed write.
void writeImage(const std::filesystem::path& path, const LinearImage& image, float exposure = 1.0f,
                Tonemap tonemap = Tonemap::Aces);

// Throws std::runtime_error naming the file unless it ends in .png, .pfm or .exr
// (checked before rendering, so a typo does not cost a render).
void checkImageExtension(const std::filesystem::path& path);

std::vector<uint8_t> toSrgb8(const LinearImage& image, float exposure, Tonemap tonemap);

// Reads a PFM written by writeImage (tests, image comparison tools).
LinearImage readPfm(const std::filesystem::path& path);

}  // namespace qlight::image
