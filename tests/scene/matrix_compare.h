// Largest element-wise difference of two matrices, for transform tests.
#pragma once
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace qlight::scene {

inline float maxDifference(const glm::mat4& a, const glm::mat4& b) {
  float d = 0.0f;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) d = std::max(d, std::abs(a[c][r] - b[c][r]));
  return d;
}

}  // namespace qlight::scene
