// The shared traversal (shaders/shared/bvh_traverse.h) compiled for the CPU:
// the texel macros read from per-thread pointers that a CpuBvhBinding sets.
// Tests and benchmarks run the very code the shader runs.
#pragma once

#include <glm/glm.hpp>

#include "engine/bvh/flat_bvh.h"

namespace qlight::bvh::cpu {
inline constinit thread_local const glm::vec4* tNodes = nullptr;
inline constinit thread_local const glm::vec4* tTriangles = nullptr;
inline constinit thread_local const glm::vec4* tInstances = nullptr;
}  // namespace qlight::bvh::cpu

#define QL_BVH_NODE(i) (::qlight::bvh::cpu::tNodes[(i)])
#define QL_BVH_TRI(i) (::qlight::bvh::cpu::tTriangles[(i)])
#define QL_BVH_INST(i) (::qlight::bvh::cpu::tInstances[(i)])
#include "shaders/shared/bvh_traverse.h"

namespace qlight::bvh {

// Points this thread's traversal at a FlatBvh for the binding's lifetime (the
// FlatBvh must outlive it and not be resized meanwhile); restores the
// previous binding on destruction, so bindings nest.
class CpuBvhBinding {
 public:
  explicit CpuBvhBinding(const FlatBvh& bvh)
      : nodes_(cpu::tNodes), triangles_(cpu::tTriangles), instances_(cpu::tInstances) {
    cpu::tNodes = bvh.nodes.data();
    cpu::tTriangles = bvh.triangles.data();
    cpu::tInstances = bvh.instances.data();
  }
  ~CpuBvhBinding() {
    cpu::tNodes = nodes_;
    cpu::tTriangles = triangles_;
    cpu::tInstances = instances_;
  }
  CpuBvhBinding(const CpuBvhBinding&) = delete;
  CpuBvhBinding& operator=(const CpuBvhBinding&) = delete;

 private:
  const glm::vec4* nodes_;
  const glm::vec4* triangles_;
  const glm::vec4* instances_;
};

}  // namespace qlight::bvh
