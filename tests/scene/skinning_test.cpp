// Skins: a tiny two-joint file posed by hand (every skinned vertex and normal computed on
// paper), SimpleSkin at a key of its animation, and the ECS path (animation -> transforms ->
// deformSystem) giving the same vertices.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/gltf/gltf_loader.h"
#include "engine/scene/deform.h"
#include "engine/scene/instantiate.h"
#include "engine/scene/transforms.h"
#include "tests/gltf/gltf_doc_builder.h"

namespace qlight::scene {
namespace {

using gltf::testing::DocBuilder;
using gltf::testing::json;
using gltf::testing::TempDir;
using gltf::testing::writeDoc;

const std::filesystem::path kFeatures = std::filesystem::path(QLIGHT_SAMPLES_DIR) / "features";

void expectNear(glm::vec3 actual, glm::vec3 expected, const std::string& what) {
  EXPECT_NEAR(actual.x, expected.x, 1e-5f) << what;
  EXPECT_NEAR(actual.y, expected.y, 1e-5f) << what;
  EXPECT_NEAR(actual.z, expected.z, 1e-5f) << what;
}

// A strip in the xy plane (normals +z): rows at y = 0, 1, 2, two vertices each (x = -0.5,
// 0.5). Joint 0 at the origin, joint 1 at (0, 1, 0) its child, rotated 90 degrees about +x
// by `animated` (a rotation channel: identity at t = 0, 90 degrees at t = 1) or statically.
// Row 0 follows joint 0, row 1 both halves, row 2 joint 1. The skinned node's own
// translation (5, 0, 0) must be ignored.
json twoJointStrip(bool animated) {
  DocBuilder b;
  const int positions = b.addFloats(
      {-0.5f, 0, 0, 0.5f, 0, 0, -0.5f, 1, 0, 0.5f, 1, 0, -0.5f, 2, 0, 0.5f, 2, 0}, "VEC3");
  const int normals = b.addFloats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3");
  const int joints = b.add<uint8_t>(
      {0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, 5121, "VEC4");
  const int weights = b.addFloats(
      {1, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0, 0.5f, 0.5f, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, "VEC4");
  const int indices = b.add<uint16_t>({0, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4}, 5123, "SCALAR");
  const int inverseBind = b.addFloats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0,  0, 1,
                                       1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1},
                                      "MAT4");
  const float s = std::sqrt(0.5f);
  json joint1 = {{"translation", {0, 1, 0}}};
  json doc = {{"scene", 0},
              {"scenes", json::array({{{"nodes", {0, 1}}}})},
              {"skins", json::array({{{"joints", {1, 2}}, {"inverseBindMatrices", inverseBind}}})},
              {"meshes", json::array({{{"primitives", json::array({{{"attributes",
                                                                     {{"POSITION", positions},
                                                                      {"NORMAL", normals},
                                                                      {"JOINTS_0", joints},
                                                                      {"WEIGHTS_0", weights}}},
                                                                    {"indices", indices}}})}}})}};
  if (animated) {
    const int times = b.addFloats({0, 1}, "SCALAR");
    const int rotations = b.addFloats({0, 0, 0, 1, s, 0, 0, s}, "VEC4");
    doc["animations"] = json::array(
        {{{"samplers", json::array({{{"input", times}, {"output", rotations}}})},
          {"channels",
           json::array({{{"sampler", 0}, {"target", {{"node", 2}, {"path", "rotation"}}}}})}}});
  } else {
    joint1["rotation"] = {s, 0, 0, s};
  }
  doc["nodes"] = json::array(
      {{{"mesh", 0}, {"skin", 0}, {"translation", {5, 0, 0}}}, {{"children", {2}}}, joint1});
  return b.finish(doc);
}

// Joint 1's matrix is T(0,1,0) Rx(90) T(0,-1,0): (x, y, z) -> (x, 1 - z, y - 1).
// Row 2 (y = 2): (x, 1, 1), normal (0, -1, 0). Row 1 (y = 1) blends (x, 1, 0) with itself:
// unmoved, and its normal, by the inverse transpose of (I + Rx(90)) / 2 (a 45-degree rotation
// about x times a scale), is (0, -s, s). Row 0 stays.
void expectHandPose(const DeformedVertices& v) {
  const float s = std::sqrt(0.5f);
  ASSERT_EQ(v.positions.size(), 6u);
  for (int side = 0; side < 2; ++side) {
    const float x = side == 0 ? -0.5f : 0.5f;
    expectNear(v.positions[0 + side], {x, 0, 0}, "row 0");
    expectNear(v.normals[0 + side], {0, 0, 1}, "row 0 normal");
    expectNear(v.positions[2 + side], {x, 1, 0}, "row 1");
    expectNear(v.normals[2 + side], {0, -s, s}, "row 1 normal");
    expectNear(v.positions[4 + side], {x, 1, 1}, "row 2");
    expectNear(v.normals[4 + side], {0, -1, 0}, "row 2 normal");
  }
}

TEST(Skinning, TwoJointsWithOneTurned90DegreesGiveTheHandComputedPose) {
  TempDir dir;
  const SceneAsset scene = gltf::loadGltf(writeDoc(dir, "strip.gltf", twoJointStrip(false)));
  EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
  ASSERT_EQ(scene.skins.size(), 1u);
  ASSERT_EQ(scene.nodes[0].skin, 0);
  const MeshAsset& mesh = scene.meshes[0];
  ASSERT_TRUE(mesh.deform.skinnable());
  EXPECT_EQ(mesh.deform.joints[2], glm::uvec4(0, 1, 0, 0));
  EXPECT_EQ(mesh.deform.weights[2], glm::vec4(0.5f, 0.5f, 0, 0));

  const std::vector<glm::mat4> world = worldTransforms(scene, restPose(scene));
  expectHandPose(deformMesh(mesh, {}, jointMatrices(scene.skins[0], world)));
  // The bounds are the skinned pose's (the node's translation of 5 plays no part).
  EXPECT_NEAR(scene.bounds.max.x, 0.5f, 1e-5f);
  EXPECT_NEAR(scene.bounds.max.z, 1.0f, 1e-5f);
}

TEST(Skinning, TheEcsPosesTheSkinAsItsJointsAnimate) {
  TempDir dir;
  const SceneAsset scene = gltf::loadGltf(writeDoc(dir, "strip.gltf", twoJointStrip(true)));
  ecs::Registry registry;
  const InstantiatedScene made = instantiate(scene, registry);
  auto step = [&](float t) {
    animationSystem(registry, scene, t);
    transformSystem(registry);
    deformSystem(registry, scene);
    const DeformedMesh& d = registry.get<DeformedMesh>(made.nodeEntities[0]);
    return DeformedVertices{d.positions, d.normals};
  };
  const DeformedVertices rest = step(0.0f);  // the bind pose
  for (size_t i = 0; i < rest.positions.size(); ++i)
    expectNear(rest.positions[i], scene.meshes[0].positions[i], "bind pose");
  const uint64_t before = registry.get<DeformedMesh>(made.nodeEntities[0]).version;
  step(0.0f);
  EXPECT_EQ(registry.get<DeformedMesh>(made.nodeEntities[0]).version, before)
      << "an unchanged pose is not deformed again";
  expectHandPose(step(1.0f));
  EXPECT_GT(registry.get<DeformedMesh>(made.nodeEntities[0]).version, before);
}

// SimpleSkin (the glTF tutorial's): at t = 1 s its animation holds joint 1 (node 2, at
// (0, 1, 0) with inverse bind T(0, -1, 0)) at 90 degrees about z: (x, y) -> (1 - y, x + 1).
TEST(Skinning, SimpleSkinAtOneSecondHasItsTopBentNinetyDegrees) {
  const SceneAsset scene = gltf::loadGltf(kFeatures / "SimpleSkin/glTF/SimpleSkin.gltf");
  for (const std::string& w : scene.warnings) EXPECT_EQ(w.find("skin"), std::string::npos) << w;
  ecs::Registry registry;
  const InstantiatedScene made = instantiate(scene, registry);
  animationSystem(registry, scene, 1.0f);
  transformSystem(registry);
  deformSystem(registry, scene);
  const DeformedMesh& d = registry.get<DeformedMesh>(made.nodeEntities[0]);
  // Without normals in the file each triangle owns its vertices: look them up by bind position.
  const std::vector<glm::vec3>& bind = scene.meshes[0].positions;
  ASSERT_EQ(d.positions.size(), bind.size());
  auto posed = [&](glm::vec3 at) {
    for (size_t i = 0; i < bind.size(); ++i)
      if (bind[i] == at) return d.positions[i];
    ADD_FAILURE() << "no vertex at " << at.x << ", " << at.y;
    return glm::vec3(0.0f);
  };
  expectNear(posed({-0.5f, 0, 0}), {-0.5f, 0, 0}, "(-0.5, 0): joint 0 only");
  expectNear(posed({0.5f, 2, 0}), {-1.0f, 1.5f, 0}, "(0.5, 2): joint 1 only");
  expectNear(posed({-0.5f, 2, 0}), {-1.0f, 0.5f, 0}, "(-0.5, 2): joint 1 only");
  // (0.5, 1) half and half: (0.5, 1) and (0, 1.5).
  expectNear(posed({0.5f, 1, 0}), {0.25f, 1.25f, 0}, "(0.5, 1)");
  // (0.5, 1.5) a quarter joint 0, three quarters joint 1: (0.5, 1.5) and (-0.5, 1.5).
  expectNear(posed({0.5f, 1.5f, 0}), {-0.25f, 1.5f, 0}, "(0.5, 1.5)");
  // Flat normals follow the bent faces: the top quad now faces +z still (a rotation about z).
  for (const glm::vec3& n : d.normals) EXPECT_NEAR(std::abs(n.z), 1.0f, 1e-5f);
}

TEST(Skinning, MissingWeightsAndStrayJointIndicesAreOneLineErrors) {
  TempDir dir;
  json doc = twoJointStrip(false);
  doc["meshes"][0]["primitives"][0]["attributes"].erase("WEIGHTS_0");
  gltf::testing::expectLoadError(writeDoc(dir, "noweights.gltf", doc),
                                 "JOINTS_0 without WEIGHTS_0");
  json stray = twoJointStrip(false);
  stray["skins"][0]["joints"] = {1};
  stray["skins"][0].erase("inverseBindMatrices");
  gltf::testing::expectLoadError(writeDoc(dir, "stray.gltf", stray),
                                 "uses joint 1 of a skin with 1 joints");
}

TEST(Skinning, MoreThanFourInfluencesAreAWarning) {
  TempDir dir;
  json doc = twoJointStrip(false);
  doc["meshes"][0]["primitives"][0]["attributes"]["JOINTS_1"] =
      doc["meshes"][0]["primitives"][0]["attributes"]["JOINTS_0"];
  const SceneAsset scene = gltf::loadGltf(writeDoc(dir, "eight.gltf", doc));
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_NE(scene.warnings[0].find("more than 4 joint influences (JOINTS_1)"), std::string::npos);
}

}  // namespace
}  // namespace qlight::scene
