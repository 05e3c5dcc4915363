#include "engine/render/scene_accel.h"

#include "engine/bvh/cpu_traversal.h"
#include "engine/bvh/scene_bvh.h"

namespace qlight::render {

struct SceneAccel::Impl {
  bvh::SceneBvh bvh;
};

SceneAccel::SceneAccel() : impl_(std::make_unique<Impl>()) {}
SceneAccel::~SceneAccel() = default;
SceneAccel::SceneAccel(SceneAccel&&) noexcept = default;
SceneAccel& SceneAccel::operator=(SceneAccel&&) noexcept = default;

void SceneAccel::buildMeshes(const std::vector<scene::MeshAsset>& meshes) {
  std::vector<bvh::MeshInput> inputs;
  for (const scene::MeshAsset& m : meshes) inputs.push_back({m.positions, m.indices});
  impl_->bvh.addMeshes(inputs);
}

void SceneAccel::setMaxMergedTriangles(uint32_t count) { impl_->bvh.setMaxMergedTriangles(count); }

void SceneAccel::refitMesh(uint32_t mesh, std::span<const glm::vec3> positions,
                           std::span<const uint32_t> indices) {
  impl_->bvh.refitMesh(mesh, positions, indices);
}

void SceneAccel::buildInstances(const std::vector<MeshDraw>& draws) {
  std::vector<bvh::Instance> instances;
  instances.reserve(draws.size());
  for (uint32_t i = 0; i < draws.size(); ++i)
    instances.push_back({draws[i].worldFromObject, draws[i].mesh, i, draws[i].fixed});
  impl_->bvh.rebuildTopLevel(instances);
}

uint64_t SceneAccel::trianglesVersion() const { return impl_->bvh.trianglesVersion(); }

const std::vector<glm::vec4>& SceneAccel::nodeTexels() const { return impl_->bvh.flat().nodes; }
const std::vector<glm::vec4>& SceneAccel::triangleTexels() const {
  return impl_->bvh.flat().triangles;
}
const std::vector<glm::vec4>& SceneAccel::instanceTexels() const {
  return impl_->bvh.flat().instances;
}

std::optional<float> SceneAccel::closestHit(glm::vec3 origin, glm::vec3 direction) const {
  if (impl_->bvh.flat().nodes.empty()) return std::nullopt;
  bvh::CpuBvhBinding binding(impl_->bvh.flat());
  shared::BvhHit hit;
  if (!shared::traceClosest(origin, glm::normalize(direction), 1e30f, hit)) return std::nullopt;
  return hit.t;
}

}  // namespace qlight::render
