// The light arriving from infinitely far away, as the user chose it (--env, --sky): an
// equirectangular radiance map (shaders/shared/environment.h says how it wraps the sphere)
// or one uniform colour. Not part of glTF: the caller puts it into SceneAsset::environment.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace qlight::scene {

struct EnvironmentAsset {
  std::string name;  // the map's file, for messages; "" for a uniform colour
  // The map, rows from the top (+Y): width * height linear radiance texels, each finite and
  // non-negative. Empty (0 x 0): a uniform sky of radiance `color`.
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<glm::vec3> radiance;
  glm::vec3 color{1.0f};         // the sky's radiance, or a tint multiplying the map
  float strength = 1.0f;         // multiplies either
  float rotationDegrees = 0.0f;  // about +Y, right-handed

  bool hasMap() const { return width > 0 && height > 0; }
  glm::vec3 scale() const { return color * strength; }
};

}  // namespace qlight::scene
