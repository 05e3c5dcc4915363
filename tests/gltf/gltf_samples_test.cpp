// The Khronos sample files (test data by others) load, with the counts and values they hold.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/gtc/quaternion.hpp>

#include "engine/gltf/gltf_loader.h"
#include "engine/scene/animation.h"
#include "engine/scene/transforms.h"

namespace qlight::gltf {
namespace {

const std::filesystem::path kSamples = QLIGHT_SAMPLES_DIR;

SceneAsset loadSample(const char* name) { return loadGltf(kSamples / name); }

size_t meshInstanceCount(const SceneAsset& scene) {
  size_t count = 0;
  for (uint32_t n : nodesParentFirst(scene)) count += scene.nodes[n].mesh >= 0;
  return count;
}

size_t triangleCount(const SceneAsset& scene) {
  size_t count = 0;
  for (const MeshAsset& m : scene.meshes) count += m.triangleCount();
  return count;
}

// Every mesh is well formed: parallel arrays, indices in range, unit normals, one material
// per triangle that exists.
void expectWellFormed(const SceneAsset& scene) {
  for (const MeshAsset& m : scene.meshes) {
    ASSERT_EQ(m.normals.size(), m.positions.size());
    ASSERT_EQ(m.uv0.size(), m.positions.size());
    ASSERT_EQ(m.indices.size() % 3, 0u);
    ASSERT_EQ(m.triangleMaterials.size(), m.triangleCount());
    for (uint32_t i : m.indices) ASSERT_LT(i, m.positions.size());
    for (const glm::vec3& n : m.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-5f);
    for (uint32_t mat : m.triangleMaterials) ASSERT_LT(mat, scene.materials.size());
  }
  EXPECT_FALSE(scene.bounds.empty());
}

TEST(GltfSamples, EveryFileLoads) {
  size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kSamples)) {
    const auto ext = entry.path().extension();
    if (ext != ".gltf" && ext != ".glb") continue;
    SCOPED_TRACE(entry.path().filename().string());
    SceneAsset scene;
    ASSERT_NO_THROW(scene = loadGltf(entry.path()));
    expectWellFormed(scene);
    EXPECT_GT(triangleCount(scene), 0u);
    ++files;
  }
  EXPECT_EQ(files, 9u);  // the README lists nine files
}

TEST(GltfSamples, BoxHasTwelveTrianglesAndOneRedMaterial) {
  const SceneAsset scene = loadSample("Box.gltf");
  EXPECT_EQ(triangleCount(scene), 12u);
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.defaultMaterial, -1);
  const MaterialAsset& m = scene.materials[0];
  EXPECT_NEAR(m.baseColorFactor.r, 0.8f, 1e-6f);
  EXPECT_EQ(m.baseColorFactor.g, 0.0f);
  EXPECT_EQ(m.baseColorFactor.b, 0.0f);
  EXPECT_EQ(m.metallicFactor, 1.0f);  // left at the glTF default in the file
  EXPECT_FALSE(m.isEmissive());
  // The root's Y-up -> Z-up matrix rotates the unit cube: bounds stay [-0.5, 0.5]^3.
  EXPECT_NEAR(scene.bounds.min.x, -0.5f, 1e-5f);
  EXPECT_NEAR(scene.bounds.max.z, 0.5f, 1e-5f);
}

