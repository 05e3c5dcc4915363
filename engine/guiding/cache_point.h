// A cache point as an ECS component: a surface point with a hemisphere of
// learned incident radiance. Its dense storage uploads as it is to the GPU
// (same layout as shared::GpuCachePoint); its index there is its Q table slot.
#pragma once
#include <glm/glm.hpp>

#include "shaders/shared/guiding_types.h"

namespace qlight::guiding {

struct CachePoint {
  glm::vec3 position{0.0f};
  float radius = 0.0f;  // rejection distance it was accepted with
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  uint32_t pad = 0;
};
static_assert(sizeof(CachePoint) == sizeof(shared::GpuCachePoint));

// A surface point a dart or a camera path landed on.
struct PointCandidate {
  glm::vec3 position;
  glm::vec3 normal;
  float occlusion = 0.0f;  // 0: open, 1: fully occluded within the AO radius
};

}  // namespace qlight::guiding
