// Axis-aligned boxes for the BVH builder.
#pragma once

#include <glm/glm.hpp>
#include <limits>

namespace qlight::bvh {

struct Aabb {
  glm::vec3 min{std::numeric_limits<float>::max()};
  glm::vec3 max{-std::numeric_limits<float>::max()};

  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  void grow(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void grow(const Aabb& b) {
    min = glm::min(min, b.min);
    max = glm::max(max, b.max);
  }
  glm::vec3 extent() const { return max - min; }
  // Half the surface area: the SAH only compares ratios. 0 for an empty box.
  float halfArea() const {
    if (empty()) return 0.0f;
    glm::vec3 e = extent();
    return e.x * e.y + e.y * e.z + e.z * e.x;
  }
  bool contains(const Aabb& b) const {
    return glm::all(glm::lessThanEqual(min, b.min)) && glm::all(glm::lessThanEqual(b.max, max));
  }
};

inline Aabb unite(Aabb a, const Aabb& b) {
  a.grow(b);
  return a;
}

}  // namespace qlight::bvh
