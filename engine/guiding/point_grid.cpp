#include "engine/guiding/point_grid.h"

#include <stdexcept>

// The shader's search code, compiled for the CPU: its buffer reads go through
// these per-thread pointers, set by findNearestPoint.
namespace qlight::guiding::cpu {
thread_local const shared::GpuCachePoint* tPoints = nullptr;
thread_local const uint32_t* tBuckets = nullptr;
thread_local const uint32_t* tGridPoints = nullptr;
}  // namespace qlight::guiding::cpu
#define QL_POINT_AT(i) (::qlight::guiding::cpu::tPoints[(i)])
#define QL_GRID_BUCKET_AT(h) (::qlight::guiding::cpu::tBuckets[(h)])
#define QL_GRID_POINT_AT(j) (::qlight::guiding::cpu::tGridPoints[(j)])
#include "shaders/shared/point_search.h"

namespace qlight::guiding {

PointGrid buildPointGrid(std::span<const CachePoint> points, float cellSize, uint32_t hashSize,
                         std::span<const uint32_t> ids) {
  if (hashSize == 0 || (hashSize & (hashSize - 1)) != 0)
    throw std::invalid_argument("grid hash size must be a power of two");
  if (!ids.empty() && ids.size() != points.size())
    throw std::invalid_argument("grid ids must match the points");
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
  for (size_t i = 0; i < points.size(); ++i)
    g.points[cursor[bucketOf[i]]++] = ids.empty() ? uint32_t(i) : ids[i];
  return g;
}

uint32_t findNearestPoint(const PointGrid& grid, std::span<const CachePoint> points,
                          const glm::vec3& p, const glm::vec3& n, float searchRadius,
                          float normalCosine) {
  static_assert(sizeof(CachePoint) == sizeof(shared::GpuCachePoint));
  cpu::tPoints = reinterpret_cast<const shared::GpuCachePoint*>(points.data());
  cpu::tBuckets = grid.buckets.data();
  cpu::tGridPoints = grid.points.data();
  return shared::findNearestCachePoint(p, n, grid.cellSize, grid.hashSize, searchRadius,
                                       normalCosine);
}

}  // namespace qlight::guiding
