// The BVH as the GPU reads it: texel arrays ready to upload as RGBA32F texel
// buffers (layout: shaders/shared/bvh_types.h).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace qlight::bvh {

struct FlatBvh {
  std::vector<glm::vec4> nodes;           // 4 texels per node; node 0 is the header
  std::vector<glm::vec4> triangles;       // 3 texels per triangle, leaf order, object space
  std::vector<uint32_t> triangleIndices;  // per triangle above: its index within its mesh
  std::vector<glm::vec4> instances;       // 8 texels per instance
};

}  // namespace qlight::bvh
