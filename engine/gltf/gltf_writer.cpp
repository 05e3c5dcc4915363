#include "engine/gltf/gltf_writer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace qlight::gltf {
namespace {

using nlohmann::json;

constexpr int kFloat = 5126, kUnsignedShort = 5123, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

// One binary buffer with its buffer views and accessors.
class BufferBuilder {
 public:
  int addView(const void* data, size_t size, int target) {
    while (bytes_.size() % 4 != 0) bytes_.push_back(0);
    json view = {{"buffer", 0}, {"byteOffset", bytes_.size()}, {"byteLength", size}};
    if (target != 0) view["target"] = target;
    const auto* p = static_cast<const uint8_t*>(data);
    bytes_.insert(bytes_.end(), p, p + size);
    views_.push_back(view);
    return int(views_.size() - 1);
  }

  int addAccessor(int view, size_t byteOffset, int componentType, size_t count, const char* type,
                  json min = nullptr, json max = nullptr) {
    json accessor = {
        {"bufferView", view}, {"componentType", componentType}, {"count", count}, {"type", type}};
    if (byteOffset != 0) accessor["byteOffset"] = byteOffset;
    if (!min.is_null()) accessor["min"] = min;
    if (!max.is_null()) accessor["max"] = max;
    accessors_.push_back(accessor);
    return int(accessors_.size() - 1);
  }

  template <typename T>
  int addFloats(const std::vector<T>& values, const char* type, int target, bool withBounds) {
    constexpr int n = sizeof(T) / sizeof(float);
    json min = nullptr, max = nullptr;
    if (withBounds && !values.empty()) {
      min = json::array();
      max = json::array();
      for (int c = 0; c < n; ++c) {
        float lo = INFINITY, hi = -INFINITY;
        for (const T& v : values) {
          const float x = reinterpret_cast<const float*>(&v)[c];
          lo = std::min(lo, x);
          hi = std::max(hi, x);
        }
        min.push_back(lo);
        max.push_back(hi);
      }
    }
    const int view = addView(values.data(), values.size() * sizeof(T), target);
    return addAccessor(view, 0, kFloat, values.size(), type, min, max);
  }

  const std::vector<uint8_t>& bytes() const { return bytes_; }
  json views() const { return views_; }
  json accessors() const { return accessors_; }

