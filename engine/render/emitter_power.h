// The emission of each emissive triangle averaged over the texels of its emissive texture, so
// that NEE picks emitters by the light they give. A glow map is mostly black (DamagedHelmet:
// 15,452 triangles whose material emits, most of them over black texels): chosen by the
// factor alone, most shadow rays would go to triangles that emit nothing. Any selection power
// keeps NEE unbiased (the choice and the MIS weight read the same CDF); a triangle whose every
// nearby texel is black gets 0 and is left out of the light list, and scattered rays that hit
// it count its emission with MIS weight 1.
#pragma once
#include <glm/glm.hpp>
#include <vector>

#include "engine/scene/scene_asset.h"

namespace qlight::render {

// Per mesh, per triangle: the material's emissive factor times the mean of its emissive
// texture over the triangle (linear RGB); the factor alone where the material has no emissive
// texture, 0 where it does not emit. Each texture is averaged at the mip level where the
// triangle's UV box spans at most 8 texels, over the texels whose centres the triangle covers;
// where it covers none, or only black ones, over its UV box grown by a texel (a conservative
// zero: bilinear filtering reads that far). A mesh with no emissive material gets no entries.
std::vector<std::vector<glm::vec3>> triangleEmissions(const scene::SceneAsset& scene);

}  // namespace qlight::render
