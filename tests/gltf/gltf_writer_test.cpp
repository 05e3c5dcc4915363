// saveGltf then loadGltf gives back what was written (the generator relies on it).
#include <gtest/gtest.h>

#include <fstream>
#include <glm/gtc/quaternion.hpp>
#include <sstream>

#include "engine/scene/procedural.h"
#include "tests/gltf/gltf_test_files.h"

namespace qlight::gltf {
namespace {

SceneAsset sampleScene() {
  SceneAsset scene;
  MaterialAsset wall;
  wall.name = "wall";
  wall.baseColorFactor = {0.5f, 0.25f, 0.125f, 1.0f};
  wall.metallicFactor = 0.0f;
  wall.roughnessFactor = 0.75f;
  wall.specularFactor = 0.0f;
  MaterialAsset lamp;
  lamp.name = "lamp";
  lamp.emissive = {17.0f, 12.0f, 4.0f};
  lamp.doubleSided = true;
  scene.materials = {wall, lamp};

  MeshAsset mesh;
  mesh.name = "stuff";
  addBox(mesh, glm::mat4(1.0f), {1, 2, 3}, 0);
  addQuad(mesh, {0, 5, 0}, {1, 5, 0}, {1, 5, 1}, {0, 5, 1}, 1);
  addBox(mesh, glm::mat4(1.0f), {0.1f, 0.1f, 0.1f}, 0, true);
  scene.meshes.push_back(mesh);

  CameraAsset camera;
  camera.yfov = 0.9f;
  camera.aspectRatio = 1.5f;
  camera.znear = 0.05f;
  scene.cameras.push_back(camera);  // zfar infinite
  LightAsset spot;
  spot.type = LightType::Spot;
  spot.color = {1, 0.5f, 0.25f};
  spot.intensity = 12.0f;
  spot.range = 9.0f;
  spot.innerConeAngle = 0.1f;
  spot.outerConeAngle = 0.5f;
  scene.lights.push_back(spot);

  NodeAsset root, child, eye;
  root.name = "root";
  root.mesh = 0;
  root.local.translation = {1, 2, 3};
  root.local.rotation = glm::angleAxis(0.4f, glm::vec3(0, 1, 0));
  root.local.scale = {2, 2, 2};
  child.name = "child";
  child.light = 0;
  eye.name = "eye";
  eye.camera = 0;
  const uint32_t r = addNode(scene, root);
  addNode(scene, child, int32_t(r));
  addNode(scene, eye);

  AnimationChannel c;
  c.node = 1;
  c.path = AnimationPath::Scale;
  c.interpolation = Interpolation::Step;
  c.times = {0.0f, 0.5f};
  c.values = {{1, 1, 1, 0}, {2, 3, 4, 0}};
  AnimationAsset a;
  a.name = "grow";
  a.channels.push_back(c);
  a.duration = 0.5f;
  scene.animations.push_back(a);
  refreshBounds(scene);
  return scene;
}

TEST(GltfWriter, RoundTripKeepsEverythingWritten) {
  const SceneAsset in = sampleScene();
  testing::TempDir dir;
  saveGltf(in, dir / "round.gltf");
  const SceneAsset out = loadGltf(dir / "round.gltf");
  EXPECT_TRUE(out.warnings.empty());

  ASSERT_EQ(out.materials.size(), 2u);
  EXPECT_EQ(out.materials[0].name, "wall");
  EXPECT_EQ(out.materials[0].baseColorFactor, in.materials[0].baseColorFactor);
  EXPECT_EQ(out.materials[0].roughnessFactor, 0.75f);
  EXPECT_EQ(out.materials[0].specularFactor, 0.0f);
  EXPECT_EQ(out.materials[1].specularFactor, 1.0f);
  EXPECT_NEAR(glm::length(out.materials[1].emissive - in.materials[1].emissive), 0.0f, 1e-5f);
  EXPECT_TRUE(out.materials[1].doubleSided);

  ASSERT_EQ(out.meshes.size(), 1u);
  EXPECT_EQ(out.meshes[0].positions, in.meshes[0].positions);
  EXPECT_EQ(out.meshes[0].normals, in.meshes[0].normals);
  EXPECT_EQ(out.meshes[0].uv0, in.meshes[0].uv0);
  EXPECT_EQ(out.meshes[0].indices, in.meshes[0].indices);
  EXPECT_EQ(out.meshes[0].triangleMaterials, in.meshes[0].triangleMaterials);

  ASSERT_EQ(out.nodes.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(out.nodes[i].name, in.nodes[i].name);
    EXPECT_EQ(out.nodes[i].parent, in.nodes[i].parent);
    EXPECT_EQ(out.nodes[i].mesh, in.nodes[i].mesh);
    EXPECT_EQ(out.nodes[i].camera, in.nodes[i].camera);
    EXPECT_EQ(out.nodes[i].light, in.nodes[i].light);
    EXPECT_EQ(out.nodes[i].local.translation, in.nodes[i].local.translation);
    EXPECT_NEAR(std::abs(glm::dot(out.nodes[i].local.rotation, in.nodes[i].local.rotation)), 1.0f,
                1e-6f);
    EXPECT_EQ(out.nodes[i].local.scale, in.nodes[i].local.scale);
  }
  EXPECT_EQ(out.rootNodes, in.rootNodes);

  ASSERT_EQ(out.cameras.size(), 1u);
  EXPECT_EQ(out.cameras[0].yfov, 0.9f);
  EXPECT_EQ(out.cameras[0].aspectRatio, 1.5f);
  EXPECT_TRUE(std::isinf(out.cameras[0].zfar));
  ASSERT_EQ(out.lights.size(), 1u);
  EXPECT_EQ(out.lights[0].type, LightType::Spot);
  EXPECT_EQ(out.lights[0].color, in.lights[0].color);
  EXPECT_EQ(out.lights[0].range, 9.0f);
  EXPECT_EQ(out.lights[0].outerConeAngle, 0.5f);

  ASSERT_EQ(out.animations.size(), 1u);
  EXPECT_EQ(out.animations[0].name, "grow");
  EXPECT_EQ(out.animations[0].channels[0].times, in.animations[0].channels[0].times);
  EXPECT_EQ(out.animations[0].channels[0].values, in.animations[0].channels[0].values);
  EXPECT_EQ(out.bounds.min, in.bounds.min);
  EXPECT_EQ(out.bounds.max, in.bounds.max);
}

TEST(GltfWriter, UsesEmissiveStrengthAboveOneAndDeclaresExtensions) {
  const SceneAsset in = sampleScene();
  const testing::json doc = testing::json::parse(toGltfJson(in));
  const auto& lamp = doc["materials"][1];
  EXPECT_EQ(lamp["emissiveFactor"][0].get<double>(), 1.0);
  EXPECT_EQ(lamp["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"].get<double>(),
            17.0);
  const auto used = doc["extensionsUsed"].get<std::vector<std::string>>();
  for (const char* ext :
       {"KHR_materials_emissive_strength", "KHR_materials_specular", "KHR_lights_punctual"})
    EXPECT_NE(std::find(used.begin(), used.end(), ext), used.end()) << ext;
  EXPECT_FALSE(doc.contains("extensionsRequired"));  // other viewers still open the files
}

TEST(GltfWriter, Base64MatchesTheStandardAlphabetAndPadding) {
  EXPECT_EQ(base64Encode("", 0), "");
  EXPECT_EQ(base64Encode("f", 1), "Zg==");
  EXPECT_EQ(base64Encode("fo", 2), "Zm8=");
  EXPECT_EQ(base64Encode("foo", 3), "Zm9v");
  EXPECT_EQ(base64Encode("foobar", 6), "Zm9vYmFy");
  const uint8_t high[3] = {0xfb, 0xff, 0xbf};
  EXPECT_EQ(base64Encode(high, 3), "+/+/");
}

}  // namespace
}  // namespace qlight::gltf
