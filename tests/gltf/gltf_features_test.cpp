// glTF features the Khronos samples do not cover, each in a file written by the test:
// interleaved vertices, normalized integer UVs, every index type, strips and fans, sparse
// accessors, GLB and external buffers, punctual lights, emissive strength, several
// primitives per mesh, scene choice.
#include <fstream>
#include <glm/gtc/quaternion.hpp>

#include "engine/scene/transforms.h"
#include "tests/gltf/gltf_test_files.h"

namespace qlight::gltf {
namespace {

using testing::Bytes;
using testing::json;
using testing::TempDir;
using testing::triangleDoc;
using testing::writeDoc;

// A unit square in the xy plane as 4 vertices interleaved with normalized USHORT uvs:
// stride 16 = float3 position (12) + ushort2 uv (4).
TEST(GltfFeatures, InterleavedVerticesWithNormalizedShortUvs) {
  TempDir dir;
  Bytes b;
  const float positions[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const uint16_t uvs[4][2] = {{0, 0}, {65535, 0}, {65535, 32768}, {0, 65535}};
  for (int i = 0; i < 4; ++i) {
    b.add<float>({positions[i][0], positions[i][1], positions[i][2]});
    b.add<uint16_t>({uvs[i][0], uvs[i][1]});
  }
  b.add<uint8_t>({0, 1, 2, 0, 2, 3}).pad4();  // UNSIGNED_BYTE indices at 64
  json doc = triangleDoc();
  testing::setBuffer(doc, b.data);
  doc["bufferViews"] =
      json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 64}, {"byteStride", 16}},
                   {{"buffer", 0}, {"byteOffset", 64}, {"byteLength", 6}}});
  doc["accessors"] =
      json::array({{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
                   {{"bufferView", 1}, {"componentType", 5121}, {"count", 6}, {"type", "SCALAR"}},
                   {{"bufferView", 0},
                    {"byteOffset", 12},
                    {"componentType", 5123},
                    {"normalized", true},
                    {"count", 4},
                    {"type", "VEC2"}}});
  doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 2;
  const SceneAsset scene = loadGltf(writeDoc(dir, "interleaved.gltf", doc));
  const MeshAsset& mesh = scene.meshes[0];
  ASSERT_EQ(mesh.triangleCount(), 2u);
  // Flat normals: un-indexed, 6 vertices; triangle 1 is vertices 0, 2, 3.
  ASSERT_EQ(mesh.positions.size(), 6u);
  EXPECT_EQ(mesh.positions[4], glm::vec3(1, 1, 0));
  EXPECT_EQ(mesh.positions[5], glm::vec3(0, 1, 0));
  EXPECT_EQ(mesh.uv0[1], glm::vec2(1.0f, 0.0f));
  EXPECT_FLOAT_EQ(mesh.uv0[2].y, 32768.0f / 65535.0f);
  EXPECT_EQ(mesh.uv0[5], glm::vec2(0.0f, 1.0f));
  for (const glm::vec3& n : mesh.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

TEST(GltfFeatures, NormalizedByteUvs) {
  TempDir dir;
  json doc = triangleDoc();
  Bytes b;
  b.data = testing::triangleBytes();
  b.add<uint8_t>({0, 0, 255, 0, 51, 255}).pad4();  // at 44
  testing::setBuffer(doc, b.data);
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 44}, {"byteLength", 6}});
  doc["accessors"].push_back({{"bufferView", 2},
                              {"componentType", 5121},
                              {"normalized", true},
                              {"count", 3},
                              {"type", "VEC2"}});
  doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 2;
  const SceneAsset scene = loadGltf(writeDoc(dir, "uv8.gltf", doc));
  EXPECT_EQ(scene.meshes[0].uv0[1], glm::vec2(1.0f, 0.0f));
  EXPECT_FLOAT_EQ(scene.meshes[0].uv0[2].x, 0.2f);
  EXPECT_EQ(scene.meshes[0].uv0[2].y, 1.0f);

  // Integer UVs that are not normalized are not glTF.
  doc["accessors"][2]["normalized"] = false;
  testing::expectLoadError(writeDoc(dir, "uv8.gltf", doc), "must be FLOAT or a normalized integer");
}