TEST(GltfSamples, BoxMatrixNodeIsDecomposedIntoARotation) {
  const SceneAsset scene = loadSample("Box.gltf");
  // Box's root matrix maps y to -z and z to y: a -90 degree turn about x.
  const NodeAsset& root = scene.nodes[scene.rootNodes[0]];
  const glm::vec3 y = root.local.rotation * glm::vec3(0, 1, 0);
  EXPECT_NEAR(glm::length(y - glm::vec3(0, 0, -1)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::length(root.local.scale - glm::vec3(1)), 0.0f, 1e-5f);
}

TEST(GltfSamples, SimpleMeshesInstancesOneMeshTwice) {
  const SceneAsset scene = loadSample("SimpleMeshes.gltf");
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(meshInstanceCount(scene), 2u);
  EXPECT_EQ(scene.nodes[0].mesh, 0);
  EXPECT_EQ(scene.nodes[1].mesh, 0);
  EXPECT_EQ(scene.nodes[1].local.translation, glm::vec3(1, 0, 0));
  // No material in the file: the default one, with glTF's default values.
  ASSERT_EQ(scene.defaultMaterial, 0);
  EXPECT_EQ(scene.materials[0].baseColorFactor, glm::vec4(1.0f));
  EXPECT_EQ(scene.materials[0].metallicFactor, 1.0f);
  EXPECT_EQ(scene.materials[0].roughnessFactor, 1.0f);
}

TEST(GltfSamples, TriangleWithoutIndicesIsOneTriangle) {
  const SceneAsset scene = loadSample("TriangleWithoutIndices.gltf");
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].triangleCount(), 1u);
  // No normals in the file: flat, +z for this counter-clockwise triangle in the xy plane.
  for (const glm::vec3& n : scene.meshes[0].normals)
    EXPECT_NEAR(glm::length(n - glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
}

TEST(GltfSamples, CamerasAreFoundAndOrthographicFallsBackToPerspective) {
  const SceneAsset scene = loadSample("Cameras.gltf");
  ASSERT_EQ(scene.cameras.size(), 2u);
  EXPECT_FALSE(scene.cameras[0].fromOrthographic);
  EXPECT_NEAR(scene.cameras[0].yfov, 0.7f, 1e-6f);
  EXPECT_EQ(scene.cameras[0].aspectRatio, 1.0f);
  EXPECT_NEAR(scene.cameras[0].znear, 0.01f, 1e-7f);
  EXPECT_EQ(scene.cameras[0].zfar, 100.0f);
  EXPECT_TRUE(scene.cameras[1].fromOrthographic);
  // ymag 1 framed at the distance of the scene's center along the view axis (z = 3 -> about
  // the quad's plane): yfov = 2 atan(1 / d) with d between 2.5 and 3.5.
  EXPECT_GT(scene.cameras[1].yfov, 2.0f * std::atan(1.0f / 3.5f));
  EXPECT_LT(scene.cameras[1].yfov, 2.0f * std::atan(1.0f / 2.5f));
  EXPECT_EQ(scene.cameras[1].aspectRatio, 1.0f);
  EXPECT_EQ(scene.nodes[1].camera, 0);
  EXPECT_EQ(scene.nodes[2].camera, 1);
  EXPECT_FALSE(scene.warnings.empty());  // the orthographic fallback is reported
}

TEST(GltfSamples, BoxTexturedHasA211x211SrgbTexture) {
  const SceneAsset scene = loadSample("BoxTextured.gltf");
  ASSERT_EQ(scene.textures.size(), 1u);
  const TextureAsset& t = scene.textures[0];
  EXPECT_EQ(t.width, 211u);
  EXPECT_EQ(t.height, 211u);
  EXPECT_EQ(t.rgba8.size(), 211u * 211u * 4u);
  EXPECT_TRUE(t.srgb);
  EXPECT_EQ(t.wrapS, TextureWrap::Repeat);
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].baseColorTexture.index, 0);
  // TEXCOORD_0 is read: its range is the accessor's min/max in the file, [0, 0] to [6, 1].
  glm::vec2 lo(1e9f), hi(-1e9f);
  for (const glm::vec2& uv : scene.meshes[0].uv0) {
    lo = glm::min(lo, uv);
    hi = glm::max(hi, uv);
  }
  EXPECT_EQ(lo, glm::vec2(0.0f, 0.0f));
  EXPECT_EQ(hi, glm::vec2(6.0f, 1.0f));
}