 private:
  std::vector<uint8_t> bytes_;
  json views_ = json::array();
  json accessors_ = json::array();
};

json vec(glm::vec3 v) { return {v.x, v.y, v.z}; }

json writeMesh(const MeshAsset& mesh, size_t meshIndex, const std::vector<int>& materialIndex,
               BufferBuilder& buffer) {
  if (mesh.triangleCount() == 0)
    throw std::runtime_error("saveGltf: mesh " + std::to_string(meshIndex) + " has no triangles");
  json attributes = {{"POSITION", buffer.addFloats(mesh.positions, "VEC3", kArrayBuffer, true)},
                     {"NORMAL", buffer.addFloats(mesh.normals, "VEC3", kArrayBuffer, false)},
                     {"TEXCOORD_0", buffer.addFloats(mesh.uv0, "VEC2", kArrayBuffer, false)}};

  const bool shortIndices = mesh.positions.size() <= 65535;
  std::vector<uint8_t> indexBytes;
  for (uint32_t i : mesh.indices) {
    if (shortIndices) {
      const auto s = uint16_t(i);
      indexBytes.insert(indexBytes.end(), {uint8_t(s & 0xff), uint8_t(s >> 8)});
    } else {
      uint8_t b[4];
      std::memcpy(b, &i, 4);
      indexBytes.insert(indexBytes.end(), b, b + 4);
    }
  }
  const int indexView = buffer.addView(indexBytes.data(), indexBytes.size(), kElementArrayBuffer);
  const size_t indexSize = shortIndices ? 2 : 4;

  // One primitive per run of triangles with the same material.
  json primitives = json::array();
  const size_t triangles = mesh.triangleCount();
  for (size_t start = 0; start < triangles;) {
    size_t end = start + 1;
    while (end < triangles && mesh.triangleMaterials[end] == mesh.triangleMaterials[start]) ++end;
    json primitive = {{"attributes", attributes}, {"mode", 4}};
    primitive["indices"] = buffer.addAccessor(indexView, start * 3 * indexSize,
                                              shortIndices ? kUnsignedShort : kUnsignedInt,
                                              (end - start) * 3, "SCALAR");
    const int material = materialIndex.at(mesh.triangleMaterials[start]);
    if (material >= 0) primitive["material"] = material;
    primitives.push_back(primitive);
    start = end;
  }
  json out = {{"primitives", primitives}};
  if (!mesh.name.empty()) out["name"] = mesh.name;
  return out;
}

json writeMaterial(const MaterialAsset& m, bool& usesStrength, bool& usesSpecular) {
  json pbr = {
      {"baseColorFactor",
       {m.baseColorFactor.r, m.baseColorFactor.g, m.baseColorFactor.b, m.baseColorFactor.a}},
      {"metallicFactor", m.metallicFactor},
      {"roughnessFactor", m.roughnessFactor}};
  json out = {{"pbrMetallicRoughness", pbr}};
  if (!m.name.empty()) out["name"] = m.name;
  const float peak = std::max({m.emissive.r, m.emissive.g, m.emissive.b});
  if (peak > 0.0f) {
    const float strength = std::max(peak, 1.0f);
    out["emissiveFactor"] = vec(m.emissive / strength);
    if (strength > 1.0f) {
      out["extensions"]["KHR_materials_emissive_strength"] = {{"emissiveStrength", strength}};
      usesStrength = true;
    }
  }
  if (m.specularFactor != 1.0f) {
    out["extensions"]["KHR_materials_specular"] = {{"specularFactor", m.specularFactor}};
    usesSpecular = true;
  }
  if (m.doubleSided) out["doubleSided"] = true;
  if (m.alphaMode == AlphaMode::Mask) {
    out["alphaMode"] = "MASK";
    out["alphaCutoff"] = m.alphaCutoff;
  } else if (m.alphaMode == AlphaMode::Blend) {
    out["alphaMode"] = "BLEND";
  }
  return out;
}

json writeNode(const NodeAsset& n) {
  json out = json::object();
  if (!n.name.empty()) out["name"] = n.name;
  if (n.local.translation != glm::vec3(0.0f)) out["translation"] = vec(n.local.translation);
  const glm::quat& q = n.local.rotation;
  if (q != glm::quat(1.0f, 0.0f, 0.0f, 0.0f)) out["rotation"] = {q.x, q.y, q.z, q.w};
  if (n.local.scale != glm::vec3(1.0f)) out["scale"] = vec(n.local.scale);
  if (!n.children.empty()) out["children"] = n.children;
  if (n.mesh >= 0) out["mesh"] = n.mesh;
  if (n.camera >= 0) out["camera"] = n.camera;
  if (n.light >= 0) out["extensions"]["KHR_lights_punctual"] = {{"light", n.light}};
  return out;
}

json writeCamera(const CameraAsset& c) {
  json perspective = {{"yfov", c.yfov}, {"znear", c.znear}};
  if (std::isfinite(c.zfar)) perspective["zfar"] = c.zfar;
  if (c.aspectRatio > 0.0f) perspective["aspectRatio"] = c.aspectRatio;
  json out = {{"type", "perspective"}, {"perspective", perspective}};
  if (!c.name.empty()) out["name"] = c.name;
  return out;
}

json writeLight(const LightAsset& l) {
  static const char* kTypes[] = {"directional", "point", "spot"};
  json out = {{"type", kTypes[int(l.type)]}, {"color", vec(l.color)}, {"intensity", l.intensity}};
  if (!l.name.empty()) out["name"] = l.name;
  if (l.range > 0.0f && l.type != LightType::Directional) out["range"] = l.range;
  if (l.type == LightType::Spot)
    out["spot"] = {{"innerConeAngle", l.innerConeAngle}, {"outerConeAngle", l.outerConeAngle}};
  return out;
}

json writeAnimation(const AnimationAsset& a, BufferBuilder& buffer) {
  static const char* kPaths[] = {"translation", "rotation", "scale"};
  static const char* kInterpolations[] = {"STEP", "LINEAR", "CUBICSPLINE"};
  json samplers = json::array(), channels = json::array();
  for (const AnimationChannel& c : a.channels) {
    if (c.path == AnimationPath::Weights) continue;  // morph targets are not written
    const int input = buffer.addFloats(c.times, "SCALAR", 0, true);
    int output;
    if (c.path == AnimationPath::Rotation) {
      output = buffer.addFloats(c.values, "VEC4", 0, false);
    } else {
      std::vector<glm::vec3> v3(c.values.size());
      for (size_t i = 0; i < v3.size(); ++i) v3[i] = glm::vec3(c.values[i]);
      output = buffer.addFloats(v3, "VEC3", 0, false);
    }
    samplers.push_back({{"input", input},
                        {"output", output},
                        {"interpolation", kInterpolations[int(c.interpolation)]}});
    channels.push_back({{"sampler", samplers.size() - 1},
                        {"target", {{"node", c.node}, {"path", kPaths[int(c.path)]}}}});
  }
  json out = {{"samplers", samplers}, {"channels", channels}};
  if (!a.name.empty()) out["name"] = a.name;
  return out;
}

}  // namespace

