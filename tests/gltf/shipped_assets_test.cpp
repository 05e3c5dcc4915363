// The scenes in assets/ (written by tools/gen_scenes): they load cleanly, are small, light
// themselves with front-facing emitters, and have the properties they are shipped for
// (the door scene's light is invisible from its camera, the animated light loops, the
// many-lights room has over a hundred emitters). Visibility is checked by brute-force ray
// casting against every triangle.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <glm/gtc/quaternion.hpp>
#include <optional>

#include "engine/gltf/gltf_loader.h"
#include "engine/scene/animation.h"
#include "engine/scene/transforms.h"

namespace qlight::gltf {
namespace {

const std::filesystem::path kAssets = std::filesystem::path(QLIGHT_SOURCE_DIR) / "assets";
const char* const kShipped[] = {"cornell_box.gltf", "door_ajar.gltf", "animated_light.gltf",
                                "many_lights.gltf"};

struct Triangle {
  glm::dvec3 a, b, c;
  uint32_t material;
  glm::dvec3 normal() const { return glm::normalize(glm::cross(b - a, c - a)); }
  glm::dvec3 centroid() const { return (a + b + c) / 3.0; }
};

std::vector<Triangle> worldTriangles(const SceneAsset& scene, float t) {
  const std::vector<glm::mat4> world = worldTransforms(scene, animate(scene, t));
  std::vector<Triangle> out;
  for (uint32_t n : nodesParentFirst(scene)) {
    if (scene.nodes[n].mesh < 0) continue;
    const MeshAsset& mesh = scene.meshes[size_t(scene.nodes[n].mesh)];
    auto at = [&](uint32_t i) { return glm::dvec3(world[n] * glm::vec4(mesh.positions[i], 1)); };
    for (size_t k = 0; k < mesh.triangleCount(); ++k)
      out.push_back({at(mesh.indices[3 * k]), at(mesh.indices[3 * k + 1]),
                     at(mesh.indices[3 * k + 2]), mesh.triangleMaterials[k]});
  }
  return out;
}

// Nearest hit distance along origin + s * direction for s in (0, maxDistance), either side.
std::optional<double> nearestHit(const std::vector<Triangle>& triangles, glm::dvec3 origin,
                                 glm::dvec3 direction, double maxDistance,
                                 const Triangle* ignore = nullptr) {
  std::optional<double> best;
  for (const Triangle& tri : triangles) {
    if (&tri == ignore) continue;
    const glm::dvec3 e1 = tri.b - tri.a, e2 = tri.c - tri.a;
    const glm::dvec3 p = glm::cross(direction, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-14) continue;
    const glm::dvec3 s = origin - tri.a;
    const double u = glm::dot(s, p) / det;
    if (u < 0.0 || u > 1.0) continue;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(direction, q) / det;
    if (v < 0.0 || u + v > 1.0) continue;
    const double dist = glm::dot(e2, q) / det;
    if (dist > 1e-9 && dist < maxDistance && (!best || dist < *best)) best = dist;
  }
  return best;
}

bool isEmitter(const SceneAsset& scene, const Triangle& t) {
  return scene.materials[t.material].isEmissive();
}

glm::dvec3 cameraPosition(const SceneAsset& scene) {
  const std::vector<glm::mat4> world = worldTransforms(scene, restPose(scene));
  for (uint32_t n : nodesParentFirst(scene))
    if (scene.nodes[n].camera >= 0) return glm::dvec3(world[n][3]);
  ADD_FAILURE() << "no camera";
  return {};
}

TEST(ShippedAssets, EachLoadsCleanlyIsSmallAndHasEmittersAndACamera) {
  for (const char* name : kShipped) {
    SCOPED_TRACE(name);
    const std::filesystem::path path = kAssets / name;
    ASSERT_TRUE(std::filesystem::exists(path));
    EXPECT_LT(std::filesystem::file_size(path), 200u * 1024u);
    const SceneAsset scene = loadGltf(path);
    EXPECT_TRUE(scene.warnings.empty());
    EXPECT_EQ(scene.cameras.size(), 1u);
    EXPECT_FALSE(scene.bounds.empty());
    size_t emitters = 0;
    for (const Triangle& t : worldTriangles(scene, 0.0f)) emitters += isEmitter(scene, t);
    EXPECT_GE(emitters, 2u);
    for (const MaterialAsset& m : scene.materials) {
      EXPECT_EQ(m.metallicFactor, 0.0f) << m.name;  // exactly Lambertian scenes
      EXPECT_EQ(m.specularFactor, 0.0f) << m.name;
      EXPECT_FALSE(m.doubleSided) << m.name;
    }
  }
}

// Every emitter faces into the scene: straight out of its front there is room (the nearest
// surface is at least 20 cm away) and what it meets faces back towards it.
TEST(ShippedAssets, EmittersFaceIntoTheRoom) {
  for (const char* name : kShipped) {
    SCOPED_TRACE(name);
    const SceneAsset scene = loadGltf(kAssets / name);
    const std::vector<Triangle> triangles = worldTriangles(scene, 0.0f);
    for (const Triangle& t : triangles) {
      if (!isEmitter(scene, t)) continue;
      const std::optional<double> hit = nearestHit(triangles, t.centroid(), t.normal(), 1e3, &t);
      ASSERT_TRUE(hit.has_value()) << "an emitter faces out of the scene";
      EXPECT_GT(*hit, 0.2);
    }
  }
}

TEST(ShippedAssets, CornellBoxIsClassic) {
  const SceneAsset scene = loadGltf(kAssets / "cornell_box.gltf");
  size_t red = 0, green = 0, lights = 0;
  for (const MaterialAsset& m : scene.materials) {
    red += m.baseColorFactor.r > 0.5f && m.baseColorFactor.g < 0.1f;
    green += m.baseColorFactor.g > 0.3f && m.baseColorFactor.r < 0.2f;
    if (m.isEmissive()) {
      ++lights;
      EXPECT_GT(m.emissive.r, 1.0f);  // emissiveFactor x KHR_materials_emissive_strength
    }
  }
  EXPECT_EQ(red, 1u);
  EXPECT_EQ(green, 1u);
  EXPECT_EQ(lights, 1u);
  // The camera stands in front of the open side and sees the light directly.
  const glm::dvec3 eye = cameraPosition(scene);
  EXPECT_GT(eye.z, scene.bounds.max.z);
  const std::vector<Triangle> triangles = worldTriangles(scene, 0.0f);
  for (const Triangle& t : triangles) {
    if (!isEmitter(scene, t)) continue;
    const glm::dvec3 toLight = t.centroid() - eye;
    const double distance = glm::length(toLight);
    const std::optional<double> hit =
        nearestHit(triangles, eye, toLight / distance, distance * (1.0 + 1e-6));
    EXPECT_NEAR(hit.value_or(0.0), distance, 1e-6);
  }
}

// Veach's door: from the camera, every point of every emitter is hidden behind geometry (or
// turned away), the light is in the other room, and the door leaves a gap of about 10 cm.
TEST(ShippedAssets, DoorAjarHidesItsLightFromTheCamera) {
  const SceneAsset scene = loadGltf(kAssets / "door_ajar.gltf");
  const std::vector<Triangle> triangles = worldTriangles(scene, 0.0f);
  EXPECT_LE(triangles.size(), 400u);
  const glm::dvec3 eye = cameraPosition(scene);
  EXPECT_LT(eye.x, 4.0);  // room A
  size_t samples = 0;
  for (const Triangle& t : triangles) {
    if (!isEmitter(scene, t)) continue;
    EXPECT_GT(t.centroid().x, 4.1);  // room B
    for (int i = 0; i <= 10; ++i) {
      for (int j = 0; i + j <= 10; ++j) {
        const double u = i / 10.0, v = j / 10.0;
        const glm::dvec3 p = t.a + u * (t.b - t.a) + v * (t.c - t.a);
        const glm::dvec3 toPoint = p - eye;
        const double distance = glm::length(toPoint);
        const bool facesAway = glm::dot(t.normal(), -toPoint) <= 0.0;
        const std::optional<double> hit =
            nearestHit(triangles, eye, toPoint / distance, distance * (1.0 - 1e-6), &t);
        EXPECT_TRUE(facesAway || hit.has_value()) << "emitter point seen from the camera";
        ++samples;
      }
    }
  }
  EXPECT_GT(samples, 0u);

  // The gap: the door's vertex nearest to the far jamb edge (x = 4, z = 1.6) is ~10 cm away.
  const std::vector<glm::mat4> world = worldTransforms(scene, restPose(scene));
  double gap = 1e9;
  bool foundDoor = false;
  for (uint32_t n = 0; n < scene.nodes.size(); ++n) {
    if (scene.nodes[n].name != "door") continue;
    foundDoor = true;
    for (const glm::vec3& p : scene.meshes[size_t(scene.nodes[n].mesh)].positions) {
      const glm::vec3 w(world[n] * glm::vec4(p, 1.0f));
      gap = std::min(gap, double(glm::length(glm::vec2(w.x - 4.0f, w.z - 1.6f))));
    }
  }
  EXPECT_TRUE(foundDoor);
  EXPECT_NEAR(gap, 0.10, 0.01);
}

TEST(ShippedAssets, AnimatedLightLoopsInsideTheBox) {
  const SceneAsset scene = loadGltf(kAssets / "animated_light.gltf");
  ASSERT_EQ(scene.animations.size(), 1u);
  ASSERT_EQ(scene.animations[0].channels.size(), 1u);
  const AnimationChannel& path = scene.animations[0].channels[0];
  EXPECT_EQ(path.path, AnimationPath::Translation);
  EXPECT_EQ(path.interpolation, Interpolation::Linear);
  EXPECT_GE(scene.animations[0].duration, 2.0f);
  EXPECT_EQ(path.values.front(), path.values.back());  // a closed loop
  const uint32_t lightNode = path.node;
  ASSERT_GE(scene.nodes[lightNode].mesh, 0);

  glm::vec3 previous(1e9f);
  const float duration = scene.animations[0].duration;
  for (int k = 0; k < 16; ++k) {
    const float t = duration * float(k) / 16.0f;
    const std::vector<glm::mat4> world = worldTransforms(scene, animate(scene, t, true));
    const glm::vec3 position(world[lightNode][3]);
    EXPECT_GT(glm::length(position - previous), 0.05f) << "the light moves, t = " << t;
    previous = position;
    // All of the light stays strictly inside the room at every time.
    for (const glm::vec3& p : scene.meshes[size_t(scene.nodes[lightNode].mesh)].positions) {
      const glm::vec3 w(world[lightNode] * glm::vec4(p, 1.0f));
      EXPECT_GT(w.x, -1.0f);
      EXPECT_LT(w.x, 1.0f);
      EXPECT_GT(w.z, -1.0f);
      EXPECT_LT(w.z, 1.0f);
      EXPECT_LT(w.y, 2.0f);
    }
  }
  // Looping: t and t + duration give the same pose.
  const auto a = animate(scene, 1.3f, true), b = animate(scene, 1.3f + duration, true);
  EXPECT_NEAR(glm::length(a[lightNode].translation - b[lightNode].translation), 0.0f, 1e-5f);
}

TEST(ShippedAssets, ManyLightsHasOverAHundredEmittersOfVaryingStrength) {
  const SceneAsset scene = loadGltf(kAssets / "many_lights.gltf");
  size_t emissiveMaterials = 0;
  float weakest = 1e9f, strongest = 0.0f;
  for (const MaterialAsset& m : scene.materials) {
    if (!m.isEmissive()) continue;
    ++emissiveMaterials;
    const float peak = std::max({m.emissive.r, m.emissive.g, m.emissive.b});
    weakest = std::min(weakest, peak);
    strongest = std::max(strongest, peak);
  }
  size_t emissiveTriangles = 0;
  const std::vector<Triangle> triangles = worldTriangles(scene, 0.0f);
  for (const Triangle& t : triangles) emissiveTriangles += isEmitter(scene, t);
  EXPECT_GE(emissiveMaterials, 100u);
  EXPECT_GE(emissiveTriangles, 200u);  // two per quad
  EXPECT_GT(strongest / weakest, 10.0f);
  // Occluders: from the camera, a good share of the emitters is hidden.
  const glm::dvec3 eye = cameraPosition(scene);
  size_t hidden = 0;
  for (const Triangle& t : triangles) {
    if (!isEmitter(scene, t)) continue;
    const glm::dvec3 toLight = t.centroid() - eye;
    const double distance = glm::length(toLight);
    hidden += nearestHit(triangles, eye, toLight / distance, distance * (1 - 1e-6), &t).has_value();
  }
  EXPECT_GT(hidden, emissiveTriangles / 5);
  EXPECT_LT(hidden, emissiveTriangles);
}

}  // namespace
}  // namespace qlight::gltf
