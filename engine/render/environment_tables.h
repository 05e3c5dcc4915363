// The environment map's GPU tables (layout in shaders/shared/environment.h): its texels with
// the sampler's density, and the marginal and conditional CDFs of luminance x sin(theta).
#pragma once
#include <glm/glm.hpp>
#include <vector>

#include "engine/scene/environment_asset.h"

namespace qlight::render {

struct EnvironmentTables {
  std::vector<glm::vec4> texels;  // header, then (radiance, p_uv) per pixel
  std::vector<float> cdf;         // rows within tiles, then the tiles' marginals
  // Per tile (ty * tilesX + tx): the integral of the map's luminance over its directions.
  std::vector<double> tileLuminanceIntegrals;
  // Integral over the sphere of the map's luminance (unscaled): its power is this times the
  // scene's cross-section.
  double luminanceIntegral = 0.0;
};

// Throws std::invalid_argument when the asset has no map or its size and texels disagree.
EnvironmentTables buildEnvironmentTables(const scene::EnvironmentAsset& env);

}  // namespace qlight::render
