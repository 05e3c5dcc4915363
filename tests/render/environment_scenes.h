// Scenes and maps for the environment light tests: a Lambertian plane facing up and seen from
// above (nothing else in the scene, so every pixel's radiance is albedo/pi times the
// irradiance the map gives it), a sky with a sun of known integral, and a box.
#pragma once
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "engine/scene/procedural.h"
#include "tests/math/sphere_quadrature.h"
#include "tests/render/render_support.h"

namespace qlight::test {

inline scene::MaterialAsset lambertian(float albedo) {
  scene::MaterialAsset m;
  m.baseColorFactor = glm::vec4(albedo, albedo, albedo, 1.0f);
  m.metallicFactor = 0.0f;
  m.specularFactor = 0.0f;  // exactly Lambertian
  return m;
}

// A 40 x 40 quad at y = 0 facing +Y; the camera 1 above it looks straight down and sees only
// the plane. With `emitterBelow`, a bright quad under the plane shines down, away from it: a
// second light for NEE to choose (by power, or learned) that adds nothing to the image.
inline scene::SceneAsset upwardPlane(float albedo, bool emitterBelow = false) {
  scene::SceneAsset s;
  s.materials.push_back(lambertian(albedo));
  scene::MeshAsset mesh;
  const float h = 20.0f;
  scene::addQuad(mesh, {-h, 0, h}, {h, 0, h}, {h, 0, -h}, {-h, 0, -h}, 0);
  if (emitterBelow) {
    scene::MaterialAsset light = lambertian(0.0f);
    light.emissive = glm::vec3(3000.0f);
    s.materials.push_back(light);
    scene::addQuad(mesh, {-0.5f, -1, -0.5f}, {0.5f, -1, -0.5f}, {0.5f, -1, 0.5f}, {-0.5f, -1, 0.5f},
                   1);
  }
  scene::addMeshAtOrigin(s, mesh);
  scene::addCameraNode(s, 0.6f, glm::vec3(0.0f, 1.0f, 0.0f),
                       glm::angleAxis(-0.5f * glm::pi<float>(), glm::vec3(1, 0, 0)));
  scene::refreshBounds(s);
  return s;
}

// A unit cube at the origin, seen from (2.2, 0.4, 2.2): its +Z face fills the left of the
// image, its +X face the right.
inline scene::SceneAsset boxSeenFromCorner() {
  scene::SceneAsset s;
  s.materials.push_back(lambertian(0.8f));
  scene::MeshAsset mesh;
  scene::addBox(mesh, glm::mat4(1.0f), glm::vec3(0.5f), 0);
  scene::addMeshAtOrigin(s, mesh);
  glm::vec3 eye(2.2f, 0.4f, 2.2f);
  glm::quat look = glm::quatLookAt(glm::normalize(-eye), glm::vec3(0, 1, 0));
  scene::addCameraNode(s, 0.55f, eye, look);
  scene::refreshBounds(s);
  return s;
}

inline scene::EnvironmentAsset uniformMap(uint32_t width, uint32_t height, glm::vec3 radiance) {
  scene::EnvironmentAsset env;
  env.width = width;
  env.height = height;
  env.radiance.assign(size_t(width) * height, radiance);
  return env;
}

// 32 x 16: a bluish sky brightening toward the horizon, a 2 x 1 pixel sun 30 degrees above the
// horizon at u = 0.5 (toward -Z unrotated), a dark ground.
inline scene::EnvironmentAsset skyWithSun() {
  scene::EnvironmentAsset env = uniformMap(32, 16, glm::vec3(0.0f));
  for (uint32_t row = 0; row < env.height; ++row)
    for (uint32_t col = 0; col < env.width; ++col) {
      glm::vec3& l = env.radiance[row * env.width + col];
      l = row < 8 ? glm::vec3(0.4f, 0.6f, 1.0f) * (0.5f + 0.1f * float(row))
                  : glm::vec3(0.05f, 0.04f, 0.03f);
    }
  env.radiance[5 * env.width + 15] = env.radiance[5 * env.width + 16] = glm::vec3(60, 50, 40);
  return env;
}

// Irradiance on a surface facing +Y from a map read without filtering (each pixel a constant
// patch): each upper-hemisphere pixel's radiance times the integral of cos(theta) over it,
// (2 pi / width) (sin^2 theta1 - sin^2 theta0) / 2. Rotation about +Y does not change it.
inline glm::dvec3 irradianceFacingUp(const scene::EnvironmentAsset& env) {
  glm::dvec3 e(0.0);
  for (uint32_t row = 0; row < env.height; ++row) {
    double t0 = kPiD * row / env.height, t1 = std::min(kPiD * (row + 1) / env.height, kPiD / 2);
    if (t0 >= kPiD / 2) break;
    double cosIntegral =
        (2 * kPiD / env.width) * 0.5 * (std::pow(std::sin(t1), 2) - std::pow(std::sin(t0), 2));
    for (uint32_t col = 0; col < env.width; ++col)
      e += glm::dvec3(env.radiance[row * env.width + col]) * cosIntegral;
  }
  return e * double(env.strength) * glm::dvec3(env.color);
}

}  // namespace qlight::test