std::string base64Encode(const void* data, size_t size) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* p = static_cast<const uint8_t*>(data);
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  for (size_t i = 0; i < size; i += 3) {
    const uint32_t b0 = p[i], b1 = i + 1 < size ? p[i + 1] : 0, b2 = i + 2 < size ? p[i + 2] : 0;
    const uint32_t triple = (b0 << 16) | (b1 << 8) | b2;
    out += kAlphabet[(triple >> 18) & 63];
    out += kAlphabet[(triple >> 12) & 63];
    out += i + 1 < size ? kAlphabet[(triple >> 6) & 63] : '=';
    out += i + 2 < size ? kAlphabet[triple & 63] : '=';
  }
  return out;
}

std::string toGltfJson(const SceneAsset& scene, const std::string& generator) {
  BufferBuilder buffer;
  json doc = {{"asset", {{"version", "2.0"}, {"generator", generator}}}};

  // The loader's synthetic default material is not written: its primitives get none.
  std::vector<int> materialIndex(scene.materials.size(), -1);
  json materials = json::array();
  bool usesStrength = false, usesSpecular = false;
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    if (int32_t(i) == scene.defaultMaterial) continue;
    materialIndex[i] = int(materials.size());
    materials.push_back(writeMaterial(scene.materials[i], usesStrength, usesSpecular));
  }

  json meshes = json::array();
  for (size_t i = 0; i < scene.meshes.size(); ++i)
    meshes.push_back(writeMesh(scene.meshes[i], i, materialIndex, buffer));
  json nodes = json::array();
  for (const NodeAsset& n : scene.nodes) nodes.push_back(writeNode(n));
  json animations = json::array();
  for (const AnimationAsset& a : scene.animations) animations.push_back(writeAnimation(a, buffer));

  json extensionsUsed = json::array();
  if (usesStrength) extensionsUsed.push_back("KHR_materials_emissive_strength");
  if (usesSpecular) extensionsUsed.push_back("KHR_materials_specular");
  if (!scene.lights.empty()) {
    extensionsUsed.push_back("KHR_lights_punctual");
    json lights = json::array();
    for (const LightAsset& l : scene.lights) lights.push_back(writeLight(l));
    doc["extensions"]["KHR_lights_punctual"]["lights"] = lights;
  }
  if (!extensionsUsed.empty()) doc["extensionsUsed"] = extensionsUsed;

  doc["scene"] = 0;
  doc["scenes"] = json::array({{{"nodes", scene.rootNodes}}});
  if (!nodes.empty()) doc["nodes"] = nodes;
  if (!meshes.empty()) doc["meshes"] = meshes;
  if (!materials.empty()) doc["materials"] = materials;
  if (!scene.cameras.empty()) {
    json cameras = json::array();
    for (const CameraAsset& c : scene.cameras) cameras.push_back(writeCamera(c));
    doc["cameras"] = cameras;
  }
  if (!animations.empty()) doc["animations"] = animations;
  if (!buffer.bytes().empty()) {
    doc["buffers"] =
        json::array({{{"byteLength", buffer.bytes().size()},
                      {"uri", "data:application/octet-stream;base64," +
                                  base64Encode(buffer.bytes().data(), buffer.bytes().size())}}});
    doc["bufferViews"] = buffer.views();
    doc["accessors"] = buffer.accessors();
  }
  return doc.dump(1) + "\n";
}

void saveGltf(const SceneAsset& scene, const std::filesystem::path& path,
              const std::string& generator) {
  const std::string text = toGltfJson(scene, generator);
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error(path.string() + ": cannot open for writing");
  out.write(text.data(), std::streamsize(text.size()));
  if (!out) throw std::runtime_error(path.string() + ": write failed");
}

}  // namespace qlight::gltf
