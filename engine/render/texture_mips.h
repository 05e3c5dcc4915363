// Mipmap chains for the path tracer's textures: each level half the previous one (rounded
// down, at least 1), a 2x2 box filter (edge texels repeated for odd sizes), averaged in
// linear light for sRGB textures. The shader picks a level from the ray cone's footprint.
#pragma once
#include <cstdint>
#include <vector>

#include "engine/scene/scene_asset.h"

namespace qlight::render {

// Levels of a width x height texture: 1 + floor(log2(max(width, height))).
uint32_t mipLevelCount(uint32_t width, uint32_t height);
// Texels (RGBA8 packed in a uint32 each) of all levels, level 0 first.
uint64_t mipChainTexels(uint32_t width, uint32_t height);
std::vector<uint32_t> buildMipChain(const scene::TextureAsset& texture);
// An 8-bit channel as linear light (decoded from sRGB when srgb).
float toLinear(uint8_t c, bool srgb);

}  // namespace qlight::render
