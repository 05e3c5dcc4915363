// The scenes in assets/ (written by tools/gen_scenes): they load cleanly, are small, light
// themselves with front-facing emitters, and have the properties they are shipped for
// (the door scene's light is invisible from its camera, the animated light loops, the
// many-lights room has over a hundred emitters; in the indirect-light benchmark scenes the
// camera sees no directly lit point, or no light). Visibility is checked by brute-force ray
// casting against every triangle.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <glm/gtc/quaternion.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "engine/gltf/gltf_loader.h"
#include "engine/scene/animation.h"
#include "engine/scene/transforms.h"

namespace qlight::gltf {
namespace {

const std::filesystem::path kAssets = std::filesystem::path(QLIGHT_SOURCE_DIR) / "assets";
// Scenes too large for the repository: the build writes them (tools/gen_scenes --large).
const std::filesystem::path kGenerated = QLIGHT_GENERATED_ASSETS_DIR;
std::filesystem::path scenePath(const std::string& name) {
  return (name == "furnished_room.gltf" ? kGenerated : kAssets) / name;
}
const char* const kShipped[] = {"cornell_box.gltf",
                                "door_ajar.gltf",
                                "animated_light.gltf",
                                "many_lights.gltf",
                                "door_ajar_moving_light.gltf",
                                "door_ajar_jumping_light.gltf"};
// Benchmark scenes for guiding in hard indirect light; the furnished room is large, and the
// glossy floor is the one material that is not Lambertian.
const char* const kIndirect[] = {"corridor.gltf", "glossy_floor.gltf", "furnished_room.gltf"};

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

// Nearest hit distance along origin + s * direction for s in (0, maxDistance), either side;
// hitTriangle, when given, receives the triangle hit.
std::optional<double> nearestHit(const std::vector<Triangle>& triangles, glm::dvec3 origin,
                                 glm::dvec3 direction, double maxDistance,
                                 const Triangle* ignore = nullptr,
                                 const Triangle** hitTriangle = nullptr) {
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
    if (dist > 1e-9 && dist < maxDistance && (!best || dist < *best)) {
      best = dist;
      if (hitTriangle) *hitTriangle = &tri;
    }
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

// Room pairs split along x: the camera before `cameraBelowX`, every emitter's centroid beyond
// `emittersBeyondX`. Returns the camera position.
glm::dvec3 expectCameraAndLightsApart(const SceneAsset& scene,
                                      const std::vector<Triangle>& triangles, double cameraBelowX,
                                      double emittersBeyondX) {
  const glm::dvec3 eye = cameraPosition(scene);
  EXPECT_LT(eye.x, cameraBelowX);
  for (const Triangle& t : triangles)
    if (isEmitter(scene, t)) {
      EXPECT_GT(t.centroid().x, emittersBeyondX);
    }
  return eye;
}

// Points on a triangular grid over each emitter triangle, with the triangle they lie on.
std::vector<std::pair<glm::dvec3, const Triangle*>> emitterPoints(
    const SceneAsset& scene, const std::vector<Triangle>& triangles) {
  std::vector<std::pair<glm::dvec3, const Triangle*>> out;
  for (const Triangle& t : triangles) {
    if (!isEmitter(scene, t)) continue;
    for (int i = 0; i <= 10; ++i)
      for (int j = 0; i + j <= 10; ++j)
        out.push_back({t.a + (i / 10.0) * (t.b - t.a) + (j / 10.0) * (t.c - t.a), &t});
  }
  return out;
}

// How many emitter points the eye sees: in front of their emitter, nothing in between.
size_t emitterPointsSeen(const SceneAsset& scene, const std::vector<Triangle>& triangles,
                         glm::dvec3 eye) {
  size_t seen = 0;
  for (const auto& [p, t] : emitterPoints(scene, triangles)) {
    const glm::dvec3 toPoint = p - eye;
    const double distance = glm::length(toPoint);
    const bool facesAway = glm::dot(t->normal(), -toPoint) <= 0.0;
    seen +=
        !facesAway && !nearestHit(triangles, eye, toPoint / distance, distance * (1.0 - 1e-6), t);
  }
  return seen;
}

// The surface points the camera sees through a cols x rows grid over its image (for which
// keep is true), and how many of them some emitter point lights directly: each in front of
// the other with nothing in between.
struct DirectLight {
  size_t seen = 0, lit = 0;
};
template <typename Keep>
DirectLight directlyLitPointsSeen(const SceneAsset& scene, const std::vector<Triangle>& triangles,
                                  Keep keep, int cols = 64, int rows = 36) {
  const std::vector<glm::mat4> world = worldTransforms(scene, restPose(scene));
  glm::dmat4 view(1.0);
  const CameraAsset* camera = nullptr;
  for (uint32_t n : nodesParentFirst(scene)) {
    if (scene.nodes[n].camera < 0) continue;
    view = glm::dmat4(world[n]);
    camera = &scene.cameras[size_t(scene.nodes[n].camera)];
  }
  if (camera == nullptr) {
    ADD_FAILURE() << "no camera";
    return {};
  }
  const glm::dvec3 eye(view[3]), right(glm::normalize(glm::dvec3(view[0]))),
      up(glm::normalize(glm::dvec3(view[1]))), forward(-glm::normalize(glm::dvec3(view[2])));
  const double tanY = std::tan(0.5 * camera->yfov), tanX = tanY * camera->aspectRatio;
  const auto lights = emitterPoints(scene, triangles);
  DirectLight out;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const double sx = (2.0 * (c + 0.5) / cols - 1.0) * tanX;
      const double sy = (1.0 - 2.0 * (r + 0.5) / rows) * tanY;
      const glm::dvec3 dir = glm::normalize(forward + sx * right + sy * up);
      const Triangle* surface = nullptr;
      const std::optional<double> hit = nearestHit(triangles, eye, dir, 1e3, nullptr, &surface);
      if (!hit || isEmitter(scene, *surface)) continue;
      const glm::dvec3 p = eye + *hit * dir;
      if (!keep(p)) continue;
      ++out.seen;
      glm::dvec3 n = surface->normal();
      if (glm::dot(n, dir) > 0.0) n = -n;  // the side the camera sees
      for (const auto& [q, light] : lights) {
        const glm::dvec3 toLight = q - p;
        const double distance = glm::length(toLight);
        if (glm::dot(n, toLight) <= 0.0 || glm::dot(light->normal(), -toLight) <= 0.0) continue;
        // Starting just off the surface, so its coplanar neighbors cannot shadow it.
        if (!nearestHit(triangles, p + 1e-6 * n, toLight / distance, distance * (1.0 - 1e-6),
                        surface)) {
          ++out.lit;
          break;
        }
      }
    }
  }
  return out;
}

// Distance from the far jamb edge (x, z) to the nearest vertex of the node named "door".
double doorGap(const SceneAsset& scene, float jambX, float jambZ) {
  const std::vector<glm::mat4> world = worldTransforms(scene, restPose(scene));
  double gap = 1e9;
  bool foundDoor = false;
  for (uint32_t n = 0; n < scene.nodes.size(); ++n) {
    if (scene.nodes[n].name != "door") continue;
    foundDoor = true;
    for (const glm::vec3& p : scene.meshes[size_t(scene.nodes[n].mesh)].positions) {
      const glm::vec3 w(world[n] * glm::vec4(p, 1.0f));
      gap = std::min(gap, double(glm::length(glm::vec2(w.x - jambX, w.z - jambZ))));
    }
  }
  EXPECT_TRUE(foundDoor);
  return gap;
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

TEST(ShippedAssets, IndirectLightScenesLoadCleanlyWithACamera) {
  for (const char* name : kIndirect) {
    SCOPED_TRACE(name);
    const bool large = std::string(name) == "furnished_room.gltf";
    const std::filesystem::path path = scenePath(name);
    ASSERT_TRUE(std::filesystem::exists(path));
    EXPECT_LT(std::filesystem::file_size(path), large ? 12u * 1024u * 1024u : 200u * 1024u);
    const SceneAsset scene = loadGltf(path);
    EXPECT_TRUE(scene.warnings.empty());
    ASSERT_EQ(scene.cameras.size(), 1u);
    EXPECT_NEAR(scene.cameras[0].aspectRatio, 16.0f / 9.0f, 1e-4f);
    EXPECT_FALSE(scene.bounds.empty());
    size_t emitters = 0;
    for (const Triangle& t : worldTriangles(scene, 0.0f)) emitters += isEmitter(scene, t);
    EXPECT_GE(emitters, 2u);
    for (const MaterialAsset& m : scene.materials) {
      EXPECT_EQ(m.metallicFactor, 0.0f) << m.name;
      if (m.name != "glossy_floor") {
        EXPECT_EQ(m.specularFactor, 0.0f) << m.name;
      }
      EXPECT_FALSE(m.doubleSided) << m.name;
    }
  }
}

// Every emitter faces into the scene: straight out of its front there is room (the nearest
// surface is at least 20 cm away) and what it meets faces back towards it.
TEST(ShippedAssets, EmittersFaceIntoTheRoom) {
  std::vector<const char*> names(std::begin(kShipped), std::end(kShipped));
  names.insert(names.end(), std::begin(kIndirect), std::end(kIndirect));
  for (const char* name : names) {
    SCOPED_TRACE(name);
    const SceneAsset scene = loadGltf(scenePath(name));
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
  const glm::dvec3 eye = expectCameraAndLightsApart(scene, triangles, 4.0, 4.1);  // A, B
  EXPECT_FALSE(emitterPoints(scene, triangles).empty());
  EXPECT_EQ(emitterPointsSeen(scene, triangles, eye), 0u) << "emitter points seen from the camera";

  // The gap: the door's vertex nearest to the far jamb edge (x = 4, z = 1.6) is ~10 cm away.
  EXPECT_NEAR(doorGap(scene, 4.0f, 1.6f), 0.10, 0.01);
}

// The corridor: the camera in leg A (x < 1.5, z > -6), the light in leg B (x > 1.5), and no
// surface point the camera sees is lit directly; light reaches it around the corner.
TEST(ShippedAssets, CorridorLightsWhatTheCameraSeesOnlyAroundTheCorner) {
  const SceneAsset scene = loadGltf(kAssets / "corridor.gltf");
  const std::vector<Triangle> triangles = worldTriangles(scene, 0.0f);
  EXPECT_LT(triangles.size(), 300u);
  const glm::dvec3 eye = expectCameraAndLightsApart(scene, triangles, 1.5, 3.0);  // legs A, B
  EXPECT_GT(eye.z, -6.0);
  const DirectLight direct =
      directlyLitPointsSeen(scene, triangles, [](glm::dvec3) { return true; });
  EXPECT_GT(direct.seen, 2000u);  // nearly every pixel sees a surface
  EXPECT_EQ(direct.lit, 0u);
}

// The glossy floor: one glossy dielectric (room A's floor), the camera in room A, and no point
// of room A it sees lit directly (the light faces away from the doorway).
TEST(ShippedAssets, GlossyFloorRoomIsLitOnlyThroughTheDoorway) {
  const SceneAsset scene = loadGltf(kAssets / "glossy_floor.gltf");
  size_t glossy = 0;
  for (const MaterialAsset& m : scene.materials) {
    if (m.specularFactor == 0.0f) continue;
    ++glossy;
    EXPECT_EQ(m.specularFactor, 1.0f);
    EXPECT_NEAR(m.roughnessFactor, 0.25f, 0.05f);
  }
  EXPECT_EQ(glossy, 1u);
  const std::vector<Triangle> triangles = worldTriangles(scene, 0.0f);
  EXPECT_LT(triangles.size(), 1000u);
  const glm::dvec3 eye = cameraPosition(scene);
  EXPECT_LT(eye.x, 5.0);  // room A
  EXPECT_EQ(emitterPointsSeen(scene, triangles, eye), 0u);
  const DirectLight direct =
      directlyLitPointsSeen(scene, triangles, [](glm::dvec3 p) { return p.x < 5.0; });
  EXPECT_GT(direct.seen, 1000u);
  EXPECT_EQ(direct.lit, 0u);
}

// The furnished door-ajar pair: 150k-250k triangles, the light in room B hidden from the
// camera in room A, the door open about 12 cm.
TEST(ShippedAssets, FurnishedRoomIsDetailedAndHidesItsLight) {
  const SceneAsset scene = loadGltf(scenePath("furnished_room.gltf"));
  const std::vector<Triangle> triangles = worldTriangles(scene, 0.0f);
  EXPECT_GT(triangles.size(), 150000u);
  EXPECT_LT(triangles.size(), 250000u);
  const glm::dvec3 eye = expectCameraAndLightsApart(scene, triangles, 6.0, 6.1);  // A, B
  EXPECT_EQ(emitterPointsSeen(scene, triangles, eye), 0u);
  EXPECT_NEAR(doorGap(scene, 6.0f, 2.3f), 0.12, 0.01);
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

// The door-ajar light's centre at time t (its node's translation).
glm::vec3 animatedLightCentre(const SceneAsset& scene, float t) {
  const uint32_t node = scene.animations.at(0).channels.at(0).node;
  return glm::vec3(worldTransforms(scene, animate(scene, t, true))[node][3]);
}

// The demo's scene: the light glides through room B (never into the wall, never seen from
// the camera) and loops; the door is the one of door_ajar.gltf.
TEST(ShippedAssets, DoorAjarMovingLightGlidesThroughRoomBHidden) {
  const SceneAsset scene = loadGltf(kAssets / "door_ajar_moving_light.gltf");
  ASSERT_EQ(scene.animations.size(), 1u);
  const float duration = scene.animations[0].duration;
  EXPECT_GE(duration, 4.0f);
  EXPECT_EQ(scene.animations[0].channels[0].interpolation, Interpolation::Linear);
  EXPECT_NEAR(doorGap(scene, 4.0f, 1.6f), 0.10, 0.01);
  glm::vec3 previous(1e9f);
  for (int k = 0; k < 12; ++k) {
    const float t = duration * float(k) / 12.0f;
    SCOPED_TRACE(t);
    const std::vector<Triangle> triangles = worldTriangles(scene, t);
    const glm::dvec3 eye = expectCameraAndLightsApart(scene, triangles, 4.0, 4.4);
    EXPECT_EQ(emitterPointsSeen(scene, triangles, eye), 0u);
    const glm::vec3 centre = animatedLightCentre(scene, t);
    EXPECT_GT(glm::length(centre - previous), 0.3f) << "the light moves";
    EXPECT_LT(centre.x, 7.8f);
    EXPECT_GT(centre.z, 0.3f);
    EXPECT_LT(centre.z, 3.7f);
    previous = centre;
  }
  EXPECT_LT(
      glm::length(animatedLightCentre(scene, 1.0f) - animatedLightCentre(scene, 1.0f + duration)),
      1e-4f);
}

// The tracking study's jump: the light stands still in room B, then in room A, then back.
TEST(ShippedAssets, DoorAjarJumpingLightJumpsBetweenTheRooms) {
  const SceneAsset scene = loadGltf(kAssets / "door_ajar_jumping_light.gltf");
  ASSERT_EQ(scene.animations.size(), 1u);
  EXPECT_EQ(scene.animations[0].channels[0].interpolation, Interpolation::Step);
  const glm::vec3 inB = animatedLightCentre(scene, 0.0f);
  const glm::vec3 inA = animatedLightCentre(scene, 6.0f);
  EXPECT_GT(inB.x, 4.4f);
  EXPECT_LT(inA.x, 4.0f);
  for (float t : {0.5f, 3.0f, 5.9f, 12.5f}) EXPECT_EQ(animatedLightCentre(scene, t), inB) << t;
  for (float t : {6.1f, 9.0f, 11.9f}) EXPECT_EQ(animatedLightCentre(scene, t), inA) << t;
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
