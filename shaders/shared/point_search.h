// Nearest cache point search in the hashed grid, shared by GLSL and C++ (the
// C++ tests run this very code). The includer defines, before including:
//   QL_POINT_AT(i)        -> GpuCachePoint i
//   QL_GRID_BUCKET_AT(h)  -> first entry of bucket h (hashSize + 1 entries)
//   QL_GRID_POINT_AT(j)   -> point index of grid entry j
#ifndef QLIGHT_SHARED_POINT_SEARCH_H
#define QLIGHT_SHARED_POINT_SEARCH_H
#include "guiding_types.h"

QL_BEGIN
// The nearest point within searchRadius whose normal is compatible
// (dot >= normalCosine), or kNoCachePoint. The grid lists in each cell every
// point within searchRadius of some position in the cell
// (engine/guiding/point_grid.cpp), so the cell holding p alone has all the
// candidates: one bucket to visit, and cells of searchRadius keep the list short.
QL_FN uint findNearestCachePoint(vec3 p, vec3 n, float cellSize, uint hashSize, float searchRadius,
                                 float normalCosine) {
  vec3 g = p / cellSize;
  uint h = gridCellHash(ivec3(int(floor(g.x)), int(floor(g.y)), int(floor(g.z))), hashSize);
  float best = searchRadius * searchRadius;
  uint bestIndex = kNoCachePoint;
  uint end = QL_GRID_BUCKET_AT(h + 1u);
  for (uint j = QL_GRID_BUCKET_AT(h); j < end; ++j) {
    uint index = QL_GRID_POINT_AT(j);
    GpuCachePoint cp = QL_POINT_AT(index);
    vec3 d = cp.position - p;
    float d2 = dot(d, d);
    if (d2 < best && dot(cp.normal, n) >= normalCosine) {
      best = d2;
      bestIndex = index;
    }
  }
  return bestIndex;
}
QL_END

#endif
