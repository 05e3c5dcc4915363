#include "engine/guiding/point_grid.h"

#include <cmath>
#include <stdexcept>
#include <utility>

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

PointGrid buildPointGrid(std::span<const CachePoint> points, float searchRadius, uint32_t hashSize,
                         std::span<const uint32_t> ids) {
  if (hashSize == 0 || (hashSize & (hashSize - 1)) != 0)
    throw std::invalid_argument("grid hash size must be a power of two");
  if (!ids.empty() && ids.size() != points.size())
    throw std::invalid_argument("grid ids must match the points");
  if (!(searchRadius > 0.0f) || !std::isfinite(searchRadius))
    throw std::invalid_argument("grid search radius must be positive");
  PointGrid g;
  g.cellSize = searchRadius;
  g.hashSize = hashSize;
  g.buckets.assign(hashSize + 1, 0);
  // (bucket, entry) of every cell within searchRadius of each point; a point's cells that
  // share a bucket list it once. The margin covers a query's rounding into its cell.
  const float reach = searchRadius * (1.0f + 1e-4f);
  std::vector<std::pair<uint32_t, uint32_t>> entries;
  entries.reserve(points.size() * 20);
  for (size_t i = 0; i < points.size(); ++i) {
    const glm::vec3 p = points[i].position;
    const glm::ivec3 lo(glm::floor((p - reach) / searchRadius));
    const glm::ivec3 hi(glm::floor((p + reach) / searchRadius));
    const size_t first = entries.size();
    for (int z = lo.z; z <= hi.z; ++z)
      for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x) {
          const glm::vec3 cellMin = glm::vec3(x, y, z) * searchRadius;
          const glm::vec3 nearest = glm::clamp(p, cellMin, cellMin + searchRadius);
          const glm::vec3 d = nearest - p;
          if (glm::dot(d, d) >= reach * reach) continue;
          const uint32_t bucket = shared::gridCellHash(glm::ivec3(x, y, z), hashSize);
          bool listed = false;
          for (size_t e = first; e < entries.size() && !listed; ++e)
            listed = entries[e].first == bucket;
          if (!listed) entries.emplace_back(bucket, ids.empty() ? uint32_t(i) : ids[i]);
        }
  }
  for (const auto& e : entries) ++g.buckets[e.first + 1];
  for (uint32_t b = 0; b < hashSize; ++b) g.buckets[b + 1] += g.buckets[b];
  g.points.resize(entries.size());
  std::vector<uint32_t> cursor(g.buckets.begin(), g.buckets.end() - 1);
  for (const auto& e : entries) g.points[cursor[e.first]++] = e.second;
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