// AnimatedTriangle's keys (from its buffer): at 0, 0.25, 0.5, 0.75, 1 s the rotation about z
// is 0, 90, 180, 270, 360 degrees, written as quaternions (0,0,0,1), (0,0,.707,.707),
// (0,0,1,0), (0,0,.707,-.707), (0,0,0,1).
TEST(GltfSamples, AnimatedTriangleRotationIsTheSlerpOfItsKeys) {
  const SceneAsset scene = loadSample("AnimatedTriangle.gltf");
  ASSERT_EQ(scene.animations.size(), 1u);
  ASSERT_EQ(scene.animations[0].channels.size(), 1u);
  const AnimationChannel& channel = scene.animations[0].channels[0];
  EXPECT_EQ(channel.path, AnimationPath::Rotation);
  EXPECT_EQ(channel.interpolation, Interpolation::Linear);
  ASSERT_EQ(channel.times.size(), 5u);
  EXPECT_FLOAT_EQ(scene.animations[0].duration, 1.0f);

  for (float t : {0.0f, 0.1f, 0.25f, 0.3f, 0.5f, 0.6f, 0.75f, 0.9f, 1.0f, 1.5f}) {
    SCOPED_TRACE(t);
    // Consecutive keys are 90 degrees apart, so the slerp turns uniformly: angle = 360 t
    // (clamped at 1 s). Compare rotated vectors: q and -q are the same rotation.
    const float angle = glm::radians(360.0f * std::min(t, 1.0f));
    const glm::vec3 expectedX(std::cos(angle), std::sin(angle), 0.0f);
    const std::vector<LocalTransform> pose = animate(scene, t);
    const glm::vec3 x = pose[0].rotation * glm::vec3(1, 0, 0);
    EXPECT_NEAR(glm::length(x - expectedX), 0.0f, 2e-4f);
    EXPECT_NEAR(glm::length(pose[0].rotation), 1.0f, 1e-5f);
  }
}

TEST(GltfSamples, BoxAnimatedHasTwoChannelsOfDifferentLengths) {
  const SceneAsset scene = loadSample("BoxAnimated.gltf");
  EXPECT_EQ(scene.meshes.size(), 2u);
  EXPECT_EQ(scene.materials.size(), 2u);
  EXPECT_EQ(scene.materials[0].metallicFactor, 0.0f);
  ASSERT_EQ(scene.animations.size(), 1u);
  ASSERT_EQ(scene.animations[0].channels.size(), 2u);
  EXPECT_EQ(scene.animations[0].channels[0].node, 2u);
  EXPECT_EQ(scene.animations[0].channels[0].path, AnimationPath::Rotation);
  EXPECT_EQ(scene.animations[0].channels[0].times.size(), 2u);
  EXPECT_EQ(scene.animations[0].channels[1].node, 0u);
  EXPECT_EQ(scene.animations[0].channels[1].path, AnimationPath::Translation);
  EXPECT_EQ(scene.animations[0].channels[1].times.size(), 4u);
  EXPECT_NEAR(scene.animations[0].duration, 3.708f, 1e-3f);
  // Node 2 hangs under node 1 under node 0.
  EXPECT_EQ(scene.nodes[2].parent, 1);
  EXPECT_EQ(scene.nodes[1].parent, 0);
}

TEST(GltfSamples, SimpleMorphKeepsItsTargetsAndWeightsChannel) {
  const SceneAsset scene = loadSample("SimpleMorph.gltf");
  EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
  ASSERT_EQ(scene.animations.size(), 1u);
  ASSERT_EQ(scene.animations[0].channels.size(), 1u);
  EXPECT_EQ(scene.animations[0].channels[0].path, AnimationPath::Weights);
  EXPECT_EQ(scene.animations[0].channels[0].weightCount, 2u);
  ASSERT_EQ(scene.meshes[0].deform.targets.size(), 2u);
  EXPECT_EQ(scene.meshes[0].deform.defaultWeights, (std::vector<float>{0.5f, 0.5f}));
  // The mesh's own vertices are at its default weights: the apex (0.5, 0.5, 0) moved by
  // 0.5 * (-1, 1, 0) + 0.5 * (1, 1, 0) (targets from the file).
  float top = 0.0f;
  for (const glm::vec3& p : scene.meshes[0].positions) top = std::max(top, p.y);
  EXPECT_NEAR(top, 1.5f, 1e-6f);
  // The bounds are the pose at t = 0, where the animation's weights are (0, 0).
  EXPECT_NEAR(scene.bounds.max.y, 0.5f, 1e-6f);
}

}  // namespace
}  // namespace qlight::gltf
