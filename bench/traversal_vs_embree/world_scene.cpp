#include "bench/traversal_vs_embree/world_scene.h"

#include <stdexcept>

#include "engine/gltf/gltf_loader.h"
#include "engine/session/scene_world.h"

namespace qlight::bench {

WorldTriangle WorldScene::triangle(uint32_t instance, uint32_t primitive) const {
  const WorldInstance& inst = instances.at(instance);
  const std::vector<uint32_t>& idx = asset.meshes[inst.mesh].indices;
  return {inst.positions[idx[3 * primitive]], inst.positions[idx[3 * primitive + 1]],
          inst.positions[idx[3 * primitive + 2]]};
}

WorldScene loadWorldScene(const std::filesystem::path& path, float aspect) {
  WorldScene s;
  s.name = path.filename().string();
  s.path = path;
  s.asset = gltf::loadGltf(path);
  {
    // The ECS world runs qlight's own systems (transforms, camera framing);
    // it reads the asset in place, so it lives only while s.asset stays put.
    session::SceneWorld world(s.asset, aspect);
    s.draws = world.draw().meshes;
    s.camera = world.camera();
    for (const render::PunctualDraw& l : world.draw().lights)
      if (l.light.type != scene::LightType::Directional)
        s.punctualPositions.push_back(glm::vec3(l.worldFromLight[3]));
  }
  scene::Bounds bounds;
  for (const render::MeshDraw& d : s.draws) {
    const scene::MeshAsset& mesh = s.asset.meshes.at(d.mesh);
    WorldInstance inst;
    inst.mesh = d.mesh;
    inst.positions.reserve(mesh.positions.size());
    for (const glm::vec3& p : mesh.positions) {
      inst.positions.push_back(glm::vec3(d.worldFromObject * glm::vec4(p, 1.0f)));
      bounds.include(inst.positions.back());
    }
    s.triangleCount += mesh.triangleCount();
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
      if (!s.asset.materials[mesh.triangleMaterials[t]].isEmissive()) continue;
      WorldTriangle w{inst.positions[mesh.indices[3 * t]], inst.positions[mesh.indices[3 * t + 1]],
                      inst.positions[mesh.indices[3 * t + 2]]};
      if (glm::length(glm::cross(w.p1 - w.p0, w.p2 - w.p0)) > 0.0f) s.emitters.push_back(w);
    }
    s.instances.push_back(std::move(inst));
  }
  for (const scene::MeshAsset& m : s.asset.meshes) s.meshTriangleCount += m.triangleCount();
  if (s.triangleCount == 0)
    throw std::runtime_error(path.string() + ": the scene has no triangles");
  s.boundsMin = bounds.min;
  s.boundsMax = bounds.max;
  return s;
}

}  // namespace qlight::bench