TEST(GltfFeatures, EveryIndexComponentType) {
  TempDir dir;
  for (int type : {5121, 5123, 5125}) {
    SCOPED_TRACE(type);
    Bytes b;
    b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0});
    if (type == 5121) b.add<uint8_t>({2, 0, 1});
    if (type == 5123) b.add<uint16_t>({2, 0, 1});
    if (type == 5125) b.add<uint32_t>({2, 0, 1});
    const size_t indexBytes = b.data.size() - 36;
    b.pad4();
    json doc = triangleDoc();
    testing::setBuffer(doc, b.data);
    doc["bufferViews"][1]["byteLength"] = indexBytes;
    doc["accessors"][1]["componentType"] = type;
    // With normals given, the mesh stays indexed and the indices come through as written.
    Bytes normals;
    normals.add<float>({0, 0, 1, 0, 0, 1, 0, 0, 1});
    std::vector<uint8_t> all = b.data;
    all.insert(all.end(), normals.data.begin(), normals.data.end());
    testing::setBuffer(doc, all);
    doc["bufferViews"].push_back(
        {{"buffer", 0}, {"byteOffset", b.data.size()}, {"byteLength", 36}});
    doc["accessors"].push_back(
        {{"bufferView", 2}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}});
    doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 2;
    const SceneAsset scene = loadGltf(writeDoc(dir, "indices.gltf", doc));
    EXPECT_EQ(scene.meshes[0].indices, (std::vector<uint32_t>{2, 0, 1}));
  }
}

// Five vertices along a zig-zag in the xy plane; as a strip or a fan, every triangle must
// keep the counter-clockwise (+z) winding.
json polygonDoc(int mode, const std::vector<float>& positions) {
  Bytes b;
  for (float p : positions) b.add<float>({p});
  json doc = triangleDoc();
  testing::setBuffer(doc, b.data);
  doc["bufferViews"] = json::array({{{"buffer", 0}, {"byteLength", b.data.size()}}});
  doc["accessors"] = json::array({{{"bufferView", 0},
                                   {"componentType", 5126},
                                   {"count", positions.size() / 3},
                                   {"type", "VEC3"}}});
  doc["meshes"][0]["primitives"][0].erase("indices");
  doc["meshes"][0]["primitives"][0]["mode"] = mode;
  return doc;
}

