// Broken files: each one throws a one-line std::runtime_error naming the file and the
// problem, and none crashes or hangs. Things the loader can do without are warnings.
#include <limits>

#include "tests/gltf/gltf_test_files.h"

namespace qlight::gltf {
namespace {

using testing::Bytes;
using testing::expectLoadError;
using testing::json;
using testing::TempDir;
using testing::triangleDoc;
using testing::writeDoc;

TEST(GltfBadInput, TheReferenceTriangleLoads) {
  // Every case below breaks this valid document in one place.
  TempDir dir;
  const SceneAsset scene = loadGltf(writeDoc(dir, "good.gltf", triangleDoc()));
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].triangleCount(), 1u);
  EXPECT_TRUE(scene.warnings.empty());
}

TEST(GltfBadInput, MissingFile) {
  TempDir dir;
  expectLoadError(dir / "nowhere.gltf", "file not found");
}

TEST(GltfBadInput, DirectoryAndEmptyFile) {
  TempDir dir;
  std::filesystem::create_directories(dir / "folder.gltf");
  expectLoadError(dir / "folder.gltf", "not a regular file");
  testing::writeText(dir / "empty.gltf", "");
  expectLoadError(dir / "empty.gltf", "file is empty");
}

TEST(GltfBadInput, MalformedJson) {
  TempDir dir;
  testing::writeText(dir / "broken.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [");
  expectLoadError(dir / "broken.gltf", "malformed JSON");
  testing::writeText(dir / "array.gltf", "[1, 2, 3]");
  expectLoadError(dir / "array.gltf", "top level is not an object");
  testing::writeText(dir / "noasset.gltf", "{\"nodes\": []}");
  expectLoadError(dir / "noasset.gltf", "no \"asset\"");
}

TEST(GltfBadInput, MissingExternalBuffer) {
  TempDir dir;
  json doc = triangleDoc();
  doc["buffers"][0]["uri"] = "geometry.bin";
  expectLoadError(writeDoc(dir, "scene.gltf", doc), "buffer 0 file 'geometry.bin' is missing");
}

TEST(GltfBadInput, TruncatedExternalBuffer) {
  TempDir dir;
  json doc = triangleDoc();
  doc["buffers"][0]["uri"] = "geometry.bin";
  const std::vector<uint8_t> bytes = testing::triangleBytes();
  testing::writeBytes(dir / "geometry.bin", bytes.data(), 20);
  expectLoadError(writeDoc(dir, "scene.gltf", doc), "buffer 0 file 'geometry.bin' is truncated");
}

TEST(GltfBadInput, TruncatedDataUri) {
  TempDir dir;
  json doc = triangleDoc();
  std::vector<uint8_t> bytes = testing::triangleBytes();
  bytes.resize(24);
  doc["buffers"][0]["uri"] = testing::dataUri(bytes);  // byteLength still says 44
  expectLoadError(writeDoc(dir, "scene.gltf", doc), "buffer 0 is truncated");
}

TEST(GltfBadInput, BufferViewPastTheEndOfItsBuffer) {
  TempDir dir;
  json doc = triangleDoc();
  doc["bufferViews"][1]["byteLength"] = 40;  // 36 + 40 > 44
  expectLoadError(writeDoc(dir, "scene.gltf", doc), "buffer view 1 reads past the end of buffer 0");
  doc = triangleDoc();
  doc["bufferViews"][0]["buffer"] = 3;
  expectLoadError(writeDoc(dir, "scene.gltf", doc), "refers to buffer 3, which does not exist");
}

TEST(GltfBadInput, AccessorPastTheEndOfItsBufferView) {
  TempDir dir;
  json doc = triangleDoc();
  doc["accessors"][0]["count"] = 4;  // 48 bytes from a 36-byte view
  expectLoadError(writeDoc(dir, "scene.gltf", doc),
                  "accessor 0 reads past the end of buffer view 0");
  doc = triangleDoc();
  doc["accessors"][1]["byteOffset"] = 2;  // 2 + 6 > 6
  expectLoadError(writeDoc(dir, "scene.gltf", doc),
                  "accessor 1 reads past the end of buffer view 1");
  doc = triangleDoc();
  doc["accessors"][0]["count"] = 4000000000u;  // would wrap 32-bit size arithmetic
  expectLoadError(writeDoc(dir, "scene.gltf", doc), "accessor 0");
}

TEST(GltfBadInput, ByteStrideSmallerThanTheElement) {
  TempDir dir;
  json doc = triangleDoc();
  doc["bufferViews"][0]["byteStride"] = 8;  // VEC3 float needs 12
  expectLoadError(writeDoc(dir, "scene.gltf", doc), "larger than the byteStride 8");
}

