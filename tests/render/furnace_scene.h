// The white furnace: a closed box whose walls all have albedo a and emit E
// (exactly Lambertian), seen from inside; the radiance everywhere is E / (1 - a).
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include "engine/scene/procedural.h"
#include "tests/render/render_support.h"

namespace qlight::test {

inline scene::SceneAsset whiteFurnace(float albedo, float emission) {
  scene::SceneAsset s;
  scene::MaterialAsset m;
  m.baseColorFactor = glm::vec4(albedo, albedo, albedo, 1.0f);
  m.metallicFactor = 0.0f;
  m.specularFactor = 0.0f;  // exactly Lambertian
  m.emissive = glm::vec3(emission);
  s.materials.push_back(m);
  scene::MeshAsset mesh;
  scene::addBox(mesh, glm::mat4(1.0f), glm::vec3(1.0f, 0.7f, 1.3f), 0, /*facingInward=*/true);
  scene::addMeshAtOrigin(s, mesh);
  scene::addCameraNode(s, 1.2f, glm::vec3(0.2f, -0.1f, 0.6f),
                       glm::angleAxis(0.4f, glm::normalize(glm::vec3(0.3f, 1.0f, 0.1f))));
  scene::refreshBounds(s);
  return s;
}

}  // namespace qlight::test
