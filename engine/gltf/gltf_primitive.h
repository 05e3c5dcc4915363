// Internal to the glTF loader: one primitive's vertices before they join their mesh, and the
// reading of what deforms them (JOINTS_0/WEIGHTS_0 and morph targets; gltf_mesh_deform.cpp),
// kept apart from gltf_meshes.cpp so that more per-vertex attributes stay local edits.
#pragma once

#include <tiny_gltf.h>

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "engine/gltf/gltf_context.h"
#include "engine/scene/scene_asset.h"

namespace qlight::gltf::detail {
using namespace ::qlight::scene;

struct PrimitiveDeform {
  std::vector<glm::uvec4> joints;  // JOINTS_0, empty without a skin
  std::vector<glm::vec4> weights;  // WEIGHTS_0
  // Morph targets: the vertices before any target, and each target's offsets (normals empty
  // when the target has none, or the primitive's normals are generated).
  std::vector<glm::vec3> basePositions, baseNormals;
  std::vector<std::vector<glm::vec3>> targetPositions, targetNormals;
};

struct PrimitiveData {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // empty: generate flat normals
  std::vector<glm::vec2> uv0;
  std::vector<glm::vec2> uv1;  // empty: none (as the next two)
  std::vector<glm::vec4> colors;
  std::vector<glm::vec4> tangents;
  std::vector<uint32_t> triangles;  // 3 per triangle
  PrimitiveDeform deform;
};

// JOINTS_n and WEIGHTS_n: read by readSkinAttributes, not by the generic attribute loop.
bool isSkinAttribute(const std::string& name);
// JOINTS_0 and WEIGHTS_0 (both or neither); JOINTS_1 and above are ignored with a warning.
void readSkinAttributes(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                        const std::string& owner, PrimitiveData& data, LoadContext& ctx);
// POSITION and NORMAL targets (others are bounds-checked only): positions and normals become
// the mesh's default weights' pose, the base and offsets are kept for animation.
void readMorphTargets(const tinygltf::Model& model, const tinygltf::Mesh& mesh,
                      const tinygltf::Primitive& prim, const std::string& owner,
                      PrimitiveData& data, LoadContext& ctx);
// The deform arrays reordered as the vertices were: new vertex i was old vertex order[i].
void reorderDeform(PrimitiveDeform& deform, const std::vector<uint32_t>& order);
// Appends a primitive's deform data to its mesh, whose positions/normals already hold the
// primitive's vertices from `firstVertex` on. finishDeform pads every array to the mesh's
// vertex count and normalizes the skin weights.
void appendDeform(MeshAsset& mesh, const PrimitiveDeform& deform, size_t firstVertex);
void finishDeform(MeshAsset& mesh, const tinygltf::Mesh& source, const std::string& owner,
                  LoadContext& ctx);

}  // namespace qlight::gltf::detail
