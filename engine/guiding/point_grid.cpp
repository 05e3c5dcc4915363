#include "engine/guiding/point_grid.h"

#include <stdexcept>

namespace qlight::guiding {

PointGrid buildPointGrid(std::span<const CachePoint> points, float cellSize, uint32_t hashSize) {
  if (hashSize == 0 || (hashSize & (hashSize - 1)) != 0)
    throw std::invalid_argument("grid hash size must be a power of two");
  PointGrid g;
  g.cellSize = cellSize;
  g.hashSize = hashSize;
  g.buckets.assign(hashSize + 1, 0);
  std::vector<uint32_t> bucketOf(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    glm::ivec3 cell(glm::floor(points[i].position / cellSize));
    bucketOf[i] = shared::gridCellHash(cell, hashSize);
    ++g.buckets[bucketOf[i] + 1];
  }
  for (uint32_t b = 0; b < hashSize; ++b) g.buckets[b + 1] += g.buckets[b];
  g.points.resize(points.size());
  std::vector<uint32_t> cursor(g.buckets.begin(), g.buckets.end() - 1);
  for (size_t i = 0; i < points.size(); ++i) g.points[cursor[bucketOf[i]]++] = uint32_t(i);
  return g;
}

uint32_t findNearestPoint(const PointGrid& grid, std::span<const CachePoint> points,
                          const glm::vec3& p, const glm::vec3& n, float searchRadius,
                          float normalCosine) {
  glm::ivec3 base(glm::floor(p / grid.cellSize - 0.5f));
  float best = searchRadius * searchRadius;
  uint32_t bestIndex = shared::kNoCachePoint;
  for (int i = 0; i < 8; ++i) {
    uint32_t h = shared::gridCellHash(base + glm::ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1), grid.hashSize);
    for (uint32_t j = grid.buckets[h]; j < grid.buckets[h + 1]; ++j) {
      const CachePoint& cp = points[grid.points[j]];
      glm::vec3 d = cp.position - p;
      float d2 = glm::dot(d, d);
      if (d2 < best && glm::dot(cp.normal, n) >= normalCosine) {
        best = d2;
        bestIndex = grid.points[j];
      }
    }
  }
  return bestIndex;
}

}  // namespace qlight::guiding
