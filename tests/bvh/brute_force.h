// Reference answers: every triangle of every instance, with the same
// watertight test and the same object-space ray as the traversal (so equal
// triangles give bit-equal t), but no tree. Triangles come from the original
// meshes, not from the BVH's reordered copy.
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "engine/bvh/cpu_traversal.h"
#include "tests/bvh/test_scenes.h"

namespace qlight::bvh::testing {

// Needs a CpuBvhBinding for the instance texels (objectFromWorld).
inline bool bruteClosest(const Scene& scene, const glm::vec3& origin, const glm::vec3& dir,
                         float tMax, shared::BvhHit& hit) {
  hit = {tMax, 0.0f, 0.0f, shared::kBvhInvalidIndex, shared::kBvhInvalidIndex};
  bool found = false;
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& instance = scene.instances[i];
    if (glm::determinant(glm::dmat4(instance.worldFromObject)) == 0.0) continue;
    const Mesh& mesh = scene.meshes[instance.blas];
    shared::BvhLocalRay local = shared::bvhInstanceRay(i, origin, dir);
    for (uint32_t t = 0; t < mesh.triangleCount(); ++t) {
      const glm::vec3& p0 = mesh.positions[mesh.indices[3 * t]];
      const glm::vec3& p1 = mesh.positions[mesh.indices[3 * t + 1]];
      const glm::vec3& p2 = mesh.positions[mesh.indices[3 * t + 2]];
      if (isDegenerateTriangle(p0, p1, p2)) continue;
      glm::vec3 tuv(0.0f);
      if (shared::bvhIntersectTriangle(local, p0, p1, p2, hit.t, tuv)) {
        hit = {tuv.x, tuv.y, tuv.z, i, t};
        found = true;
      }
    }
  }
  return found;
}

// Compares a traversal result with the reference; returns "" when they agree
// (same instance and triangle, or a different one at exactly the same t) and
// a description otherwise.
inline std::string compareHits(bool found, const shared::BvhHit& hit, bool refFound,
                               const shared::BvhHit& ref) {
  auto describe = [](bool f, const shared::BvhHit& h) {
    return f ? "hit(t=" + std::to_string(h.t) + " inst=" + std::to_string(h.instance) +
                   " prim=" + std::to_string(h.primitive) + ")"
             : std::string("miss");
  };
  std::string diff = describe(found, hit) + " vs reference " + describe(refFound, ref);
  if (found != refFound) return diff;
  if (!found) return "";
  bool same = hit.instance == ref.instance && hit.primitive == ref.primitive;
  if (!same && hit.t != ref.t) return diff;
  if (same && (hit.u != ref.u || hit.v != ref.v)) return diff + " (barycentrics differ)";
  if (std::abs(hit.t - ref.t) > 1e-5f * std::abs(ref.t)) return diff;
  return "";
}

}  // namespace qlight::bvh::testing
