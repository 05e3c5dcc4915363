// A cache point as an ECS component: a surface point with a hemisphere of
// learned incident radiance. It uploads as it is to the GPU (same layout as
// shared::GpuCachePoint) at its slot: the point's row in the learned tables and
// its index in the GPU point array, kept for the point's lifetime (PointSet).
#pragma once
#include <cstddef>
#include <glm/glm.hpp>

#include "shaders/shared/guiding_types.h"

namespace qlight::guiding {

struct CachePoint {
  glm::vec3 position{0.0f};
  float radius = 0.0f;  // rejection distance it was accepted with
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  uint32_t slot = 0;  // the GPU struct's last word, unread by the shaders
};
static_assert(sizeof(CachePoint) == sizeof(shared::GpuCachePoint));
static_assert(offsetof(CachePoint, slot) == sizeof(shared::GpuCachePoint) - 4);

// A surface point a dart or a camera path landed on.
struct PointCandidate {
  glm::vec3 position;
  glm::vec3 normal;
  float occlusion = 0.0f;  // 0: open, 1: fully occluded within the AO radius
};

}  // namespace qlight::guiding
