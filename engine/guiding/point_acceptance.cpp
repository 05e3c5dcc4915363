#include "engine/guiding/point_acceptance.h"

#include <cmath>
#include <stdexcept>

namespace qlight::guiding {

PointAcceptor::PointAcceptor(float maxRadius, float normalCosine)
    : cellSize_(maxRadius), normalCosine_(normalCosine) {
  if (!(maxRadius > 0.0f) || !std::isfinite(maxRadius))
    throw std::invalid_argument("rejection distance must be positive and finite");
}

glm::ivec3 PointAcceptor::cellOf(const glm::vec3& p) const {
  return glm::ivec3(glm::floor(p / cellSize_));
}

uint64_t PointAcceptor::cellKey(const glm::ivec3& c) const {
  // 21 bits per axis: cells far outside any scene wrap, which only costs a check.
  auto bits = [](int v) { return uint64_t(uint32_t(v) & 0x1fffffu); };
  return bits(c.x) | bits(c.y) << 21 | bits(c.z) << 42;
}

void PointAcceptor::insert(const CachePoint& point) {
  cells_[cellKey(cellOf(point.position))].push_back(uint32_t(points_.size()));
  points_.push_back(point);
}

bool PointAcceptor::tryAccept(const PointCandidate& c, float radius, CachePoint& accepted) {
  if (!std::isfinite(c.position.x + c.position.y + c.position.z)) return false;
  glm::ivec3 center = cellOf(c.position);
  float r2 = radius * radius;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        auto it = cells_.find(cellKey(center + glm::ivec3(dx, dy, dz)));
        if (it == cells_.end()) continue;
        for (uint32_t i : it->second) {
          const CachePoint& p = points_[i];
          glm::vec3 d = p.position - c.position;
          if (glm::dot(d, d) < r2 && glm::dot(p.normal, c.normal) >= normalCosine_) return false;
        }
      }
  accepted = CachePoint{c.position, radius, c.normal, 0};
  insert(accepted);
  return true;
}

}  // namespace qlight::guiding