TEST(GltfBadInput, AccessorIndexOutOfRange) {
  TempDir dir;
  json doc = triangleDoc();
  doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 7;
  expectLoadError(writeDoc(dir, "scene.gltf", doc), "accessor 7 does not exist");
}

TEST(GltfBadInput, IndexValueOutOfRange) {
  TempDir dir;
  json doc = triangleDoc();
  Bytes b;
  b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0});
  b.add<uint16_t>({0, 1, 7}).pad4();
  testing::setBuffer(doc, b.data);
  expectLoadError(writeDoc(dir, "scene.gltf", doc),
                  "mesh 0 primitive 0 index 7 at position 2 is out of range (3 vertices)");
}

TEST(GltfBadInput, ReferencesToMissingObjects) {
  TempDir dir;
  json doc = triangleDoc();
  doc["meshes"][0]["primitives"][0]["material"] = 2;
  expectLoadError(writeDoc(dir, "scene.gltf", doc), "uses material 2, which does not exist");
  doc = triangleDoc();
  doc["nodes"][0]["mesh"] = 5;
  expectLoadError(writeDoc(dir, "scene.gltf", doc), "node 0 uses mesh 5, which does not exist");
  doc = triangleDoc();
  doc["nodes"][0]["children"] = {9};
  expectLoadError(writeDoc(dir, "scene.gltf", doc), "node 0 has child 9, which does not exist");
  doc = triangleDoc();
  doc["scenes"][0]["nodes"] = {4};
  expectLoadError(writeDoc(dir, "scene.gltf", doc), "scene 0 uses node 4, which does not exist");
}

TEST(GltfBadInput, UnknownRequiredExtension) {
  TempDir dir;
  json doc = triangleDoc();
  doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  expectLoadError(writeDoc(dir, "scene.gltf", doc),
                  "requires unsupported extension KHR_draco_mesh_compression");
  // The supported ones may be required.
  doc["extensionsUsed"] = {"KHR_lights_punctual", "KHR_materials_emissive_strength"};
  doc["extensionsRequired"] = {"KHR_lights_punctual", "KHR_materials_emissive_strength"};
  EXPECT_NO_THROW(loadGltf(writeDoc(dir, "scene.gltf", doc)));
}

TEST(GltfBadInput, PointsAndLinesAreSkippedWithAWarning) {
  TempDir dir;
  json doc = triangleDoc();
  json triangles = doc["meshes"][0]["primitives"][0];
  json points = triangles, lines = triangles;
  points["mode"] = 0;
  lines["mode"] = 1;
  lines.erase("indices");
  lines["attributes"]["POSITION"] = 0;
  doc["meshes"][0]["primitives"] = {points, triangles, lines};
  const SceneAsset scene = loadGltf(writeDoc(dir, "scene.gltf", doc));
  EXPECT_EQ(scene.meshes[0].triangleCount(), 1u);  // only the triangle primitive
  bool pointsWarned = false, linesWarned = false;
  for (const std::string& w : scene.warnings) {
    EXPECT_NE(w.find("scene.gltf"), std::string::npos);
    pointsWarned = pointsWarned ||
                   w.find("primitive 0 is POINTS, not triangles; skipped") != std::string::npos;
    linesWarned =
        linesWarned || w.find("primitive 2 is LINES, not triangles; skipped") != std::string::npos;
  }
  EXPECT_TRUE(pointsWarned);
  EXPECT_TRUE(linesWarned);
}

TEST(GltfBadInput, NanInAnAccessor) {
  TempDir dir;
  json doc = triangleDoc();
  Bytes b;
  b.add<float>({0, 0, 0, 1, std::numeric_limits<float>::quiet_NaN(), 0, 0, 1, 0});
  b.add<uint16_t>({0, 1, 2}).pad4();
  testing::setBuffer(doc, b.data);
  expectLoadError(writeDoc(dir, "scene.gltf", doc),
                  "accessor 0 holds a non-finite value (NaN or Inf) at element 1");
}

