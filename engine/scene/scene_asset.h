// A glTF 2.0 scene as plain data: what loadGltf() returns and what the GPU upload and the ECS
// instantiation read. Indices between arrays are glTF's own (node i here is node i in the
// file, material i is material i, texture i is texture i), so animation channels and
// debugging output line up with the file. -1 means "none" wherever an index is int32_t.
#pragma once

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "engine/scene/environment_asset.h"

namespace qlight::scene {

// A morph target's per-vertex offsets over a whole mesh (zero where a primitive's target
// leaves a vertex alone); normals empty when no primitive's target moves normals.
struct MorphTarget {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
};

// What moves a mesh's vertices at run time (engine/scene/deform.h); all empty for a rigid
// mesh. Per-vertex arrays have the mesh's vertex count.
struct MeshDeformation {
  std::vector<MorphTarget> targets;   // glTF order
  std::vector<float> defaultWeights;  // mesh.weights, one per target (0 where the file has none)
  // The vertices before any target (MeshAsset::positions/normals hold them at the default
  // weights, so code that ignores deformation sees the mesh as the file means it at rest).
  std::vector<glm::vec3> basePositions;
  std::vector<glm::vec3> baseNormals;
  // JOINTS_0 / WEIGHTS_0: four influences per vertex, weights normalized to sum 1.
  std::vector<glm::uvec4> joints;
  std::vector<glm::vec4> weights;
  // Triangles whose normals were generated flat: recomputed after each deformation.
  std::vector<uint32_t> flatTriangles;

  bool morphed() const { return !targets.empty(); }
  bool skinnable() const { return !joints.empty(); }
};

// One glTF mesh: all its triangle primitives concatenated into one indexed triangle list.
// positions/normals/uv0 always have the same length; uv0 is (0,0) where the file has no
// TEXCOORD_0. Normals missing in the file are generated flat (the glTF spec asks for flat
// normals): such a primitive is un-indexed so each triangle owns its three vertices.
// uv1, colors and tangents are either empty or one per position (a primitive without them
// gets (0,0), white and a generated tangent).
struct MeshAsset {
  std::string name;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // unit length
  std::vector<glm::vec2> uv0;
  std::vector<glm::vec2> uv1;               // TEXCOORD_1
  std::vector<glm::vec4> colors;            // COLOR_0, linear RGBA (RGB files: alpha 1)
  std::vector<glm::vec4> tangents;          // xyz unit, w = +-1 (bitangent = w * cross(n, t))
  std::vector<uint32_t> indices;            // 3 per triangle, each < positions.size()
  std::vector<uint32_t> triangleMaterials;  // 1 per triangle, index into SceneAsset::materials
  glm::vec3 boundsMin{0.0f};                // object space, over all positions
  glm::vec3 boundsMax{0.0f};
  MeshDeformation deform;  // morph targets and skin weights, if any

  size_t triangleCount() const { return indices.size() / 3; }
};

enum class AlphaMode : uint8_t { Opaque, Mask, Blend };

// How a material reads one texture: its UV set and KHR_texture_transform, applied as
// uv' = T(offset) R(rotation) S(scale) uv (the extension's order and sign of rotation).
struct TextureBinding {
  int32_t index = -1;     // into SceneAsset::textures; -1: none
  uint32_t texCoord = 0;  // TEXCOORD_0 or TEXCOORD_1
  glm::vec2 offset{0.0f};
  float rotation = 0.0f;  // radians
  glm::vec2 scale{1.0f};

  bool present() const { return index >= 0; }
};

// glTF metallic-roughness material. Textures index SceneAsset::textures.
struct MaterialAsset {
  std::string name;
  glm::vec4 baseColorFactor{1.0f};  // linear RGBA
  TextureBinding baseColorTexture;  // sRGB
  float metallicFactor = 1.0f;
  float roughnessFactor = 1.0f;
  TextureBinding metallicRoughnessTexture;  // linear; G = roughness, B = metallic
  // emissiveFactor x KHR_materials_emissive_strength: linear radiance, multiplied by the
  // emissive texture when there is one.
  glm::vec3 emissive{0.0f};
  TextureBinding emissiveTexture;  // sRGB
  TextureBinding normalTexture;    // tangent-space normals, linear
  float normalScale = 1.0f;        // scales the map's x and y
  // KHR_materials_unlit: the surface shows its base colour as emission and scatters nothing.
  bool unlit = false;
  // KHR_materials_transmission: the share of the diffuse base replaced by thin-walled
  // transmission; KHR_materials_ior: the dielectric's index of refraction (its F0).
  float transmissionFactor = 0.0f;
  float ior = 1.5f;
  // KHR_materials_volume with a thickness: the mesh is a solid the transmission refracts
  // into (its attenuation is not modelled); without it, a thin wall.
  bool volume = false;
  // KHR_materials_specular specularFactor: weight of the dielectric specular layer. 0 with
  // metallic 0 makes an exactly Lambertian surface (the generated scenes use it).
  float specularFactor = 1.0f;
  bool doubleSided = false;  // emitters emit from both sides only when set
  AlphaMode alphaMode = AlphaMode::Opaque;
  float alphaCutoff = 0.5f;

