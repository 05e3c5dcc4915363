#include "engine/session/scene_world.h"

#include "engine/scene/components.h"

namespace qlight::session {
namespace {

// Whether an animation channel moves the entity or one of its ancestors.
bool movesOrAncestorMoves(const ecs::Registry& r, ecs::Entity e) {
  for (int depth = 0; e != ecs::kNullEntity && depth < 1024; ++depth) {
    if (const scene::AnimatedNode* a = r.tryGet<scene::AnimatedNode>(e))
      if (a->translation.valid() || a->rotation.valid() || a->scale.valid()) return true;
    const scene::Parent* parent = r.tryGet<scene::Parent>(e);
    e = parent ? parent->entity : ecs::kNullEntity;
  }
  return false;
}

}  // namespace

SceneWorld::SceneWorld(const scene::SceneAsset& asset, float aspect) : asset_(asset) {
  instance_ = scene::instantiate(asset, registry_, aspect);
  // Registered out of order on purpose: the scheduler orders them by what
  // they read and write (animation -> transforms -> deform -> extract).
  scheduler_.add("extract")
      .phase(ecs::Phase::Extract)
      .reads<scene::WorldTransform, scene::MeshInstance, scene::PunctualLight, scene::Skinned,
             scene::DeformedMesh, scene::AnimatedNode, scene::Parent>()
      .writes<render::SceneDraw>()
      .run([this](ecs::Registry& r) { extract(r); });
  scheduler_.add("transforms")
      .reads<scene::LocalTransform, scene::Parent>()
      .writes<scene::WorldTransform>()
      .run([](ecs::Registry& r) { scene::transformSystem(r); });
  scheduler_.add("deform")
      .reads<scene::WorldTransform, scene::MorphWeights, scene::Skinned>()
      .writes<scene::DeformedMesh>()
      .run([this](ecs::Registry& r) { scene::deformSystem(r, asset_); });
  scheduler_.add("animation")
      .reads<scene::AnimatedNode>()
      .writes<scene::LocalTransform, scene::MorphWeights>()
      .run([this](ecs::Registry& r) { scene::animationSystem(r, asset_, time_, /*loop=*/true); });
  scheduler_.compile();
  registry_.storage<scene::WorldTransform>().markAllDirty();
  advance(0.0f);
}

void SceneWorld::advance(float seconds) {
  time_ = seconds;
  scheduler_.runPhase(registry_, ecs::Phase::Simulate);
  scheduler_.runPhase(registry_, ecs::Phase::Extract);
}

void SceneWorld::extract(ecs::Registry& r) {
  auto& world = r.storage<scene::WorldTransform>();
  auto& deformed = r.storage<scene::DeformedMesh>();
  auto dirty = world.dirtyRange(), reposed = deformed.dirtyRange();
  moved_ = dirty.end > dirty.begin || reposed.end > reposed.begin;
  world.clearDirty();
  deformed.clearDirty();
  if (!moved_ && !draw_.meshes.empty()) return;
  draw_ = {};
  std::vector<bool> deformedMesh(asset_.meshes.size(), false);
  r.view<const scene::DeformedMesh>().each([&](const scene::DeformedMesh& d) {
    if (d.mesh < deformedMesh.size()) deformedMesh[d.mesh] = true;
  });
  r.view<const scene::WorldTransform, const scene::MeshInstance>().each(
      [&](ecs::Entity e, const scene::WorldTransform& w, const scene::MeshInstance& m) {
        const bool skinned = r.has<scene::Skinned>(e);  // already in world space
        const bool fixed = !skinned && !(m.mesh < deformedMesh.size() && deformedMesh[m.mesh]) &&
                           !movesOrAncestorMoves(r, e);
        draw_.meshes.push_back({m.mesh, skinned ? glm::mat4(1.0f) : w.worldFromLocal, fixed});
      });
  r.view<const scene::DeformedMesh>().each([&](const scene::DeformedMesh& d) {
    if (d.version != 0) draw_.deformed.push_back({d.mesh, d.version, d.positions, d.normals});
  });
  r.view<const scene::WorldTransform, const scene::PunctualLight>().each(
      [&](const scene::WorldTransform& w, const scene::PunctualLight& l) {
        scene::LightAsset light;
        light.type = l.type;
        light.color = l.color;
        light.intensity = l.intensity;
        light.range = l.range;
        light.innerConeAngle = l.innerConeAngle;
        light.outerConeAngle = l.outerConeAngle;
        draw_.lights.push_back({light, w.worldFromLocal});
      });
}

render::CameraView SceneWorld::camera() const {
  const auto& w = registry_.get<scene::WorldTransform>(instance_.camera);
  const auto& c = registry_.get<scene::Camera>(instance_.camera);
  return render::cameraFromTransform(w.worldFromLocal, c.yfov);
}

}  // namespace qlight::session