TEST(GltfBadInput, InfinityInAFactorOrTransform) {
  // JSON has no Inf: a number beyond double's range is how a file spells it.
  TempDir dir;
  json doc = triangleDoc();
  doc["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 1}}}}}});
  std::string text = doc.dump();
  text.replace(text.find("[1,1,1,1]"), 9, "[1e999,1,1,1]");
  testing::writeText(dir / "factor.gltf", text);
  expectLoadError(dir / "factor.gltf", "not finite");

  doc = triangleDoc();
  doc["nodes"][0]["translation"] = {0, 0, 0};
  text = doc.dump();
  text.replace(text.find("[0,0,0]"), 7, "[0,-1e400,0]");
  testing::writeText(dir / "node.gltf", text);
  expectLoadError(dir / "node.gltf", "not finite");
}

TEST(GltfBadInput, NanInAnAnimation) {
  TempDir dir;
  json doc = triangleDoc();
  Bytes b;
  b.data = testing::triangleBytes();                                      // 44 bytes
  b.add<float>({0.0f, 1.0f});                                             // times at 44
  b.add<float>({0, 0, 0, std::numeric_limits<float>::infinity(), 0, 0});  // translations at 52
  testing::setBuffer(doc, b.data);
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 44}, {"byteLength", 8}});
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 52}, {"byteLength", 24}});
  doc["accessors"].push_back({{"bufferView", 2},
                              {"componentType", 5126},
                              {"count", 2},
                              {"type", "SCALAR"},
                              {"min", {0}},
                              {"max", {1}}});
  doc["accessors"].push_back(
      {{"bufferView", 3}, {"componentType", 5126}, {"count", 2}, {"type", "VEC3"}});
  doc["animations"] = json::array(
      {{{"samplers", json::array({{{"input", 2}, {"output", 3}}})},
        {"channels",
         json::array({{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}})}}});
  const auto path = writeDoc(dir, "scene.gltf", doc);
  expectLoadError(path, "accessor 3 holds a non-finite value (NaN or Inf) at element 1");
}

TEST(GltfBadInput, AnimationKeyTimesMustIncrease) {
  TempDir dir;
  json doc = triangleDoc();
  Bytes b;
  b.data = testing::triangleBytes();
  b.add<float>({1.0f, 0.5f});
  b.add<float>({0, 0, 0, 1, 0, 0});
  testing::setBuffer(doc, b.data);
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 44}, {"byteLength", 8}});
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 52}, {"byteLength", 24}});
  doc["accessors"].push_back(
      {{"bufferView", 2}, {"componentType", 5126}, {"count", 2}, {"type", "SCALAR"}});
  doc["accessors"].push_back(
      {{"bufferView", 3}, {"componentType", 5126}, {"count", 2}, {"type", "VEC3"}});
  doc["animations"] = json::array(
      {{{"samplers", json::array({{{"input", 2}, {"output", 3}, {"interpolation", "STEP"}}})},
        {"channels",
         json::array({{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}})}}});
  expectLoadError(writeDoc(dir, "scene.gltf", doc),
                  "animation 0 sampler 0 key times are not strictly increasing");
}

TEST(GltfBadInput, HierarchyCyclesAndSharedChildren) {
  TempDir dir;
  json doc = triangleDoc();
  doc["nodes"] = json::array({{{"mesh", 0}}, {{"children", {2}}}, {{"children", {1}}}});
  expectLoadError(writeDoc(dir, "scene.gltf", doc), "node hierarchy has a cycle through node 1");
  doc["nodes"] = json::array({{{"mesh", 0}, {"children", {0}}}});
  expectLoadError(writeDoc(dir, "scene.gltf", doc), "cycle through node 0");
  doc["nodes"] = json::array({{{"children", {2}}}, {{"children", {2}}}, {{"mesh", 0}}});
  doc["scenes"][0]["nodes"] = {0, 1};
  expectLoadError(writeDoc(dir, "scene.gltf", doc), "node 2 has two parents (0 and 1)");
}

TEST(GltfBadInput, WrongAccessorTypes) {
  TempDir dir;
  json doc = triangleDoc();
  doc["accessors"][0]["type"] = "VEC2";
  expectLoadError(writeDoc(dir, "scene.gltf", doc), "POSITION: accessor 0 must be VEC3");
  doc = triangleDoc();
  doc["accessors"][1]["componentType"] = 5122;  // signed SHORT indices
  expectLoadError(writeDoc(dir, "scene.gltf", doc),
                  "indices: accessor 1 (indices) must be UNSIGNED");
}

TEST(GltfBadInput, SparseIndexOutOfRange) {
  TempDir dir;
  json doc = testing::sparseTriangleDoc(5, {2, 2, 2});  // index 5 of 3 elements
  expectLoadError(writeDoc(dir, "scene.gltf", doc), "accessor 0 sparse index 5 is out of range");
}

