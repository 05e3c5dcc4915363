// The hashed uniform grid the GPU searches for the nearest cache point:
// bucket starts (hashSize + 1) and point indices sorted by bucket. Cells are
// searchRadius wide and each lists every point within searchRadius of it (a
// point is in up to 27 cells), so a search visits the one cell it falls in.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "engine/guiding/cache_point.h"

namespace qlight::guiding {

struct PointGrid {
  float cellSize = 1.0f;  // the search radius it was built for
  uint32_t hashSize = 1;  // power of two
  std::vector<uint32_t> buckets;
  std::vector<uint32_t> points;
};

// The grid's entries are ids[i] for points[i] when ids are given (the points' table slots),
// else the index i.
PointGrid buildPointGrid(std::span<const CachePoint> points, float searchRadius, uint32_t hashSize,
                         std::span<const uint32_t> ids = {});

// The same search as guiding.glsl's findCachePoint (tests compare against brute force);
// `points` indexed by the grid's entries.
uint32_t findNearestPoint(const PointGrid& grid, std::span<const CachePoint> points,
                          const glm::vec3& p, const glm::vec3& n, float searchRadius,
                          float normalCosine);

}  // namespace qlight::guiding
