// What the window shows of the learning (issue 12, "seeing the learning"): every cache
// point's position with its learned irradiance and confidence (the overlay), and one point's
// Q over its strata and its learned light values (the hemisphere view). Reads the tables
// back from the GPU, so callers ask a few times a second, not every frame.
#pragma once
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "engine/ecs/registry.h"
#include "engine/guiding/cache_point.h"
#include "engine/guiding/dqn_guide.h"
#include "engine/guiding/q_guide.h"

namespace qlight::guiding {

struct PointSummary {
  glm::vec3 position, normal;
  float irradiance = 0;  // sum over strata of Q times the stratum's cosine integral
  float confidence = 0;  // 0..1, as the path passes weigh the point's guided share
};
std::vector<PointSummary> summarizePoints(ecs::Registry& registry, const QGuide& guide);

struct PointDetail {
  CachePoint point;
  uint32_t rows = 0, cols = 0;
  std::vector<float> q;  // rows x cols, row-major (rows: equal cos theta zones; trees: at centres)
  std::vector<float> lightValues;  // V per light (empty without light learning)
  float confidence = 0;
};
// The point the guide would use at `position` seen from `towardViewer` (unit): the nearest
// within the search radius whose normal faces the viewer; none when no point is in reach.
std::optional<PointDetail> inspectPointAt(ecs::Registry& registry, const QGuide& guide,
                                          glm::vec3 position, glm::vec3 towardViewer);
// Deep Q: what the network says at a surface position with its geometric normal (facing the
// viewer), in the same strata; confidence is the network's guided share factor.
PointDetail inspectNetworkAt(const DqnGuide& guide, glm::vec3 position, glm::vec3 normal);

}  // namespace qlight::guiding