TEST(GltfBadInput, TruncatedAndMalformedGlb) {
  TempDir dir;
  const std::vector<uint8_t> glb = testing::makeGlb(triangleDoc(), testing::triangleBytes());
  testing::writeBytes(dir / "whole.glb", glb.data(), glb.size());
  EXPECT_NO_THROW(loadGltf(dir / "whole.glb"));

  testing::writeBytes(dir / "cut.glb", glb.data(), glb.size() - 10);
  expectLoadError(dir / "cut.glb", "truncated");
  testing::writeBytes(dir / "header.glb", glb.data(), 10);
  expectLoadError(dir / "header.glb", "GLB file is truncated");

  std::vector<uint8_t> v1 = glb;
  v1[4] = 1;
  testing::writeBytes(dir / "v1.glb", v1.data(), v1.size());
  expectLoadError(dir / "v1.glb", "GLB version 1 is not supported");

  std::vector<uint8_t> hugeJson = glb;
  hugeJson[12] = 0xff;
  hugeJson[13] = 0xff;
  hugeJson[14] = 0xff;
  testing::writeBytes(dir / "json.glb", hugeJson.data(), hugeJson.size());
  expectLoadError(dir / "json.glb", "GLB JSON chunk runs past the end of the file");

  // A BIN chunk shorter than the buffer's byteLength.
  json doc = triangleDoc();
  std::vector<uint8_t> shortBin = testing::makeGlb(doc, std::vector<uint8_t>(20, 0));
  // makeGlb sets byteLength to 20; claim 44 instead by rewriting the JSON.
  doc["buffers"] = json::array({{{"byteLength", 44}}});
  std::string text = doc.dump();
  while (text.size() % 4 != 0) text += ' ';
  Bytes out;
  out.add<uint32_t>({0x46546C67u, 2u, uint32_t(12 + 8 + text.size() + 8 + 20),
                     uint32_t(text.size()), 0x4E4F534Au});
  out.data.insert(out.data.end(), text.begin(), text.end());
  out.add<uint32_t>({20u, 0x004E4942u});
  out.data.resize(out.data.size() + 20, 0);
  testing::writeBytes(dir / "shortbin.glb", out.data.data(), out.data.size());
  expectLoadError(dir / "shortbin.glb",
                  "buffer 0 is truncated: the GLB BIN chunk has 20 of its 44 bytes");
}

TEST(GltfBadInput, BadCameraAndLightValues) {
  TempDir dir;
  json doc = triangleDoc();
  doc["cameras"] =
      json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.0}, {"znear", 0.1}}}}});
  doc["nodes"][0]["camera"] = 0;
  expectLoadError(writeDoc(dir, "scene.gltf", doc), "camera 0 yfov must be in (0, pi)");

  doc = triangleDoc();
  doc["extensionsUsed"] = {"KHR_lights_punctual"};
  doc["extensions"]["KHR_lights_punctual"]["lights"] = json::array({{{"type", "area"}}});
  expectLoadError(writeDoc(dir, "scene.gltf", doc), "light 0 type 'area'");

  doc = triangleDoc();
  doc["extensionsUsed"] = {"KHR_lights_punctual"};
  doc["extensions"]["KHR_lights_punctual"]["lights"] = json::array({{{"type", "point"}}});
  doc["nodes"][0]["extensions"]["KHR_lights_punctual"] = {{"light", 3}};
  expectLoadError(writeDoc(dir, "scene.gltf", doc), "node 0 uses light 3, which does not exist");
}

}  // namespace
}  // namespace qlight::gltf

namespace qlight::gltf {
namespace {

// Material extensions with values of the wrong type: one line naming the material, the
// extension and the key.
TEST(GltfBadInput, MalformedMaterialExtensionsAreOneLineErrors) {
  TempDir dir;
  auto withMaterial = [](json material) {
    json doc = testing::triangleDoc();
    doc["textures"] = json::array({json::object()});  // no image: white, with a warning
    doc["materials"] = json::array({material});
    doc["meshes"][0]["primitives"][0]["material"] = 0;
    return doc;
  };
  auto transformed = [&](json transform) {
    return withMaterial(
        {{"pbrMetallicRoughness",
          {{"baseColorTexture",
            {{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}}}}}});
  };
  expectLoadError(writeDoc(dir, "offset.gltf", transformed({{"offset", "abc"}})),
                  "material 0 baseColorTexture KHR_texture_transform offset needs 2 numbers");
  expectLoadError(writeDoc(dir, "scale.gltf", transformed({{"scale", {1}}})),
                  "KHR_texture_transform scale needs 2 numbers");
  expectLoadError(writeDoc(dir, "rotation.gltf", transformed({{"rotation", "half"}})),
                  "KHR_texture_transform rotation is not a number");
  expectLoadError(
      writeDoc(dir, "transmission.gltf",
               withMaterial({{"extensions",
                              {{"KHR_materials_transmission", {{"transmissionFactor", "x"}}}}}})),
      "material 0 transmissionFactor is not a number");
  // An ior below 1 is a documented fallback (1.5, with a warning), not an error.
  const SceneAsset scene = loadGltf(writeDoc(
      dir, "ior.gltf", withMaterial({{"extensions", {{"KHR_materials_ior", {{"ior", 0.5}}}}}})));
  EXPECT_FLOAT_EQ(scene.materials[0].ior, 1.5f);
  EXPECT_FALSE(scene.warnings.empty());
}

}  // namespace
}  // namespace qlight::gltf