TEST(GltfFeatures, TriangleStripsAndFansBecomeListsWithTheirWinding) {
  TempDir dir;
  // Strip: 0 (0,0) 1 (1,0) 2 (0,1) 3 (1,1) 4 (0,2) -> triangles 012, 213 (as 1 3 2), 234.
  const SceneAsset strip = loadGltf(
      writeDoc(dir, "strip.gltf", polygonDoc(5, {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 2, 0})));
  EXPECT_EQ(strip.meshes[0].triangleCount(), 3u);
  for (const glm::vec3& n : strip.meshes[0].normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));

  // Fan around (0,0): (1,0) (1,1) (0,1) (-1,1) -> 3 triangles.
  const SceneAsset fan = loadGltf(
      writeDoc(dir, "fan.gltf", polygonDoc(6, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, -1, 1, 0})));
  EXPECT_EQ(fan.meshes[0].triangleCount(), 3u);
  for (const glm::vec3& n : fan.meshes[0].normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

TEST(GltfFeatures, SparseAccessorReplacesValues) {
  TempDir dir;
  json doc = testing::sparseTriangleDoc(2, {0.0f, 3.0f, 0.0f});  // a new position of vertex 2
  const SceneAsset scene = loadGltf(writeDoc(dir, "sparse.gltf", doc));
  EXPECT_EQ(scene.meshes[0].positions[2], glm::vec3(0, 3, 0));
  EXPECT_EQ(scene.bounds.max.y, 3.0f);
}

TEST(GltfFeatures, GlbAndExternalBuffers) {
  TempDir dir;
  const std::vector<uint8_t> glb = testing::makeGlb(triangleDoc(), testing::triangleBytes());
  testing::writeBytes(dir / "triangle.glb", glb.data(), glb.size());
  EXPECT_EQ(loadGltf(dir / "triangle.glb").meshes[0].triangleCount(), 1u);

  json doc = triangleDoc();
  doc["buffers"][0]["uri"] = "tri%20angle.bin";  // URIs are percent-encoded
  const std::vector<uint8_t> bytes = testing::triangleBytes();
  testing::writeBytes(dir / "tri angle.bin", bytes.data(), bytes.size());
  EXPECT_EQ(loadGltf(writeDoc(dir, "external.gltf", doc)).meshes[0].triangleCount(), 1u);
}

TEST(GltfFeatures, PunctualLightsAndEmissiveStrength) {
  TempDir dir;
  json doc = triangleDoc();
  doc["extensionsUsed"] = {"KHR_lights_punctual", "KHR_materials_emissive_strength",
                           "KHR_materials_specular"};
  doc["extensions"]["KHR_lights_punctual"]["lights"] =
      json::array({{{"type", "point"}, {"color", {1, 0.5, 0.25}}, {"intensity", 20}, {"range", 5}},
                   {{"type", "spot"}, {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.6}}}},
                   {{"type", "directional"}, {"intensity", 3}}});
  doc["nodes"] = json::array({{{"mesh", 0}},
                              {{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}},
                              {{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}},
                              {{"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}}});
  doc["scenes"][0]["nodes"] = {0, 1, 2, 3};
  doc["materials"] = json::array(
      {{{"emissiveFactor", {1.0, 0.5, 0.0}},
        {"extensions",
         {{"KHR_materials_emissive_strength", {{"emissiveStrength", 8.0}}},
          {"KHR_materials_specular", {{"specularFactor", 0.25}}}}},
        {"doubleSided", true},
        {"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 0.5}}}}});
  doc["meshes"][0]["primitives"][0]["material"] = 0;
  const SceneAsset scene = loadGltf(writeDoc(dir, "lights.gltf", doc));

  ASSERT_EQ(scene.lights.size(), 3u);
  EXPECT_EQ(scene.lights[0].type, LightType::Point);
  EXPECT_EQ(scene.lights[0].color, glm::vec3(1, 0.5, 0.25));
  EXPECT_EQ(scene.lights[0].intensity, 20.0f);
  EXPECT_EQ(scene.lights[0].range, 5.0f);
  EXPECT_EQ(scene.lights[1].type, LightType::Spot);
  EXPECT_FLOAT_EQ(scene.lights[1].innerConeAngle, 0.2f);
  EXPECT_FLOAT_EQ(scene.lights[1].outerConeAngle, 0.6f);
  EXPECT_EQ(scene.lights[2].type, LightType::Directional);
  EXPECT_EQ(scene.nodes[1].light, 0);
  EXPECT_EQ(scene.nodes[3].light, 2);

  ASSERT_EQ(scene.materials.size(), 1u);
  const MaterialAsset& m = scene.materials[0];
  EXPECT_EQ(m.emissive, glm::vec3(8.0f, 4.0f, 0.0f));  // factor x strength
  EXPECT_TRUE(m.doubleSided);
  EXPECT_EQ(m.specularFactor, 0.25f);
  EXPECT_EQ(m.metallicFactor, 0.0f);
  EXPECT_EQ(m.roughnessFactor, 0.5f);
  EXPECT_TRUE(scene.warnings.empty());
}

TEST(GltfFeatures, PrimitivesConcatenateWithTheirMaterials) {
  TempDir dir;
  json doc = triangleDoc();
  json first = doc["meshes"][0]["primitives"][0];
  json second = first;
  first["material"] = 1;
  second.erase("material");  // default material
  doc["meshes"][0]["primitives"] = {first, second};
  doc["materials"] = json::array({{{"name", "a"}}, {{"name", "b"}}});
  const SceneAsset scene = loadGltf(writeDoc(dir, "two.gltf", doc));
  const MeshAsset& mesh = scene.meshes[0];
  ASSERT_EQ(mesh.triangleCount(), 2u);
  ASSERT_EQ(scene.materials.size(), 3u);  // a, b, default
  EXPECT_EQ(scene.defaultMaterial, 2);
  EXPECT_EQ(mesh.triangleMaterials, (std::vector<uint32_t>{1, 2}));
  // The second primitive's vertices follow the first's (flat normals: 3 each).
  EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
}

TEST(GltfFeatures, SceneChoiceAndMatrixNodes) {
  TempDir dir;
  json doc = triangleDoc();
  // Node 1: translate (1,2,3) * rotate 90 degrees about z * scale 2, as a matrix.
  doc["nodes"] =
      json::array({{{"mesh", 0}},
                   {{"mesh", 0}, {"matrix", {0, 2, 0, 0, -2, 0, 0, 0, 0, 0, 2, 0, 1, 2, 3, 1}}}});
  doc["scenes"] = json::array({{{"nodes", {0}}}, {{"nodes", {1}}}});
  doc["scene"] = 1;
  const SceneAsset scene = loadGltf(writeDoc(dir, "scenes.gltf", doc));
  EXPECT_EQ(scene.rootNodes, (std::vector<uint32_t>{1}));
  const LocalTransform& local = scene.nodes[1].local;
  EXPECT_NEAR(glm::length(local.translation - glm::vec3(1, 2, 3)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(local.scale - glm::vec3(2)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(local.rotation * glm::vec3(1, 0, 0) - glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
  // Bounds cover only scene 1: the triangle (0,0)(1,0)(0,1) mapped to (1,2)(1,4)(-1,2).
  EXPECT_NEAR(scene.bounds.min.x, -1.0f, 1e-5f);
  EXPECT_NEAR(scene.bounds.max.y, 4.0f, 1e-5f);
  EXPECT_NEAR(scene.bounds.min.z, 3.0f, 1e-5f);
}

// A file without scenes (a glTF "library") shows every parentless node, with a warning.
TEST(GltfFeatures, NoSceneShowsEveryRootNodeWithAWarning) {
  TempDir dir;
  json doc = triangleDoc();
  doc["nodes"] = json::array({{{"mesh", 0}, {"children", {2}}}, {{"mesh", 0}}, {{"mesh", 0}}});
  doc.erase("scenes");
  doc.erase("scene");
  const SceneAsset scene = loadGltf(writeDoc(dir, "noscene.gltf", doc));
  EXPECT_EQ(scene.rootNodes, (std::vector<uint32_t>{0, 1}));
  bool warned = false;
  for (const std::string& w : scene.warnings)
    warned = warned || w.find("defines no scene: showing all 2 root nodes") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(GltfFeatures, UnreadableImagesBecomeWhiteTexturesWithAWarning) {
  TempDir dir;
  std::ifstream in(std::filesystem::path(QLIGHT_SAMPLES_DIR) / "BoxTextured.gltf");
  json doc = json::parse(in);
  doc["images"][0] = {{"uri", "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAAB"}};
  const SceneAsset corrupt = loadGltf(writeDoc(dir, "corrupt.gltf", doc));
  ASSERT_EQ(corrupt.textures.size(), 1u);
  EXPECT_EQ(corrupt.textures[0].width, 1u);
  EXPECT_EQ(corrupt.textures[0].rgba8, (std::vector<uint8_t>{255, 255, 255, 255}));
  EXPECT_FALSE(corrupt.warnings.empty());

  doc["images"][0] = {{"uri", "missing.png"}};
  const SceneAsset missing = loadGltf(writeDoc(dir, "missing.gltf", doc));
  EXPECT_EQ(missing.textures[0].width, 1u);
  EXPECT_FALSE(missing.warnings.empty());
}

}  // namespace
}  // namespace qlight::gltf
