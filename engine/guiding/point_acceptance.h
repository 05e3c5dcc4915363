// Dart throwing on the CPU: a candidate becomes a cache point when no
// compatible point (similar normal) lies within its rejection distance.
#pragma once
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "engine/guiding/cache_point.h"

namespace qlight::guiding {

class PointAcceptor {
 public:
  // maxRadius bounds every rejection distance used with this acceptor.
  PointAcceptor(float maxRadius, float normalCosine);

  void insert(const CachePoint& point);
  // Accepts (and inserts) the candidate when nothing compatible is within `radius`.
  bool tryAccept(const PointCandidate& candidate, float radius, CachePoint& accepted);
  size_t size() const { return points_.size(); }

 private:
  uint64_t cellKey(const glm::ivec3& cell) const;
  glm::ivec3 cellOf(const glm::vec3& p) const;

  float cellSize_;
  float normalCosine_;
  std::vector<CachePoint> points_;
  std::unordered_map<uint64_t, std::vector<uint32_t>> cells_;
};

}  // namespace qlight::guiding
