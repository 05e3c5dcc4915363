#include "engine/scene/procedural.h"

#include "engine/scene/animation.h"
#include "engine/scene/transforms.h"

namespace qlight::scene {

void addQuad(MeshAsset& mesh, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3,
             uint32_t material) {
  const glm::vec3 normal = glm::normalize(glm::cross(p1 - p0, p3 - p0));
  const auto base = uint32_t(mesh.positions.size());
  const glm::vec3 corners[4] = {p0, p1, p2, p3};
  const glm::vec2 uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i = 0; i < 4; ++i) {
    mesh.positions.push_back(corners[i]);
    mesh.normals.push_back(normal);
    mesh.uv0.push_back(uvs[i]);
  }
  mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  mesh.triangleMaterials.insert(mesh.triangleMaterials.end(), {material, material});
}

void addBox(MeshAsset& mesh, const glm::mat4& worldFromBox, glm::vec3 h, uint32_t material,
            bool facingInward, uint32_t faces) {
  auto at = [&](float x, float y, float z) {
    return glm::vec3(worldFromBox * glm::vec4(x * h.x, y * h.y, z * h.z, 1.0f));
  };
  // Corners of each face counter-clockwise seen from outside.
  struct Face {
    BoxFace bit;
    glm::vec3 c[4];
  };
  const Face table[6] = {
      {kBoxMinX, {at(-1, -1, -1), at(-1, -1, 1), at(-1, 1, 1), at(-1, 1, -1)}},
      {kBoxMaxX, {at(1, -1, 1), at(1, -1, -1), at(1, 1, -1), at(1, 1, 1)}},
      {kBoxMinY, {at(-1, -1, -1), at(1, -1, -1), at(1, -1, 1), at(-1, -1, 1)}},
      {kBoxMaxY, {at(-1, 1, 1), at(1, 1, 1), at(1, 1, -1), at(-1, 1, -1)}},
      {kBoxMinZ, {at(1, -1, -1), at(-1, -1, -1), at(-1, 1, -1), at(1, 1, -1)}},
      {kBoxMaxZ, {at(-1, -1, 1), at(1, -1, 1), at(1, 1, 1), at(-1, 1, 1)}},
  };
  for (const Face& f : table) {
    if (!(faces & f.bit)) continue;
    if (facingInward) {
      addQuad(mesh, f.c[3], f.c[2], f.c[1], f.c[0], material);
    } else {
      addQuad(mesh, f.c[0], f.c[1], f.c[2], f.c[3], material);
    }
  }
}

uint32_t addNode(SceneAsset& scene, NodeAsset node, int32_t parent) {
  const auto index = uint32_t(scene.nodes.size());
  node.parent = parent;
  node.children.clear();
  scene.nodes.push_back(std::move(node));
  if (parent < 0) {
    scene.rootNodes.push_back(index);
  } else {
    scene.nodes[size_t(parent)].children.push_back(index);
  }
  return index;
}

void refreshBounds(SceneAsset& scene) {
  for (MeshAsset& mesh : scene.meshes) {
    if (mesh.positions.empty()) continue;
    mesh.boundsMin = mesh.boundsMax = mesh.positions[0];
    for (const glm::vec3& p : mesh.positions) {
      mesh.boundsMin = glm::min(mesh.boundsMin, p);
      mesh.boundsMax = glm::max(mesh.boundsMax, p);
    }
  }
  scene.bounds = worldBounds(scene, worldTransforms(scene, animate(scene, 0.0f)));
}

namespace {
// Appends `item` and returns its index, as a node refers to it.
template <class T>
int32_t append(std::vector<T>& items, T item) {
  items.push_back(std::move(item));
  return int32_t(items.size() - 1);
}
}  // namespace

uint32_t addMeshAtOrigin(SceneAsset& scene, MeshAsset mesh) {
  NodeAsset node;
  node.mesh = append(scene.meshes, std::move(mesh));
  return addNode(scene, node);
}

uint32_t addCameraNode(SceneAsset& scene, float yfov, glm::vec3 position, glm::quat rotation) {
  CameraAsset camera;
  camera.yfov = yfov;
  NodeAsset node;
  node.camera = append(scene.cameras, camera);
  node.local.translation = position;
  node.local.rotation = rotation;
  return addNode(scene, node);
}

uint32_t addPointLightNode(SceneAsset& scene, float intensity, glm::vec3 position) {
  LightAsset light;
  light.intensity = intensity;
  NodeAsset node;
  node.light = append(scene.lights, light);
  node.local.translation = position;
  return addNode(scene, node);
}

}  // namespace qlight::scene
