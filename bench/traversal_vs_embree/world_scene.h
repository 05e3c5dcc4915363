// A scene as both tracers get it, at time 0: qlight builds its two-level BVH
// from the meshes and draws; Embree gets every instance's triangles moved to
// world space (flattened). The ray generator reads the camera, the world
// triangles (normals at hits) and what shadow rays aim at.
#pragma once
#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "engine/render/scene_draw.h"
#include "engine/scene/scene_asset.h"

namespace qlight::bench {

// One mesh instance: instance i is draw i, which is also qlight's instance
// index (BvhHit::instance) and Embree's geometry id.
struct WorldInstance {
  uint32_t mesh = 0;                 // into SceneAsset::meshes; indices are the mesh's own
  std::vector<glm::vec3> positions;  // world space
};

struct WorldTriangle {
  glm::vec3 p0, p1, p2;
};

struct WorldScene {
  std::string name;  // the file name
  std::filesystem::path path;
  scene::SceneAsset asset;
  std::vector<render::MeshDraw> draws;
  render::CameraView camera;  // the scene's own, or qlight's default framing
  std::vector<WorldInstance> instances;
  std::vector<WorldTriangle> emitters;         // emissive triangles, world space, area > 0
  std::vector<glm::vec3> punctualPositions;    // point and spot lights
  glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // of the world triangles
  uint64_t triangleCount = 0;                  // over all instances
  uint64_t meshTriangleCount = 0;              // over the meshes (what qlight's BLASes hold)

  float size() const { return glm::length(boundsMax - boundsMin); }  // the diagonal
  WorldTriangle triangle(uint32_t instance, uint32_t primitive) const;
};

// Loads a glTF file and evaluates it at t = 0 for a view of the given aspect
// (the default camera's framing depends on it). Throws std::runtime_error
// with one line on a bad file or a scene without triangles.
WorldScene loadWorldScene(const std::filesystem::path& path, float aspect);

}  // namespace qlight::bench
