// glTF skins (joints, inverse bind matrices), the nodes' skin and morph weights, and a mesh of
// its own for every node whose mesh deforms (a node deforms its vertices by its own pose, so
// two such nodes cannot share them).
#include <glm/gtc/type_ptr.hpp>

#include "engine/gltf/gltf_accessor.h"
#include "engine/gltf/gltf_convert.h"

namespace qlight::gltf::detail {
namespace {

SkinAsset convertSkin(const tinygltf::Model& model, size_t index, LoadContext& ctx) {
  const tinygltf::Skin& skin = model.skins[index];
  const std::string owner = "skin " + std::to_string(index);
  SkinAsset out;
  out.name = skin.name;
  if (skin.joints.empty()) ctx.fail(owner + " has no joints");
  for (int joint : skin.joints) {
    if (joint < 0 || size_t(joint) >= model.nodes.size())
      ctx.fail(owner + " has joint " + std::to_string(joint) + ", which does not exist (" +
               std::to_string(model.nodes.size()) + " nodes)");
    out.joints.push_back(uint32_t(joint));
  }
  out.inverseBindMatrices.assign(out.joints.size(), glm::mat4(1.0f));
  if (skin.inverseBindMatrices >= 0) {
    const std::vector<float> m =
        readMat4Accessor(model, skin.inverseBindMatrices, owner + " inverseBindMatrices", ctx);
    if (m.size() / 16 < out.joints.size())
      ctx.fail(owner + " has " + std::to_string(m.size() / 16) + " inverseBindMatrices for " +
               std::to_string(out.joints.size()) + " joints");
    for (size_t j = 0; j < out.joints.size(); ++j)
      out.inverseBindMatrices[j] = glm::make_mat4(&m[16 * j]);
  }
  if (skin.skeleton >= 0 && size_t(skin.skeleton) >= model.nodes.size())
    ctx.fail(owner + " skeleton " + std::to_string(skin.skeleton) + " does not exist");
  return out;
}

// Joint indices the mesh's vertices use must exist in the skin.
void checkJointIndices(const MeshAsset& mesh, const SkinAsset& skin, const std::string& owner,
                       LoadContext& ctx) {
  for (size_t i = 0; i < mesh.deform.joints.size(); ++i)
    for (int k = 0; k < 4; ++k)
      if (mesh.deform.weights[i][k] > 0.0f && mesh.deform.joints[i][k] >= skin.joints.size())
        ctx.fail(owner + " vertex " + std::to_string(i) + " uses joint " +
                 std::to_string(mesh.deform.joints[i][k]) + " of a skin with " +
                 std::to_string(skin.joints.size()) + " joints");
}

bool deforms(const SceneAsset& scene, const NodeAsset& node) {
  if (node.mesh < 0) return false;
  const MeshAsset& mesh = scene.meshes[size_t(node.mesh)];
  return mesh.deform.morphed() || (node.skin >= 0 && mesh.deform.skinnable());
}

}  // namespace

void convertSkins(const tinygltf::Model& model, SceneAsset& scene, LoadContext& ctx) {
  for (size_t s = 0; s < model.skins.size(); ++s) scene.skins.push_back(convertSkin(model, s, ctx));
  for (size_t i = 0; i < model.nodes.size(); ++i) {
    const tinygltf::Node& node = model.nodes[i];
    NodeAsset& out = scene.nodes[i];
    const std::string owner = "node " + std::to_string(i);
    if (node.skin >= 0) {
      if (size_t(node.skin) >= scene.skins.size())
        ctx.fail(owner + " uses skin " + std::to_string(node.skin) + ", which does not exist (" +
                 std::to_string(scene.skins.size()) + " skins)");
      if (out.mesh < 0) {
        ctx.warn(owner + " has a skin but no mesh; the skin is ignored");
      } else if (!scene.meshes[size_t(out.mesh)].deform.skinnable()) {
        ctx.warn(owner + " has a skin but mesh " + std::to_string(out.mesh) +
                 " has no JOINTS_0/WEIGHTS_0; drawn unskinned");
      } else {
        checkJointIndices(scene.meshes[size_t(out.mesh)], scene.skins[size_t(node.skin)], owner,
                          ctx);
        out.skin = node.skin;
      }
    }
    if (!node.weights.empty()) {
      ctx.requireFiniteAll(node.weights, owner + " weights");
      const size_t targets =
          out.mesh >= 0 ? scene.meshes[size_t(out.mesh)].deform.targets.size() : 0;
      if (node.weights.size() != targets)
        ctx.warn(owner + " has " + std::to_string(node.weights.size()) + " weights for " +
                 std::to_string(targets) + " morph targets; the missing count as 0");
      out.weights.assign(node.weights.begin(), node.weights.end());
    }
  }

  // Every deforming node gets a mesh no other node uses (copies are appended, so the file's
  // mesh indices stay valid).
  std::vector<uint32_t> users(scene.meshes.size(), 0);
  for (const NodeAsset& node : scene.nodes)
    if (node.mesh >= 0) ++users[size_t(node.mesh)];
  for (NodeAsset& node : scene.nodes) {
    if (!deforms(scene, node) || users[size_t(node.mesh)] <= 1) continue;
    --users[size_t(node.mesh)];
    MeshAsset copy = scene.meshes[size_t(node.mesh)];
    scene.meshes.push_back(std::move(copy));
    node.mesh = int32_t(scene.meshes.size() - 1);
  }
}

}  // namespace qlight::gltf::detail
