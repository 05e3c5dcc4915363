// Khronos samples for material features (tests/data/gltf-samples/features): each loads
// with the values its file holds and without a warning about the feature it tests.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "engine/gltf/gltf_loader.h"

namespace qlight::gltf {
namespace {

SceneAsset loadFeature(const std::string& name) {
  return loadGltf(std::string(QLIGHT_SAMPLES_DIR) + "/features/" + name + "/glTF/" + name +
                  ".gltf");
}

bool warnsAbout(const SceneAsset& scene, const std::string& word) {
  return std::any_of(scene.warnings.begin(), scene.warnings.end(),
                     [&](const std::string& w) { return w.find(word) != std::string::npos; });
}

const MaterialAsset& materialNamed(const SceneAsset& scene, const std::string& name) {
  for (const MaterialAsset& m : scene.materials)
    if (m.name == name) return m;
  throw std::runtime_error("no material " + name);
}

TEST(GltfMaterialSamples, TextureTransformTestReadsOffsetRotationAndScale) {
  const SceneAsset scene = loadFeature("TextureTransformTest");
  EXPECT_FALSE(warnsAbout(scene, "texture_transform")) << scene.warnings.size();
  EXPECT_EQ(materialNamed(scene, "Offset U").baseColorTexture.offset, glm::vec2(0.5f, 0.0f));
  EXPECT_EQ(materialNamed(scene, "Offset UV").baseColorTexture.offset, glm::vec2(0.5f, 0.5f));
  EXPECT_FLOAT_EQ(materialNamed(scene, "Rotation").baseColorTexture.rotation, 0.39269908f);
  EXPECT_EQ(materialNamed(scene, "Scale").baseColorTexture.scale, glm::vec2(1.5f));
  const TextureBinding& all = materialNamed(scene, "All").baseColorTexture;
  EXPECT_EQ(all.offset, glm::vec2(-0.2f, -0.1f));
  EXPECT_FLOAT_EQ(all.rotation, 0.3f);
  EXPECT_EQ(all.scale, glm::vec2(1.5f));
  EXPECT_EQ(materialNamed(scene, "Correct").baseColorTexture.rotation, 0.0f);  // none given
}

TEST(GltfMaterialSamples, VertexColorTestReadsColor0AsLinearRgba) {
  const SceneAsset scene = loadFeature("VertexColorTest");
  size_t coloured = 0;
  for (const MeshAsset& mesh : scene.meshes) {
    if (mesh.colors.empty()) continue;
    ASSERT_EQ(mesh.colors.size(), mesh.positions.size());
    ++coloured;
    for (const glm::vec4& c : mesh.colors) {
      for (int k = 0; k < 4; ++k) EXPECT_TRUE(c[k] >= 0.0f && c[k] <= 1.0f);
    }
  }
  EXPECT_GE(coloured, 1u);
  // The test row multiplies its checks by pure red, green and blue.
  bool red = false, green = false, blue = false;
  for (const MeshAsset& mesh : scene.meshes)
    for (const glm::vec4& c : mesh.colors) {
      red |= c == glm::vec4(1, 0, 0, 1);
      green |= c == glm::vec4(0, 1, 0, 1);
      blue |= c == glm::vec4(0, 0, 1, 1);
    }
  EXPECT_TRUE(red && green && blue);
}

TEST(GltfMaterialSamples, BoxVertexColorsHasAColourPerVertex) {
  const SceneAsset scene = loadFeature("BoxVertexColors");
  ASSERT_FALSE(scene.meshes.empty());
  EXPECT_EQ(scene.meshes[0].colors.size(), scene.meshes[0].positions.size());
}

TEST(GltfMaterialSamples, UnlitTestIsRequiredAndLoadsUnlitMaterials) {
  const SceneAsset scene = loadFeature("UnlitTest");  // lists KHR_materials_unlit as required
  ASSERT_EQ(scene.materials.size(), 2u);
  for (const MaterialAsset& m : scene.materials) {
    EXPECT_TRUE(m.unlit) << m.name;
    EXPECT_FALSE(m.isEmissive()) << "unlit surfaces are not lights";
  }
}

TEST(GltfMaterialSamples, MultiUvTestReadsTexcoord1ForTheEmissiveTexture) {
  const SceneAsset scene = loadFeature("MultiUVTest");
  EXPECT_FALSE(warnsAbout(scene, "TEXCOORD_1"));
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].emissiveTexture.texCoord, 1u);
  EXPECT_EQ(scene.materials[0].baseColorTexture.texCoord, 0u);
  ASSERT_FALSE(scene.meshes.empty());
  const MeshAsset& mesh = scene.meshes[0];
  ASSERT_EQ(mesh.uv1.size(), mesh.positions.size());
  EXPECT_NE(mesh.uv1, mesh.uv0);  // a second, different parameterisation
}

TEST(GltfMaterialSamples, TextureCoordinateTestLoadsWithoutWarnings) {
  const SceneAsset scene = loadFeature("TextureCoordinateTest");
  EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
}

}  // namespace
}  // namespace qlight::gltf