  // Emitters in the light list: unlit surfaces emit their base colour but are not lights.
  bool isEmissive() const {
    return !unlit && (emissive.x > 0.0f || emissive.y > 0.0f || emissive.z > 0.0f);
  }
};

enum class TextureWrap : uint8_t { Repeat, ClampToEdge, MirroredRepeat };

// A decoded texture: one per glTF texture, RGBA8 rows top to bottom (uv (0,0) is the first
// texel, as glTF says). A texture whose image could not be read is 1x1 white, with a warning.
struct TextureAsset {
  std::string name;
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> rgba8;  // width * height * 4
  bool srgb = false;           // used as baseColor or emissive
  TextureWrap wrapS = TextureWrap::Repeat;
  TextureWrap wrapT = TextureWrap::Repeat;
  bool nearestFilter = false;  // glTF magFilter NEAREST
};

// A node's transform relative to its parent: parentFromLocal = T * R * S (glTF order). Also the
// ECS component that animation writes (see components.h).
struct LocalTransform {
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // unit; glm's constructor order is w, x, y, z
  glm::vec3 scale{1.0f};

  friend bool operator==(const LocalTransform&, const LocalTransform&) = default;
};

struct NodeAsset {
  std::string name;
  int32_t parent = -1;
  std::vector<uint32_t> children;
  LocalTransform local;  // a `matrix` in the file is decomposed into T, R, S
  int32_t mesh = -1;
  int32_t camera = -1;
  int32_t light = -1;  // KHR_lights_punctual
  int32_t skin = -1;   // index into SceneAsset::skins, with a mesh that has JOINTS_0/WEIGHTS_0
  std::vector<float> weights;  // the node's morph weights (empty: the mesh's defaults)
  // EXT_mesh_gpu_instancing: the mesh is drawn once per transform (worldFromNode * instance),
  // not at the node itself. Empty: drawn once, at the node.
  std::vector<LocalTransform> instances;
};

// A glTF skin: joint nodes and their inverse bind matrices (identity where the file has none).
// A skinned vertex is sum_i w_i * worldFromJoint_i * inverseBind_i * v, in world space: the
// skinned node's own transform is ignored, as glTF says.
struct SkinAsset {
  std::string name;
  std::vector<uint32_t> joints;                // node indices
  std::vector<glm::mat4> inverseBindMatrices;  // one per joint
};

// A perspective camera looking down its node's -Z with +Y up (glTF).
struct CameraAsset {
  std::string name;
  float yfov = 0.7854f;   // radians
  float aspectRatio = 0;  // 0: use the viewport's
  float znear = 0.01f;
  float zfar = std::numeric_limits<float>::infinity();  // infinite when the file gives none
  // The file's camera was orthographic; it was replaced by a perspective camera at the same
  // node that frames the same xmag x ymag extent at the distance of the scene's center.
  bool fromOrthographic = false;
};

enum class LightType : uint8_t { Directional, Point, Spot };

// KHR_lights_punctual, in its units: point/spot intensity in candela (lm/sr), directional in
// lux. The light points down its node's -Z.
struct LightAsset {
  std::string name;
  LightType type = LightType::Point;
  glm::vec3 color{1.0f};
  float intensity = 1.0f;
  float range = 0.0f;  // 0: infinite
  float innerConeAngle = 0.0f;
  float outerConeAngle = 0.7853981634f;
};

enum class AnimationPath : uint8_t { Translation, Rotation, Scale, Weights };
enum class Interpolation : uint8_t { Step, Linear, CubicSpline };

// One channel with its sampler's data copied in. values hold (x, y, z, 0) for translation and
// scale and (x, y, z, w) for rotation. For CubicSpline there are three values per key:
// in-tangent, value, out-tangent (glTF order); otherwise one per key. A Weights channel keeps
// its values in `weights` instead: weightCount floats per value, in the same order.
struct AnimationChannel {
  uint32_t node = 0;
  AnimationPath path = AnimationPath::Translation;
  Interpolation interpolation = Interpolation::Linear;
  std::vector<float> times;  // seconds, strictly increasing, at least one key
  std::vector<glm::vec4> values;
  std::vector<float> weights;
  uint32_t weightCount = 0;  // morph targets of the node's mesh (Weights channels)
};

struct AnimationAsset {
  std::string name;
  std::vector<AnimationChannel> channels;
  float duration = 0.0f;  // last key time over all channels
};

struct Bounds {
  glm::vec3 min{std::numeric_limits<float>::infinity()};
  glm::vec3 max{-std::numeric_limits<float>::infinity()};

  bool empty() const { return !(min.x <= max.x && min.y <= max.y && min.z <= max.z); }
  glm::vec3 center() const { return empty() ? glm::vec3(0.0f) : 0.5f * (min + max); }
  float radius() const { return empty() ? 0.0f : 0.5f * glm::length(max - min); }
  void include(glm::vec3 p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
};

struct SceneAsset {
  std::filesystem::path source;
  std::vector<MeshAsset> meshes;
  std::vector<MaterialAsset> materials;  // the file's, then the default one if needed
  std::vector<TextureAsset> textures;
  std::vector<NodeAsset> nodes;     // every node in the file
  std::vector<uint32_t> rootNodes;  // roots of the scene shown (`scene`, else scenes[0])
  std::vector<CameraAsset> cameras;
  std::vector<LightAsset> lights;
  std::vector<SkinAsset> skins;
  std::vector<AnimationAsset> animations;
  // Index of the material given to primitives without one (-1 if every primitive has one):
  // glTF's default, baseColor 1, metallic 1, roughness 1, kept as the spec says.
  int32_t defaultMaterial = -1;
  Bounds bounds;                      // world space, of the shown scene's mesh instances at t = 0
  std::vector<std::string> warnings;  // one line each, also printed to stderr when loading
  // The user's environment light (not from the file); absent: the fallback sky lights a
  // scene without any light (GpuScene).
  std::optional<EnvironmentAsset> environment;

  // Longest animation, 0 without animations.
  float animationDuration() const {
    float d = 0.0f;
    for (const AnimationAsset& a : animations) d = d > a.duration ? d : a.duration;
    return d;
  }
};

}  // namespace qlight::scene
